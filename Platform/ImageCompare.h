#pragma once
// Golden-frame comparison: exact when the bytes agree, otherwise a per-channel threshold and a maximum
// fraction of differing pixels, so a frame that looks the same on another CPU's llvmpipe still passes; beside
// it the frame's SSIM (docs/app.md, "Golden comparison"), which alone can also let a frame pass (--min-ssim).

#include <string>

#include "Platform/Image.h"

struct CompareThresholds {
    /// A pixel differs when any channel differs by more than this (0..255).
    int channelTolerance = 8;
    /// The frame passes when at most this fraction of its pixels differ.
    double maxDifferingFraction = 0.002;
    /// --min-ssim: a frame whose SSIM is at least this passes whatever its pixel counts; negative: off.
    double minSsim = -1.0;
};

struct CompareResult {
    bool sizeMismatch = false;
    bool exact = false;        ///< every byte equal
    bool passed = false;       ///< exact, or within the thresholds
    int maxChannelDiff = 0;    ///< largest |expected - actual| over all channels
    long differingPixels = 0;  ///< pixels with some channel beyond the tolerance
    long totalPixels = 0;
    double meanAbsDiff = 0.0;   ///< mean |difference| over all channels
    double ssim = 0.0;          ///< Ssim(expected, actual); 1 when exact, 0 on a size mismatch
    bool passedOnSsim = false;  ///< beyond the pixel thresholds, passed by --min-ssim
    double DifferingFraction() const { return totalPixels ? double(differingPixels) / double(totalPixels) : 1.0; }
};

/// The mean structural similarity of the two images' luminance (Y = 0.299 R + 0.587 G + 0.114 B, 0..255), over
/// 8x8 windows with uniform weights placed every 4 pixels (the last row and column of windows moved in to end at
/// the border; an image under 8 pixels on a side is one window that wide). Per window, with population
/// variances and covariance, SSIM = (2 mu_a mu_b + C1)(2 cov + C2) / ((mu_a^2 + mu_b^2 + C1)(var_a + var_b + C2)),
/// C1 = (0.01 * 255)^2, C2 = (0.03 * 255)^2, the usual SSIM constants. In -1..1; 1 for equal images. Same size only
/// (0 otherwise).
double Ssim(const Image& a, const Image& b);
/// Compares actual with expected. Images of different sizes never pass.
CompareResult CompareImages(const Image& expected, const Image& actual, const CompareThresholds& thresholds);
/// A diff image of expected's size: pixels beyond the tolerance in saturated red, others as a dimmed grey of
/// expected (so the scene stays recognisable), within-tolerance differences in yellow.
Image MakeDiffImage(const Image& expected, const Image& actual, const CompareThresholds& thresholds);
/// |expected - actual| per channel times `gain` (clamped to 255) on black: differences too small to see in the
/// frames stand out. Black where the sizes differ.
Image MakeAmplifiedDiff(const Image& expected, const Image& actual, int gain);
/// One line: "exact, SSIM 1" or "max channel diff 12, 34 of 120000 pixels (0.028%) beyond 8, mean 0.01, SSIM
/// 0.99871: pass" (": pass on SSIM" when only --min-ssim lets it pass).
std::string DescribeComparison(const CompareResult& r, const CompareThresholds& thresholds);
