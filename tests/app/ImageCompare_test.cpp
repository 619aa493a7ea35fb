#include "Platform/ImageCompare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace {

const double kC1 = (0.01 * 255) * (0.01 * 255);
const double kC2 = (0.03 * 255) * (0.03 * 255);

Image Flat(int w, int h, std::uint8_t v) {
    Image img(w, h);
    std::fill(img.rgb.begin(), img.rgb.end(), v);
    return img;
}

}  // namespace

TEST(ImageCompare, IdenticalImagesAreExact) {
    const Image a = Flat(10, 10, 100);
    const CompareResult r = CompareImages(a, a, {});
    EXPECT_TRUE(r.exact);
    EXPECT_TRUE(r.passed);
    EXPECT_EQ(DescribeComparison(r, {}), "exact, SSIM 1");
    EXPECT_EQ(r.ssim, 1.0);
}

TEST(ImageCompare, DifferencesWithinTheChannelToleranceAreNotCounted) {
    const Image a = Flat(10, 10, 100);
    Image b = a;
    b.Pixel(3, 4)[1] = 108;  // exactly the tolerance of 8
    const CompareResult r = CompareImages(a, b, {8, 0.0});
    EXPECT_FALSE(r.exact);
    EXPECT_TRUE(r.passed);
    EXPECT_EQ(r.maxChannelDiff, 8);
    EXPECT_EQ(r.differingPixels, 0);
}

TEST(ImageCompare, FractionOfDifferingPixelsDecides) {
    const Image a = Flat(10, 10, 100);  // 100 pixels
    Image b = a;
    b.Pixel(0, 0)[0] = 0;
    b.Pixel(9, 9)[2] = 255;
    const CompareResult r = CompareImages(a, b, {8, 0.02});
    EXPECT_EQ(r.differingPixels, 2);
    EXPECT_DOUBLE_EQ(r.DifferingFraction(), 0.02);
    EXPECT_TRUE(r.passed);  // at most 2 %
    EXPECT_EQ(r.maxChannelDiff, 155);
    EXPECT_FALSE(CompareImages(a, b, {8, 0.019}).passed);
    EXPECT_NEAR(r.meanAbsDiff, (100.0 + 155.0) / 300.0, 1e-12);
}

TEST(ImageCompare, SizeMismatchFails) {
    const CompareResult r = CompareImages(Flat(10, 10, 0), Flat(10, 11, 0), {});
    EXPECT_TRUE(r.sizeMismatch);
    EXPECT_FALSE(r.passed);
}

TEST(ImageCompare, DiffImageMarksOnlyPixelsBeyondTheTolerance) {
    const Image a = Flat(4, 1, 100);
    Image b = a;
    b.Pixel(1, 0)[0] = 103;  // within tolerance: yellow
    b.Pixel(2, 0)[0] = 200;  // beyond: red
    const Image d = MakeDiffImage(a, b, {8, 0.0});
    EXPECT_EQ(d.Pixel(2, 0)[0], 255);
    EXPECT_EQ(d.Pixel(2, 0)[1], 0);
    EXPECT_EQ(d.Pixel(1, 0)[1], 220);
    EXPECT_EQ(d.Pixel(0, 0)[0], d.Pixel(0, 0)[1]);  // unchanged: grey
}

// ---- SSIM (Platform/ImageCompare.h Ssim: luminance, 8x8 uniform windows every 4 px).

namespace {

/// Grey level v in every channel: its luminance is v (the weights sum to 1).
Image Grey(int w, int h, std::uint8_t v) { return Flat(w, h, v); }

/// A deterministic pseudo-random colour image (a 32-bit LCG), so the reference below sees every kind of window.
Image Noise(int w, int h, std::uint32_t seed) {
    Image img(w, h);
    for (std::uint8_t& c : img.rgb) {
        seed = seed * 1664525u + 1013904223u;
        c = std::uint8_t(seed >> 24);
    }
    return img;
}

/// Straightforward reference: every window's statistics summed pixel by pixel (no running sums), the windows
/// listed as "0, 4, 8, ... while the window fits, then one ending at the border if that one is new".
double ReferenceSsim(const Image& a, const Image& b) {
    auto luma = [](const Image& img, int x, int y) {
        const std::uint8_t* p = img.Pixel(x, y);
        return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
    };
    auto origins = [](int size) {
        std::vector<int> list;
        const int window = size < 8 ? size : 8;
        for (int o = 0; o + window <= size; o += 4) list.push_back(o);
        if (list.back() != size - window) list.push_back(size - window);
        return list;
    };
    const int ww = a.width < 8 ? a.width : 8, wh = a.height < 8 ? a.height : 8;
    double total = 0;
    int count = 0;
    for (int y0 : origins(a.height)) {
        for (int x0 : origins(a.width)) {
            double ma = 0, mb = 0;
            for (int y = y0; y < y0 + wh; ++y)
                for (int x = x0; x < x0 + ww; ++x) ma += luma(a, x, y), mb += luma(b, x, y);
            const double n = ww * wh;
            ma /= n, mb /= n;
            double va = 0, vb = 0, cov = 0;
            for (int y = y0; y < y0 + wh; ++y)
                for (int x = x0; x < x0 + ww; ++x) {
                    const double da = luma(a, x, y) - ma, db = luma(b, x, y) - mb;
                    va += da * da, vb += db * db, cov += da * db;
                }
            va /= n, vb /= n, cov /= n;
            total += (2 * ma * mb + kC1) * (2 * cov + kC2) / ((ma * ma + mb * mb + kC1) * (va + vb + kC2));
            ++count;
        }
    }
    return total / count;
}

}  // namespace

TEST(Ssim, EqualImagesGiveOne) {
    const Image a = Noise(33, 17, 7);
    EXPECT_DOUBLE_EQ(Ssim(a, a), 1.0);
}

TEST(Ssim, FlatImagesGiveTheLuminanceTermAlone) {
    // No variance: every window is (2 v w + C1) / (v^2 + w^2 + C1), so the mean is that too.
    for (const auto& [v, w] : {std::pair<int, int>{100, 100}, {100, 120}, {0, 255}, {30, 200}}) {
        const double expected = (2.0 * v * w + kC1) / (double(v) * v + double(w) * w + kC1);
        EXPECT_NEAR(Ssim(Grey(24, 16, std::uint8_t(v)), Grey(24, 16, std::uint8_t(w))), expected, 1e-9)
            << v << " vs " << w;
    }
}

TEST(Ssim, InvertedStripesGiveTheNegativeStructureTerm) {
    // One 8x8 window of columns 0 / 200: mean 100, variance 100^2; its inverse (200 - a) has the same mean and
    // variance and covariance -100^2, so SSIM = (2 * 100^2 + C1)(-2 * 100^2 + C2) / ((2 * 100^2 + C1)(2 * 100^2 + C2)).
    Image a(8, 8), b(8, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) {
                a.Pixel(x, y)[c] = std::uint8_t(x % 2 ? 200 : 0);
                b.Pixel(x, y)[c] = std::uint8_t(200 - a.Pixel(x, y)[c]);
            }
    const double s = 100.0 * 100.0;
    EXPECT_NEAR(Ssim(a, b), (-2 * s + kC2) / (2 * s + kC2), 1e-9);
    // Halving the contrast (columns 50 / 150) keeps the means: SSIM = (2 cov + C2) / (var_a + var_b + C2) with
    // cov = 100 * 50, var_b = 50^2.
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) b.Pixel(x, y)[c] = std::uint8_t(x % 2 ? 150 : 50);
    EXPECT_NEAR(Ssim(a, b), (2 * 5000.0 + kC2) / (s + 2500.0 + kC2), 1e-9);
}

TEST(Ssim, MatchesAStraightforwardReferenceOnOddSizes) {
    // Sizes whose last window is moved in (37 = 4 * 7 + 9), exactly fits (24), or is smaller than 8 (5, 3).
    const std::pair<int, int> sizes[] = {{37, 21}, {24, 16}, {5, 3}, {8, 8}, {9, 40}};
    std::uint32_t seed = 1;
    for (const auto& [w, h] : sizes) {
        const Image a = Noise(w, h, seed++);
        Image b = a;  // a correlated copy: a band of noise added to a third of the pixels
        const Image n = Noise(w, h, seed++);
        for (std::size_t i = 0; i < b.rgb.size(); i += 3) b.rgb[i] = std::uint8_t(b.rgb[i] + n.rgb[i] / 8);
        const double reference = ReferenceSsim(a, b);
        EXPECT_NEAR(Ssim(a, b), reference, 1e-9) << w << "x" << h;
        EXPECT_LT(reference, 1.0);
        EXPECT_NEAR(Ssim(a, Noise(w, h, seed)), ReferenceSsim(a, Noise(w, h, seed)), 1e-9) << w << "x" << h;
    }
}

TEST(Ssim, SizesThatDifferGiveZero) { EXPECT_EQ(Ssim(Grey(8, 8, 10), Grey(8, 9, 10)), 0.0); }

TEST(ImageCompare, MinSsimLetsAFramePassOnSsimAlone) {
    // A 2-pixel-wide bar moved by one pixel: 40 of 400 pixels differ by 160 (10 %); SSIM about 0.67.
    Image a = Flat(20, 20, 90), b = a;
    for (int y = 0; y < 20; ++y)
        for (int c = 0; c < 3; ++c) a.Pixel(9, y)[c] = a.Pixel(10, y)[c] = b.Pixel(10, y)[c] = b.Pixel(11, y)[c] = 250;
    CompareThresholds t{8, 0.002};
    const CompareResult strict = CompareImages(a, b, t);
    EXPECT_FALSE(strict.passed);
    EXPECT_FALSE(strict.passedOnSsim);
    EXPECT_NEAR(strict.ssim, ReferenceSsim(a, b), 1e-9);
    t.minSsim = strict.ssim;  // at least S passes
    const CompareResult lenient = CompareImages(a, b, t);
    EXPECT_TRUE(lenient.passed);
    EXPECT_TRUE(lenient.passedOnSsim);
    char ssim[32];
    std::snprintf(ssim, sizeof ssim, "SSIM %.5f: pass on SSIM", strict.ssim);
    EXPECT_NE(DescribeComparison(lenient, t).find(ssim), std::string::npos) << DescribeComparison(lenient, t);
    EXPECT_NE(DescribeComparison(lenient, t).find(": pass on SSIM"), std::string::npos);
    t.minSsim = std::nextafter(strict.ssim, 2.0);
    EXPECT_FALSE(CompareImages(a, b, t).passed);
    // Within the pixel thresholds it is a plain pass, whatever --min-ssim says.
    t = {8, 0.1, 0.9999};
    EXPECT_TRUE(CompareImages(a, b, t).passed);
    EXPECT_FALSE(CompareImages(a, b, t).passedOnSsim);
}

TEST(ImageCompare, AmplifiedDiffScalesEachChannelDifference) {
    const Image a = Flat(3, 1, 100);
    Image b = a;
    b.Pixel(1, 0)[0] = 103;  // 3 x 16 = 48
    b.Pixel(2, 0)[2] = 0;    // 100 x 16, clamped to 255
    const Image d = MakeAmplifiedDiff(a, b, 16);
    EXPECT_EQ(d.Pixel(0, 0)[0], 0);
    EXPECT_EQ(d.Pixel(1, 0)[0], 48);
    EXPECT_EQ(d.Pixel(1, 0)[1], 0);
    EXPECT_EQ(d.Pixel(2, 0)[2], 255);
}
