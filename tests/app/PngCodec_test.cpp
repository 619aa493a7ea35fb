#include "Platform/PngCodec.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

Image Pattern(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = img.Pixel(x, y);
            p[0] = std::uint8_t(x * 7 + y), p[1] = std::uint8_t(y * 13), p[2] = std::uint8_t((x ^ y) * 3);
        }
    return img;
}

std::string TempDir() {
    const std::string dir = ::testing::TempDir() + "psb_png_" + std::to_string(getpid());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

}  // namespace

TEST(PngCodec, RoundTripIsLosslessAtEveryLevelAndFilterMode) {
    const Image img = Pattern(37, 23);  // odd sizes: no row alignment assumptions
    for (int level : {0, 1, 6, 9}) {
        for (PngFilter filter : {PngFilter::None, PngFilter::Sub, PngFilter::Up, PngFilter::Adaptive}) {
            std::vector<std::uint8_t> bytes;
            std::string error;
            ASSERT_TRUE(EncodePng(img, {level, filter}, &bytes, &error)) << error;
            Image back;
            ASSERT_TRUE(DecodePng(bytes, &back, &error)) << error;
            EXPECT_TRUE(back == img) << "level " << level << " filter " << int(filter);
        }
    }
}

TEST(PngCodec, EncodingIsDeterministic) {
    const Image img = Pattern(64, 48);
    std::vector<std::uint8_t> a, b;
    std::string error;
    ASSERT_TRUE(EncodePng(img, {}, &a, &error));
    ASSERT_TRUE(EncodePng(img, {}, &b, &error));
    EXPECT_EQ(a, b);
}

TEST(PngCodec, RejectsEmptyImagesAndGarbage) {
    std::vector<std::uint8_t> bytes;
    std::string error;
    EXPECT_FALSE(EncodePng(Image(), {}, &bytes, &error));
    EXPECT_NE(error.find("0x0"), std::string::npos);
    Image img;
    const std::vector<std::uint8_t> junk = {1, 2, 3, 4, 5};
    EXPECT_FALSE(DecodePng(junk, &img, &error));
}

TEST(PngCodec, AtomicWriteLeavesWholeFileOrNothing) {
    const std::string dir = TempDir();
    const std::string path = dir + "/frame.png";
    const std::vector<std::uint8_t> bytes = {1, 2, 3};
    std::string error;
    ASSERT_TRUE(WriteFileAtomic(path, bytes, &error)) << error;
    std::vector<std::uint8_t> back;
    ASSERT_TRUE(ReadFileBytes(path, &back, &error));
    EXPECT_EQ(back, bytes);
    EXPECT_FALSE(std::filesystem::exists(dir + "/.frame.png.tmp"));

    // Renaming onto a directory fails: the error names the path and no temporary remains.
    std::filesystem::create_directories(dir + "/blocked.png");
    EXPECT_FALSE(WriteFileAtomic(dir + "/blocked.png", bytes, &error));
    EXPECT_NE(error.find(dir + "/blocked.png"), std::string::npos) << error;
    EXPECT_FALSE(std::filesystem::exists(dir + "/.blocked.png.tmp"));
    // Whatever the temporary is called: the directory holds exactly the written file and the blocking directory.
    std::vector<std::string> entries;
    for (const auto& e : std::filesystem::directory_iterator(dir)) entries.push_back(e.path().filename().string());
    std::sort(entries.begin(), entries.end());
    EXPECT_EQ(entries, (std::vector<std::string>{"blocked.png", "frame.png"}));

    EXPECT_FALSE(WriteFileAtomic(dir + "/no/such/dir/frame.png", bytes, &error));
    EXPECT_NE(error.find("no/such/dir/frame.png"), std::string::npos) << error;
    std::filesystem::remove_all(dir);
}
