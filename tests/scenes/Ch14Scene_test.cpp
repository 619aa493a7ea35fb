// The CH14 scene: the book's spawns (docs/book-reference.md §0), constraints (2.1), the y < -5 clamp, and a long run
// that keeps every particle finite and above the ground for every integrator.
#include "Demos/Scenes/Ch14Scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tests/support/Approx.h"

TEST(Ch14Scene, FirstSpawnsEqualTheBooks) {
    Ch14Scene scene;
    ASSERT_EQ(scene.Particles().size(), 50u);
    const auto& ps = scene.Particles();
    EXPECT_TRUE(VecNear(ps[0].GetPosition(), vec3(-4.34086f, 6.75434f, -3.48493f), tol::kBook));
    EXPECT_NEAR(ps[0].GetBounce(), 0.80874f, tol::kBook);
    EXPECT_TRUE(VecNear(ps[1].GetPosition(), vec3(0.15466f, 6.41949f, -2.21810f), tol::kBook));
    EXPECT_NEAR(ps[1].GetBounce(), 0.89596f, tol::kBook);
    EXPECT_TRUE(VecNear(ps[2].GetPosition(), vec3(1.98619f, 7.48642f, -3.63984f), tol::kBook));
    EXPECT_NEAR(ps[2].GetBounce(), 0.85894f, tol::kBook);
}

TEST(Ch14Scene, ConstraintsAreTheBooks) {
    const auto c = Ch14Scene::Constraints();
    EXPECT_TRUE(VecNear(c[0].size, vec3(10, 0.15f, 10), 0.0f));
    EXPECT_TRUE(VecNear(GetRow(c[1].orientation, 1), vec3(0, 0.85971f, 0.51078f), tol::kBook));
    EXPECT_TRUE(VecNear(GetRow(c[1].orientation, 2), vec3(0, -0.51078f, 0.85971f), tol::kBook));
    EXPECT_TRUE(VecNear(GetRow(c[2].orientation, 0), vec3(0.93671f, 0.13157f, 0.32443f), tol::kBook));
    EXPECT_TRUE(VecNear(GetRow(c[2].orientation, 1), vec3(0.08174f, 0.81889f, -0.56811f), tol::kBook));
    EXPECT_TRUE(VecNear(GetRow(c[2].orientation, 2), vec3(-0.34042f, 0.55867f, 0.75631f), tol::kBook));
    EXPECT_TRUE(VecNear(GetRow(c[3].orientation, 1), vec3(0, 0.90849f, 0.41790f), tol::kBook));
    EXPECT_TRUE(VecNear(c[3].size, vec3(2, 0.15f, 0.7817011f), 0.0f));
    EXPECT_TRUE(VecNear(c[2].position, vec3(-1, 3.6f, 1.2f), 0.0f));
    Ch14Scene scene;
    ASSERT_EQ(scene.System().Constraints().size(), 4u);
}

TEST(Ch14Scene, SpawnsStayInTheBooksBoxAndSeedChangesThem) {
    Ch14Params params;
    params.particleCount = 300;
    Ch14Scene scene(params);
    ASSERT_EQ(scene.Particles().size(), 300u);
    for (const Particle& p : scene.Particles()) {
        const vec3 x = p.GetPosition();
        EXPECT_LE(std::fabs(x.x - Ch14Scene::kSpawnCenter.x), Ch14Scene::kSpawnHalfSize.x + 1e-5f);
        EXPECT_LE(std::fabs(x.y - Ch14Scene::kSpawnCenter.y), Ch14Scene::kSpawnHalfSize.y + 1e-5f);
        EXPECT_LE(std::fabs(x.z - Ch14Scene::kSpawnCenter.z), Ch14Scene::kSpawnHalfSize.z + 1e-5f);
        EXPECT_GE(p.GetBounce(), 0.0f);
        EXPECT_LE(p.GetBounce(), 1.0f);
    }
    params.seed = 7;
    Ch14Scene other(params);
    EXPECT_FALSE(VecNear(other.Particles()[0].GetPosition(), scene.Particles()[0].GetPosition(), 1e-3f));
    params.particleCount = 0;
    EXPECT_EQ(Ch14Scene(params).Particles().size(), 1u);
}

// Book: a particle with y < -5 after the step is put back at y = -5 with SetPosition (oldPosition reset).
TEST(Ch14Scene, ParticlesBelowMinusFiveAreClamped) {
    Ch14Params params;
    params.particleCount = 1;
    Ch14Scene scene(params);
    Particle& p = scene.Particles()[0];
    p.SetPosition(vec3(20, -4.99f, 0));  // off the ground, falling
    p.SetVelocity(vec3(0, -3, 0));
    scene.Step(scene.Params().dt);
    EXPECT_EQ(p.GetPosition().y, -5.0f);
    EXPECT_EQ(p.GetOldPosition().y, -5.0f);
    EXPECT_EQ(p.GetPosition().x, 20.0f);
}

TEST(Ch14Scene, LongRunKeepsEveryParticleFiniteAndAboveTheGround) {
    for (Integrator i : kAllIntegrators) {
        Ch14Params params;
        params.particleCount = 300;
        params.integrator = i;
        Ch14Scene scene(params);
        for (int s = 0; s < 1000; ++s) scene.Step(scene.Params().dt);
        ASSERT_EQ(scene.Particles().size(), 300u);
        for (const Particle& p : scene.Particles()) {
            const vec3 x = p.GetPosition();
            ASSERT_TRUE(std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z)) << ToString(i);
            EXPECT_GE(x.y, 0.15f) << ToString(i);  // everything ends on the ground or a board
            EXPECT_LT(std::fabs(x.x), 10.0f) << ToString(i);
            EXPECT_LT(std::fabs(x.z), 10.0f) << ToString(i);
        }
    }
}

TEST(Ch14Scene, IntegratorSwitchesAtRunTimeAndStepTakesItsDt) {
    Ch14Scene scene;
    scene.SetIntegrator(Integrator::RK4);
    EXPECT_EQ(scene.System().settings.integrator, Integrator::RK4);
    // Step(dt) advances by its argument; zero, negative and non-finite steps do nothing.
    const vec3 start = scene.Particles()[0].GetPosition();
    for (float dt : {0.0f, -1.0f, std::nanf(""), std::numeric_limits<float>::infinity()}) scene.Step(dt);
    EXPECT_EQ(scene.System().StepCount(), 0);
    EXPECT_EQ(scene.Particles()[0].GetPosition().y, start.y);
    scene.Step(0.01f);
    EXPECT_EQ(scene.System().StepCount(), 1);
    EXPECT_LT(scene.Particles()[0].GetPosition().y, start.y);
}
