#pragma once
// The physics-sandbox command line (docs/app.md). Every flag is defined once, in the table in CommandLine.cpp
// (name, value type, inclusive range, help text); the parser and --help both read it. Parsing is GL-free and
// knows no demo: the runner checks the demo id and the --set keys against the registry before it writes
// anything.

#include <string>
#include <utility>
#include <vector>

#include "Application/FrameClock.h"
#include "Platform/ImageCompare.h"

struct Options {
    enum class Mode { Run, List, Help };
    Mode mode = Mode::Run;
    /// --window: the interactive desktop window instead of headless frames (Application/WindowedRunner.h).
    bool window = false;

    std::string demo;
    std::string scene;        ///< --scene FILE: a scene file (docs/scenes.md) instead of --demo
    std::string exportScene;  ///< --export-scene FILE: write the demo's scene as a scene file and exit
    int frames = 1;
    bool framesGiven = false;  ///< --frames was on the command line (--window then closes after that many)
    std::string outDir;        ///< "" = frames are rendered but not written
    int width = 800;
    int height = 600;
    std::vector<std::pair<std::string, std::string>> sets;  ///< --set key=value, in order
    bool noUi = false;
    /// Set by the run, not a flag: a GL context is made and frames drawn only for --out, --compare or --video.
    bool draws = true;
    bool showParams = false;  ///< --params: print the demo's parameters (after --set) and exit
    /// --explain-model: with an auto model (`--set model=auto`, a scene's "model": "auto"), print every candidate
    /// with its estimated error and cost, the chosen one marked, and exit without running (docs/model-choice.md).
    bool explainModel = false;
    std::string stateFile;
    std::string videoFile;         ///< --video: every frame into an .mp4, .webm or .gif (Platform/VideoEncoder.h)
    std::string backend = "auto";  ///< --backend: "auto", "osmesa" or "egl" (Platform/HeadlessContext.h)

    // Camera (the orbit camera's yaw = rotation.x, pitch = rotation.y, in degrees; zoom = distance).
    bool hasYaw = false, hasPitch = false, hasZoom = false, hasTarget = false;
    float yaw = 0.0f, pitch = 0.0f, zoom = 0.0f;
    float target[3] = {0.0f, 0.0f, 0.0f};
    float orbitDegreesPerFrame = 0.0f;  ///< added to the yaw every output frame

    Rational frameTime{1, 60};  ///< simulated seconds per output frame (--fps 60)
    Rational step{3, 100};      ///< fixed physics step (--dt 0.03, docs/book-reference.md §1.2)

    std::vector<int> onlyFrames;  ///< --only-frames: write/compare just these (sorted, unique); empty = all
    std::string compareDir;
    bool updateGolden = false;
    CompareThresholds thresholds;

    int pngLevel = 3;
    bool encodeThread = true;  ///< --serial-encode turns it off (same files, slower)
    int progressEvery = 0;     ///< 0 = automatic (see docs/app.md)
    bool quiet = false;
    /// --threads: threads of every world's rigid-body step (SetDefaultThreadCount); 0 = the hardware's concurrency.
    int threads = 0;
    /// Test hook: report frame N as non-finite (exercises the exit-3 path; DemoBase::StateIsFinite is the
    /// real check). -1 = off.
    int debugNonFiniteAt = -1;
    /// Every flag on the command line, by its name in the flag table, in order (repeats included): a flag that
    /// the chosen mode (--window, --export-scene) would ignore is refused.
    std::vector<std::string> flagsGiven;
    /// One-line notes for stderr about values the parser adjusted (a --dt rounded to whole microseconds).
    std::vector<std::string> notes;
};

enum class ParseStatus { Ok, Error };

/// Parses argv[1..]. On error returns ParseStatus::Error and sets *error to a one-line message that names
/// the flag, the bad value and what was expected (the flag's range). Does not touch the file system.
ParseStatus ParseCommandLine(int argc, const char* const* argv, Options* options, std::string* error);
/// The one rule for a physics step (docs/app.md, "Steps"), as `--dt` reads it: exact as n/d when it can be
/// (n, d <= 10^6), else rounded to whole microseconds with *note ("S s rounded to ..."; "" when exact); in
/// `--dt`'s range. False with *error ("expected a step in seconds ...") otherwise.
bool ParseHostStep(const std::string& text, Rational* step, std::string* error, std::string* note);
/// The --help text, generated from the flag table.
std::string UsageText();
