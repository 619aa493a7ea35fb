// Joining GIF files that share a screen and colour table (Platform/GifFile.h), on hand-built 1 x 1 GIFs.
#include "Platform/GifFile.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

namespace fs = std::filesystem;

/// A 1 x 1 GIF89a with a two-entry global colour table (black and `white`), a NETSCAPE looping extension and
/// `frames` frames, each a graphic control extension and an image whose one pixel is colour index `pixel`.
std::string OnePixelGif(int frames, int pixel, unsigned char white = 0xFF) {
    std::string g = "GIF89a";
    g += std::string("\x01\x00\x01\x00\x80\x00\x00", 7);                // 1 x 1, global table of 2 entries
    g += std::string("\x00\x00\x00", 3) + std::string(3, char(white));  // the table
    g += std::string("\x21\xFF\x0B", 3) + "NETSCAPE2.0" + std::string("\x03\x01\x00\x00\x00", 5);
    for (int i = 0; i < frames; ++i) {
        g += std::string("\x21\xF9\x04\x00\x02\x00\x00\x00", 8);           // delay 2/100 s
        g += std::string("\x2C\x00\x00\x00\x00\x01\x00\x01\x00\x00", 10);  // image 1 x 1 at (0, 0)
        g += std::string("\x02\x02", 2) + char(pixel ? 0x4C : 0x44) +
             std::string("\x01\x00", 2);  // LZW: clear, index, end
    }
    return g + "\x3B";
}

/// Number of frames: graphic control extensions after the first frame's offset, walked block by block.
int Frames(const std::string& g) {
    std::size_t i = 0;
    if (!GifFirstFrameOffset(g, &i)) return -1;
    int frames = 0;
    while (i < g.size() && static_cast<unsigned char>(g[i]) != 0x3B) {
        if (g[i] == 0x21) {  // extension: label, then sub-blocks
            if (static_cast<unsigned char>(g[i + 1]) == 0xF9) ++frames;
            i += 2;
        } else {  // image descriptor (10 bytes), LZW minimum code size, sub-blocks
            i += 11;
        }
        while (g[i] != 0) i += 1 + static_cast<unsigned char>(g[i]);
        ++i;
    }
    return frames;
}

class GifFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("psb-gif-test-" + std::to_string(getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    std::string Write(const std::string& name, const std::string& bytes) {
        const std::string path = (dir / name).string();
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }
    static std::string Read(const std::string& path) {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    fs::path dir;
};

TEST(GifFirstFrameOffset, SkipsTheHeaderTableAndApplicationExtension) {
    std::size_t offset = 0;
    ASSERT_TRUE(GifFirstFrameOffset(OnePixelGif(1, 0), &offset));
    EXPECT_EQ(offset, 6u + 7u + 6u + 19u);  // signature, screen, table, NETSCAPE extension
    // No frame at all, a cut-off extension, or no GIF signature: no offset.
    EXPECT_FALSE(GifFirstFrameOffset(OnePixelGif(0, 0), &offset));
    EXPECT_FALSE(GifFirstFrameOffset(OnePixelGif(1, 0).substr(0, 30), &offset));
    EXPECT_FALSE(GifFirstFrameOffset("PNG89a" + OnePixelGif(1, 0).substr(6), &offset));
    EXPECT_FALSE(GifFirstFrameOffset("GIF89a", &offset));
}

TEST_F(GifFileTest, AppendsTheSecondFilesFramesAfterTheFirsts) {
    const std::string a = Write("a.gif", OnePixelGif(3, 0));
    const std::string b = Write("b.gif", OnePixelGif(2, 1));
    ASSERT_EQ(Frames(Read(a)), 3);
    std::string error;
    ASSERT_TRUE(AppendGifFrames(a, b, &error)) << error;
    const std::string joined = Read(a);
    EXPECT_EQ(Frames(joined), 5);
    // The first file's bytes but its trailer, then the second's from its first frame, trailer included.
    const std::string first = OnePixelGif(3, 0), second = OnePixelGif(2, 1);
    std::size_t frame = 0;
    ASSERT_TRUE(GifFirstFrameOffset(second, &frame));
    EXPECT_EQ(joined, first.substr(0, first.size() - 1) + second.substr(frame));
}

TEST_F(GifFileTest, RefusesDifferentColourTablesAndLeavesTheFirstUnchanged) {
    const std::string a = Write("a.gif", OnePixelGif(1, 0));
    const std::string b = Write("b.gif", OnePixelGif(1, 1, 0xFE));
    std::string error;
    EXPECT_FALSE(AppendGifFrames(a, b, &error));
    EXPECT_NE(error.find("colour tables"), std::string::npos) << error;
    EXPECT_EQ(Read(a), OnePixelGif(1, 0));
    const std::string cut = Write("cut.gif", OnePixelGif(1, 0).substr(0, 40));
    EXPECT_FALSE(AppendGifFrames(cut, b, &error));
    EXPECT_NE(error.find("cut.gif"), std::string::npos) << error;
    EXPECT_FALSE(AppendGifFrames(a, (dir / "missing.gif").string(), &error));
    EXPECT_NE(error.find("missing.gif"), std::string::npos) << error;
    EXPECT_EQ(Read(a), OnePixelGif(1, 0));
}

}  // namespace
