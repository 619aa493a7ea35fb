// Conservation Of Momentum scene (docs/book-reference.md §2.4).
#include "Demos/Scenes/MomentumScene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "tests/support/Approx.h"

namespace {
constexpr float kBookDt = 0.03f;
}

TEST(MomentumScene, BuildsTheBookScene) {
    MomentumScene scene;
    const std::vector<RigidbodyVolume>& b = scene.Bodies();
    ASSERT_EQ(b.size(), 6u);
    EXPECT_NEAR(b[3].position.x, 6.00006f, 1e-5f);
    EXPECT_NEAR(b[4].position.x, 12.00012f, 1e-5f);
    EXPECT_TRUE(VecNear(b[4].velocity, vec3(-20, 0, 0), tol::kTight));
    EXPECT_EQ(scene.System().settings.solverIterations, 20);
    for (const RigidbodyVolume& s : b) EXPECT_TRUE(VecNear(s.sphere.position, s.position, tol::kExact));  // 5.2-28
    ParameterSet set;
    scene.AddParameters(&set);
    std::string error;
    scene.Step(kBookDt);
    EXPECT_TRUE(set.Set("reset", "1", &error)) << error;
    EXPECT_TRUE(VecNear(scene.Bodies()[4].position, vec3(12.00012f, 1.16f, 0), 1e-5f));
}

// Impulses isolated (damping 1, no gravity, so the 0.01 m gap to the ground never closes): the chain of
// impacts conserves the total momentum to 1e-4 relative (float sums over 2 s of contacts), and it ends up
// carried forward: sphere 0 moves towards -x.
TEST(MomentumScene, ChainOfImpactsConservesMomentumWithDampingIsolated) {
    MomentumParams params;
    params.velocityRetention = 1.0f;
    params.gravity = false;
    MomentumScene scene(params);
    const vec3 p0 = scene.TotalMomentum();
    float worst = 0;
    for (int i = 0; i < 67; ++i) {
        scene.Step(kBookDt);
        worst = std::fmax(worst, Magnitude(scene.TotalMomentum() - p0) / Magnitude(p0));
    }
    std::printf("momentum, damping isolated: worst relative change %.2e, v0 %.3f\n", worst,
                scene.Bodies()[0].velocity.x);
    EXPECT_LT(worst, 1e-4f);
    EXPECT_LT(scene.Bodies()[0].velocity.x, -1.0f);
}

// With the book's settings the only losses are the per-step damping (factor 0.98 on every sphere's velocity)
// and ground friction once the spheres settle onto the ground. The x momentum after n steps is therefore at most
// P0 * 0.98^n (impulses between spheres add none), and the spheres' impacts alone cost nothing: with gravity off
// and damping on, it equals P0 * 0.98^n to 1e-4 relative.
TEST(MomentumScene, BookSettingsLoseOnlyTheDamping) {
    MomentumParams noGravity;
    noGravity.gravity = false;
    MomentumScene damped(noGravity);
    MomentumScene book;
    const float p0 = damped.TotalMomentum().x;
    for (int n = 1; n <= 67; ++n) {
        damped.Step(kBookDt);
        book.Step(kBookDt);
        const float expected = p0 * std::pow(0.98f, static_cast<float>(n));
        ASSERT_NEAR(damped.TotalMomentum().x, expected, 1e-4f * std::fabs(p0)) << "step " << n;
        ASSERT_LE(std::fabs(book.TotalMomentum().x), std::fabs(expected) * (1 + 1e-4f)) << "step " << n;
    }
}

// The book's solver is the default; --set solver=soft selects the soft step at once, with its settings, and a
// reset keeps them (the scene's own 20 book iterations stay).
TEST(MomentumScene, SolverParameterSelectsTheSoftSolver) {
    MomentumScene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    EXPECT_EQ(scene.System().settings.contactSolver, ContactSolver::Book);
    std::string error;
    ASSERT_TRUE(set.Set("solver", "soft", &error)) << error;
    ASSERT_TRUE(set.Set("soft-substeps", "2", &error)) << error;
    ASSERT_TRUE(set.Set("soft-contact-hertz", "120", &error)) << error;
    EXPECT_EQ(scene.System().settings.contactSolver, ContactSolver::Soft);
    EXPECT_EQ(scene.System().settings.soft.substeps, 2);
    EXPECT_EQ(scene.System().settings.soft.contactHertz, 120.0f);
    ASSERT_TRUE(set.Set("reset", "1", &error)) << error;
    EXPECT_EQ(scene.System().settings.contactSolver, ContactSolver::Soft);
    EXPECT_EQ(scene.System().settings.soft.substeps, 2);
    EXPECT_EQ(scene.System().settings.solverIterations, 20);
    ASSERT_TRUE(set.Set("solver", "accumulated", &error)) << error;
    EXPECT_EQ(scene.System().settings.contactSolver, ContactSolver::Accumulated);
}
