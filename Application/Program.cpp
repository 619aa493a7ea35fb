#include "Application/Program.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "Application/CommandLine.h"
#include "Application/ExitCodes.h"
#include "Application/Runner.h"
#include "Application/StepSetting.h"
#if PSB_HAVE_WINDOW
#include "Application/WindowedRunner.h"
#endif
#include "Demos/DemoRegistry.h"
#include "Physics/JobPool.h"
#include "Platform/Files/TempRegistry.h"

namespace {

int RunWindow(const Options& o) {
#if PSB_HAVE_WINDOW
    if (!o.demo.empty()) {
        if (const int code = CheckDemoId(o.demo); code != kExitOk) return code;
    }
    WindowedOptions w;
    w.demo = o.demo;
    w.sets = o.sets;
    if (std::find(o.flagsGiven.begin(), o.flagsGiven.end(), "--dt") != o.flagsGiven.end())
        w.sets.insert(w.sets.begin(), {"dt", RationalText(o.step)});  // one setting with --set dt=
    w.frames = o.framesGiven ? o.frames : 0;
    w.width = o.width;
    w.height = o.height;
    w.step = o.step;
    w.noUi = o.noUi;
    w.quiet = o.quiet;
    return RunWindowed(w);
#else
    (void)o;
    std::fprintf(stderr, "physics-sandbox: --window: this build has no window (CMake PSB_WITH_WINDOW, libglfw3-dev)\n");
    return kExitUsage;
#endif
}

}  // namespace

int RunCommandLine(int argc, const char* const* argv) {
    InstallTemporaryCleanupOnSignals("physics-sandbox");
    Options options;
    std::string error;
    if (ParseCommandLine(argc, argv, &options, &error) != ParseStatus::Ok) {
        std::fprintf(stderr, "physics-sandbox: %s\n", error.c_str());
        return kExitUsage;
    }
    for (const std::string& note : options.notes) std::fprintf(stderr, "physics-sandbox: %s\n", note.c_str());
    SetDefaultThreadCount(options.threads);  // before any world steps; 0 keeps the hardware's concurrency
    if (options.mode == Options::Mode::Help) {
        std::fputs(UsageText().c_str(), stdout);
        return FinishStdout();
    }
    if (options.mode == Options::Mode::List) {
        for (const DemoInfo& d : AllDemos()) std::printf("%s\t%s\n", d.id.c_str(), d.title.c_str());
        return FinishStdout();
    }
    if (options.window) return RunWindow(options);
    RunStats stats;
    return RunSandbox(options, &stats);
}
