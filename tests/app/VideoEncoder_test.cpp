// Video recording through ffmpeg (Platform/VideoEncoder.h): frame count, size and duration read back with
// ffprobe, the GIF's colours, and nothing left behind on failure. Skipped, saying so, without ffmpeg.
#include "Platform/VideoEncoder.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

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
    std::string Record(const std::string& name, int w, int h, int count, double fps, int gifPartFrames = 0) {
        const std::string path = (dir / name).string();
        VideoEncoder video;
        video.SetGifPartFrames(gifPartFrames);
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
    EXPECT_EQ(Probe(path, "stream=color_range,color_space"), "tv\nsmpte170m") << "tagged as Yuv420 converts";
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

/// Frame i of a run whose colours change every frame: the moving square, and a band of eight colours found in
/// no other frame (so 60 frames hold 480 colours, more than one palette can, and any 7 of them 56 and a few).
Image ManyColourFrame(int w, int h, int i) {
    Image image = Frame(w, h, i);
    for (int x = 0; x < w; ++x)
        for (int y = 30; y < 38; ++y) {
            std::uint8_t* p = image.Pixel(x, y);
            const int k = i * 8 + x * 8 / w;  // 0 .. 479
            p[0] = std::uint8_t(k & 0xFF), p[1] = std::uint8_t(40 + (k >> 8) * 100), p[2] = std::uint8_t(255 - k / 2);
        }
    return image;
}

/// Decodes every frame of a video into w x h RGB images (empty on failure).
std::vector<Image> DecodeAll(const std::string& path, const std::string& raw, int w, int h) {
    Shell("ffmpeg -v error -y -i '" + path + "' -f rawvideo -pix_fmt rgb24 '" + raw + "'");
    std::vector<Image> frames;
    std::FILE* f = std::fopen(raw.c_str(), "rb");
    if (!f) return frames;
    for (Image image(w, h); std::fread(image.rgb.data(), 1, image.rgb.size(), f) == image.rgb.size();)
        frames.push_back(image);
    std::fclose(f);
    return frames;
}

/// Records ManyColourFrame 0..59 at 60 fps into dir/name with the encoder as `configure` sets it, and checks
/// that the GIF's 50 frames come back exactly: output frame j is input frame round(1.2 j), the input frame
/// nearest its time.
template <typename Configure>
void ExpectManyColourGifExact(const fs::path& dir, const std::string& name, Configure configure) {
    const int w = 64, h = 48;
    const std::string path = (dir / name).string();
    VideoEncoder video;
    configure(&video);
    std::string error;
    ASSERT_TRUE(video.Open(path, w, h, 60.0, &error)) << error;
    for (int i = 0; i < 60; ++i) ASSERT_TRUE(video.WriteFrame(ManyColourFrame(w, h, i), &error)) << error;
    ASSERT_TRUE(video.Finish(&error)) << error;
    const std::vector<Image> decoded = DecodeAll(path, (dir / (name + ".rgb")).string(), w, h);
    ASSERT_EQ(decoded.size(), 50u);
    for (int j = 0; j < 50; ++j) {
        const int i = (12 * j + 5) / 10;  // round(1.2 j); 1.2 j is never halfway
        EXPECT_TRUE(decoded[std::size_t(j)] == ManyColourFrame(w, h, i)) << "GIF frame " << j << ", input frame " << i;
    }
}

TEST_F(VideoEncoderTest, GifPartsEachGetThePaletteOfTheirFramesAndJoinExactly) {
    // Parts of 7 (8 parts, the last of one frame), each with its own palette. The run's 480 band colours do not
    // fit one palette; each part's do, so every frame comes back exactly.
    ExpectManyColourGifExact(dir, "parts.gif", [](VideoEncoder* video) { video->SetGifPartFrames(7); });
    const std::string path = (dir / "parts.gif").string();
    EXPECT_EQ(Leftovers("parts.gif") - 1, 0) << "only the GIF and its decoded frames: parts and raw files are gone";
    EXPECT_EQ(Probe(path, "stream=nb_read_frames"), "50");
    EXPECT_NEAR(std::stod(Probe(path, "format=duration")), 1.0, 0.021);
}

/// Images in a GIF file and how many of them carry a local colour table (walks the GIF89a blocks).
std::pair<int, int> ImagesAndLocalTables(const std::string& path) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    std::vector<std::uint8_t> b;
    if (f) {
        for (int c; (c = std::fgetc(f)) != EOF;) b.push_back(std::uint8_t(c));
        std::fclose(f);
    }
    int images = 0, local = 0;
    if (b.size() < 13) return {-1, -1};
    std::size_t i = 13 + ((b[10] & 0x80) ? 3u * (2u << (b[10] & 7)) : 0u);
    auto skipBlocks = [&] {
        while (i < b.size() && b[i] != 0) i += b[i] + 1u;
        ++i;
    };
    while (i < b.size() && b[i] != 0x3B) {
        if (b[i] == 0x21) {
            i += 2;
            skipBlocks();
        } else if (b[i] == 0x2C && i + 10 <= b.size()) {
            ++images;
            const std::uint8_t packed = b[i + 9];
            if (packed & 0x80) ++local;
            i += 10 + ((packed & 0x80) ? 3u * (2u << (packed & 7)) : 0u) + 1;
            skipBlocks();
        } else {
            return {-1, -1};
        }
    }
    return {images, local};
}

TEST_F(VideoEncoderTest, GifPartsOfFewColoursShareOnePalette) {
    // 60 frames, parts of 7 (8 parts), the square a new colour every frame: 61 colours in all, met part by part.
    // The parts go on with the colours of those before, and each gets the last palette, so the joined GIF keeps
    // one global table. ffmpeg gives each part's first image a small local table of its own; a palette per part
    // would add one to each of the 43 images of parts 2 to 8.
    const std::string path = (dir / "shared.gif").string();
    VideoEncoder video;
    video.SetGifPartFrames(7);
    std::string error;
    ASSERT_TRUE(video.Open(path, 64, 48, 60.0, &error)) << error;
    std::vector<Image> sent;
    for (int i = 0; i < 60; ++i) {
        Image frame = Frame(64, 48, i);
        for (std::size_t k = 0; k < frame.rgb.size(); k += 3)
            if (frame.rgb[k + 1] == 255) frame.rgb[k] = std::uint8_t(20 + 3 * i);  // the square's red
        sent.push_back(frame);
        ASSERT_TRUE(video.WriteFrame(frame, &error)) << error;
    }
    ASSERT_TRUE(video.Finish(&error)) << error;
    const std::pair<int, int> counts = ImagesAndLocalTables(path);
    EXPECT_EQ(counts.first, 50);
    EXPECT_LE(counts.second, 8) << "at most one local table a part";
    const std::vector<Image> decoded = DecodeAll(path, (dir / "shared.rgb").string(), 64, 48);
    ASSERT_EQ(decoded.size(), 50u);
    for (int j = 0; j < 50; ++j) EXPECT_TRUE(decoded[std::size_t(j)] == sent[std::size_t((12 * j + 5) / 10)]) << j;
}

TEST(VideoEncoderGifPlan, TheLastPartsShrinkAndThePartsAddUp) {
    using V = std::vector<int>;
    EXPECT_EQ(VideoEncoder::PlanGifParts(250, 100), (V{79, 100, 44, 19, 8}));  // 300 frames at 60 fps
    EXPECT_EQ(VideoEncoder::PlanGifParts(50, 100), (V{23, 19, 8}));
    EXPECT_EQ(VideoEncoder::PlanGifParts(5, 100), (V{5}));
    EXPECT_EQ(VideoEncoder::PlanGifParts(30, 7), (V{2, 7, 7, 7, 7}));
    EXPECT_TRUE(VideoEncoder::PlanGifParts(0, 100).empty()) << "no frames expected: parts of the default size";
    for (int frames : {1, 9, 99, 101, 999, 12345}) {
        const V plan = VideoEncoder::PlanGifParts(frames, 100);
        int sum = 0;
        for (std::size_t k = 0; k < plan.size(); ++k) {
            sum += plan[k];
            EXPECT_GE(plan[k], 1);
            EXPECT_LE(plan[k], 100);
            if (k >= 2) {
                EXPECT_LE(plan[k], plan[k - 1]) << "shrinking after the first part";
            }
        }
        EXPECT_EQ(sum, frames);
        EXPECT_LE(plan.back(), 8);
    }
}

TEST_F(VideoEncoderTest, AGifOfAKnownLengthInPlannedPartsJoinsExactly) {
    // 60 frames expected at 60 fps: 50 GIF frames in parts of 23, 19 and 8, each frame back exactly.
    ExpectManyColourGifExact(dir, "planned.gif", [](VideoEncoder* video) { video->ExpectFrames(60); });
}

TEST_F(VideoEncoderTest, AGifPartOfMoreThan256ColoursGetsAGeneratedPalette) {
    // Every pixel a colour of its own (3,072): the part's palette comes from palettegen, and the frames come
    // back close (no dithering: each pixel maps to its nearest palette colour).
    const int w = 64, h = 48;
    Image gradient(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = gradient.Pixel(x, y);
            p[0] = std::uint8_t(x * 4), p[1] = std::uint8_t(y * 5), p[2] = std::uint8_t((x + y) * 2);
        }
    const std::string path = (dir / "many.gif").string();
    VideoEncoder video;
    video.SetGifPartFrames(4);
    std::string error;
    ASSERT_TRUE(video.Open(path, w, h, 25.0, &error)) << error;
    for (int i = 0; i < 10; ++i) ASSERT_TRUE(video.WriteFrame(i == 5 ? gradient : Frame(w, h, i), &error)) << error;
    ASSERT_TRUE(video.Finish(&error)) << error;
    const std::vector<Image> decoded = DecodeAll(path, (dir / "many.rgb").string(), w, h);
    ASSERT_EQ(decoded.size(), 10u) << "25 fps is kept";
    // Parts of four: frames 0-3, 4-7 (the gradient's), 8-9.
    EXPECT_TRUE(decoded[3] == Frame(w, h, 3)) << "the parts of few colours stay exact";
    EXPECT_TRUE(decoded[8] == Frame(w, h, 8));
    // Frame 4 was stored as indices before the part met its 257th colour, then rewritten as BGRA: its two
    // colours, the most frequent of the part, come back exactly.
    EXPECT_TRUE(decoded[4] == Frame(w, h, 4)) << "the frame stored before the part overflowed";
    double sum = 0.0;
    for (std::size_t k = 0; k < gradient.rgb.size(); ++k)
        sum += std::abs(int(decoded[5].rgb[k]) - int(gradient.rgb[k]));
    EXPECT_LT(sum / double(gradient.rgb.size()), 4.0) << "mean error of the 256-colour approximation";
    EXPECT_GT(sum, 0.0) << "3,072 colours cannot all be exact";
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
    {
        VideoEncoder video;  // a GIF with parts being mapped and one waiting for its palette
        video.SetGifPartFrames(2);
        std::string error;
        ASSERT_TRUE(video.Open((dir / "c.gif").string(), 32, 32, 30.0, &error)) << error;
        for (int i = 0; i < 7; ++i) ASSERT_TRUE(video.WriteFrame(Frame(32, 32, i), &error)) << error;
        EXPECT_GT(Leftovers(), 3) << "raw frames and parts in progress";
        video.Abort();
        errno = 0;
        EXPECT_EQ(waitpid(-1, nullptr, WNOHANG), -1) << "every ffmpeg was reaped";
        EXPECT_EQ(errno, ECHILD);
    }
    {
        VideoEncoder video;  // after a failed frame, nothing more is recorded and Finish refuses
        std::string error;
        ASSERT_TRUE(video.Open((dir / "d.mp4").string(), 32, 32, 60.0, &error)) << error;
        EXPECT_FALSE(video.WriteFrame(Frame(16, 16, 0), &error));
        EXPECT_FALSE(video.WriteFrame(Frame(32, 32, 1), &error));
        EXPECT_FALSE(video.Finish(&error));
        EXPECT_NE(error.find("earlier frame"), std::string::npos) << error;
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
