#pragma once
// Runs of a reference scene through the path the application takes: a FileScene, its ParameterSet
// (FileScene::AddParameters) and `--set`-style assignments, or `model: auto` through AutoModel::Choose and
// AutoModel::AfterFrame; frames of the host step, each running whole physics steps of the scene's current step.
// Thread CPU time covers everything from the choice (calibration included) to the last step.

#include <string>
#include <utility>
#include <vector>

#include "Demos/Scenes/AutoModel.h"
#include "Demos/Scenes/SceneFile.h"
#include "bench/model_choice/ReferenceProblems.h"

namespace modelchoice {

using Assignments = std::vector<std::pair<std::string, std::string>>;

/// What one run measured.
struct RunResult {
    bool ok = true;           ///< false: an assignment was refused (message says which)
    bool refused = false;     ///< auto only: Choose returned false (message holds its reason)
    double error = 0.0;       ///< the problem's error (its unit), inf when the run left the problem's bounds
    double simSeconds = 0.0;  ///< s simulated
    double cpuSeconds = 0.0;  ///< thread CPU s of the run (the smallest over the repeats)
    double cpuPerSimSecond = 0.0;
    long long steps = 0;               ///< physics steps
    std::string model;                 ///< the model in effect at the end (FileScene::ModelSummary, or auto's current)
    std::string message;               ///< refusal or failure
    std::vector<double> endPositions;  ///< WorldPositions at the end (m)
    double startEnergy = 0.0, endEnergy = 0.0;  ///< WorldEnergy before the first step and at the end (J)
    // auto only
    std::string chosen;               ///< the calibration's choice
    double estimate = 0.0;            ///< its estimated error at the end of the run (auto's budget unit)
    double overheadCpuSeconds = 0.0;  ///< calibration and watch
    int switches = 0;
    std::string explain;           ///< AutoModel::Explain after the choice (or the refusal)
    std::vector<std::string> log;  ///< AutoModel::Log at the end                 ///< model changes during the run
};

/// The host step of a scene (s): its own step, else the book's 0.03 s.
double HostStep(const SceneDescription& scene);

/// Runs `scene` for its duration with the assignments applied (the `--set` keys of FileScene::AddParameters), or,
/// with `request`, with auto choosing the model. Repeats the run until `minCpuSeconds` of CPU have been spent (at
/// most `maxRepeats` times) and keeps the smallest CPU time; the error is the first run's (runs are deterministic).
/// `tuning` is auto's (its safety factor, for one).
RunResult RunScene(const SceneDescription& scene, const ReferenceProblem& problem, const Assignments& assignments,
                   const AutoModelRequest* request, double minCpuSeconds = 0.05, int maxRepeats = 20,
                   const ChoiceSettings& tuning = {});

/// Runs `scene` at a fixed step dt for round(seconds / dt) steps, exactly as the sweep steps its problems (no
/// frames): the scene-file counterpart of a sweep row, for the equivalence check.
RunResult RunSweepStyle(const SceneDescription& scene, const ReferenceProblem& problem, const Assignments& assignments,
                        double dt, double seconds);

}  // namespace modelchoice
