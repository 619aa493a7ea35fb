// Joint Demo scene (docs/book-reference.md §2.8): CH14's spawn and ramps, pairs (i, i + n/2) held by distance joints,
// erratum 5.2-23 (odd count), joints at rest keep their length, determinism.
#include "Demos/Scenes/JointScene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>
#include <vector>

#include "tests/support/Approx.h"

namespace {

std::vector<float> Snapshot(const JointScene& scene) {
    std::vector<float> out;
    for (const Particle& p : scene.Particles())
        for (const vec3& v : {p.GetPosition(), p.GetVelocity()}) out.insert(out.end(), {v.x, v.y, v.z});
    return out;
}

}  // namespace

TEST(JointScene, BookSpawnAndConstraints) {
    JointScene scene;
    ASSERT_EQ(scene.Particles().size(), 50u);
    ASSERT_EQ(scene.Joints().size(), 25u);
    // The first particles are CH14's (MSVC rand, seed 1; docs/book-reference.md §0).
    EXPECT_TRUE(VecNear(scene.Particles()[0].GetPosition(), vec3(-4.34086f, 6.75434f, -3.48493f), tol::kBook));
    EXPECT_NEAR(scene.Particles()[0].GetBounce(), 0.80874f, tol::kBook);
    EXPECT_TRUE(VecNear(scene.Particles()[1].GetPosition(), vec3(0.15466f, 6.41949f, -2.21810f), tol::kBook));
    const auto& c = scene.System().Constraints();
    ASSERT_EQ(c.size(), 4u);
    EXPECT_TRUE(VecNear(c[0].size, vec3(10, 0.15f, 10), 0.0f));
    EXPECT_TRUE(VecNear(c[1].position, vec3(0, 1.86f, -1.92f), 0.0f));
    EXPECT_TRUE(VecNear(vec3(c[1].orientation.asArray[3], c[1].orientation.asArray[4], c[1].orientation.asArray[5]),
                        vec3(0, 0.85971f, 0.51078f), tol::kBook));
    EXPECT_TRUE(VecNear(c[2].position, vec3(-1, 3.6f, 1.2f), 0.0f));
    EXPECT_TRUE(VecNear(vec3(c[2].orientation.asArray[0], c[2].orientation.asArray[1], c[2].orientation.asArray[2]),
                        vec3(0.93671f, 0.13157f, 0.32443f), tol::kBook));
    EXPECT_TRUE(VecNear(c[3].size, vec3(2, 0.15f, 0.7817011f), 0.0f));
    for (int i = 0; i < 25; ++i) {
        EXPECT_EQ(scene.Joints()[i].p1, &scene.Particles()[i]);
        EXPECT_EQ(scene.Joints()[i].p2, &scene.Particles()[i + 25]);
        EXPECT_GE(scene.Joints()[i].length, 0.5f);
        EXPECT_LE(scene.Joints()[i].length, 1.0f);
    }
    for (const Particle& p : scene.Particles()) {
        const vec3 d = p.GetPosition() - JointScene::SpawnCenter();
        EXPECT_LE(std::fabs(d.x), JointScene::SpawnHalfSize().x + 1e-4f);
        EXPECT_LE(std::fabs(d.y), JointScene::SpawnHalfSize().y + 1e-4f);
        EXPECT_LE(std::fabs(d.z), JointScene::SpawnHalfSize().z + 1e-4f);
    }
}

// erratum 5.2-23: for an odd count the book bumps the SLIDER and still creates the odd number, leaving one
// particle without a joint (51 particles, 25 joints). The fix creates the even count: every particle jointed.
TEST(JointScene, Erratum5_2_23_OddCountCreatesEvenJointedSet) {
    JointParams params;
    params.particleCount = 51;
    JointScene scene(params);
    EXPECT_EQ(scene.Params().particleCount, 51);  // the slider value is left alone
    ASSERT_EQ(scene.Particles().size(), 52u);
    ASSERT_EQ(scene.Joints().size(), 26u);
    std::set<const Particle*> jointed;
    for (const DistanceJoint& j : scene.Joints()) {
        jointed.insert(j.p1);
        jointed.insert(j.p2);
    }
    EXPECT_EQ(jointed.size(), 52u);
}

// Joints are solved last each step, so after the pile has come down (2,000 steps = 60 s) every pair is at its length
// within 1e-5 m (float positions near 5 m have an ulp of 5e-7), for every integrator.
TEST(JointScene, JointsKeepLengthAtRest) {
    for (Integrator integrator : kAllIntegrators) {
        JointParams params;
        params.integrator = integrator;
        JointScene scene(params);
        for (int i = 0; i < 2000; ++i) ASSERT_TRUE(scene.Step(scene.Params().dt)) << scene.Monitor().Report().message;
        for (const DistanceJoint& j : scene.Joints()) {
            EXPECT_NEAR(Magnitude(j.p2->GetPosition() - j.p1->GetPosition()), j.length, 1e-5f) << ToString(integrator);
        }
        for (const Particle& p : scene.Particles()) EXPECT_GE(p.GetPosition().y, 0.15f - 0.01f);  // on or above ground
    }
}

TEST(JointScene, ResetDrawsNewSpawnFromTheSameGenerator) {
    // The book never reseeds rand(): a second reset spawns elsewhere; a fresh generator replays the first.
    MsvcRand rng;
    JointScene scene(JointParams(), &rng);
    const vec3 first = scene.Particles()[0].GetPosition();
    scene.Reset();
    EXPECT_FALSE(VecNear(scene.Particles()[0].GetPosition(), first, 1e-3f));
    JointScene fresh;
    EXPECT_TRUE(VecNear(fresh.Particles()[0].GetPosition(), first, 0.0f));
}

TEST(JointScene, ParametersCoverThePanel) {
    JointScene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    for (const char* key : {"count", "reset", "integrator", "dt"}) EXPECT_NE(set.Find(key), nullptr) << key;
    std::string error;
    ASSERT_TRUE(set.Set("count", "7", &error)) << error;
    EXPECT_EQ(scene.Particles().size(), 8u);
    EXPECT_FALSE(set.Set("count", "1", &error));  // slider 2..100
    EXPECT_FALSE(set.Set("count", "101", &error));
}

TEST(JointScene, DeterministicBitForBit) {
    JointScene a, b;
    for (int i = 0; i < 500; ++i) {
        a.Step(a.Params().dt);
        b.Step(b.Params().dt);
    }
    const std::vector<float> sa = Snapshot(a), sb = Snapshot(b);
    ASSERT_EQ(sa.size(), 50u * 6u);
    ASSERT_EQ(sa.size(), sb.size());
    EXPECT_EQ(std::memcmp(sa.data(), sb.data(), sa.size() * sizeof(float)), 0);
}
