// physics-sandbox --video under hostile conditions (docs/app.md, "Video"): a video is whole or absent. A write
// failure (a file-size limit), an ffmpeg that exits 0 without writing, and an ffmpeg that hangs each end the
// run with exit 3 and a message, leave nothing behind, and leave an earlier file at the same path untouched.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "tests/app/SandboxRun.h"

namespace {

namespace fs = std::filesystem;

class VideoFailure : public ::testing::Test {
protected:
    void SetUp() override {
        if (RunShellScript("command -v ffmpeg && command -v ffprobe").exitCode != 0)
            GTEST_SKIP() << "ffmpeg/ffprobe not installed (Debian package 'ffmpeg', scripts/install-deps.sh)";
    }
    /// A scratch directory holding one good recording `name` of ch15 (60 frames at 320x240); returns the dir.
    std::string WithGoodVideo(const std::string& test, const std::string& name) {
        const std::string dir = ScratchDir(test);
        const SandboxResult r = RunSandboxExe(
            {"--demo", "ch15", "--frames", "60", "--size", "320x240", "--video", dir + "/" + name, "--quiet"});
        EXPECT_EQ(r.exitCode, 0) << r.err;
        good = ReadText(dir + "/" + name);
        EXPECT_FALSE(good.empty());
        return dir;
    }
    /// A directory with an executable `ffmpeg` that runs body (a shell script), to put first on PATH.
    static std::string FakeFfmpeg(const std::string& test, const std::string& body) {
        const std::string bin = ScratchDir(test + "-bin");
        const SandboxResult r = RunShellScript("printf '#!/bin/sh\\n%s\\n' '" + body + "' > '" + bin +
                                               "/ffmpeg' && chmod +x '" + bin + "/ffmpeg'");
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return bin;
    }
    /// Every entry of dir, hidden ones included.
    static std::vector<std::string> Entries(const std::string& dir) {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }
    std::string good;
};

TEST_F(VideoFailure, AFileSizeLimitExitsThreeAndKeepsTheEarlierVideo) {
    // ffmpeg inherits the ignored SIGXFSZ, fails to write its trailer ("File too large") and exits 0: the file
    // it leaves (20 KB of MP4 without its moov box; WebM without its last frames) must not replace the good one.
    for (const auto& [name, limit] : {std::pair<const char*, const char*>{"v.mp4", "20"}, {"v.webm", "12"}}) {
        const std::string dir = WithGoodVideo(std::string("video-fsize-") + name, name);
        ASSERT_GT(good.size(), std::stoul(limit) * 1024) << "the limit must cut the new recording short";
        const SandboxResult r = RunSandboxShell(
            std::string("ulimit -f ") + limit + ";",
            {"--demo", "ch15", "--frames", "60", "--size", "320x240", "--video", dir + "/" + name, "--quiet"});
        EXPECT_EQ(r.exitCode, 3) << name << ": " << r.err;
        EXPECT_NE(r.err.find(dir + "/" + name), std::string::npos) << "names the path: " << r.err;
        EXPECT_NE(r.err.find("File too large"), std::string::npos) << "gives the reason: " << r.err;
        EXPECT_TRUE(ReadText(dir + "/" + name) == good) << name << ": the earlier video must stay as it was";
        EXPECT_EQ(Entries(dir), std::vector<std::string>{name}) << "no temporary left";
    }
}

TEST_F(VideoFailure, AnFfmpegThatExitsZeroWithoutWritingExitsThreeAndKeepsTheEarlierVideo) {
    // One fake reads every frame and writes nothing, the other exits at once.
    for (const char* body : {"cat >/dev/null; exit 0", "exit 0"}) {
        const std::string bin = FakeFfmpeg("video-fake", body);
        for (const char* name : {"v.mp4", "v.webm", "v.gif"}) {
            const std::string dir = WithGoodVideo(std::string("video-fake-") + name, name);
            // With --state: a run whose video failed keeps no CSV either.
            const SandboxResult r = RunSandboxShell("PATH='" + bin + "':$PATH",
                                                    {"--demo", "ch15", "--frames", "60", "--size", "320x240", "--video",
                                                     dir + "/" + name, "--state", dir + "/s.csv", "--quiet"});
            EXPECT_EQ(r.exitCode, 3) << body << ", " << name << ": " << r.err;
            EXPECT_NE(r.err.find("--video " + dir + "/" + name), std::string::npos) << r.err;
            EXPECT_TRUE(ReadText(dir + "/" + name) == good) << body << ", " << name << ": the earlier video must stay";
            EXPECT_EQ(Entries(dir), std::vector<std::string>{name})
                << body << ": nothing else left (no temporary, no CSV)";
        }
    }
}

TEST_F(VideoFailure, AStuckFfmpegIsStoppedAfterTheTimeoutAndNothingIsLeft) {
    // `exec sleep 1000` neither reads its input nor ends. PSB_ENCODER_TIMEOUT=1 (seconds without progress); the
    // outer `timeout 30` only keeps a broken build from hanging the suite.
    const std::string bin = ScratchDir("video-stuck-bin");
    RunShellScript("printf '#!/bin/sh\\necho $$ >> \"%s/pids\"\\nexec sleep 1000\\n' '" + bin + "' > '" + bin +
                   "/ffmpeg' && chmod +x '" + bin + "/ffmpeg'");
    // MP4 blocks on the pipe (60 frames of 320x240 are 6.9 MB); GIF waits for its part's ffmpeg; 5 MP4 frames fit
    // in the pipe, so that run waits for ffmpeg to end.
    for (const auto& [name, frames] :
         {std::pair<const char*, const char*>{"v.mp4", "60"}, {"v.gif", "60"}, {"v.mp4", "5"}}) {
        const std::string dir = ScratchDir(std::string("video-stuck-") + name + frames);
        const SandboxResult r = RunSandboxShell(
            "PSB_ENCODER_TIMEOUT=1 PATH='" + bin + "':$PATH timeout -s KILL 30",
            {"--demo", "ch15", "--frames", frames, "--size", "320x240", "--video", dir + "/" + name, "--quiet"});
        EXPECT_EQ(r.exitCode, 3) << name << " " << frames << ": " << r.err;
        EXPECT_NE(r.err.find("PSB_ENCODER_TIMEOUT"), std::string::npos) << "says why: " << r.err;
        EXPECT_TRUE(Entries(dir).empty()) << name << ": " << Entries(dir).size() << " entries left";
    }
    // Every fake ffmpeg started was killed.
    std::istringstream pids(ReadText(bin + "/pids"));
    int count = 0;
    for (std::string pid; pids >> pid; ++count)
        EXPECT_NE(RunShellScript("kill -0 " + pid).exitCode, 0) << "ffmpeg " << pid << " still runs";
    EXPECT_GE(count, 3);
    RunShellScript("for p in $(cat '" + bin + "/pids'); do kill -9 $p; done 2>/dev/null");
}

}  // namespace
