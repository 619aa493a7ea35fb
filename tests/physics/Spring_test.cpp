// Spring (docs/book-reference.md §3.6): Hooke force with the book's sign, damping along the axis (erratum 5.2-20),
// guard for coincident particles (erratum 5.2-6). Hand-computed cases; dynamics are in PhysicsSystemSprings_test.
#include "Physics/Spring.h"

#include <gtest/gtest.h>

#include <cmath>

#include "Physics/Particle.h"
#include "tests/support/Approx.h"

namespace {

struct Pair {
    Particle a, b;
    Pair(const vec3& pa, const vec3& pb) {
        a.SetPosition(pa);
        b.SetPosition(pb);
    }
};

Spring Make(Pair& pair, float k, float b, float rest) {
    Spring s(k, b, rest);
    s.SetParticles(&pair.a, &pair.b);
    return s;
}

}  // namespace

TEST(Spring, ConstructorAndSetters) {
    Spring s(-2.0f, 0.5f, 1.5f);
    EXPECT_EQ(s.k, -2.0f);
    EXPECT_EQ(s.b, 0.5f);
    EXPECT_EQ(s.restingLength, 1.5f);
    EXPECT_EQ(s.GetP1(), nullptr);
    s.SetConstants(-4.0f, 0.25f);
    EXPECT_EQ(s.k, -4.0f);
    EXPECT_EQ(s.b, 0.25f);
    Particle p, q;
    s.SetParticles(&p, &q);
    EXPECT_EQ(s.GetP1(), &p);
    EXPECT_EQ(s.GetP2(), &q);
}

TEST(Spring, StretchedNegativeKAttracts) {
    // |relPos| = 2, rest 1, k = -10: F = -k*x = 10 along p1->p2 on p1, opposite on p2.
    Pair pair(vec3(0, 0, 0), vec3(2, 0, 0));
    Make(pair, -10.0f, 0.0f, 1.0f).ApplyForce(0.03f);
    EXPECT_TRUE(VecNear(pair.a.GetForces(), vec3(10, 0, 0), tol::kExact));
    EXPECT_TRUE(VecNear(pair.b.GetForces(), vec3(-10, 0, 0), tol::kExact));
}

TEST(Spring, CompressedNegativeKRepels) {
    // Diagonal axis (0.6, 0.8), length 0.5, rest 1: x = -0.5, F = -(-4)(-0.5) = -2 along the axis on p1.
    Pair pair(vec3(1, 1, 1), vec3(1.3f, 1.4f, 1));
    Make(pair, -4.0f, 0.0f, 1.0f).ApplyForce(0.03f);
    EXPECT_TRUE(VecNear(pair.a.GetForces(), vec3(-1.2f, -1.6f, 0), tol::kTight));
    EXPECT_TRUE(VecNear(pair.b.GetForces(), vec3(1.2f, 1.6f, 0), tol::kTight));
}

TEST(Spring, ForcesAddToExistingForcesAndLeaveVelocityAlone) {
    // The force is integrated by the system over the step (erratum 5.2-20): ApplyForce must not change
    // velocity (the book added F*invMass to velocity directly).
    Pair pair(vec3(0, 0, 0), vec3(0, 3, 0));
    pair.a.AddForce(vec3(0, -1, 0));
    Make(pair, -1.0f, 0.0f, 1.0f).ApplyForce(0.03f);
    EXPECT_TRUE(VecNear(pair.a.GetForces(), vec3(0, 1, 0), tol::kExact));
    EXPECT_TRUE(VecNear(pair.a.GetVelocity(), vec3(), 0.0f));
    EXPECT_TRUE(VecNear(pair.b.GetVelocity(), vec3(), 0.0f));
}

TEST(Spring, ForceDoesNotDependOnDtArgument) {
    Pair p1(vec3(0, 0, 0), vec3(2, 0, 0)), p2(vec3(0, 0, 0), vec3(2, 0, 0));
    Make(p1, -3.0f, 0.0f, 1.0f).ApplyForce(0.001f);
    Make(p2, -3.0f, 0.0f, 1.0f).ApplyForce(0.1f);
    EXPECT_TRUE(VecNear(p1.a.GetForces(), p2.a.GetForces(), 0.0f));
}

// erratum 5.2-20: the book's damping is -b*|relVel|. For a separating pair at rest length it PUSHES the
// particles apart (-b*v on p1 along the axis); the fix pulls them together (+b*v), opposing separation.
TEST(Spring, Erratum5_2_20_DampingOpposesSeparation) {
    Pair pair(vec3(0, 0, 0), vec3(1, 0, 0));
    pair.b.SetVelocity(vec3(3, 0, 0));  // separating at 3 m/s
    Make(pair, -5.0f, 2.0f, 1.0f).ApplyForce(0.03f);
    EXPECT_TRUE(VecNear(pair.a.GetForces(), vec3(6, 0, 0), tol::kExact));  // the book gives (-6, 0, 0)
    EXPECT_TRUE(VecNear(pair.b.GetForces(), vec3(-6, 0, 0), tol::kExact));
}

TEST(Spring, Erratum5_2_20_DampingOpposesApproach) {
    Pair pair(vec3(0, 0, 0), vec3(1, 0, 0));
    pair.a.SetVelocity(vec3(1, 0, 0));  // approaching at 1 m/s
    Make(pair, -5.0f, 2.0f, 1.0f).ApplyForce(0.03f);
    EXPECT_TRUE(VecNear(pair.a.GetForces(), vec3(-2, 0, 0), tol::kExact));
    EXPECT_TRUE(VecNear(pair.b.GetForces(), vec3(2, 0, 0), tol::kExact));
}

// erratum 5.2-20: velocity perpendicular to the spring does not change its length, so it is not damped.
// The book's -b*|relVel| gives a force of magnitude b*|v| = 8 here.
TEST(Spring, Erratum5_2_20_PerpendicularVelocityIsNotDamped) {
    Pair pair(vec3(0, 0, 0), vec3(1, 0, 0));
    pair.b.SetVelocity(vec3(0, 4, -2));
    Make(pair, -5.0f, 2.0f, 1.0f).ApplyForce(0.03f);
    EXPECT_TRUE(VecNear(pair.a.GetForces(), vec3(), tol::kExact));
    EXPECT_TRUE(VecNear(pair.b.GetForces(), vec3(), tol::kExact));
}

// erratum 5.2-6: the book normalises the zero relPos of coincident particles and writes NaN.
TEST(Spring, Erratum5_2_6_CoincidentParticlesGiveFiniteZeroForce) {
    Pair pair(vec3(1, 2, 3), vec3(1, 2, 3));
    pair.b.SetVelocity(vec3(1, 0, 0));
    Make(pair, -5.0f, 1.0f, 1.0f).ApplyForce(0.03f);
    EXPECT_TRUE(IsFinite(pair.a.GetForces()));
    EXPECT_TRUE(IsFinite(pair.b.GetForces()));
    EXPECT_TRUE(VecNear(pair.a.GetForces(), vec3(), 0.0f));
}

TEST(Spring, ZeroRestLengthPullsTogether) {
    Pair pair(vec3(0, 0, 0), vec3(0, 0, 0.5f));
    Make(pair, -2.0f, 0.0f, 0.0f).ApplyForce(0.03f);
    EXPECT_TRUE(VecNear(pair.a.GetForces(), vec3(0, 0, 1), tol::kExact));
    Pair same(vec3(0, 0, 0), vec3(0, 0, 0));
    Make(same, -2.0f, 0.0f, 0.0f).ApplyForce(0.03f);
    EXPECT_TRUE(VecNear(same.a.GetForces(), vec3(), 0.0f));
}

TEST(Spring, WithoutParticlesDoesNothing) {
    Spring s(-1.0f, 0.0f, 1.0f);
    s.ApplyForce(0.03f);  // must not crash
    EXPECT_EQ(s.PotentialEnergy(), 0.0f);
}

TEST(Spring, PotentialEnergy) {
    Pair pair(vec3(0, 0, 0), vec3(0, 3, 0));
    EXPECT_NEAR(Make(pair, -4.0f, 0.0f, 1.0f).PotentialEnergy(), 0.5f * 4.0f * 4.0f, tol::kTight);
    EXPECT_NEAR(Make(pair, -4.0f, 0.0f, 5.0f).PotentialEnergy(), 0.5f * 4.0f * 4.0f, tol::kTight);
}

TEST(Spring, BookConstantConversion) {
    // A book k is a velocity change per 0.03 s step: k_phys = k_book / 0.03.
    EXPECT_EQ(kBookSpringStep, 0.03f);
    EXPECT_NEAR(FromBookSpringConstant(-3.0f), -100.0f, 1e-4f);
    EXPECT_NEAR(FromBookSpringConstant(0.5f), 16.6666667f, 1e-4f);
    EXPECT_EQ(FromBookSpringConstant(0.0f), 0.0f);
}
