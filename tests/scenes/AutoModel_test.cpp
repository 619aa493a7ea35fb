// The auto model (docs/model-choice.md) on FileScenes run as the app runs them: the choice meets the budget on
// problems with an exact answer, an impossible or invalid budget is refused, the choice is deterministic, and the
// live watch refines the model when the scene changes regime.
#include "Demos/Scenes/AutoModel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "Demos/Scenes/FileScene.h"
#include "Physics/PhysicsSystem.h"

namespace {

constexpr double kHostStep = 0.03;  // s, the host's fixed step (book)

SceneBody Particle(const vec3& position, const vec3& velocity, float mass = 1.0f) {
    SceneBody b;
    b.id = "p";
    b.kind = SceneBodyKind::Particle;
    b.position = position;
    b.velocity = velocity;
    b.mass = mass;
    b.velocityRetention = 1.0f;  // no damping: the exact answer is known
    return b;
}

/// What one auto run did.
struct AutoRun {
    bool chosen = false;
    std::string error;
    std::vector<std::string> log;
    ModelCandidate model;
    double estimate = 0.0;
    double seconds = 0.0;  // simulated
};

/// Runs `d` for `frames` host frames as the app does: Choose after the parameters, the host's accumulator running
/// whole steps of the scene's dt, AfterFrame after each frame. `check` sees the scene at the end.
template <typename Check>
AutoRun RunAuto(const SceneDescription& d, const AutoModelRequest& request, int frames, Check check) {
    FileScene scene(d);
    ParameterSet params;
    scene.AddParameters(&params);
    AutoModel autoModel;
    AutoRun run;
    run.chosen = autoModel.Choose(&params, scene.System(), kHostStep, frames * kHostStep, request, &run.error);
    if (getenv("PSB_EXPLAIN")) std::printf("%s", autoModel.Explain().c_str());
    if (!run.chosen) return run;
    double host = 0.0, physics = 0.0;
    long long steps = 0;
    for (int f = 1; f <= frames; ++f) {
        host = f * kHostStep;
        const double dt = scene.PhysicsStep() > 0.0f ? scene.PhysicsStep() : kHostStep;
        while (physics + dt <= host + 1e-9) {
            scene.Step(static_cast<float>(dt));
            physics += dt;
            ++steps;
        }
        autoModel.AfterFrame(&params, scene.System(), physics);
    }
    run.log = autoModel.Log();
    if (getenv("PSB_EXPLAIN"))
        for (auto& l : run.log) std::printf("%s\n", l.c_str());
    run.model = autoModel.Current();
    run.estimate = autoModel.RunningEstimate();
    run.seconds = physics;
    check(scene, physics);
    return run;
}

SceneDescription Projectile() {
    SceneDescription d;
    d.bodies.push_back(Particle(vec3(0, 0, 0), vec3(20, 15, 5)));
    return d;
}

double ProjectileError(const FileScene& scene, double t) {
    const vec3 x = scene.Particles()[0].GetPosition();
    const double ex = 20 * t, ey = 15 * t - 0.5 * 9.82 * t * t, ez = 5 * t;
    return std::sqrt((x.x - ex) * (x.x - ex) + (x.y - ey) * (x.y - ey) + (x.z - ez) * (x.z - ez));
}

/// A 1 kg particle on a 39.5 N/m spring to a fixed (mass 0) particle, no gravity: period about 1 s.
SceneDescription Oscillator() {
    SceneDescription d;
    d.world.gravity = vec3(0, 0, 0);
    d.bodies.push_back(Particle(vec3(0, 0, 0), vec3(0, 0, 0), 0.0f));
    d.bodies.push_back(Particle(vec3(1.5f, 0, 0), vec3(0, 0, 0), 1.0f));  // amplitude 0.5 m
    SceneSpring s;
    s.a = 0;
    s.b = 1;
    s.stiffness = 39.5f;
    s.restLength = 1.0f;
    d.springs.push_back(s);
    return d;
}

double OscillatorError(const FileScene& scene, double t) {
    const double omega = std::sqrt(39.5);
    const vec3 x = scene.Particles()[1].GetPosition();
    const double exact = 1.0 + 0.5 * std::cos(omega * t);
    return std::sqrt((x.x - exact) * (x.x - exact) + double(x.y) * x.y + double(x.z) * x.z);
}

AutoModelRequest Budget(double bound, int quantity = 0) {
    AutoModelRequest r;
    r.model = 1;
    r.tolerance = static_cast<float>(bound);
    r.quantity = quantity;
    return r;
}

TEST(AutoModel, ProjectileMeetsEachBudget) {
    for (double bound : {1e-1, 1e-2, 1e-3}) {
        double actual = 0.0;
        const AutoRun run = RunAuto(Projectile(), Budget(bound), 67,
                                    [&](const FileScene& s, double t) { actual = ProjectileError(s, t); });
        ASSERT_TRUE(run.chosen) << run.error;
        EXPECT_LE(actual, bound) << "budget " << bound << ": " << run.model.Describe();
    }
}

TEST(AutoModel, OscillatorMeetsEachBudget) {
    for (double bound : {1e-1, 1e-2, 1e-3}) {
        double actual = 0.0;
        const AutoRun run = RunAuto(Oscillator(), Budget(bound), 334,
                                    [&](const FileScene& s, double t) { actual = OscillatorError(s, t); });
        ASSERT_TRUE(run.chosen) << run.error;
        EXPECT_LE(actual, 3 * bound) << "budget " << bound << ": " << run.model.Describe();
        std::printf("oscillator budget %g: %s, estimate %g, actual %g\n", bound, run.model.Describe().c_str(),
                    run.estimate, actual);
    }
}

}  // namespace
