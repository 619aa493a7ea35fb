// physics-sandbox --scene FILE (docs/scenes.md): a scene file runs as a demo does (frames, --state, --set on its
// model, its panel); a bad file exits 2 naming the file, the JSON path and the value, with nothing written.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/app/SandboxRun.h"

namespace {

std::string WriteScene(const std::string& dir, const std::string& name, const std::string& text) {
    const std::string path = dir + "/" + name;
    std::ofstream(path) << text;
    return path;
}

const char* kDrop = R"({"format": 1, "name": "Drop", "duration": 0.5,
  "bodies": [{"id": "ground", "type": "box", "position": [0, -1, 0], "halfExtents": [5, 1, 5], "mass": 0},
             {"id": "ball", "type": "sphere", "position": [0, 3, 0], "radius": 0.5},
             {"id": "dot", "type": "particle", "position": [2, 3, 0]}],
  "constraints": [{"position": [0, -1, 0], "halfExtents": [5, 1, 5]}]})";

int CountLines(const std::string& text) {
    int n = 0;
    for (char c : text) n += c == '\n';
    return n;
}

}  // namespace

TEST(SceneRun, RunsTheFilesDurationAndWritesState) {
    const std::string dir = ScratchDir("scene_run");
    const std::string scene = WriteScene(dir, "drop.json", kDrop);
    const SandboxResult r = RunSandboxExe({"--scene", scene, "--state", dir + "/s.csv", "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string csv = ReadText(dir + "/s.csv");
    // 0.5 s at 60 frames per second = 30 frames, 3 bodies each, plus the header.
    EXPECT_EQ(CountLines(csv), 1 + 30 * 3);
    EXPECT_NE(csv.find(",0,box,"), std::string::npos);
    EXPECT_NE(csv.find(",1,sphere,"), std::string::npos);
    EXPECT_NE(csv.find(",2,particle,"), std::string::npos);
}

TEST(SceneRun, OnlyFramesAreCheckedAgainstTheFilesLength) {
    // Without --frames the run's length is the file's duration (30 frames here), known only after loading:
    // frame 29 is the last one, 30 is refused with nothing written. cli_fuzz leaves this case to the Runner.
    const std::string dir = ScratchDir("scene_only_frames");
    const std::string scene = WriteScene(dir, "drop.json", kDrop);
    const SandboxResult late =
        RunSandboxExe({"--scene", scene, "--only-frames", "30", "--out", dir + "/late", "--no-ui", "--quiet"});
    EXPECT_EQ(late.exitCode, 2);
    EXPECT_NE(late.err.find("--only-frames 30 is not below the scene's 30 frames"), std::string::npos) << late.err;
    EXPECT_EQ(FilesIn(dir), std::vector<std::string>{"drop.json"});
    const SandboxResult last =
        RunSandboxExe({"--scene", scene, "--only-frames", "29", "--out", dir + "/last", "--no-ui", "--quiet"});
    ASSERT_EQ(last.exitCode, 0) << last.err;
    EXPECT_EQ(FilesIn(dir + "/last"), std::vector<std::string>{"frame_00029.png"});
}

TEST(SceneRun, IsDeterministicAndSetChangesTheModel) {
    const std::string dir = ScratchDir("scene_set");
    const std::string scene = WriteScene(dir, "drop.json", kDrop);
    auto run = [&](const std::string& csv, std::vector<std::string> extra) {
        std::vector<std::string> args = {"--scene", scene, "--frames", "60", "--state", dir + "/" + csv, "--quiet"};
        args.insert(args.end(), extra.begin(), extra.end());
        const SandboxResult r = RunSandboxExe(args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return ReadText(dir + "/" + csv);
    };
    const std::string a = run("a.csv", {});
    EXPECT_EQ(a, run("b.csv", {}));
    EXPECT_NE(a, run("c.csv", {"--set", "integrator=rk4"}));
    EXPECT_NE(a, run("d.csv", {"--set", "dt=0.01"}));
}

TEST(SceneRun, ParamsListTheModelSettings) {
    const std::string dir = ScratchDir("scene_params");
    const std::string scene = WriteScene(dir, "drop.json", kDrop);
    const SandboxResult r = RunSandboxExe({"--scene", scene, "--set", "solver=accumulated", "--params"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("integrator"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("accumulated"), std::string::npos) << r.out;
    const SandboxResult bad = RunSandboxExe({"--scene", scene, "--set", "nonsense=1"});
    EXPECT_EQ(bad.exitCode, 2);
}

TEST(SceneRun, PanelShowsTheScenesNameAndDiffersFromNoUi) {
    const std::string dir = ScratchDir("scene_panel");
    const std::string scene = WriteScene(dir, "drop.json", kDrop);
    const SandboxResult ui = RunSandboxExe({"--scene", scene, "--frames", "1", "--out", dir + "/ui", "--quiet"});
    const SandboxResult none =
        RunSandboxExe({"--scene", scene, "--frames", "1", "--out", dir + "/none", "--no-ui", "--quiet"});
    ASSERT_EQ(ui.exitCode, 0) << ui.err;
    ASSERT_EQ(none.exitCode, 0) << none.err;
    EXPECT_NE(ReadText(dir + "/ui/frame_00000.png"), ReadText(dir + "/none/frame_00000.png"));
}

TEST(SceneRun, BadFileExitsTwoAndWritesNothing) {
    const std::string dir = ScratchDir("scene_bad");
    const std::string scene = WriteScene(dir, "bad.json", R"({"format": 1, "name": "x",
  "bodies": [{"id": "a", "type": "box", "position": [0, 1, 0], "mass": -2}]})");
    const SandboxResult r =
        RunSandboxExe({"--scene", scene, "--frames", "5", "--out", dir + "/out", "--state", dir + "/s.csv"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find(scene + ": bodies[0].mass: must be 0 or in [1e-06, 1e+09] (got -2)"), std::string::npos)
        << r.err;
    EXPECT_EQ(FilesIn(dir), std::vector<std::string>{"bad.json"});

    const std::string broken = WriteScene(dir, "broken.json", "{\n  \"format\": 1,\n  \"name\": }\n");
    const SandboxResult s = RunSandboxExe({"--scene", broken});
    EXPECT_EQ(s.exitCode, 2);
    EXPECT_NE(s.err.find(broken + ":3:11: syntax error"), std::string::npos) << s.err;

    EXPECT_EQ(RunSandboxExe({"--scene", dir + "/missing.json"}).exitCode, 2);
}

// A file that cannot be opened gives the system's reason, as --compare does: a missing file, a dangling link and a
// link to itself are each refused with exit 2 and their own reason, not "not a regular file".
TEST(SceneRun, UnopenableFilesGiveTheSystemsReason) {
    const std::string dir = ScratchDir("scene_unopenable");
    ASSERT_EQ(RunShellScript("cd '" + dir + "' && ln -s nothing dangling.json && ln -s loop.json loop.json").exitCode,
              0);
    const struct {
        std::string file, reason;
    } cases[] = {{dir + "/missing.json", "No such file or directory"},
                 {dir + "/dangling.json", "No such file or directory"},
                 {dir + "/loop.json", "Too many levels of symbolic links"},
                 {dir, "not a regular file"}};
    for (const auto& c : cases) {
        const SandboxResult r = RunSandboxExe({"--scene", c.file, "--frames", "1", "--out", dir + "/out"});
        EXPECT_EQ(r.exitCode, 2) << c.file;
        EXPECT_NE(r.err.find(c.file + ": cannot read: " + c.reason), std::string::npos) << r.err;
    }
    EXPECT_FALSE(std::ifstream(dir + "/out").good());
}

// Nesting costs what the file's size says: a 40 KB file nested 20,000 deep and a 2 MB one nested 1,000,000 deep
// (both under the 4 MiB limit) are refused with their depth and the limit, within 400 MB of address space (the
// executable alone maps about 190 MB) (the depth-20000 file once took 835 MB, a path string per open level in the
// duplicate-key check).
TEST(SceneRun, DeepNestingIsRefusedWithItsDepthInLittleMemory) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit this test sets";
#endif
    const std::string dir = ScratchDir("scene_deep");
    for (const int depth : {20000, 1000000}) {
        const std::string scene = WriteScene(
            dir, "deep.json",
            R"({"format": 1, "name": "d", "extra": )" + std::string(depth, '[') + std::string(depth, ']') + "}");
        const SandboxResult r = RunSandboxShell("ulimit -v 400000;", {"--scene", scene, "--frames", "1", "--no-ui"});
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_NE(r.err.find(scene + ":1:"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("nest " + std::to_string(depth + 1) + " levels deep, over the limit of 64"),
                  std::string::npos)
            << r.err;
    }
}

TEST(SceneRun, ExactlyOneOfDemoAndScene) {
    const SandboxResult both = RunSandboxExe({"--demo", "ch14", "--scene", "x.json"});
    EXPECT_EQ(both.exitCode, 2);
    EXPECT_NE(both.err.find("--demo and --scene"), std::string::npos) << both.err;
    const SandboxResult none = RunSandboxExe({"--frames", "2"});
    EXPECT_EQ(none.exitCode, 2);
    EXPECT_NE(none.err.find("no --demo or --scene"), std::string::npos) << none.err;
}

TEST(SceneRun, EveryShippedSceneRuns) {
    const std::string dir = ScratchDir("scene_shipped");
    for (const std::string& name : FilesIn(std::string(PSB_SOURCE_DIR) + "/scenes")) {
        if (name.size() < 5 || name.substr(name.size() - 5) != ".json" || name == "scene.schema.json") continue;
        const SandboxResult r = RunSandboxExe({"--scene", std::string(PSB_SOURCE_DIR) + "/scenes/" + name, "--frames",
                                               "30", "--state", dir + "/" + name + ".csv", "--quiet"});
        EXPECT_EQ(r.exitCode, 0) << name << ": " << r.err;
    }
}

TEST(SceneRun, BookScenesGiveTheirDemosStateByteForByte) {
    const std::string dir = ScratchDir("scene_book");
    for (const std::string id : {"ch14", "ch15", "ch16"}) {
        const SandboxResult demo = RunSandboxExe(
            {"--demo", id, "--frames", "300", "--no-ui", "--state", dir + "/" + id + "-demo.csv", "--quiet"});
        const SandboxResult scene =
            RunSandboxExe({"--scene", std::string(PSB_SOURCE_DIR) + "/scenes/" + id + ".json", "--frames", "300",
                           "--no-ui", "--state", dir + "/" + id + "-scene.csv", "--quiet"});
        ASSERT_EQ(demo.exitCode, 0) << demo.err;
        ASSERT_EQ(scene.exitCode, 0) << scene.err;
        const std::string a = ReadText(dir + "/" + id + "-demo.csv");
        EXPECT_GT(CountLines(a), 300) << id;
        EXPECT_TRUE(a == ReadText(dir + "/" + id + "-scene.csv"))
            << id << ": scenes/" << id << ".json differs from --demo";
    }
}

TEST(SceneRun, ExportedDemoScenesRunAsTheirDemos) {
    const std::string dir = ScratchDir("scene_export");
    for (const std::string id : {"ch15", "ch16", "springs", "momentum", "linear-impulse"}) {
        const std::string file = dir + "/" + id + ".json";
        const SandboxResult exported = RunSandboxExe({"--demo", id, "--export-scene", file});
        ASSERT_EQ(exported.exitCode, 0) << id << ": " << exported.err;
        const SandboxResult demo = RunSandboxExe(
            {"--demo", id, "--frames", "120", "--no-ui", "--state", dir + "/" + id + "-demo.csv", "--quiet"});
        const SandboxResult scene = RunSandboxExe(
            {"--scene", file, "--frames", "120", "--no-ui", "--state", dir + "/" + id + "-scene.csv", "--quiet"});
        ASSERT_EQ(demo.exitCode, 0) << demo.err;
        ASSERT_EQ(scene.exitCode, 0) << scene.err;
        EXPECT_TRUE(ReadText(dir + "/" + id + "-demo.csv") == ReadText(dir + "/" + id + "-scene.csv")) << id;
    }
}

// The export writes the demo's own camera (ch15 and momentum zoom 12, the others 9; docs/book-reference.md §1.4),
// and the run's camera flags over it, as a run starts.
TEST(SceneRun, ExportWritesTheDemosCamera) {
    const std::string dir = ScratchDir("scene_export_camera");
    const struct {
        const char* id;
        const char* zoom;
    } demos[] = {{"ch15", "\"zoom\": 12.0"},
                 {"momentum", "\"zoom\": 12.0"},
                 {"linear-impulse", "\"zoom\": 9.0"},
                 {"ch16", "\"zoom\": 9.0"}};
    for (const auto& d : demos) {
        const std::string file = dir + "/" + d.id + ".json";
        const SandboxResult r = RunSandboxExe({"--demo", d.id, "--export-scene", file});
        ASSERT_EQ(r.exitCode, 0) << d.id << ": " << r.err;
        const std::string text = ReadText(file);
        EXPECT_NE(text.find(d.zoom), std::string::npos) << d.id << ":\n" << text;
        EXPECT_NE(text.find("-67.9312"), std::string::npos) << d.id << ": the book's yaw";
    }
    const std::string file = dir + "/flags.json";
    const SandboxResult r =
        RunSandboxExe({"--demo", "ch15", "--camera-zoom", "20", "--camera-yaw", "10", "--export-scene", file});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string text = ReadText(file);
    EXPECT_NE(text.find("\"zoom\": 20.0"), std::string::npos) << text;
    EXPECT_EQ(text.find("-67.9312"), std::string::npos) << "the yaw flag replaces the preset's: " << text;
}

// Soft solver settings given with --set are exported (only where they differ from the defaults).
TEST(SceneRun, ExportWritesTheSoftSolversSettings) {
    const std::string dir = ScratchDir("scene_export_soft");
    const SandboxResult r = RunSandboxExe(
        {"--demo", "ch15", "--set", "solver=soft", "--set", "soft-substeps=8", "--export-scene", dir + "/ch15.json"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string text = ReadText(dir + "/ch15.json");
    EXPECT_NE(text.find("\"contactSolver\": \"soft\""), std::string::npos) << text;
    EXPECT_NE(text.find("\"soft\": {\n      \"substeps\": 8\n    }"), std::string::npos) << text;
    const SandboxResult plain = RunSandboxExe({"--demo", "ch15", "--export-scene", dir + "/plain.json"});
    ASSERT_EQ(plain.exitCode, 0) << plain.err;
    EXPECT_EQ(ReadText(dir + "/plain.json").find("\"soft\""), std::string::npos);
    // The exported scene runs as the demo with the same --set (the settings reach both worlds alike).
    const SandboxResult demo = RunSandboxExe({"--demo", "ch15", "--set", "solver=soft", "--set", "soft-substeps=8",
                                              "--frames", "120", "--no-ui", "--state", dir + "/demo.csv", "--quiet"});
    const SandboxResult scene = RunSandboxExe(
        {"--scene", dir + "/ch15.json", "--frames", "120", "--no-ui", "--state", dir + "/scene.csv", "--quiet"});
    ASSERT_EQ(demo.exitCode, 0) << demo.err;
    ASSERT_EQ(scene.exitCode, 0) << scene.err;
    EXPECT_TRUE(ReadText(dir + "/demo.csv") == ReadText(dir + "/scene.csv"));
}

TEST(SceneRun, ExportSaysWhatItCouldNotExpress) {
    const std::string dir = ScratchDir("scene_export_notes");
    const SandboxResult ch14 = RunSandboxExe({"--demo", "ch14", "--export-scene", dir + "/ch14.json"});
    EXPECT_EQ(ch14.exitCode, 0) << ch14.err;
    EXPECT_NE(ch14.err.find("not expressed: constraints[1]: orientation"), std::string::npos) << ch14.err;
    EXPECT_NE(ch14.err.find("y = -5"), std::string::npos) << ch14.err;
    const SandboxResult raycast = RunSandboxExe({"--demo", "raycast", "--export-scene", dir + "/raycast.json"});
    EXPECT_EQ(raycast.exitCode, 2);
    EXPECT_NE(raycast.err.find("scripted, not simulated"), std::string::npos) << raycast.err;
    EXPECT_EQ(FilesIn(dir), std::vector<std::string>{"ch14.json"});
    // --set applies before the export.
    const SandboxResult set =
        RunSandboxExe({"--demo", "ch15", "--set", "iterations=13", "--export-scene", dir + "/ch15.json"});
    ASSERT_EQ(set.exitCode, 0) << set.err;
    EXPECT_NE(ReadText(dir + "/ch15.json").find("\"iterations\": 13"), std::string::npos);
}

// A world's memory is bounded: 3,000 spheres at one point (4.5 million overlapping pairs, a legal file; 10,000 took
// 6.6 GB) stop at the first step with exit 3 naming the pair limit (WorldSettings::maxPairs), within 500 MB of
// address space, and leave no --state file.
TEST(SceneRun, OverlappingBodiesBeyondThePairLimitExitThreeNamingIt) {
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit this test sets";
#endif
    const std::string dir = ScratchDir("scene_pile");
    std::string bodies;
    for (int i = 0; i < 3000; ++i)
        bodies += std::string(i ? "," : "") + R"({"id": "s)" + std::to_string(i) +
                  R"(", "type": "sphere", "position": [0, 0, 0], "radius": 0.5})";
    const std::string scene =
        WriteScene(dir, "pile.json", R"({"format": 1, "name": "pile", "bodies": [)" + bodies + "]}");
    const SandboxResult r = RunSandboxShell(
        "ulimit -v 500000;",
        {"--scene", scene, "--frames", "5", "--no-ui", "--size", "64x48", "--state", dir + "/s.csv", "--quiet"});
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.err.find("step 1: more than 250000 pairs of volumes overlap, the limit of one pair search "
                         "(WorldSettings::maxPairs)"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(FilesIn(dir), std::vector<std::string>{"pile.json"});
}
