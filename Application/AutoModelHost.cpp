#include "Application/AutoModelHost.h"

#include <cstdio>

#include "Application/ExitCodes.h"
#include "Demos/DemoBase.h"
#include "Demos/Scenes/AutoModel.h"

int ChooseAutoModel(DemoBase& demo, AutoModel& model, const AutoModelHost& host, bool* explained) {
    const AutoModelRequest* request = demo.AutoModelRequestOf();
    if (request == nullptr || !request->Auto() || demo.World() == nullptr) {
        if (!host.explain) return kExitOk;
        std::fprintf(stderr,
                     "physics-sandbox: --explain-model: %s runs its fixed model; it needs --set model=auto (or a "
                     "scene file with \"model\": \"auto\")\n",
                     host.name.c_str());
        return kExitUsage;
    }
    demo.ShowAutoModel(&model);  // its panel row, once the model is active
    std::string error;
    // Never silent for more than a second while choosing (docs/model-choice.md, "The cost of choosing").
    ChoiceSettings tuning;
    const std::string name = host.name;
    if (!host.quiet) {
        tuning.progress = [name](const std::string& line) {
            std::fprintf(stderr, "physics-sandbox: %s: model auto: %s\n", name.c_str(), line.c_str());
            std::fflush(stderr);
        };
    }
    const bool chosen =
        model.Choose(&demo.Parameters(), *demo.World(), host.hostStep, host.runSeconds, *request, &error, tuning);
    // The table also when the budget is refused: it shows how close each candidate came.
    if (host.explain && !model.Choice().candidates.empty()) std::fputs(model.Explain().c_str(), stdout);
    if (!chosen) {
        if (host.explain) FinishStdout();
        std::fprintf(stderr, "physics-sandbox: %s: model auto: %s\n", host.name.c_str(), error.c_str());
        return kExitUsage;
    }
    if (host.explain) {
        *explained = true;
        return FinishStdout();
    }
    if (!host.quiet) std::fprintf(stderr, "physics-sandbox: %s: %s\n", host.name.c_str(), model.Summary().c_str());
    return kExitOk;
}

std::vector<std::string> WatchAutoModel(DemoBase& demo, AutoModel& model, double time, std::size_t* printed) {
    if (!model.Active() || demo.World() == nullptr) return {};
    model.AfterFrame(&demo.Parameters(), *demo.World(), time);
    const std::vector<std::string>& log = model.Log();
    std::vector<std::string> lines;
    for (; *printed < log.size(); ++*printed) lines.push_back(log[*printed]);
    return lines;
}
