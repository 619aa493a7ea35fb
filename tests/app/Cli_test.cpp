// The executable's command line end to end: exit codes, messages, nothing written on bad usage, whole
// frames only, determinism and the golden comparison.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "Platform/PngCodec.h"
#include "tests/app/SandboxRun.h"

namespace fs = std::filesystem;

namespace {

// The first registered demo. The registry is complete, so an empty one is a failure, never a skip.
std::string AnyDemo() {
    const std::vector<std::string> ids = ListDemoIds();
    return ids.empty() ? std::string() : ids.front();
}

#define REQUIRE_DEMO(id)              \
    const std::string id = AnyDemo(); \
    ASSERT_FALSE(id.empty()) << "no demo registered in DemoRegistry (--list printed nothing)"

// The nine demos of the book's app (docs/book-reference.md §1.7).
const std::vector<std::string> kBookDemoIds = {
    "raycast", "ch14", "collision-features", "linear-impulse", "momentum", "ch15", "springs", "ch16", "joints"};

bool HasTemporaries(const std::string& dir) {
    for (const std::string& f : FilesIn(dir))
        if (IsTemporaryName(f)) return true;
    return false;
}

}  // namespace

TEST(Cli, HelpAndList) {
    const SandboxResult help = RunSandboxExe({"--help"});
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("--demo ID"), std::string::npos);
    const SandboxResult list = RunSandboxExe({"--list"});
    EXPECT_EQ(list.exitCode, 0);
    // Every demo of the book is listed, once (a loop over an empty listing would check nothing).
    std::vector<std::string> ids = ListDemoIds(), expected = kBookDemoIds;
    std::sort(ids.begin(), ids.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(ids, expected);
    std::istringstream lines(list.out);
    std::string line;
    while (std::getline(lines, line)) {
        const std::size_t tab = line.find('\t');
        ASSERT_NE(tab, std::string::npos) << line;
        EXPECT_GT(tab, 0u);
        EXPECT_LT(tab + 1, line.size()) << "empty title: " << line;
    }
}

TEST(Cli, BadUsageExitsTwoAndWritesNothing) {
    const std::string dir = ScratchDir("bad_usage");
    const std::string out = dir + "/frames";
    const std::vector<std::vector<std::string>> cases = {
        {"--bogus"},
        {"--demo", "no-such-demo", "--out", out},
        {"--demo", "raycast", "--size", "800by600", "--out", out},
        {"--demo", "raycast", "--frames", "0", "--out", out},
        {"--demo", "raycast", "--frames", "-3", "--out", out},
        {"--demo", "raycast", "--set", "nokey", "--out", out},
        {"--demo", "raycast", "--out"},
    };
    for (const auto& args : cases) {
        const SandboxResult r = RunSandboxExe(args);
        EXPECT_EQ(r.exitCode, 2) << args.front() << ": " << r.err;
        EXPECT_NE(r.err.find("physics-sandbox: "), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(out)) << "bad usage created " << out;
    }
    const SandboxResult unknown = RunSandboxExe({"--demo", "no-such-demo", "--out", out});
    EXPECT_NE(unknown.err.find("unknown demo 'no-such-demo'"), std::string::npos) << unknown.err;
    EXPECT_NE(unknown.err.find("valid ids"), std::string::npos) << unknown.err;
}

TEST(Cli, UnknownParameterListsTheValidOnes) {
    REQUIRE_DEMO(id);
    const std::string out = ScratchDir("bad_set") + "/frames";
    const SandboxResult r =
        RunSandboxExe({"--demo", id, "--set", "no_such_key=1", "--out", out, "--state", out + ".csv"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("no_such_key"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("parameters of " + id), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(out + ".csv"));
}

TEST(Cli, ParamsPrintsTheTableWithValuesAfterSet) {
    const std::string out = ScratchDir("params") + "/frames";
    const SandboxResult r = RunSandboxExe({"--demo", "ch16", "--set", "count=20", "--params", "--out", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("parameters of ch16"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("count = 20"), std::string::npos) << r.out;  // the value in effect after --set
    EXPECT_NE(r.out.find("integrator"), std::string::npos) << r.out;  // every key is listed
    EXPECT_FALSE(fs::exists(out)) << "--params renders nothing";
}

// ch15, linear-impulse and momentum take the soft solver and its settings; --params lists them in effect, and a
// run with them goes through (the book's solver stays each demo's default: the goldens).
TEST(Cli, RigidDemosTakeTheSoftSolverAndListItsKeys) {
    const std::string dir = ScratchDir("params_soft");
    for (const std::string id : {"ch15", "linear-impulse", "momentum"}) {
        const SandboxResult defaults = RunSandboxExe({"--demo", id, "--params"});
        ASSERT_EQ(defaults.exitCode, 0) << id << ": " << defaults.err;
        EXPECT_NE(defaults.out.find("solver = book  [book|accumulated|soft]"), std::string::npos) << defaults.out;
        const SandboxResult r = RunSandboxExe({"--demo", id, "--set", "solver=soft", "--set", "soft-substeps=8",
                                               "--set", "soft-contact-hertz=60", "--params"});
        ASSERT_EQ(r.exitCode, 0) << id << ": " << r.err;
        for (const char* line : {"solver = soft", "soft-substeps = 8  [integer 1..64]", "soft-contact-hertz = 60",
                                 "soft-contact-damping-ratio = 1", "soft-max-pushout-speed = 3"}) {
            EXPECT_NE(r.out.find(line), std::string::npos) << id << " lacks '" << line << "':\n" << r.out;
        }
        const SandboxResult run = RunSandboxExe({"--demo", id, "--set", "solver=soft", "--frames", "10", "--no-ui",
                                                 "--state", dir + "/" + id + ".csv", "--quiet"});
        EXPECT_EQ(run.exitCode, 0) << id << ": " << run.err;
        const SandboxResult bad = RunSandboxExe({"--demo", id, "--set", "soft-substeps=0", "--params"});
        EXPECT_EQ(bad.exitCode, 2) << id;
        EXPECT_NE(bad.err.find("soft-substeps"), std::string::npos) << bad.err;
    }
}

TEST(Cli, BadParameterValueIsRejected) {
    // Find a demo with a numeric or boolean parameter from the listing --set prints, then give it junk.
    for (const std::string& id : ListDemoIds()) {
        const SandboxResult listing = RunSandboxExe({"--demo", id, "--set", "no_such_key=1"});
        const std::size_t table = listing.err.find("parameters of");
        ASSERT_NE(table, std::string::npos) << id << ": " << listing.err;
        std::istringstream lines(listing.err.substr(table));
        std::string line;
        std::getline(lines, line);
        while (std::getline(lines, line)) {
            std::istringstream words(line);
            std::string key;
            words >> key;
            if (key.empty()) continue;
            const std::string out = ScratchDir("bad_value") + "/frames";
            const SandboxResult r = RunSandboxExe({"--demo", id, "--set", key + "=not-a-value", "--out", out});
            if (r.exitCode != 2) continue;  // an action or free-form key accepts it
            EXPECT_NE(r.err.find("not-a-value"), std::string::npos) << r.err;
            EXPECT_FALSE(fs::exists(out));
            return;
        }
    }
    // Every demo has numeric parameters (dt, iterations, counts, ...): reaching here means none was validated.
    FAIL() << "no registered demo has a parameter that rejects a junk value";
}

TEST(Cli, UnwritableOutputExitsThreeNamingThePath) {
    REQUIRE_DEMO(id);
    const std::string dir = ScratchDir("unwritable");
    std::ofstream(dir + "/file") << "x";
    const SandboxResult r = RunSandboxExe({"--demo", id, "--out", dir + "/file/frames", "--quiet"});
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.err.find(dir + "/file/frames"), std::string::npos) << r.err;
}

TEST(Cli, FailedFrameWriteExitsThreeAndLeavesNoPartialFrame) {
    REQUIRE_DEMO(id);
    const std::string out = ScratchDir("blocked");
    fs::create_directories(out + "/frame_00002.png");  // renaming a frame onto a directory fails
    const SandboxResult r =
        RunSandboxExe({"--demo", id, "--frames", "5", "--size", "64x48", "--out", out, "--state", out + "/s.csv"});
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.err.find(out + "/frame_00002.png"), std::string::npos) << r.err;
    EXPECT_FALSE(HasTemporaries(out));
    EXPECT_TRUE(fs::exists(out + "/frame_00000.png"));
    EXPECT_FALSE(fs::exists(out + "/frame_00003.png"));
    EXPECT_FALSE(fs::exists(out + "/s.csv")) << "state of a failed run must not be left as if complete";
}

TEST(Cli, NonFiniteStateExitsThreeNamingFrameAndBody) {
    REQUIRE_DEMO(id);
    // The check itself is DemoBase::StateIsFinite; this drives the runner's reporting path.
    const SandboxResult r =
        RunSandboxExe({"--demo", id, "--frames", "4", "--size", "64x48", "--debug-nonfinite-at", "2"});
    EXPECT_EQ(r.exitCode, 3) << r.err;
    EXPECT_NE(r.err.find("frame 2"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("body"), std::string::npos) << r.err;
}

TEST(Cli, SameCommandGivesByteIdenticalFramesAndState) {
    const std::vector<std::string> ids = ListDemoIds();
    ASSERT_EQ(ids.size(), kBookDemoIds.size()) << "every demo must be covered";
    for (const std::string& id : ids) {
        std::vector<std::string> dirs;
        for (const char* mode : {"threaded", "again", "serial"}) {
            const std::string out = ScratchDir(id + "_det_" + mode);
            std::vector<std::string> args = {
                "--demo",    id,      "--frames", "40",      "--size",           "160x120", "--only-frames",
                "0,1,20,39", "--out", out,        "--state", out + "/state.csv", "--quiet"};
            if (std::string(mode) == "serial") args.push_back("--serial-encode");
            const SandboxResult r = RunSandboxExe(args);
            ASSERT_EQ(r.exitCode, 0) << id << ": " << r.err;
            dirs.push_back(out);
        }
        const std::vector<std::string> files = FilesIn(dirs[0]);
        ASSERT_EQ(files, (std::vector<std::string>{"frame_00000.png", "frame_00001.png", "frame_00020.png",
                                                   "frame_00039.png", "state.csv"}));
        for (std::size_t k = 1; k < dirs.size(); ++k) {
            EXPECT_EQ(FilesIn(dirs[k]), files);
            for (const std::string& f : files)
                EXPECT_EQ(ReadText(dirs[0] + "/" + f), ReadText(dirs[k] + "/" + f)) << id << " " << f;
        }
        const std::string state = ReadText(dirs[0] + "/state.csv");
        EXPECT_EQ(state.rfind("frame,time,body,kind,x,y,z,vx,vy,vz\n", 0), 0u) << id;
    }
}

TEST(Cli, MinSsimPassesAFrameFromTheOtherBackEndThatPixelsFail) {
    // Goldens through OSMesa; frames through EGL (docs/rendering.md "Back ends"), once as made and once seen from
    // 0.93 degrees further round (SSIM about 0.999 at 160x120), compared with no pixel tolerance at all.
    const std::string golden = ScratchDir("ssim_golden");
    const std::vector<std::string> base = {"--demo", "ch15",   "--frames", "31",     "--only-frames",
                                           "30",     "--size", "160x120",  "--quiet"};
    auto args = base;
    args.insert(args.end(), {"--backend", "osmesa", "--compare", golden, "--update-golden"});
    SandboxResult r = RunSandboxExe(args);
    if (r.exitCode == 2 && r.err.find("this build has no") != std::string::npos) GTEST_SKIP() << r.err;
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string out = ScratchDir("ssim_out");
    auto compare = [&](const std::vector<std::string>& extra) {
        fs::remove_all(out);
        auto a = base;
        a.insert(a.end(),
                 {"--backend", "egl", "--compare", golden, "--out", out, "--tolerance", "0", "--max-diff", "0"});
        a.insert(a.end(), extra.begin(), extra.end());
        return RunSandboxExe(a);
    };
    r = compare({"--min-ssim", "0.99"});
    if (r.exitCode == 2 || r.err.find("no OpenGL context") != std::string::npos) GTEST_SKIP() << "no EGL: " << r.err;
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(ReadText(out + "/compare.txt").find("frame_00030.png: "), std::string::npos);

    r = compare({"--camera-yaw", "-67"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find(", SSIM 0.99"), std::string::npos) << r.err;
    EXPECT_TRUE(fs::exists(out + "/mismatch/frame_00030.amplified.png"));
    r = compare({"--camera-yaw", "-67", "--min-ssim", "0.995"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    const std::string report = ReadText(out + "/compare.txt");
    EXPECT_NE(report.find(": pass on SSIM"), std::string::npos) << report;
    EXPECT_NE(report.find("min SSIM 0.995"), std::string::npos) << report;
    EXPECT_EQ(compare({"--camera-yaw", "-67", "--min-ssim", "0.9999"}).exitCode, 1);
}

TEST(Cli, CompareReportsExactAndFlagsAMismatch) {
    REQUIRE_DEMO(id);
    const std::string golden = ScratchDir("golden");
    const std::vector<std::string> base = {"--demo", id, "--frames", "3", "--size", "96x72"};
    auto args = base;
    args.insert(args.end(), {"--compare", golden, "--update-golden", "--quiet"});
    ASSERT_EQ(RunSandboxExe(args).exitCode, 0);
    ASSERT_EQ(FilesIn(golden),
              (std::vector<std::string>{"frame_00000.png", "frame_00001.png", "frame_00002.png", "renderer.txt"}));
    const std::string made = ReadText(golden + "/renderer.txt");
    EXPECT_EQ(made.rfind("GL_VENDOR ", 0), 0u) << made;
    EXPECT_NE(made.find("; GL_RENDERER "), std::string::npos) << made;
    EXPECT_NE(made.find("; GL_VERSION "), std::string::npos) << made;

    const std::string out = ScratchDir("compare_out");
    args = base;
    args.insert(args.end(), {"--compare", golden, "--out", out});
    SandboxResult r = RunSandboxExe(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("frame_00001.png: exact"), std::string::npos) << r.err;
    // compare.txt names the renderer of both sides.
    const std::string line = made.substr(0, made.find('\n'));
    EXPECT_NE(ReadText(out + "/compare.txt").find("\nrenderer: " + line + "\ngolden renderer: " + line + "\n"),
              std::string::npos)
        << ReadText(out + "/compare.txt");

    // Paint a block of frame 1's golden: beyond any tolerance over ~4 % of the pixels.
    Image img;
    std::string error;
    ASSERT_TRUE(ReadPngFile(golden + "/frame_00001.png", &img, &error)) << error;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) img.Pixel(x, y)[0] ^= 0x80;
    std::vector<std::uint8_t> bytes;
    ASSERT_TRUE(EncodePng(img, {}, &bytes, &error));
    ASSERT_TRUE(WriteFileAtomic(golden + "/frame_00001.png", bytes, &error));

    r = RunSandboxExe(args);
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("frame_00000.png: exact"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("frame_00001.png: max channel diff 128"), std::string::npos) << r.err;
    for (const char* f :
         {"frame_00001.expected.png", "frame_00001.actual.png", "frame_00001.diff.png", "frame_00001.amplified.png"})
        EXPECT_TRUE(fs::exists(out + "/mismatch/" + f)) << f;
    EXPECT_FALSE(fs::exists(out + "/mismatch/frame_00000.diff.png"));
    EXPECT_NE(ReadText(out + "/compare.txt").find("1 mismatch"), std::string::npos);
}
