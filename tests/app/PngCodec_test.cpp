#include "Platform/PngCodec.h"

#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "Platform/ImageCompare.h"

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

namespace {

void Append(png_structp png, png_bytep data, png_size_t n) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + n);
}

// img as a 16-bit RGBA PNG, each channel v stored as v * 257 (the exact 8-to-16-bit widening), alpha opaque.
std::vector<std::uint8_t> Encode16BitRgba(const Image& img) {
    std::vector<std::uint8_t> out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    std::vector<std::uint8_t> row(std::size_t(img.width) * 8);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return {};
    }
    png_set_write_fn(png, &out, Append, nullptr);
    png_set_IHDR(png, info, png_uint_32(img.width), png_uint_32(img.height), 16, PNG_COLOR_TYPE_RGBA,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const std::uint8_t v = c < 3 ? img.Pixel(x, y)[c] : 255;
                row[std::size_t(x) * 8 + std::size_t(c) * 2] = v;  // big-endian v * 257: both bytes are v
                row[std::size_t(x) * 8 + std::size_t(c) * 2 + 1] = v;
            }
        png_write_row(png, row.data());
    }
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return out;
}

}  // namespace

TEST(PngCodec, SixteenBitGoldenOfTheSameImageDecodesIdentically) {
    const Image img = Pattern(37, 23);
    const std::vector<std::uint8_t> bytes = Encode16BitRgba(img);
    ASSERT_FALSE(bytes.empty());
    Image back;
    std::string error;
    ASSERT_TRUE(DecodePng(bytes, &back, &error)) << error;
    EXPECT_TRUE(back == img) << "16-bit channels must keep their high byte, with no gamma conversion";
    EXPECT_EQ(CompareImages(img, back, {}).maxChannelDiff, 0);
}

TEST(PngCodec, HeaderIsReadWithoutDecodingAndHugeImagesAreRefused) {
    std::vector<std::uint8_t> bytes;
    std::string error;
    ASSERT_TRUE(EncodePng(Pattern(40, 30), {}, &bytes, &error));
    int w = 0, h = 0;
    ASSERT_TRUE(ReadPngHeader(bytes, &w, &h, &error)) << error;
    EXPECT_EQ(w, 40);
    EXPECT_EQ(h, 30);
    // Truncated inside the pixel data: the header still reads, the decode reports the truncation.
    bytes.resize(bytes.size() / 2);
    EXPECT_TRUE(ReadPngHeader(bytes, &w, &h, &error)) << error;
    Image img;
    EXPECT_FALSE(DecodePng(bytes, &img, &error));
    EXPECT_NE(error.find("truncated"), std::string::npos) << error;
    // An image wider than the largest frame is refused before its pixels are allocated.
    ASSERT_TRUE(EncodePng(Image(kMaxPngSide + 1, 1), {}, &bytes, &error)) << error;
    EXPECT_FALSE(DecodePng(bytes, &img, &error));
    EXPECT_NE(error.find("larger than"), std::string::npos) << error;
}
