// physics-sandbox --video: every frame of the run in an .mp4, .webm or .gif (checked with ffprobe), beside
// --out and --only-frames; bad names and a missing ffmpeg are refused up front with nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/app/SandboxRun.h"

namespace {

namespace fs = std::filesystem;

std::string Probe(const std::string& path, const std::string& entries) {
    const SandboxResult r = RunShellScript("ffprobe -v error -select_streams v:0 -count_frames -show_entries " +
                                           entries + " -of default=noprint_wrappers=1:nokey=1 '" + path + "'");
    std::string out = r.out;
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    return out;
}

class VideoRun : public ::testing::Test {
protected:
    void SetUp() override {
        if (RunShellScript("command -v ffmpeg && command -v ffprobe").exitCode != 0)
            GTEST_SKIP() << "ffmpeg/ffprobe not installed (Debian package 'ffmpeg', scripts/install-deps.sh)";
    }
};

TEST_F(VideoRun, Mp4HoldsEveryFrameAtTheRunsSizeAndDurationBesideThePngFrames) {
    const std::string dir = ScratchDir("video-mp4");
    const SandboxResult r = RunSandboxExe({"--demo", "ch15", "--frames", "90", "--size", "320x240", "--only-frames",
                                           "0,89", "--out", dir + "/frames", "--video", dir + "/run.mp4", "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(Probe(dir + "/run.mp4", "stream=nb_read_frames"), "90");
    EXPECT_EQ(Probe(dir + "/run.mp4", "stream=width,height"), "320\n240");
    EXPECT_NEAR(std::stod(Probe(dir + "/run.mp4", "format=duration")), 1.5, 1.0 / 60.0);
    EXPECT_EQ(FilesIn(dir + "/frames"), (std::vector<std::string>{"frame_00000.png", "frame_00089.png"}));
    EXPECT_EQ(FilesIn(dir), (std::vector<std::string>{"run.mp4"})) << "no temporary left beside the video";
}

TEST_F(VideoRun, WebmAndGifFollowTheFrameRate) {
    const std::string dir = ScratchDir("video-webm-gif");
    SandboxResult r = RunSandboxExe({"--demo", "springs", "--frames", "30", "--fps", "30", "--size", "160x120",
                                     "--video", dir + "/run.webm", "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(Probe(dir + "/run.webm", "stream=nb_read_frames"), "30");
    EXPECT_NEAR(std::stod(Probe(dir + "/run.webm", "format=duration")), 1.0, 1.0 / 30.0 + 1e-3);
    r = RunSandboxExe(
        {"--demo", "ch14", "--frames", "60", "--size", "160x120", "--video", dir + "/run.gif", "--quiet"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(Probe(dir + "/run.gif", "stream=nb_read_frames"), "50") << "60 fps becomes 50 (GIF delays: 1/100 s)";
    EXPECT_NEAR(std::stod(Probe(dir + "/run.gif", "format=duration")), 1.0, 0.021);
}

TEST_F(VideoRun, AVideoMayGoIntoTheDirectoriesOutCreates) {
    // --out creates its directory and those on the way before the recording starts.
    const std::string dir = ScratchDir("video-in-out");
    for (const auto& [out, video] : {std::pair<std::string, std::string>{dir + "/o", dir + "/o/run.mp4"},
                                     {dir + "/a/frames", dir + "/a/run.gif"}}) {
        const SandboxResult r =
            RunSandboxExe({"--demo", "ch14", "--frames", "3", "--size", "64x48", "--out", out, "--video", video});
        ASSERT_EQ(r.exitCode, 0) << video << ": " << r.err;
        EXPECT_EQ(Probe(video, "stream=nb_read_frames"), "3");
        EXPECT_EQ(FilesIn(out).size(), video.find("/o/") != std::string::npos ? 4u : 3u) << "3 frames (+ the video)";
    }
    // A directory nobody creates is still refused.
    const SandboxResult r = RunSandboxExe({"--demo", "ch14", "--out", dir + "/p", "--video", dir + "/q/run.mp4"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/p"));
}

TEST_F(VideoRun, AFailedRunLeavesNoVideo) {
    // MP4 pipes to one ffmpeg; GIF writes a raw file and pipes to palettegen at the same time: every temporary is
    // removed when the run fails.
    for (const char* name : {"run.mp4", "run.gif"}) {
        const std::string dir = ScratchDir(std::string("video-failed-") + name);
        const SandboxResult r = RunSandboxExe({"--demo", "ch14", "--frames", "10", "--size", "64x48", "--video",
                                               dir + "/" + name, "--debug-nonfinite-at", "5", "--quiet"});
        EXPECT_EQ(r.exitCode, 3) << name << ": " << r.err;
        EXPECT_TRUE(FilesIn(dir).empty()) << name << " left: " << FilesIn(dir).size() << " files";
    }
}

TEST(VideoUsage, BadNamesAndAMissingFfmpegAreRefusedWithNothingWritten) {
    const std::string dir = ScratchDir("video-usage");
    SandboxResult r = RunSandboxExe({"--demo", "ch14", "--video", dir + "/run.avi"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("run.avi"), std::string::npos) << r.err;
    r = RunSandboxExe({"--demo", "ch14", "--video", dir + "/missing/run.mp4"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("missing"), std::string::npos) << r.err;
    // No ffmpeg on PATH: exit 2 naming the Debian package.
    r = RunSandboxShell("PATH=/nonexistent", {"--demo", "ch14", "--video", dir + "/run.mp4", "--out", dir + "/o"});
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("'ffmpeg'"), std::string::npos) << r.err;
    r = RunSandboxExe({"--window", "--video", dir + "/run.mp4"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_TRUE(FilesIn(dir).empty());
}

TEST(BackendUsage, UnknownBackendsAreRefusedAndEachBuiltBackendRuns) {
    SandboxResult r = RunSandboxExe({"--demo", "ch14", "--backend", "vulkan"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("vulkan"), std::string::npos) << r.err;
    for (const char* backend : {"osmesa", "egl"}) {
        const std::string out = ScratchDir(std::string("backend-") + backend);
        r = RunSandboxExe({"--demo", "ch14", "--frames", "2", "--size", "64x48", "--backend", backend, "--out", out});
        if (r.exitCode == 2 && r.err.find("this build has no") != std::string::npos) continue;  // left out by CMake
        EXPECT_EQ(r.exitCode, 0) << backend << ": " << r.err;
        EXPECT_NE(r.err.find(std::string("via ") + backend), std::string::npos) << r.err;
    }
}

}  // namespace
