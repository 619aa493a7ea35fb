// Chapter 15 scene (docs/book-reference.md §2.5): setup, parameters, settling, determinism.
#include "Demos/Scenes/Ch15Scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "tests/support/Approx.h"

namespace {
constexpr float kBookDt = 0.03f;  // erratum 5.2-16: the book's fixed step
}

TEST(Ch15Scene, BuildsTheBookScene) {
    Ch15Scene scene;
    const std::vector<RigidbodyVolume>& b = scene.Bodies();
    ASSERT_EQ(b.size(), 3u);
    EXPECT_TRUE(
        MatNear(b[0].box.orientation, mat3(0.92106f, 0.38942f, 0, -0.38942f, 0.92106f, 0, 0, 0, 1), tol::kBook));
    EXPECT_TRUE(VecNear(b[0].box.position, vec3(0.5f, 6, 0), tol::kExact));
    EXPECT_EQ(b[1].mass, 5.0f);
    EXPECT_TRUE(VecNear(b[2].box.position, vec3(0, -0.25f, 0), tol::kExact));
    EXPECT_TRUE(VecNear(b[2].box.size, vec3(12.5f, 0.25f, 12.5f), tol::kExact));
    EXPECT_EQ(b[2].mass, 0.0f);
    EXPECT_EQ(scene.System().settings.solverIterations, 8);
    EXPECT_TRUE(scene.System().RenderRandomColors);
    // The heavy box starts exactly touching the ground: depth 0 is no contact.
    scene.Step(kBookDt);
    EXPECT_EQ(scene.System().CollisionCount(), 0u);
}

TEST(Ch15Scene, ParametersCoverEveryPanelWidget) {
    Ch15Scene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    std::string error;
    ASSERT_TRUE(set.Set("projection", "0.3", &error)) << error;
    ASSERT_TRUE(set.Set("slop", "0.05", &error)) << error;
    ASSERT_TRUE(set.Set("iterations", "12", &error)) << error;
    ASSERT_TRUE(set.Set("linear-projection", "0", &error)) << error;
    ASSERT_TRUE(set.Set("debug", "1", &error)) << error;
    EXPECT_FLOAT_EQ(scene.System().settings.projectionFraction, 0.3f);
    EXPECT_FLOAT_EQ(scene.System().settings.penetrationSlop, 0.05f);
    EXPECT_EQ(scene.System().settings.solverIterations, 12);
    EXPECT_FALSE(scene.System().settings.linearProjection);
    EXPECT_TRUE(scene.System().DebugRender);
    EXPECT_FALSE(set.Set("iterations", "21", &error));
    for (int i = 0; i < 20; ++i) scene.Step(kBookDt);
    ASSERT_TRUE(set.Set("reset", "1", &error)) << error;
    EXPECT_TRUE(VecNear(scene.Bodies()[0].position, vec3(0.5f, 6, 0), tol::kExact));
    EXPECT_EQ(scene.System().settings.solverIterations, 12);  // panel values survive Reset
}

// After 10 s at the book's 0.03 s step: the tilted box lands on the edge of the heavy one and slides off onto
// the ground beside it, as in the book's GIF (book-ch15-late.png: red and blue boxes side by side). Both rest
// face down on the ground (one axis within 2 degrees of vertical, centres at y = 1 within slop + 2 cm), do
// not overlap (centres at least 2 - 0.05 m apart horizontally) and are slow.
TEST(Ch15Scene, TiltedBoxEndsBesideTheHeavyOne) {
    Ch15Scene scene;
    for (int i = 0; i < 334; ++i) scene.Step(kBookDt);
    const RigidbodyVolume& red = scene.Bodies()[0];
    const RigidbodyVolume& blue = scene.Bodies()[1];
    auto upAlignment = [](const RigidbodyVolume& body) {
        const mat3 R = ToMat3(body.orientation);
        float up = 0;
        for (int k = 0; k < 3; ++k) up = std::fmax(up, std::fabs(R[k][1]));
        return up;
    };
    const vec3 d = red.position - blue.position;
    std::printf("ch15 after 10 s: red (%.3f, %.3f, %.3f) blue (%.3f, %.3f, %.3f), speeds %.4f %.4f\n", red.position.x,
                red.position.y, red.position.z, blue.position.x, blue.position.y, blue.position.z,
                Magnitude(red.velocity), Magnitude(blue.velocity));
    for (const RigidbodyVolume* body : {&red, &blue}) {
        EXPECT_NEAR(body->position.y, 1.0f, 0.01f + 0.02f);
        EXPECT_GT(upAlignment(*body), std::cos(DEG2RAD(2.0f)));
        EXPECT_LT(Magnitude(body->velocity), 0.05f);
    }
    EXPECT_GT(std::fmax(std::fabs(d.x), std::fabs(d.z)), 2.0f - 0.05f);
}

TEST(Ch15Scene, TwoRunsAreBitwiseIdentical) {
    Ch15Scene a, b;
    for (int i = 0; i < 200; ++i) {
        a.Step(kBookDt);
        b.Step(kBookDt);
    }
    ASSERT_EQ(a.Bodies().size(), 3u);
    ASSERT_EQ(b.Bodies().size(), 3u);
    for (std::size_t i = 0; i < a.Bodies().size(); ++i) {
        EXPECT_EQ(std::memcmp(&a.Bodies()[i].position, &b.Bodies()[i].position, sizeof(vec3)), 0);
        EXPECT_EQ(std::memcmp(&a.Bodies()[i].velocity, &b.Bodies()[i].velocity, sizeof(vec3)), 0);
        EXPECT_EQ(std::memcmp(&a.Bodies()[i].orientation, &b.Bodies()[i].orientation, sizeof(quat)), 0);
        EXPECT_EQ(std::memcmp(&a.Bodies()[i].angVel, &b.Bodies()[i].angVel, sizeof(vec3)), 0);
    }
}

// The panel values go into the world's settings when they are set (the book's sliders write its PhysicsSystem), not
// from a copy pushed into the world before every step: a setting changed in the world stays through a step, and a
// --set reaches the world before any step.
TEST(Ch15Scene, AStepLeavesTheWorldsSettingsAlone) {
    Ch15Scene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    scene.System().settings.solverIterations = 3;
    scene.Step(0.03f);
    EXPECT_EQ(scene.System().settings.solverIterations, 3);
    std::string error;
    ASSERT_TRUE(set.Set("iterations", "12", &error)) << error;
    EXPECT_EQ(scene.System().settings.solverIterations, 12);
    ASSERT_TRUE(set.Set("projection-fraction", "0.3", &error)) << error;
    EXPECT_EQ(scene.System().settings.projectionFraction, 0.3f);
}

// The "solver" parameter switches the system's contact solver (not a book widget; --set solver=...).
TEST(Ch15Scene, SolverParameterSelectsTheContactSolver) {
    Ch15Scene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    EXPECT_EQ(scene.System().settings.contactSolver, ContactSolver::Book);
    std::string error;
    ASSERT_TRUE(set.Set("solver", "accumulated", &error)) << error;
    EXPECT_EQ(scene.System().settings.contactSolver, ContactSolver::Accumulated);
    EXPECT_FALSE(set.Set("solver", "sequential", &error));
    EXPECT_NE(error.find("book|accumulated|soft"), std::string::npos) << error;
    ASSERT_TRUE(set.Set("solver", "book", &error)) << error;
    EXPECT_EQ(scene.System().settings.contactSolver, ContactSolver::Book);
}

// --set solver=soft selects the soft step, and its --set keys land in WorldSettings::soft; both survive steps and
// Reset.
TEST(Ch15Scene, SoftSolverAndItsSettingsReachTheSystem) {
    Ch15Scene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    std::string error;
    ASSERT_TRUE(set.Set("solver", "soft", &error)) << error;
    ASSERT_TRUE(set.Set("soft-substeps", "8", &error)) << error;
    ASSERT_TRUE(set.Set("soft-contact-hertz", "60", &error)) << error;
    ASSERT_TRUE(set.Set("soft-contact-damping-ratio", "2", &error)) << error;
    ASSERT_TRUE(set.Set("soft-max-pushout-speed", "0.5", &error)) << error;
    ASSERT_TRUE(set.Set("soft-iterations", "3", &error)) << error;
    ASSERT_TRUE(set.Set("soft-relax-iterations", "0", &error)) << error;
    EXPECT_FALSE(scene.System().settings.sleep.enabled);  // off, as in the book, until asked for
    ASSERT_TRUE(set.Set("sleep", "1", &error)) << error;
    auto expectSoft = [&scene](const char* when) {
        const WorldSettings& s = scene.System().settings;
        EXPECT_EQ(s.contactSolver, ContactSolver::Soft) << when;
        EXPECT_TRUE(s.sleep.enabled) << when;
        EXPECT_EQ(s.soft.substeps, 8) << when;
        EXPECT_EQ(s.soft.contactHertz, 60.0f) << when;
        EXPECT_EQ(s.soft.contactDampingRatio, 2.0f) << when;
        EXPECT_EQ(s.soft.maxPushoutSpeed, 0.5f) << when;
        EXPECT_EQ(s.soft.iterations, 3) << when;
        EXPECT_EQ(s.soft.relaxIterations, 0) << when;
        EXPECT_EQ(s.soft.linearSlop, SoftSolverSettings().linearSlop) << when;  // not a key: the default
    };
    expectSoft("after --set");
    scene.Step(0.03f);
    expectSoft("after a step");
    scene.Reset();
    expectSoft("after Reset");
    EXPECT_FALSE(set.Set("soft-substeps", "0", &error));
    EXPECT_NE(error.find("integer 1..64"), std::string::npos) << error;
    EXPECT_EQ(scene.System().settings.soft.substeps, 8);
}
