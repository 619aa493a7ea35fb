// PhysicsSystem::Collisions() with ContactSolver::Soft: the soft step's touching contacts in the book's manifold form
// (points, normal, depth), the same list every solver fills. 60 Hz; cubes of half extent 0.5 on a static ground box
// of half extents (50, 0.5, 50) whose top is y = 0.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/PhysicsSystem.h"
#include "tests/support/TestWorld.h"
#include "tests/support/Volumes.h"

namespace {

constexpr float kDt = 1.0f / 60.0f;

BodySpec Cube(const vec3& position, float mass = 1.0f) {
    BodySpec cube = BoxSpec(position, vec3(0.5f, 0.5f, 0.5f), mass);
    cube.restitution = 0.0f;
    return cube;
}

BodySpec Ground() { return GroundSpec(vec3(50.0f, 0.5f, 50.0f)); }

}  // namespace

// A cube resting on the ground: one pair, its four bottom corners at y = 0 under the cube, the normal along y,
// and as depth the deepest of the solver's own separations (a fraction of a millimetre).
TEST(SoftCollisions, RestingCubeGivesItsFourCorners) {
    TestWorld world(WithGround(Ground(), {Cube(vec3(0.3f, 0.5f, -0.2f))}));
    world.system.settings.contactSolver = ContactSolver::Soft;
    for (int i = 0; i < 60; ++i) world.system.Update(kDt);
    ASSERT_EQ(world.system.CollisionCount(), 1u);
    const CollisionPair& pair = world.system.Collisions()[0];
    EXPECT_EQ(pair.indexA, 0);
    EXPECT_EQ(pair.indexB, 1);
    EXPECT_EQ(pair.a, world.system.Volumes()[0]);
    EXPECT_EQ(pair.b, world.system.Volumes()[1]);
    const CollisionManifold& m = pair.manifold;
    EXPECT_TRUE(m.colliding);
    EXPECT_NEAR(std::fabs(m.normal.y), 1.0f, 1e-5f);
    ASSERT_EQ(m.contacts.size(), 4u);
    for (const vec3& p : m.contacts) {
        EXPECT_NEAR(p.y, 0.0f, 1e-3f);
        EXPECT_NEAR(std::fabs(p.x - 0.3f), 0.5f, 1e-3f);
        EXPECT_NEAR(std::fabs(p.z + 0.2f), 0.5f, 1e-3f);
    }
    EXPECT_GT(m.depth, 0.0f);
    EXPECT_LT(m.depth, 1e-3f);
    EXPECT_EQ(m.depth, world.system.SoftSolver().DeepestPenetration());
}

// Depth follows the solver's separations: a softer contact spring rests deeper (about g / (2 pi f)^2 at a static
// contact of f = twice contactHertz: 2.5 mm at 5 Hz, 0.008 mm at 90 Hz).
TEST(SoftCollisions, DepthFollowsContactStiffness) {
    auto depth = [](float hertz) {
        TestWorld world(WithGround(Ground(), {Cube(vec3(0.0f, 0.5f, 0.0f))}));
        world.system.settings.contactSolver = ContactSolver::Soft;
        world.system.settings.soft.contactHertz = hertz;
        for (int i = 0; i < 120; ++i) world.system.Update(kDt);
        EXPECT_EQ(world.system.CollisionCount(), 1u);
        return world.system.CollisionCount() > 0 ? world.system.Collisions()[0].manifold.depth : 0.0f;
    };
    const float soft = depth(5.0f), stiff = depth(90.0f);
    EXPECT_NEAR(soft, 9.82f / std::pow(2.0f * 3.14159f * 10.0f, 2.0f), 1e-3f);
    EXPECT_GT(stiff, 0.0f);
    EXPECT_GT(soft, 20.0f * stiff);
}

// Speculative points (within the margin, not yet touching) are the solver's but not collisions; a falling cube
// shows none until it lands. Switching solvers refills the list from the solver in effect.
TEST(SoftCollisions, SpeculativePointsAreNotCollisions) {
    TestWorld world(WithGround(Ground(), {Cube(vec3(0.0f, 0.51f, 0.0f))}));
    world.system.settings.contactSolver = ContactSolver::Soft;
    world.system.Update(kDt);
    EXPECT_GT(world.system.SoftSolver().ContactCount(), 0u) << "1 cm apart: inside the speculative margin";
    EXPECT_EQ(world.system.CollisionCount(), 0u);
    for (int i = 0; i < 30; ++i) world.system.Update(kDt);
    EXPECT_EQ(world.system.CollisionCount(), 1u);

    world.system.settings.contactSolver = ContactSolver::Book;
    world.system.Update(kDt);
    ASSERT_EQ(world.system.CollisionCount(), 1u);
    EXPECT_EQ(world.system.Collisions()[0].manifold.contacts.size(), 4u);
    world.system.ClearRigidbodys();
    EXPECT_EQ(world.system.CollisionCount(), 0u);
}
