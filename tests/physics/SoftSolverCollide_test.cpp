// SoftSolverCollide.cpp: the soft solver's narrow phase reuses a box pair's manifold while the pair has barely moved
// (SoftSolverSettings::manifoldReuseDistance, docs/soft-solver.md "Manifold reuse"), and collides it anew otherwise.
#include <gtest/gtest.h>

#include <cmath>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/SoftSolver.h"
#include "tests/support/TestWorld.h"
#include "tests/support/Volumes.h"

namespace {

constexpr float kDt = 1.0f / 60.0f;

}  // namespace

// A tower of 10 cubes at rest: after it settles its ten pairs reuse their manifolds step after step. Both towers
// stand; they sway by about 3 mm at the top over 5 s, and the reusing one ends within 2.5 mm of the one collided anew
// every step, its deepest point within 0.1 mm as deep.
TEST(SoftSolverCollide, RestingTowerReusesItsManifoldsAndEndsWhereCollidingEveryStepEnds) {
    TestWorld reusing(PeerTower(10)), colliding(PeerTower(10));
    for (TestWorld* w : {&reusing, &colliding}) w->system.settings.contactSolver = ContactSolver::Soft;
    colliding.system.settings.soft.manifoldReuseDistance = 0.0f;
    std::size_t reused = 0;
    for (int i = 0; i < 300; ++i) {
        reusing.system.Update(kDt);
        colliding.system.Update(kDt);
        reused += reusing.system.SoftSolver().ManifoldReuseCount();
        ASSERT_EQ(colliding.system.SoftSolver().ManifoldReuseCount(), 0u) << "step " << i;
    }
    EXPECT_EQ(reusing.system.SoftSolver().PairCount(), 10u);
    EXPECT_EQ(reusing.system.SoftSolver().ManifoldReuseCount(), 10u);
    EXPECT_GT(reused, 10u * 250u) << "most steps reuse every pair";
    EXPECT_EQ(reusing.system.SoftSolver().WarmStartedCount(), reusing.system.SoftSolver().ContactCount());
    for (std::size_t i = 0; i < reusing.Bodies().size(); ++i)
        EXPECT_LT(Magnitude(reusing.Body(i).position - colliding.Body(i).position), 0.0025f) << "body " << i;
    EXPECT_NEAR(reusing.system.SoftSolver().DeepestPenetration(), colliding.system.SoftSolver().DeepestPenetration(),
                1e-4f);
    EXPECT_LT(reusing.MaxDisplacement(), 0.01f);
    EXPECT_LT(colliding.MaxDisplacement(), 0.01f);
}

// A cube sliding at 5 m/s moves 8 cm a step relative to the ground: its manifold is never reused. After the body
// list is rebuilt (ClearRigidbodys), the first step reuses nothing even for a cube at rest.
TEST(SoftSolverCollide, MovingOrRebuiltPairsAreCollidedAnew) {
    BodySpec cube = BoxSpec(vec3(0.0f, 0.5f, 0.0f), vec3(0.5f, 0.5f, 0.5f), 1.0f);
    cube.friction = 0.0f;
    cube.velocity = vec3(5.0f, 0.0f, 0.0f);
    TestWorld sliding(WithGround(GroundSpec(vec3(50.0f, 0.5f, 50.0f)), {cube}));
    sliding.system.settings.contactSolver = ContactSolver::Soft;
    for (int i = 0; i < 30; ++i) {
        sliding.system.Update(kDt);
        ASSERT_EQ(sliding.system.SoftSolver().PairCount(), 1u);
        EXPECT_EQ(sliding.system.SoftSolver().ManifoldReuseCount(), 0u) << "step " << i;
    }

    cube.velocity = vec3();
    TestWorld resting(WithGround(GroundSpec(vec3(50.0f, 0.5f, 50.0f)), {cube}));
    resting.system.settings.contactSolver = ContactSolver::Soft;
    for (int i = 0; i < 60; ++i) resting.system.Update(kDt);
    EXPECT_EQ(resting.system.SoftSolver().ManifoldReuseCount(), 1u);
    resting.system.ClearRigidbodys();
    for (std::size_t i = 0; i < resting.Bodies().size(); ++i)
        ASSERT_TRUE(resting.system.AddRigidbody(&resting.Body(i)));
    resting.system.Update(kDt);
    EXPECT_EQ(resting.system.SoftSolver().ManifoldReuseCount(), 0u) << "a rebuilt body list reuses nothing";
    resting.system.Update(kDt);
    EXPECT_EQ(resting.system.SoftSolver().ManifoldReuseCount(), 1u);
}
