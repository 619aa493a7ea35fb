// Chapter 16 scene (docs/book-reference.md §2.7): book setup, drape over the posts for 2,000 steps with every stable
// integrator, explicit Euler's blow-up reported, parameters, determinism.
#include "Demos/Scenes/Ch16Scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "Physics/Spring.h"
#include "tests/support/Approx.h"

namespace {

std::vector<float> Snapshot(const Ch16Scene& scene) {
    std::vector<float> out;
    for (const Particle& p : scene.GetCloth().verts)
        for (const vec3& v : {p.GetPosition(), p.GetVelocity()}) out.insert(out.end(), {v.x, v.y, v.z});
    return out;
}

}  // namespace

TEST(Ch16Scene, BookSetup) {
    Ch16Scene scene;
    const Cloth& cloth = scene.GetCloth();
    EXPECT_EQ(cloth.verts.size(), 225u);
    EXPECT_EQ(cloth.structural.size(), 420u);
    EXPECT_EQ(cloth.shear.size(), 392u);
    EXPECT_EQ(cloth.bend.size(), 390u);
    EXPECT_TRUE(VecNear(cloth.verts[0].GetPosition(), vec3(-1.4f, 6, -1.4f), tol::kTight));
    // k_book = -3, d = 0 converted at the book's step: -3 / 0.03 = -100 N/m.
    for (const std::vector<Spring>* family : {&cloth.structural, &cloth.shear, &cloth.bend})
        for (const Spring& s : *family) {
            EXPECT_NEAR(s.k, -100.0f, 1e-3f);
            EXPECT_EQ(s.b, 0.0f);
        }
    const auto& constraints = scene.System().Constraints();
    ASSERT_EQ(constraints.size(), 5u);
    EXPECT_TRUE(VecNear(constraints[0].size, vec3(10, 0.1f, 10), 0.0f));  // ground first
    const vec3 posts[4] = {vec3(0.5f, 2.4f, 0.5f), vec3(-0.5f, 2.3f, 0.5f), vec3(-0.5f, 2.4f, -0.5f),
                           vec3(0.5f, 2.3f, -0.5f)};
    for (int i = 0; i < 4; ++i) {
        EXPECT_TRUE(VecNear(constraints[1 + i].position, posts[i], 0.0f));
        EXPECT_TRUE(VecNear(constraints[1 + i].size, vec3(0.3f, 0.5f, 0.3f), 0.0f));        // collides at 0.3 ...
        EXPECT_TRUE(VecNear(Ch16Scene::PostVisual(i).size, vec3(0.1f, 0.5f, 0.1f), 0.0f));  // ... drawn at 0.1
        EXPECT_TRUE(VecNear(Ch16Scene::PostVisual(i).position, posts[i], 0.0f));
    }
    EXPECT_EQ(scene.System().settings.integrator, Integrator::SemiImplicitEuler);
    EXPECT_EQ(scene.Params().dt, 0.03f);
}

// The cloth falls 3 m, catches on the posts (tops at y = 2.8 and 2.9) and hangs: after 2,000 steps it is
// finite and reported stable, its centre (between the posts) sags less than 0.6 m below the lower post top,
// its corners and edge midpoints hang at least 0.5 m below it, nothing is above the highest post top (+5 cm)
// or below the ground's top (y = 0.1, -1 cm).
TEST(Ch16Scene, BookClothDrapesOverPostsFor2000Steps) {
    for (Integrator integrator :
         {Integrator::SemiImplicitEuler, Integrator::VelocityVerlet, Integrator::PositionVerlet, Integrator::RK4}) {
        Ch16Params params;
        params.integrator = integrator;
        Ch16Scene scene(params);
        for (int i = 0; i < 2000; ++i) ASSERT_TRUE(scene.Step(scene.Params().dt)) << scene.Monitor().Report().message;
        const auto& v = scene.GetCloth().verts;
        const float lowTop = 2.3f + 0.5f, highTop = 2.4f + 0.5f;
        for (const Particle& p : v) {
            ASSERT_TRUE(IsFinite(p.GetPosition()) && IsFinite(p.GetVelocity()));
            EXPECT_LT(p.GetPosition().y, highTop + 0.05f) << ToString(integrator);
            EXPECT_GT(p.GetPosition().y, 0.1f - 0.01f) << ToString(integrator);
        }
        EXPECT_GT(v[7 * 15 + 7].GetPosition().y, lowTop - 0.6f) << ToString(integrator);
        for (int index : {0, 14, 210, 224, 7, 105, 119, 217})
            EXPECT_LT(v[index].GetPosition().y, lowTop - 0.5f) << ToString(integrator) << " particle " << index;
    }
}

// Explicit Euler cannot hold the book's stiffness at the book's step: the blow-up is detected and reported
// with the step and a cloth particle, and the scene stops advancing.
TEST(Ch16Scene, ExplicitEulerBlowUpIsReported) {
    Ch16Params params;
    params.integrator = Integrator::ExplicitEuler;
    Ch16Scene scene(params);
    int steps = 0;
    while (steps < 2000 && scene.Step(scene.Params().dt)) ++steps;
    ASSERT_LT(steps, 2000);
    const StabilityReport& r = scene.Monitor().Report();
    EXPECT_EQ(r.step, steps + 1);
    EXPECT_STREQ(r.kind, "cloth-particle");
    EXPECT_EQ(r.cloth, 0);
    EXPECT_GE(r.body, 0);
    EXPECT_LT(r.body, 225);
    EXPECT_NE(r.message.find("step " + std::to_string(r.step)), std::string::npos) << r.message;
    const long long before = scene.System().StepCount();
    EXPECT_FALSE(scene.Step(0.3f));  // no more steps once unstable
    EXPECT_EQ(scene.System().StepCount(), before);
}

TEST(Ch16Scene, ParametersCoverThePanelAndReset) {
    Ch16Scene scene;
    ParameterSet set;
    scene.AddParameters(&set);
    for (const char* key : {"count", "distance", "k", "damping", "reset", "integrator", "dt"})
        EXPECT_NE(set.Find(key), nullptr) << key;
    std::string error;
    ASSERT_TRUE(set.Set("count", "10", &error)) << error;
    EXPECT_EQ(scene.GetCloth().verts.size(), 100u);
    ASSERT_TRUE(set.Set("k", "-4.5", &error)) << error;
    EXPECT_NEAR(scene.GetCloth().bend[0].k, FromBookSpringConstant(-4.5f), 1e-3f);
    ASSERT_TRUE(set.Set("integrator", "rk4", &error)) << error;
    EXPECT_EQ(scene.System().settings.integrator, Integrator::RK4);
    ASSERT_TRUE(set.Set("distance", "0.5", &error)) << error;
    EXPECT_NEAR(scene.GetCloth().structural[0].restingLength, 0.5f, 1e-6f);
    EXPECT_FALSE(set.Set("count", "31", &error));  // the book's slider is 5..30
    EXPECT_FALSE(set.Set("k", "0.5", &error));     // -5..0
    EXPECT_FALSE(set.Set("integrator", "leapfrog", &error));
}

TEST(Ch16Scene, StepRunsOneStepOfItsArgumentAndRefusesBadSteps) {
    Ch16Scene scene;
    EXPECT_TRUE(scene.Step(0.03f));
    EXPECT_EQ(scene.System().StepCount(), 1);
    EXPECT_FALSE(scene.Step(0.0f));
    EXPECT_FALSE(scene.Step(-0.03f));
    EXPECT_FALSE(scene.Step(std::nanf("")));
    EXPECT_EQ(scene.System().StepCount(), 1);
    // Three steps of 0.01 s take the cloth as far as one of 0.03 s, to first order: the step is the argument.
    Ch16Scene coarse, fine;
    coarse.Step(0.03f);
    for (int i = 0; i < 3; ++i) fine.Step(0.01f);
    const float yCoarse = coarse.GetCloth().verts[0].GetPosition().y;
    const float yFine = fine.GetCloth().verts[0].GetPosition().y;
    EXPECT_LT(yFine, Ch16Scene::kClothHeight);
    EXPECT_NEAR(yFine, yCoarse, 0.01f);
}

TEST(Ch16Scene, DeterministicBitForBit) {
    Ch16Scene a, b;
    for (int i = 0; i < 300; ++i) {
        a.Step(a.Params().dt);
        b.Step(b.Params().dt);
    }
    const std::vector<float> sa = Snapshot(a), sb = Snapshot(b);
    ASSERT_EQ(sa.size(), 225u * 6u);
    ASSERT_EQ(sa.size(), sb.size());
    EXPECT_EQ(std::memcmp(sa.data(), sb.data(), sa.size() * sizeof(float)), 0);
    // A reset replays the same run.
    a.Reset();
    for (int i = 0; i < 300; ++i) a.Step(a.Params().dt);
    const std::vector<float> sr = Snapshot(a);
    ASSERT_EQ(sr.size(), sa.size());
    EXPECT_EQ(std::memcmp(sa.data(), sr.data(), sa.size() * sizeof(float)), 0);
}
