#pragma once
// The book's interactive program (docs/book-reference.md §1.2): an 800x600 "Physics Sandbox" window with
// the "Physics Demo" panel, driven by the book's wall-clock loop: events, ImGui frame, OnUpdate, fixed steps
// of the accumulator (strict >), render, swap; vsync and the book's 16 ms frame limiter. Mouse input reaches
// the demo (left pans, middle zooms, right rotates the camera) unless ImGui wants the mouse. docs/app.md,
// "Window".

#include <string>
#include <utility>
#include <vector>

#include "Application/FrameClock.h"

struct WindowedOptions {
    std::string demo;                                       ///< first demo ("" = the book's empty start screen)
    std::vector<std::pair<std::string, std::string>> sets;  ///< --set (--dt first as dt=), to the first demo
    int frames = 0;                                         ///< close after this many frames; 0 = when closed
    int width = 800, height = 600;
    /// The host's step (--dt and --set dt=, one setting: Application/StepSetting.h); book 0.03 s
    Rational step{3, 100};
    bool vsync = true;
    bool noUi = false;
    bool quiet = false;  ///< no "demo: ID" lines and no summary
};

/// Runs the window until it is closed or `frames` frames have been shown. Prints "demo: ID" (or "demo: none")
/// on stdout whenever the running demo changes, and a summary line with the frame count and the final camera
/// at the end (then, with `--set model=auto`, the auto model's summary line, "Model: auto, ..."). The caller checks the
/// demo id. Returns kExitOk, kExitUsage for a bad --set, kExitFailure when no window can be opened (no display). With
/// `--set model=auto` the first demo's model is chosen before the first frame (kExitUsage for a budget no candidate
/// meets) and watched while it runs (Application/AutoModelHost.h).
int RunWindowed(const WindowedOptions& options);
