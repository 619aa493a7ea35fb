// Video recording through ffmpeg (Platform/VideoEncoder.h): frame count, size and duration read back with
// ffprobe, the GIF's colours, and nothing left behind on failure. Skipped, saying so, without ffmpeg.
#include "Platform/VideoEncoder.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace {

namespace fs = std::filesystem;

std::string Shell(const std::string& command) {
    std::string out;
    if (FILE* p = popen(command.c_str(), "r")) {
        char buf[256];
        while (std::fgets(buf, sizeof buf, p)) out += buf;
        pclose(p);
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
    return out;
}

/// A frame of the book's blue-grey background with a green square at a position that moves with i.
Image Frame(int w, int h, int i) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = image.Pixel(x, y);
            const bool square = x >= i % (w - 8) && x < i % (w - 8) + 8 && y >= 8 && y < 16;
            p[0] = square ? 20 : 128, p[1] = square ? 255 : 153, p[2] = square ? 20 : 178;
        }
    return image;
}

class VideoEncoderTest : public ::testing::Test {
protected:
    void SetUp() override {
        std::string error;
        if (!VideoEncoder::FfmpegAvailable(&error) || Shell("command -v ffprobe").empty())
            GTEST_SKIP() << "ffmpeg/ffprobe not installed (Debian package 'ffmpeg'): " << error;
        dir = fs::temp_directory_path() / ("psb-video-test-" + std::to_string(getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override {
        if (!dir.empty()) fs::remove_all(dir);
    }
    /// Records `count` frames of w x h at fps; returns the path (empty on failure, with a test failure).
    std::string Record(const std::string& name, int w, int h, int count, double fps) {
        const std::string path = (dir / name).string();
        VideoEncoder video;
        std::string error;
        EXPECT_TRUE(video.Open(path, w, h, fps, &error)) << error;
        for (int i = 0; i < count; ++i) EXPECT_TRUE(video.WriteFrame(Frame(w, h, i), &error)) << error;
        EXPECT_FALSE(fs::exists(path)) << "the file must appear only when complete";
        EXPECT_TRUE(video.Finish(&error)) << error;
        return path;
    }
    std::string Probe(const std::string& path, const std::string& entries) {
        return Shell("ffprobe -v error -select_streams v:0 -count_frames -show_entries " + entries +
                     " -of default=noprint_wrappers=1:nokey=1 '" + path + "'");
    }
    /// Files in the directory other than `keep` (temporaries that should be gone).
    int Leftovers(const std::string& keep = "") {
        int n = 0;
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path().filename() != keep) ++n;
        return n;
    }
    fs::path dir;
};

TEST_F(VideoEncoderTest, Mp4HasEveryFrameTheSizeAndTheDuration) {
    const std::string path = Record("run.mp4", 96, 64, 45, 60.0);
    EXPECT_EQ(Probe(path, "stream=nb_read_frames"), "45");
    EXPECT_EQ(Probe(path, "stream=width,height"), "96\n64");
    EXPECT_NEAR(std::stod(Probe(path, "format=duration")), 45.0 / 60.0, 1.0 / 60.0);
    EXPECT_EQ(Leftovers("run.mp4"), 0);
}

TEST_F(VideoEncoderTest, WebmHasEveryFrameTheSizeAndTheDuration) {
    const std::string path = Record("run.webm", 64, 48, 30, 60.0);
    EXPECT_EQ(Probe(path, "stream=nb_read_frames"), "30");
    EXPECT_EQ(Probe(path, "stream=width,height"), "64\n48");
    EXPECT_NEAR(std::stod(Probe(path, "format=duration")), 0.5, 1.0 / 60.0 + 1e-3);
    EXPECT_EQ(Leftovers("run.webm"), 0);
}

TEST_F(VideoEncoderTest, OddSizesArePaddedToEven) {
    const std::string path = Record("odd.mp4", 63, 47, 10, 30.0);
    EXPECT_EQ(Probe(path, "stream=width,height"), "64\n48");
}

TEST_F(VideoEncoderTest, GifKeepsTheExactColoursAndResamplesSixtyToFifty) {
    const std::string path = Record("run.gif", 64, 48, 60, 60.0);
    // 1 s at 60 fps becomes 50 frames of 2/100 s.
    EXPECT_EQ(Probe(path, "stream=nb_read_frames"), "50");
    EXPECT_EQ(Probe(path, "stream=width,height"), "64\n48");
    EXPECT_NEAR(std::stod(Probe(path, "format=duration")), 1.0, 0.021);
    // Decode the first frame back to raw RGB: the palette keeps the two colours exactly, no dithering.
    const std::string raw = (dir / "first.rgb").string();
    Shell("ffmpeg -v error -y -i '" + path + "' -frames:v 1 -f rawvideo -pix_fmt rgb24 '" + raw + "'");
    std::FILE* f = std::fopen(raw.c_str(), "rb");
    ASSERT_NE(f, nullptr);
    Image decoded(64, 48);
    ASSERT_EQ(std::fread(decoded.rgb.data(), 1, decoded.rgb.size(), f), decoded.rgb.size());
    std::fclose(f);
    EXPECT_TRUE(decoded == Frame(64, 48, 0));
}

TEST_F(VideoEncoderTest, AbortAndFailuresLeaveNothingBehind) {
    {
        VideoEncoder video;
        std::string error;
        ASSERT_TRUE(video.Open((dir / "a.mp4").string(), 32, 32, 60.0, &error)) << error;
        ASSERT_TRUE(video.WriteFrame(Frame(32, 32, 0), &error)) << error;
        video.Abort();
    }
    {
        VideoEncoder video;  // destructor aborts
        std::string error;
        ASSERT_TRUE(video.Open((dir / "b.gif").string(), 32, 32, 60.0, &error)) << error;
        ASSERT_TRUE(video.WriteFrame(Frame(32, 32, 0), &error)) << error;
        EXPECT_FALSE(video.WriteFrame(Frame(16, 16, 0), &error));
        EXPECT_NE(error.find("16x16"), std::string::npos) << error;
    }
    EXPECT_EQ(Leftovers(), 0);
    VideoEncoder video;
    std::string error;
    EXPECT_FALSE(video.Open((dir / "missing" / "c.mp4").string(), 32, 32, 60.0, &error));
    EXPECT_NE(error.find("missing"), std::string::npos) << error;
    EXPECT_FALSE(video.Open((dir / "c.avi").string(), 32, 32, 60.0, &error));
    EXPECT_NE(error.find("c.avi"), std::string::npos) << error;
    EXPECT_EQ(Leftovers(), 0);
}

TEST(VideoEncoderFormat, TheExtensionNamesTheFormat) {
    VideoEncoder::Format f = VideoEncoder::Format::Mp4;
    EXPECT_TRUE(VideoEncoder::FormatOf("a/b.GIF", &f));
    EXPECT_EQ(f, VideoEncoder::Format::Gif);
    EXPECT_TRUE(VideoEncoder::FormatOf("x.webm", &f));
    EXPECT_EQ(f, VideoEncoder::Format::Webm);
    EXPECT_TRUE(VideoEncoder::FormatOf("x.mp4", &f));
    EXPECT_EQ(f, VideoEncoder::Format::Mp4);
    EXPECT_FALSE(VideoEncoder::FormatOf("x.mkv", &f));
    EXPECT_FALSE(VideoEncoder::FormatOf("dir.mp4/x", &f));
    EXPECT_FALSE(VideoEncoder::FormatOf("noext", &f));
}

}  // namespace
