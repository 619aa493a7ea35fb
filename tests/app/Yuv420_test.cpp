// RGB to yuv420p (Platform/Yuv420.h): BT.601 limited-range values of known colours, black padding of odd
// sizes, and agreement with ffmpeg's own conversion (when ffmpeg is installed).
#include "Platform/Yuv420.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

/// Y, U and V of a frame filled with one colour (any 2x2 block: all are the same).
struct Yuv {
    int y, u, v;
};
Yuv Convert(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    Image image(w, h);
    for (std::size_t k = 0; k < image.rgb.size(); k += 3) image.rgb[k] = r, image.rgb[k + 1] = g, image.rgb[k + 2] = b;
    std::vector<std::uint8_t> out;
    RgbToYuv420(image, &out);
    const std::size_t luma = std::size_t(EvenSide(w) * EvenSide(h));
    return {out[0], out[luma], out[luma + luma / 4]};
}

TEST(Yuv420, ColoursTakeTheirBt601StudioValues) {
    // Black, white and grey exactly; every colour of a 9x9x9 grid within one level of BT.601 with Y in 16..235
    // and chroma in 16..240: Y = 16 + 219 (0.299 R + 0.587 G + 0.114 B) / 255, U = 128 + 224 (B - Y') / 1.772 /
    // 255, V = 128 + 224 (R - Y') / 1.402 / 255, with Y' = 0.299 R + 0.587 G + 0.114 B.
    EXPECT_EQ(Convert(4, 4, 0, 0, 0).y, 16);
    EXPECT_EQ(Convert(4, 4, 255, 255, 255).y, 235);
    for (const int grey : {0, 77, 128, 255}) {
        const Yuv yuv = Convert(4, 4, std::uint8_t(grey), std::uint8_t(grey), std::uint8_t(grey));
        EXPECT_EQ(yuv.u, 128) << grey;
        EXPECT_EQ(yuv.v, 128) << grey;
    }
    for (int r = 0; r <= 256; r += 32)
        for (int g = 0; g <= 256; g += 32)
            for (int b = 0; b <= 256; b += 32) {
                const int R = std::min(r, 255), G = std::min(g, 255), B = std::min(b, 255);
                const double luma = 0.299 * R + 0.587 * G + 0.114 * B;
                const double y = 16.0 + 219.0 * luma / 255.0, u = 128.0 + 224.0 * (B - luma) / 1.772 / 255.0,
                             v = 128.0 + 224.0 * (R - luma) / 1.402 / 255.0;
                const Yuv got = Convert(2, 2, std::uint8_t(R), std::uint8_t(G), std::uint8_t(B));
                EXPECT_LE(std::abs(got.y - y), 1.0) << R << "," << G << "," << B;
                EXPECT_LE(std::abs(got.u - u), 1.0) << R << "," << G << "," << B;
                EXPECT_LE(std::abs(got.v - v), 1.0) << R << "," << G << "," << B;
            }
}

TEST(Yuv420, OddSidesArePaddedWithBlack) {
    Image white(3, 3);
    std::fill(white.rgb.begin(), white.rgb.end(), std::uint8_t(255));
    std::vector<std::uint8_t> out;
    RgbToYuv420(white, &out);
    ASSERT_EQ(out.size(), 4u * 4u * 3u / 2u);
    // Luma: the 3x3 image in the top-left corner of 4x4, black (16) in the last row and column.
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) EXPECT_EQ(out[std::size_t(y * 4 + x)], x < 3 && y < 3 ? 235 : 16) << x << "," << y;
    // Chroma stays grey: white and black have none. The block of one white and three black pixels is grey too.
    for (std::size_t k = 16; k < out.size(); ++k) EXPECT_EQ(out[k], 128) << k;
}

TEST(Yuv420, ChromaIsTheMeanOfEachBlock) {
    // A 2x2 block of red, green, blue and white: four lumas of their own, and the chroma of the block's mean
    // colour (127.5 in each channel), which is grey.
    Image block(2, 2);
    const std::uint8_t colours[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
    for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) block.rgb[std::size_t(3 * k + c)] = colours[k][c];
    std::vector<std::uint8_t> out;
    RgbToYuv420(block, &out);
    for (int k = 0; k < 4; ++k)
        EXPECT_EQ(out[std::size_t(k)], Convert(2, 2, colours[k][0], colours[k][1], colours[k][2]).y) << k;
    EXPECT_EQ(out[4], 128);
    EXPECT_EQ(out[5], 128);
}

TEST(Yuv420, AgreesWithFfmpegsConversion) {
    if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "ffmpeg not installed (Debian package 'ffmpeg')";
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("psb-yuv-test-" + std::to_string(getpid()));
    fs::create_directories(dir);
    // Flat 16x16 tiles of varied colours: ffmpeg's scaler filters chroma across a few neighbouring pixels, so
    // only the middle of each tile is compared (chroma rows and columns 2 to 5 of each 8x8 chroma tile).
    const int w = 128, h = 96;
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int t = (y / 16) * 8 + x / 16;
            std::uint8_t* p = image.Pixel(x, y);
            p[0] = std::uint8_t(t * 37 % 256), p[1] = std::uint8_t(t * 91 % 256), p[2] = std::uint8_t(t * 53 % 256);
        }
    const std::string in = (dir / "in.rgb").string(), out = (dir / "out.yuv").string();
    std::FILE* f = std::fopen(in.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    std::fwrite(image.rgb.data(), 1, image.rgb.size(), f);
    std::fclose(f);
    ASSERT_EQ(std::system(("ffmpeg -v error -y -f rawvideo -pix_fmt rgb24 -video_size 128x96 -i '" + in +
                           "' -f rawvideo -pix_fmt yuv420p '" + out + "'")
                              .c_str()),
              0);
    std::vector<std::uint8_t> theirs(std::size_t(w * h * 3 / 2)), ours;
    f = std::fopen(out.c_str(), "rb");
    ASSERT_NE(f, nullptr);
    ASSERT_EQ(std::fread(theirs.data(), 1, theirs.size(), f), theirs.size());
    std::fclose(f);
    fs::remove_all(dir);
    RgbToYuv420(image, &ours);
    ASSERT_EQ(ours.size(), theirs.size());
    int worstLuma = 0, worstChroma = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            worstLuma = std::max(worstLuma, std::abs(ours[std::size_t(y * w + x)] - theirs[std::size_t(y * w + x)]));
    for (int plane = 0; plane < 2; ++plane)
        for (int y = 0; y < h / 2; ++y)
            for (int x = 0; x < w / 2; ++x) {
                if (y % 8 < 2 || y % 8 > 5 || x % 8 < 2 || x % 8 > 5) continue;
                const std::size_t k = std::size_t(w * h + plane * (w * h / 4) + y * (w / 2) + x);
                worstChroma = std::max(worstChroma, std::abs(ours[k] - theirs[k]));
            }
    EXPECT_LE(worstLuma, 1);
    EXPECT_LE(worstChroma, 1);
}

}  // namespace
