#include "Platform/ImageCompare.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

CompareResult CompareImages(const Image& expected, const Image& actual, const CompareThresholds& thresholds) {
    CompareResult r;
    if (expected.width != actual.width || expected.height != actual.height) {
        r.sizeMismatch = true;
        return r;
    }
    r.totalPixels = long(expected.width) * expected.height;
    if (expected.rgb == actual.rgb) {
        r.exact = r.passed = true;
        return r;
    }
    double sum = 0.0;
    for (long i = 0; i < r.totalPixels; ++i) {
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(expected.rgb[i * 3 + c]) - int(actual.rgb[i * 3 + c]));
            sum += d;
            if (d > worst) worst = d;
        }
        if (worst > r.maxChannelDiff) r.maxChannelDiff = worst;
        if (worst > thresholds.channelTolerance) ++r.differingPixels;
    }
    r.meanAbsDiff = sum / double(r.totalPixels * 3);
    r.passed = r.DifferingFraction() <= thresholds.maxDifferingFraction;
    return r;
}

Image MakeDiffImage(const Image& expected, const Image& actual, const CompareThresholds& thresholds) {
    Image diff(expected.width, expected.height);
    const bool sameSize = expected.width == actual.width && expected.height == actual.height;
    for (int y = 0; y < expected.height; ++y) {
        for (int x = 0; x < expected.width; ++x) {
            const std::uint8_t* e = expected.Pixel(x, y);
            std::uint8_t* out = diff.Pixel(x, y);
            int worst = 256;  // a size mismatch marks everything
            if (sameSize) {
                const std::uint8_t* a = actual.Pixel(x, y);
                worst = 0;
                for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(e[c]) - int(a[c])));
            }
            if (worst > thresholds.channelTolerance) {
                out[0] = 255, out[1] = 0, out[2] = 0;
            } else if (worst > 0) {
                out[0] = 255, out[1] = 220, out[2] = 0;
            } else {
                const std::uint8_t grey = std::uint8_t((int(e[0]) + int(e[1]) + int(e[2])) / 12 + 32);
                out[0] = out[1] = out[2] = grey;
            }
        }
    }
    return diff;
}

std::string DescribeComparison(const CompareResult& r, const CompareThresholds& thresholds) {
    if (r.sizeMismatch) return "size mismatch: fail";
    if (r.exact) return "exact";
    char text[256];
    std::snprintf(text, sizeof text, "max channel diff %d, %ld of %ld pixels (%.4f%%) beyond %d, mean %.4f: %s",
                  r.maxChannelDiff, r.differingPixels, r.totalPixels, 100.0 * r.DifferingFraction(),
                  thresholds.channelTolerance, r.meanAbsDiff, r.passed ? "pass" : "FAIL");
    return text;
}
