#pragma once
// The headless replacement of the book's main-win32 loop (docs/book-reference.md §1.2, §7): one OSMesa context, ImGui
// with its OpenGL2 back end, a DemoWindow, the exact fixed-step accumulator, PNG frames through the encode queue, the
// --state CSV and the golden comparison.

#include <string>

#include "Application/CommandLine.h"
#include "Application/ExitCodes.h"

/// Timings of one run (steady clock, seconds). They go to the console and the benchmark, never into a frame.
struct RunStats {
    int frames = 0;
    long long steps = 0;
    double simulatedSeconds = 0.0;
    double wallSeconds = 0.0;
    double renderSeconds = 0.0;    ///< OnUpdate .. ImGui draw .. glFinish
    double readbackSeconds = 0.0;  ///< glReadPixels and the row flip
    double encodeSeconds = 0.0;    ///< PNG encode + write (+ compare), summed over jobs
    double waitSeconds = 0.0;      ///< main thread blocked on a full encode queue
    // CPU time (CLOCK_THREAD_CPUTIME_ID / CLOCK_PROCESS_CPUTIME_ID): unlike the wall clock, it does not grow
    // when other processes take the cores, so it measures the work itself on a shared machine.
    double renderCpuSeconds = 0.0;   ///< main thread: update, fixed steps, render, readback (llvmpipe
                                     ///< rasterises on this thread with LP_NUM_THREADS=0)
    double encodeCpuSeconds = 0.0;   ///< the thread running the encode jobs
    double processCpuSeconds = 0.0;  ///< whole process over the run
    std::string renderer;            ///< glGetString(GL_RENDERER) and the back end, for the summary
    /// "GL_VENDOR ...; GL_RENDERER ...; GL_VERSION ...; back end ..." ("" without drawing): the renderer line of
    /// compare.txt and of a golden directory's renderer.txt (RunOutputs::renderer).
    std::string glStrings;
};

/// Runs one parsed command line (Mode::Run). Returns an ExitCode; messages go to stderr. Out of memory is
/// exit 3 with a message, the run's partial output removed.
int RunSandbox(const Options& options, RunStats* stats);
/// --demo ID names a registered demo: kExitOk, else kExitUsage with the valid ids on stderr.
int CheckDemoId(const std::string& id);
