#include "Platform/ImageCompare.h"

#include <gtest/gtest.h>

namespace {

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
    EXPECT_EQ(DescribeComparison(r, {}), "exact");
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
