#include "Platform/ImageCompare.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

constexpr int kSsimWindow = 8;
constexpr int kSsimStride = 4;

/// Window origins along one axis of `size` pixels: every kSsimStride, the last one ending at the border.
std::vector<int> WindowOrigins(int size) {
    std::vector<int> origins;
    const int last = std::max(0, size - kSsimWindow);
    for (int o = 0; o < last; o += kSsimStride) origins.push_back(o);
    origins.push_back(last);
    return origins;
}

double Luma(const std::uint8_t* p) { return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]; }

/// Summed-area table of f(x, y) over the image, (w + 1) x (h + 1), row 0 and column 0 zero.
struct SumTable {
    int stride = 0;
    std::vector<double> sums;
    template <class F>
    SumTable(int w, int h, F f) : stride(w + 1), sums(std::size_t(w + 1) * std::size_t(h + 1), 0.0) {
        for (int y = 0; y < h; ++y) {
            double row = 0.0;
            for (int x = 0; x < w; ++x) {
                row += f(x, y);
                At(x + 1, y + 1) = At(x + 1, y) + row;
            }
        }
    }
    double& At(int x, int y) { return sums[std::size_t(y) * std::size_t(stride) + std::size_t(x)]; }
    double Box(int x0, int y0, int x1, int y1) const {
        auto at = [this](int x, int y) { return sums[std::size_t(y) * std::size_t(stride) + std::size_t(x)]; };
        return at(x1, y1) - at(x0, y1) - at(x1, y0) + at(x0, y0);
    }
};

}  // namespace

double Ssim(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height || a.width <= 0 || a.height <= 0) return 0.0;
    const int w = a.width, h = a.height;
    std::vector<double> ya(std::size_t(w) * std::size_t(h)), yb(ya.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            ya[std::size_t(y) * std::size_t(w) + std::size_t(x)] = Luma(a.Pixel(x, y));
            yb[std::size_t(y) * std::size_t(w) + std::size_t(x)] = Luma(b.Pixel(x, y));
        }
    auto index = [w](int x, int y) { return std::size_t(y) * std::size_t(w) + std::size_t(x); };
    const SumTable sa(w, h, [&](int x, int y) { return ya[index(x, y)]; });
    const SumTable sb(w, h, [&](int x, int y) { return yb[index(x, y)]; });
    const SumTable saa(w, h, [&](int x, int y) { return ya[index(x, y)] * ya[index(x, y)]; });
    const SumTable sbb(w, h, [&](int x, int y) { return yb[index(x, y)] * yb[index(x, y)]; });
    const SumTable sab(w, h, [&](int x, int y) { return ya[index(x, y)] * yb[index(x, y)]; });
    const double c1 = (0.01 * 255.0) * (0.01 * 255.0), c2 = (0.03 * 255.0) * (0.03 * 255.0);
    const int ww = std::min(kSsimWindow, w), wh = std::min(kSsimWindow, h);
    const double n = double(ww) * double(wh);
    double total = 0.0;
    long windows = 0;
    for (const int y0 : WindowOrigins(h)) {
        for (const int x0 : WindowOrigins(w)) {
            const int x1 = x0 + ww, y1 = y0 + wh;
            const double muA = sa.Box(x0, y0, x1, y1) / n, muB = sb.Box(x0, y0, x1, y1) / n;
            const double varA = std::max(0.0, saa.Box(x0, y0, x1, y1) / n - muA * muA);
            const double varB = std::max(0.0, sbb.Box(x0, y0, x1, y1) / n - muB * muB);
            const double cov = sab.Box(x0, y0, x1, y1) / n - muA * muB;
            total += (2.0 * muA * muB + c1) * (2.0 * cov + c2) / ((muA * muA + muB * muB + c1) * (varA + varB + c2));
            ++windows;
        }
    }
    return total / double(windows);
}

CompareResult CompareImages(const Image& expected, const Image& actual, const CompareThresholds& thresholds) {
    CompareResult r;
    if (expected.width != actual.width || expected.height != actual.height) {
        r.sizeMismatch = true;
        return r;
    }
    r.totalPixels = long(expected.width) * expected.height;
    if (expected.rgb == actual.rgb) {
        r.exact = r.passed = true;
        r.ssim = 1.0;
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
    r.ssim = Ssim(expected, actual);
    if (!r.passed && thresholds.minSsim >= 0.0 && r.ssim >= thresholds.minSsim) r.passed = r.passedOnSsim = true;
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

Image MakeAmplifiedDiff(const Image& expected, const Image& actual, int gain) {
    Image diff(expected.width, expected.height);
    if (expected.width != actual.width || expected.height != actual.height) return diff;
    for (std::size_t i = 0; i < expected.rgb.size(); ++i) {
        const int d = std::abs(int(expected.rgb[i]) - int(actual.rgb[i]));
        diff.rgb[i] = std::uint8_t(std::min(255, d * gain));
    }
    return diff;
}

std::string DescribeComparison(const CompareResult& r, const CompareThresholds& thresholds) {
    if (r.sizeMismatch) return "size mismatch: fail";
    if (r.exact) return "exact, SSIM 1";
    char text[256];
    std::snprintf(text, sizeof text,
                  "max channel diff %d, %ld of %ld pixels (%.4f%%) beyond %d, mean %.4f, SSIM %.5f: %s",
                  r.maxChannelDiff, r.differingPixels, r.totalPixels, 100.0 * r.DifferingFraction(),
                  thresholds.channelTolerance, r.meanAbsDiff, r.ssim,
                  r.passedOnSsim ? "pass on SSIM"
                  : r.passed     ? "pass"
                                 : "FAIL");
    return text;
}
