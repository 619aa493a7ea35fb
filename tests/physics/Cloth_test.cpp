// Cloth::Initialize (docs/book-reference.md §3.7): grid layout, spring counts and rest lengths, particle settings,
// errata 5.2-21 (late size clamp, scaled offset).
#include "Physics/Cloth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "tests/support/Approx.h"

namespace {

int Structural(int n) { return 2 * n * (n - 1); }
int Shear(int n) { return 2 * (n - 1) * (n - 1); }
int Bend(int n) { return 2 * n * (n - 2); }

bool Owns(const Cloth& c, const Particle* p) { return p >= c.verts.data() && p < c.verts.data() + c.verts.size(); }

}  // namespace

TEST(Cloth, BookCountsForFifteen) {
    Cloth cloth;
    cloth.Initialize(15, 0.2f, vec3(0, 6, 0));
    EXPECT_EQ(cloth.verts.size(), 225u);
    EXPECT_EQ(cloth.structural.size(), 420u);
    EXPECT_EQ(cloth.shear.size(), 392u);
    EXPECT_EQ(cloth.bend.size(), 390u);
    EXPECT_EQ(cloth.GridSize(), 15);
}

TEST(Cloth, CountsFollowFormulas) {
    for (int n = 3; n <= 9; ++n) {
        Cloth cloth;
        cloth.Initialize(n, 1.0f, vec3());
        EXPECT_EQ(static_cast<int>(cloth.structural.size()), Structural(n)) << n;
        EXPECT_EQ(static_cast<int>(cloth.shear.size()), Shear(n)) << n;
        EXPECT_EQ(static_cast<int>(cloth.bend.size()), Bend(n)) << n;
    }
}

TEST(Cloth, BookGridPositions) {
    // CH16: x, z in {(i - 7) * 0.2}, y = 6; index z*N + x.
    Cloth cloth;
    cloth.Initialize(15, 0.2f, vec3(0, 6, 0));
    EXPECT_TRUE(VecNear(cloth.verts[0].GetPosition(), vec3(-1.4f, 6, -1.4f), tol::kTight));
    EXPECT_TRUE(VecNear(cloth.verts[14].GetPosition(), vec3(1.4f, 6, -1.4f), tol::kTight));
    EXPECT_TRUE(VecNear(cloth.verts[15].GetPosition(), vec3(-1.4f, 6, -1.2f), tol::kTight));
    EXPECT_TRUE(VecNear(cloth.verts[7 * 15 + 7].GetPosition(), vec3(0, 6, 0), tol::kTight));
    EXPECT_TRUE(VecNear(cloth.verts[224].GetPosition(), vec3(1.4f, 6, 1.4f), tol::kTight));
    for (const Particle& p : cloth.verts) EXPECT_TRUE(VecNear(p.GetOldPosition(), p.GetPosition(), 0.0f));
}

// erratum 5.2-21: the book computes (x + position.x - half) * distance, so an off-origin cloth moves by
// position * distance: with N = 3, d = 0.5 and position (10, 2, -4) its corner lands at (4.5, 2, -2.5).
TEST(Cloth, Erratum5_2_21_OffsetIsNotScaledBySpacing) {
    Cloth cloth;
    cloth.Initialize(3, 0.5f, vec3(10, 2, -4));
    EXPECT_TRUE(VecNear(cloth.verts[0].GetPosition(), vec3(9.5f, 2, -4.5f), tol::kTight));
    EXPECT_TRUE(VecNear(cloth.verts[4].GetPosition(), vec3(10, 2, -4), tol::kTight));
    EXPECT_TRUE(VecNear(cloth.verts[8].GetPosition(), vec3(10.5f, 2, -3.5f), tol::kTight));
}

// erratum 5.2-21: the book sizes verts for the unclamped N (1 particle for N = 1) and then fills a 3 x 3
// grid, writing past the end (ASan reports it). Clamping first gives a consistent 3 x 3 cloth.
TEST(Cloth, Erratum5_2_21_SizeClampedBeforeAllocation) {
    for (int n : {-4, 0, 1, 2}) {
        Cloth cloth;
        cloth.Initialize(n, 0.2f, vec3(0, 1, 0));
        EXPECT_EQ(cloth.GridSize(), 3) << n;
        ASSERT_EQ(cloth.verts.size(), 9u) << n;
        EXPECT_EQ(static_cast<int>(cloth.structural.size()), Structural(3));
        EXPECT_EQ(static_cast<int>(cloth.shear.size()), Shear(3));
        EXPECT_EQ(static_cast<int>(cloth.bend.size()), Bend(3));
        EXPECT_TRUE(VecNear(cloth.verts[4].GetPosition(), vec3(0, 1, 0), tol::kTight));
    }
}

TEST(Cloth, ParticleSettings) {
    Cloth cloth;
    cloth.Initialize(4, 0.3f, vec3());
    for (const Particle& p : cloth.verts) {
        EXPECT_EQ(p.GetMass(), 1.0f);
        EXPECT_EQ(p.GetBounce(), 0.0f);
        EXPECT_EQ(p.GetVelocityRetention(), 0.9f);
        EXPECT_TRUE(VecNear(p.GetVelocity(), vec3(), 0.0f));
    }
    cloth.SetParticleMass(2.5f);
    cloth.SetParticleVelocityRetention(0.5f);
    for (const Particle& p : cloth.verts) {
        EXPECT_EQ(p.GetMass(), 2.5f);
        EXPECT_EQ(p.GetVelocityRetention(), 0.5f);
    }
}

TEST(Cloth, RestLengthsAndNeighbours) {
    const float d = 0.25f;
    Cloth cloth;
    cloth.Initialize(6, d, vec3(1, 2, 3));
    auto check = [&](const std::vector<Spring>& springs, float rest, const char* name) {
        std::set<std::pair<const Particle*, const Particle*>> seen;
        for (const Spring& s : springs) {
            ASSERT_TRUE(Owns(cloth, s.GetP1()) && Owns(cloth, s.GetP2())) << name;
            EXPECT_NE(s.GetP1(), s.GetP2()) << name;
            EXPECT_NEAR(s.restingLength, rest, tol::kTight) << name;
            EXPECT_NEAR(Magnitude(s.GetP2()->GetPosition() - s.GetP1()->GetPosition()), rest, tol::kTight) << name;
            EXPECT_TRUE(seen.insert({std::min(s.GetP1(), s.GetP2()), std::max(s.GetP1(), s.GetP2())}).second)
                << name << ": duplicate spring";
            EXPECT_EQ(s.k, -1.0f);  // book default
            EXPECT_EQ(s.b, 0.0f);
        }
    };
    check(cloth.structural, d, "structural");
    check(cloth.shear, d * std::sqrt(2.0f), "shear");
    check(cloth.bend, 2.0f * d, "bend");
}

TEST(Cloth, SetSpringsPerFamily) {
    Cloth cloth;
    cloth.Initialize(5, 0.2f, vec3());
    cloth.SetStructuralSprings(-1.5f, 0.1f);
    cloth.SetShearSprings(-2.5f, 0.2f);
    cloth.SetBendSprings(-3.5f, 0.3f);
    for (const Spring& s : cloth.structural) EXPECT_TRUE(s.k == -1.5f && s.b == 0.1f);
    for (const Spring& s : cloth.shear) EXPECT_TRUE(s.k == -2.5f && s.b == 0.2f);
    for (const Spring& s : cloth.bend) EXPECT_TRUE(s.k == -3.5f && s.b == 0.3f);
}

TEST(Cloth, ReinitializeReplacesEverything) {
    Cloth cloth;
    cloth.Initialize(10, 0.2f, vec3());
    cloth.Initialize(4, 0.5f, vec3(0, 3, 0));
    EXPECT_EQ(cloth.verts.size(), 16u);
    EXPECT_EQ(static_cast<int>(cloth.structural.size()), Structural(4));
    for (const Spring& s : cloth.bend) EXPECT_TRUE(Owns(cloth, s.GetP1()) && Owns(cloth, s.GetP2()));
}
