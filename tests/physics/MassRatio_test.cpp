// Large mass ratios with ContactSolver::Soft at its defaults (docs/soft-solver.md, "Mass ratios"), on the shipped scene
// files scenes/mass-*.json: 1000:1 heavy on light and light on heavy, a column of 1, 1000 and 1 kg, and 100 kg on a
// column of ten 1 kg cubes (cubes of half extent 0.5, friction 0.6, restitution 0, no damping, on a static ground).
// Each runs 10 s at 60 Hz and at the book's 0.03 s; the deepest penetration any contact reaches (Collisions()) and the
// largest sideways distance of any body from its start over the run are bounded. The shock pass's friction sweep
// must hold them without braking a slide harder than Coulomb: a box launched along the top one stops where
// v^2 / (2 mu g) says.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "Demos/Scenes/SceneFile.h"
#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/PhysicsSystem.h"
#include "tests/support/TestWorld.h"

namespace {

struct Outcome {
    float deepest = 0.0f;   // deepest penetration of any contact over the run, m
    float sideways = 0.0f;  // largest horizontal distance of any body from its start over the run, m
};

/// The boxes of scenes/`name` as body specs (the file's world settings are the soft solver's defaults).
std::vector<BodySpec> LoadBoxes(const std::string& name) {
    SceneDescription scene;
    std::vector<std::string> errors;
    EXPECT_TRUE(LoadSceneFile(std::string(PSB_SOURCE_DIR) + "/scenes/" + name, &scene, &errors)) << errors.front();
    EXPECT_EQ(scene.world.contactSolver, ContactSolver::Soft);
    std::vector<BodySpec> specs;
    for (const SceneBody& body : scene.bodies) {
        BodySpec spec = BoxSpec(body.position, body.halfExtents, body.mass);
        spec.friction = body.friction;
        spec.restitution = body.restitution;
        spec.velocityRetention = body.velocityRetention;
        spec.velocityEpsilon = body.velocityEpsilon;
        specs.push_back(spec);
    }
    return specs;
}

Outcome Run(const std::vector<BodySpec>& specs, float dt, float seconds = 10.0f) {
    TestWorld world(specs);
    world.system.settings.contactSolver = ContactSolver::Soft;
    Outcome out;
    const int steps = static_cast<int>(std::lround(seconds / dt));
    for (int s = 0; s < steps; ++s) {
        world.system.Update(dt);
        for (std::size_t k = 0; k < world.system.CollisionCount(); ++k)
            out.deepest = std::max(out.deepest, world.system.Collisions()[k].manifold.depth);
        for (std::size_t i = 0; i < specs.size(); ++i) {
            const vec3 d = world.Body(i).position - specs[i].position;
            out.sideways = std::max(out.sideways, std::sqrt(d.x * d.x + d.z * d.z));
        }
    }
    return out;
}

/// The top box of scenes/`name` launched at 2 m/s along x: it slides on the one under it and stops after
/// v^2 / (2 mu g) (mu 0.6 between the two; the one under it, held by the ground at the same mu under more load,
/// stays), at both steps.
void ExpectTopSlidesAsCoulombSays(const std::string& name) {
    std::vector<BodySpec> specs = LoadBoxes(name);
    ASSERT_GT(specs.size(), 2u);
    const float speed = 2.0f, mu = specs.back().friction;
    specs.back().velocity = vec3(speed, 0.0f, 0.0f);
    const float expected = speed * speed / (2.0f * mu * -kVolumeGravity.y);
    for (const float dt : {1.0f / 60.0f, 0.03f}) {
        TestWorld world(specs);
        world.system.settings.contactSolver = ContactSolver::Soft;
        const int steps = static_cast<int>(std::lround(2.0f / dt));
        for (int s = 0; s < steps; ++s) world.system.Update(dt);
        const std::size_t top = specs.size() - 1;
        const float slid = world.Body(top).position.x - specs[top].position.x;
        const float under = world.Body(top - 1).position.x - specs[top - 1].position.x;
        std::printf("soft %s dt %.4f s: top slid %.4f m (Coulomb %.4f m), the one under it %.5f m\n", name.c_str(),
                    static_cast<double>(dt), static_cast<double>(slid), static_cast<double>(expected),
                    static_cast<double>(under));
        EXPECT_NEAR(slid, expected, 0.03f * expected) << "dt " << dt;
        EXPECT_LE(std::fabs(under), 0.01f) << "dt " << dt;
    }
}

/// Penetration within 1 cm (the target) and sideways motion within `sideways` m at both steps.
void ExpectStands(const std::string& name, float sideways) {
    const std::vector<BodySpec> specs = LoadBoxes(name);
    ASSERT_GT(specs.size(), 2u);
    for (const float dt : {1.0f / 60.0f, 0.03f}) {
        const Outcome o = Run(specs, dt);
        std::printf("soft %s dt %.4f s: deepest %.5f m, sideways %.5f m\n", name.c_str(), static_cast<double>(dt),
                    static_cast<double>(o.deepest), static_cast<double>(o.sideways));
        EXPECT_LE(o.deepest, 0.01f) << "dt " << dt;
        EXPECT_LE(o.sideways, sideways) << "dt " << dt;
    }
}

}  // namespace

// Before shock propagation the heavy cube sank through the light one (0.97 m deep, 1.1 m sideways); with it but
// the friction at the corners of the upper body only, it drifted 6.4 / 8.6 mm (60 Hz / 0.03 s). Today's figures,
// for this test and the three below, are docs/soft-solver.md's table ("Mass ratios", scripts/mass-ratio-table.py,
// which reads what these tests print); the tests hold them to 1 cm.
TEST(MassRatio, HeavyOnLight) { ExpectStands("mass-heavy-on-light.json", 0.01f); }
// Sideways 0.27 / 0.49 mm before the friction sweep.
TEST(MassRatio, LightOnHeavy) { ExpectStands("mass-light-on-heavy.json", 0.01f); }
// Sideways 13 / 22 mm before the friction sweep.
TEST(MassRatio, HeavyBetweenLight) { ExpectStands("mass-heavy-between-light.json", 0.01f); }
// Sideways 97 / 142 mm before the friction sweep.
TEST(MassRatio, HeavyOnTowerOfTen) { ExpectStands("mass-heavy-on-tower.json", 0.01f); }

// The friction sweep adds to the solve's friction at the same pair; counted together they stay in one Coulomb
// cone. Measured 0.3367 m at 60 Hz against 0.3394 m (counted apart: 0.172 m, twice the braking).
TEST(MassRatio, HeavyBoxSlidingOnLightOneStopsWhereCoulombSays) {
    ExpectTopSlidesAsCoulombSays("mass-heavy-on-light.json");
}
// The same for the light box sliding on the heavy one (counted apart: 0.124 m).
TEST(MassRatio, LightBoxSlidingOnHeavyOneStopsWhereCoulombSays) {
    ExpectTopSlidesAsCoulombSays("mass-light-on-heavy.json");
}

// A 1 kg ball (r 0.25) rolling at 2 m/s (w = v / r) on a 1000 kg slab: the block reaches the ratio, and the
// friction sweep works at the contact point for a pair with a sphere, so rolling is not braked (matched at the
// centres it would stop within 0.34 s). Measured 1.9965 m/s after 1 s (1.9988 without shock propagation).
TEST(MassRatio, SphereRollingOnAHeavyBoxIsNotBraked) {
    BodySpec ground = BoxSpec(vec3(0.0f, -0.5f, 0.0f), vec3(50.0f, 0.5f, 50.0f), 0.0f);
    BodySpec slab = BoxSpec(vec3(0.0f, 0.5f, 0.0f), vec3(5.0f, 0.5f, 5.0f), 1000.0f);
    BodySpec ball = SphereSpec(vec3(-3.0f, 1.25f, 0.0f), 0.25f, 1.0f);
    for (BodySpec* spec : {&ground, &slab, &ball}) {
        spec->friction = 0.6f;
        spec->restitution = 0.0f;
        spec->velocityRetention = 1.0f;
        spec->velocityEpsilon = 0.0f;
    }
    ball.velocity = vec3(2.0f, 0.0f, 0.0f);
    ball.angularVelocity = vec3(0.0f, 0.0f, -8.0f);
    TestWorld world({ground, slab, ball});
    world.system.settings.contactSolver = ContactSolver::Soft;
    ASSERT_GT(world.system.settings.soft.shockMassRatio, 0.0f);
    ASSERT_LE(world.system.settings.soft.shockMassRatio, 1000.0f);
    for (int s = 0; s < 60; ++s) world.system.Update(1.0f / 60.0f);
    EXPECT_FALSE(world.system.SoftSolver().ShockPoints().empty());
    EXPECT_NEAR(world.Body(2).velocity.x, 2.0f, 0.02f);
}
