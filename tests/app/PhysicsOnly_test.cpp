// A run that writes no picture (no --out, --compare, --video or --window) makes no GL context and draws nothing
// (docs/app.md, "Runs without pictures"); its --state CSV is byte for byte that of the same run drawn with --out.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/app/SandboxRun.h"

namespace {

const char* kNoDrawing = "; no drawing)";

/// Runs `what` (--demo ID or --scene FILE plus its arguments) without and with --out; both CSVs must be equal.
void ExpectSameStateDrawnOrNot(const std::vector<std::string>& what, const std::string& name) {
    const std::string dir = ScratchDir("physics_only_" + name);
    std::vector<std::string> bare = what;
    bare.insert(bare.end(), {"--frames", "60", "--size", "96x72", "--state", dir + "/bare.csv"});
    std::vector<std::string> drawn = what;
    drawn.insert(drawn.end(), {"--frames", "60", "--size", "96x72", "--state", dir + "/drawn.csv", "--out",
                               dir + "/frames", "--only-frames", "59"});
    const SandboxResult b = RunSandboxExe(bare);
    ASSERT_EQ(b.exitCode, 0) << name << ": " << b.err;
    EXPECT_NE(b.err.find(kNoDrawing), std::string::npos) << name << ": " << b.err;
    const SandboxResult d = RunSandboxExe(drawn);
    ASSERT_EQ(d.exitCode, 0) << name << ": " << d.err;
    EXPECT_EQ(d.err.find(kNoDrawing), std::string::npos) << name << ": " << d.err;
    const std::string bareCsv = ReadText(dir + "/bare.csv");
    EXPECT_FALSE(bareCsv.empty()) << name;
    EXPECT_TRUE(bareCsv == ReadText(dir + "/drawn.csv")) << name << ": the state differs when drawn";
    EXPECT_EQ(FilesIn(dir + "/frames"), std::vector<std::string>{"frame_00059.png"}) << name;
}

}  // namespace

TEST(PhysicsOnly, EveryDemoGivesTheDrawnRunsState) {
    const std::vector<std::string> ids = ListDemoIds();
    ASSERT_FALSE(ids.empty());
    for (const std::string& id : ids) ExpectSameStateDrawnOrNot({"--demo", id}, id);
}

TEST(PhysicsOnly, EveryShippedSceneGivesTheDrawnRunsState) {
    int scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(PSB_SOURCE_DIR "/scenes")) {
        const std::string path = entry.path().string();
        if (entry.path().extension() != ".json" || path.find(".schema.") != std::string::npos) continue;
        ExpectSameStateDrawnOrNot({"--scene", path}, entry.path().stem().string());
        ++scenes;
    }
    EXPECT_GE(scenes, 5);
}

TEST(PhysicsOnly, NonBookSettingsTheUiFlagAndAnAutoModelGiveTheSameState) {
    // A changed integrator and step (the demo's own PhysicsStep), and --no-ui on the drawn side's twin.
    ExpectSameStateDrawnOrNot({"--demo", "ch16", "--set", "integrator=velocity-verlet", "--set", "dt=0.01"},
                              "ch16-verlet");
    ExpectSameStateDrawnOrNot({"--demo", "ch15", "--no-ui"}, "ch15-no-ui");
    // An auto model (docs/model-choice.md): its choice, live watch and error_estimate column.
    ExpectSameStateDrawnOrNot({"--demo", "springs", "--set", "model=auto"}, "springs-auto");
}
