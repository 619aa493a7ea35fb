// Large mass ratios with ContactSolver::Soft at its defaults (docs/ch15.md, "Mass ratios"), on the shipped scene files
// scenes/mass-*.json: 1000:1 heavy on light and light on heavy, a column of 1, 1000 and 1 kg, and 100 kg on a column
// of ten 1 kg cubes (cubes of half extent 0.5, friction 0.6, restitution 0, no damping, on a static ground). Each
// runs 10 s at 60 Hz and at the book's 0.03 s; the deepest penetration any contact reaches (Collisions()) and the
// largest sideways distance of any body from its start over the run are bounded.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "Demos/Scenes/SceneFile.h"
#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/PhysicsSystem.h"

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

Outcome Run(const std::vector<BodySpec>& specs, float dt) {
    RigidWorld world(specs);
    world.system.settings.contactSolver = ContactSolver::Soft;
    Outcome out;
    const int steps = static_cast<int>(std::lround(10.0f / dt));
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

// Before shock propagation the heavy cube sank through the light one (0.97 m deep, 1.1 m sideways). Measured
// (60 Hz / 0.03 s): deepest 0.04 / 0.11 mm, sideways 6.0 / 8.7 mm. The sideways figure is a random walk of the
// jittering heavy cube (a few cm/s either way) that any rounding-level change reshuffles: over steps of 1/60 to
// 0.032 s (the physics-sandbox state CSVs) it spans 4 to 16 mm before the soft solver's yaw friction fix and 7 to
// 15 mm after it (docs/ch15.md, "Friction at a yaw"; one version of the fix gave 20 mm at 0.03 s), so the 1 cm
// target is not met at every step; the bound is 2.5 cm.
TEST(MassRatio, HeavyOnLight) { ExpectStands("mass-heavy-on-light.json", 0.025f); }
// Measured 0.27 / 0.41 mm sideways (it stood before too).
TEST(MassRatio, LightOnHeavy) { ExpectStands("mass-light-on-heavy.json", 0.01f); }
// Measured deepest 0.13 / 1.6 mm, sideways 14 / 11 mm: the target of 1 cm sideways is not met (docs/ch15.md).
TEST(MassRatio, HeavyBetweenLight) { ExpectStands("mass-heavy-between-light.json", 0.03f); }
// Measured deepest 1.6 / 4.2 mm, sideways 86 / 144 mm (2.5 / 29 m before): the target of 1 cm sideways is not met.
TEST(MassRatio, HeavyOnTowerOfTen) { ExpectStands("mass-heavy-on-tower.json", 0.25f); }
