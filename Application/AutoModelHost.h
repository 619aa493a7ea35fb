#pragma once
// `model: auto` in the two hosts, headless (Runner) and window (WindowedRunner): the choice before the first frame
// and the live watch after each frame's fixed steps (docs/model-choice.md; docs/app.md, "Error budget"). The
// estimator is Demos/Scenes/AutoModel.h; the demo keeps its request (plain data, DemoBase::AutoModelRequestOf); the
// host owns the run's AutoModel and lends it to the demo's panel (DemoBase::ShowAutoModel).

#include <cstddef>
#include <string>
#include <vector>

class AutoModel;
class DemoBase;

/// What a host hands the choice.
struct AutoModelHost {
    std::string name;          ///< the demo's id or "scene FILE": the prefix of every message
    double hostStep = 0.03;    ///< s: the host's fixed step (--dt) when the demo names none
    double runSeconds = 10.0;  ///< s: the simulated length of the run (the estimate is for its end)
    bool explain = false;      ///< --explain-model: print the candidates on stdout and end the run
    bool quiet = false;        ///< no line on stderr about the choice (a refusal is always printed)
};

/// When the demo's request is auto, chooses its model into `model` (the host's; AutoModel::Choose, applied through the
/// demo's own keys) and prints the choice on stderr, or with host.explain the candidates on stdout, then sets
/// *explained. Returns 0 when there is nothing to choose or the model was chosen; 2 (kExitUsage), the message printed,
/// when no candidate meets the budget or --explain-model has no auto model to explain; 3 when stdout cannot be written.
int ChooseAutoModel(DemoBase& demo, AutoModel& model, const AutoModelHost& host, bool* explained);

/// After a frame's fixed steps: the demo's live watch at `time` (simulated s since the start), a switch applied
/// through its keys. Returns the log lines that are new since *printed (and advances it); none without auto.
std::vector<std::string> WatchAutoModel(DemoBase& demo, AutoModel& model, double time, std::size_t* printed);
