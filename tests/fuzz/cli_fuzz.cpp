// Fuzz target: bytes -> the command-line parser. The input is split at '\n' into argv[1..] (one argument a
// line, as tests/golden/<id>/run.args; argv[0] is "physics-sandbox"). Calls ParseCommandLine
// (Application/CommandLine.h) and checks that what it accepts lies in the ranges --help documents.
// docs/testing.md "Fuzzing".

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "Application/CommandLine.h"

namespace {

void Require(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "cli_fuzz: check failed: %s\n", what);
    std::abort();
}

void CheckAccepted(const Options& o) {
    if (o.mode != Options::Mode::Run) return;
    Require(!o.demo.empty() || !o.scene.empty() || o.window, "a headless run names a demo or a scene");
    Require(o.demo.empty() || o.scene.empty(), "never both --demo and --scene");
    Require(o.exportScene.empty() || (!o.demo.empty() && !o.window), "--export-scene exports a demo");
    Require(!o.explainModel || (!o.window && o.exportScene.empty()), "--explain-model is a headless run's");
    Require(!o.window || (o.outDir.empty() && o.compareDir.empty() && o.stateFile.empty() && o.videoFile.empty()),
            "--window takes no headless outputs");
    Require(!o.window || (o.backend == "auto" && !o.hasYaw && !o.hasPitch && !o.hasZoom && !o.hasTarget &&
                          o.orbitDegreesPerFrame == 0.0f && o.frameTime.num == 1 && o.frameTime.den == 60),
            "--window takes no flag it would ignore (a back end, a camera, a frame rate)");
    Require(o.exportScene.empty() ||
                (o.outDir.empty() && o.stateFile.empty() && o.videoFile.empty() && o.compareDir.empty() &&
                 o.onlyFrames.empty() && !o.framesGiven && !o.showParams && o.backend == "auto"),
            "--export-scene takes no run flag it would ignore (outputs, --frames)");
    Require(o.backend == "auto" || o.backend == "osmesa" || o.backend == "egl", "a known back end");
    Require(o.frames >= 1, "at least one frame");
    Require(o.width >= 16 && o.width <= 8192 && o.height >= 16 && o.height <= 8192, "size within 16..8192");
    for (std::size_t i = 1; i < o.onlyFrames.size(); ++i)
        Require(o.onlyFrames[i - 1] < o.onlyFrames[i], "--only-frames sorted and unique");
    // With --scene and no --frames the run's length comes from the file, so the parser leaves this check
    // to the Runner after loading (Application/Runner.cpp); otherwise it is the parser's.
    const bool lengthKnown = o.scene.empty() || o.framesGiven;
    Require(o.onlyFrames.empty() || (o.onlyFrames.front() >= 0 && (!lengthKnown || o.onlyFrames.back() < o.frames)),
            "--only-frames within the run");
    Require(o.frameTime.num > 0 && o.frameTime.den > 0 && o.step.num > 0 && o.step.den > 0, "positive times");
    Require(o.thresholds.channelTolerance >= 0 && o.thresholds.channelTolerance <= 255, "tolerance 0..255");
    Require(o.thresholds.maxDifferingFraction >= 0.0 && o.thresholds.maxDifferingFraction <= 1.0, "max-diff 0..1");
    Require(o.pngLevel >= 0 && o.pngLevel <= 9, "zlib level 0..9");
    Require(o.progressEvery >= 0, "a progress interval is not negative");
    Require(o.debugNonFiniteAt >= -1, "--debug-nonfinite-at is a frame number or off");
    Require(!o.updateGolden || !o.compareDir.empty(), "--update-golden has a directory");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args{"physics-sandbox"};
    std::string arg;
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == '\n') {
            args.push_back(arg);
            arg.clear();
        } else {
            arg += char(data[i]);
        }
    }
    if (!arg.empty()) args.push_back(arg);
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    argv.push_back(nullptr);

    Options options;
    std::string error;
    if (ParseCommandLine(int(args.size()), argv.data(), &options, &error) == ParseStatus::Ok)
        CheckAccepted(options);
    else
        Require(!error.empty(), "a rejected command line says why");
    return 0;
}
