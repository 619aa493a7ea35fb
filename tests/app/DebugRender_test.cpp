// The ch15 demo's debug render draws the contacts of every contact solver (Collisions(): red points, green normals).
// A frame of the same step with the debug render on and off: only the former has the contact points' red pixels.
#include <gtest/gtest.h>

#include <string>

#include "Platform/PngCodec.h"
#include "tests/app/SandboxRun.h"

namespace {

/// Pure red pixels (the contact points' colour, unlit) of frame 90 of ch15 run with `solver` and `debug`.
int RedPixels(const std::string& solver, bool debug) {
    const std::string dir = ScratchDir("debug_render_" + solver + (debug ? "_on" : "_off"));
    const SandboxResult r =
        RunSandboxExe({"--demo", "ch15", "--set", "solver=" + solver, "--set", debug ? "debug=true" : "debug=false",
                       "--frames", "91", "--only-frames", "90", "--out", dir, "--no-ui", "--quiet"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    Image image;
    std::string error;
    if (!ReadPngFile(dir + "/frame_00090.png", &image, &error)) {
        ADD_FAILURE() << error;
        return -1;
    }
    int red = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.Pixel(x, y);
            red += p[0] >= 250 && p[1] <= 5 && p[2] <= 5;
        }
    return red;
}

}  // namespace

// By frame 90 (1.5 s at 60 Hz) the boxes have landed and rest on each other and the ground.
TEST(DebugRender, DrawsContactsWithEverySolver) {
    for (const char* solver : {"book", "accumulated", "soft"}) {
        const int on = RedPixels(solver, true), off = RedPixels(solver, false);
        EXPECT_EQ(off, 0) << solver;
        // About 120-140 with every solver; 13 with the soft step's contacts left out of Collisions() (box edges).
        EXPECT_GT(on, 60) << solver << ": the debug render should draw the resting contacts";
    }
}
