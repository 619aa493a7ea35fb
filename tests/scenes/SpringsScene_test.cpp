// Simple Springs scene (docs/book-reference.md §2.6): setup, the book-constant conversion (erratum 5.2-20), settling,
// a stiff explicit-Euler run reported, parameters, determinism.
#include "Demos/Scenes/SpringsScene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "tests/support/Approx.h"

TEST(SpringsScene, BookSetup) {
    SpringsScene scene;
    const auto& p = scene.Particles();
    ASSERT_EQ(p.size(), 2u);
    EXPECT_TRUE(VecNear(p[0].GetPosition(), vec3(0, 6, 0), 0.0f));
    EXPECT_TRUE(VecNear(p[1].GetPosition(), vec3(2, 6, 0), 0.0f));
    EXPECT_EQ(p[0].GetMass(), 50.0f);
    EXPECT_EQ(p[1].GetMass(), 1.0f);
    EXPECT_EQ(p[0].GetBounce(), 0.7f);
    EXPECT_EQ(p[0].GetVelocityRetention(), 0.95f);
    ASSERT_EQ(scene.System().Springs().size(), 1u);
    const Spring& s = scene.System().Springs()[0];
    EXPECT_NEAR(s.k, -2.0f / 0.03f, 1e-3f);
    EXPECT_NEAR(s.b, 0.5f / 0.03f, 1e-3f);
    EXPECT_EQ(s.restingLength, 1.0f);
    ASSERT_EQ(scene.System().Constraints().size(), 1u);
    EXPECT_TRUE(VecNear(scene.System().Constraints()[0].size, vec3(10, 0.15f, 10), 0.0f));
}

// erratum 5.2-20 conversion: the book's first step gives the light particle dv = k x / m = -2 * 1 / 1 = -2 m/s
// along x (toward the heavy one) and the heavy one +2/50. With k_book / 0.03 integrated over the 0.03 s step
// the same velocity changes come out, so the demo looks like the book's.
TEST(SpringsScene, BookConstantsGiveTheBooksFirstStep) {
    SpringsScene scene;
    scene.Step(scene.Params().dt);
    EXPECT_NEAR(scene.Particles()[1].GetVelocity().x, -2.0f, 1e-4f);
    EXPECT_NEAR(scene.Particles()[0].GetVelocity().x, 2.0f / 50.0f, 1e-5f);
}

// After 2,000 steps both particles lie on the ground (top y = 0.15), still horizontally, a rest length apart.
TEST(SpringsScene, SettlesOnTheGround) {
    for (Integrator integrator : kAllIntegrators) {
        SpringsParams params;
        params.integrator = integrator;
        SpringsScene scene(params);
        for (int i = 0; i < 2000; ++i) ASSERT_TRUE(scene.Step(scene.Params().dt)) << scene.Monitor().Report().message;
        const auto& p = scene.Particles();
        for (const Particle& q : p) {
            EXPECT_NEAR(q.GetPosition().y, 0.15f, 0.05f) << ToString(integrator);
            // Resting contact keeps a small vertical bounce (g dt reflected each step); horizontally it is still.
            EXPECT_LT(std::fabs(q.GetVelocity().x) + std::fabs(q.GetVelocity().z), 0.05f) << ToString(integrator);
        }
        EXPECT_NEAR(Magnitude(p[1].GetPosition() - p[0].GetPosition()), 1.0f, 0.05f) << ToString(integrator);
    }
}

// The stiffest panel setting without damping under explicit Euler grows by sqrt(1 + (omega dt)^2) * 0.95 ~ 1.02
// per step: reported (step and body), not left to overflow.
TEST(SpringsScene, StiffExplicitEulerIsReported) {
    SpringsParams params;
    params.springK = -5.0f;
    params.springDamping = 0.0f;
    params.integrator = Integrator::ExplicitEuler;
    SpringsScene scene(params);
    int steps = 0;
    while (steps < 5000 && scene.Step(scene.Params().dt)) ++steps;
    ASSERT_LT(steps, 5000);
    const StabilityReport& r = scene.Monitor().Report();
    EXPECT_EQ(r.step, steps + 1);
    EXPECT_STREQ(r.kind, "particle");
    EXPECT_EQ(r.body, 1);  // the light particle carries the motion
    EXPECT_FALSE(r.message.empty());
}

TEST(SpringsScene, ParametersCoverThePanel) {
    SpringsScene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    for (const char* key : {"k", "b", "l", "reset", "integrator", "dt"}) EXPECT_NE(set.Find(key), nullptr) << key;
    std::string error;
    ASSERT_TRUE(set.Set("l", "2.5", &error)) << error;
    EXPECT_EQ(scene.System().Springs()[0].restingLength, 2.5f);
    ASSERT_TRUE(set.Set("k", "-1", &error)) << error;
    EXPECT_NEAR(scene.System().Springs()[0].k, -1.0f / 0.03f, 1e-3f);
    ASSERT_TRUE(set.Set("dt", "0.01", &error)) << error;
    EXPECT_EQ(scene.Params().dt, 0.01f);
    ASSERT_TRUE(set.Set("integrator", "verlet", &error)) << error;
    EXPECT_EQ(scene.System().settings.integrator, Integrator::PositionVerlet);
    EXPECT_FALSE(set.Set("b", "1.5", &error));
    EXPECT_FALSE(set.Set("l", "-1", &error));
}

TEST(SpringsScene, DeterministicBitForBit) {
    SpringsScene a, b;
    for (int i = 0; i < 500; ++i) {
        a.Step(a.Params().dt);
        b.Step(b.Params().dt);
    }
    ASSERT_EQ(a.Particles().size(), 2u);
    ASSERT_EQ(b.Particles().size(), 2u);
    for (int i = 0; i < 2; ++i) {
        const vec3 pa = a.Particles()[i].GetPosition(), pb = b.Particles()[i].GetPosition();
        const vec3 va = a.Particles()[i].GetVelocity(), vb = b.Particles()[i].GetVelocity();
        EXPECT_EQ(std::memcmp(&pa, &pb, sizeof(vec3)), 0);
        EXPECT_EQ(std::memcmp(&va, &vb, sizeof(vec3)), 0);
    }
}
