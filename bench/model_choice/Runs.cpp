// The host loop of psb-model-choice-bench: what Application/Runner.cpp does for a scene file, without drawing.
#include "bench/model_choice/Runs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <memory>

#include "Demos/Scenes/FileScene.h"
#include "Demos/Scenes/Parameters.h"
#include "bench/sweep/Sweep.h"

namespace modelchoice {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kHostStep = 0.03;  // s: the book's step (kBookStep), exact as the application's --dt 0.03

/// The shortest decimal that reads back as `f`, as a double: 0.01f -> 0.01, so that simulated time is counted in the
/// step the user wrote (the sweep's double dt) while the world steps the float.
double Decimal(float f) {
    char text[32];
    for (int digits = 1; digits <= 9; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, double(f));
        const double d = std::strtod(text, nullptr);
        if (float(d) == f) return d;
    }
    return double(f);
}

/// The scene's physics step now (s): its `dt` key, or the host step when that is 0.
double CurrentStep(const FileScene& scene, double hostStep) {
    return scene.PhysicsStep() > 0.0f ? Decimal(scene.PhysicsStep()) : hostStep;
}

bool Apply(ParameterSet* set, const Assignments& assignments, std::string* message) {
    for (const auto& [key, value] : assignments) {
        std::string error;
        if (!set->Set(key, value, &error)) {
            *message = key + "=" + value + ": " + error;
            return false;
        }
    }
    return true;
}

/// One run, not repeated. `sweepSteps` > 0: that many steps of the scene's step, no frames (RunSweepStyle).
RunResult RunOnce(const SceneDescription& description, const ReferenceProblem& problem, const Assignments& assignments,
                  const AutoModelRequest* request, long long sweepSteps, const ChoiceSettings& tuning = {}) {
    RunResult r;
    FileScene scene(description);
    ParameterSet set;
    scene.AddParameters(&set);
    if (!Apply(&set, assignments, &r.message)) {
        r.ok = false;
        return r;
    }
    std::unique_ptr<ErrorObserver> observer = problem.observer();
    observer->Start(scene);
    const double hostStep = HostStep(description);
    const double duration = double(description.duration);
    AutoModel autoModel;
    bool stable = true;
    const bool particles = !scene.Particles().empty() || !scene.Cloths().empty();
    bool volumes = false;
    for (const RigidbodyVolume& v : scene.Volumes()) volumes = volumes || v.mass > 0.0f;
    StepTime time;
    long long totalSteps = 0;
    time.dt = CurrentStep(scene, hostStep);

    r.startEnergy = WorldEnergy(scene.System());
    const double cpu0 = sweep::CpuNow();
    if (request != nullptr) {
        std::string error;
        if (!autoModel.Choose(&set, scene.System(), hostStep, duration, *request, &error, tuning)) {
            r.cpuSeconds = sweep::CpuNow() - cpu0;
            r.refused = true;
            r.message = error;
            r.chosen = "refused";
            r.overheadCpuSeconds = autoModel.OverheadCpuSeconds();
            r.explain = autoModel.Explain();
            return r;
        }
        r.chosen = autoModel.Current().Describe(particles, volumes);
        r.estimate = autoModel.RunningEstimate();
        r.explain = autoModel.Explain();
        time.dt = CurrentStep(scene, hostStep);
    }
    if (sweepSteps > 0) {
        for (; time.index < sweepSteps && stable; ++time.index) {
            stable = scene.Step(float(time.dt));
            observer->AfterStep(scene, time);
            ++totalSteps;
        }
    } else {
        // Frames of the host step; each runs the whole physics steps of the current step that end inside it, then
        // the auto model's watch. The step count restarts when the step changes (StepTime).
        const long long frames = std::llround(std::ceil(duration / hostStep - 1e-9));
        for (long long frame = 0; frame < frames && stable; ++frame) {
            const double frameEnd = std::min(duration, double(frame + 1) * hostStep);
            while (stable && time.After() <= frameEnd + 1e-9 * time.dt) {
                stable = scene.Step(float(time.dt));
                observer->AfterStep(scene, time);
                ++time.index;
                ++totalSteps;
            }
            if (request != nullptr && stable) {
                autoModel.AfterFrame(&set, scene.System(), time.Before());
                const double dt = CurrentStep(scene, hostStep);
                if (dt != time.dt) {
                    time.start = time.Before();
                    time.index = 0;
                    time.dt = dt;
                }
            }
        }
    }
    r.cpuSeconds = sweep::CpuNow() - cpu0;
    r.simSeconds = time.Before();
    r.steps = totalSteps;
    WorldPositions(scene.System(), &r.endPositions);
    r.endEnergy = WorldEnergy(scene.System());
    r.error = stable ? observer->Error(scene, r.simSeconds) : kInf;
    r.model = request != nullptr ? autoModel.Current().Describe(particles, volumes) : scene.ModelSummary();
    if (request != nullptr) {
        r.overheadCpuSeconds = autoModel.OverheadCpuSeconds();
        r.switches = int(autoModel.Log().size());
        r.log = autoModel.Log();
        r.estimate = autoModel.RunningEstimate();
    }
    if (!stable) r.message = scene.Monitor().Report().message;
    return r;
}

}  // namespace

double HostStep(const SceneDescription& scene) {
    return scene.world.step > 0.0f ? double(scene.world.step) : kHostStep;
}

RunResult RunScene(const SceneDescription& scene, const ReferenceProblem& problem, const Assignments& assignments,
                   const AutoModelRequest* request, double minCpuSeconds, int maxRepeats,
                   const ChoiceSettings& tuning) {
    RunResult first = RunOnce(scene, problem, assignments, request, 0, tuning);
    if (!first.ok) return first;
    double total = first.cpuSeconds;
    for (int i = 1; i < maxRepeats && total < minCpuSeconds; ++i) {
        const RunResult again = RunOnce(scene, problem, assignments, request, 0, tuning);
        total += again.cpuSeconds;
        if (again.cpuSeconds < first.cpuSeconds) {  // the fastest repeat's time and auto overhead
            first.cpuSeconds = again.cpuSeconds;
            first.overheadCpuSeconds = again.overheadCpuSeconds;
        }
    }
    first.cpuPerSimSecond = first.simSeconds > 0.0 ? first.cpuSeconds / first.simSeconds : first.cpuSeconds;
    return first;
}

RunResult RunSweepStyle(const SceneDescription& scene, const ReferenceProblem& problem, const Assignments& assignments,
                        double dt, double seconds) {
    Assignments all = assignments;
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", dt);
    all.emplace_back("dt", text);
    return RunOnce(scene, problem, all, nullptr, std::llround(seconds / dt));
}

}  // namespace modelchoice
