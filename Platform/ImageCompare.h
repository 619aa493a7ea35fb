#pragma once
// Golden-frame comparison: exact when the bytes agree, otherwise a per-channel threshold and a maximum
// fraction of differing pixels, so a frame that looks the same on another CPU's llvmpipe still passes.

#include <string>

#include "Platform/Image.h"

struct CompareThresholds {
    /// A pixel differs when any channel differs by more than this (0..255).
    int channelTolerance = 8;
    /// The frame passes when at most this fraction of its pixels differ.
    double maxDifferingFraction = 0.002;
};

struct CompareResult {
    bool sizeMismatch = false;
    bool exact = false;        ///< every byte equal
    bool passed = false;       ///< exact, or within the thresholds
    int maxChannelDiff = 0;    ///< largest |expected - actual| over all channels
    long differingPixels = 0;  ///< pixels with some channel beyond the tolerance
    long totalPixels = 0;
    double meanAbsDiff = 0.0;  ///< mean |difference| over all channels
    double DifferingFraction() const { return totalPixels ? double(differingPixels) / double(totalPixels) : 1.0; }
};

/// Compares actual with expected. Images of different sizes never pass.
CompareResult CompareImages(const Image& expected, const Image& actual, const CompareThresholds& thresholds);
/// A diff image of expected's size: pixels beyond the tolerance in saturated red, others as a dimmed grey of
/// expected (so the scene stays recognisable), within-tolerance differences in yellow.
Image MakeDiffImage(const Image& expected, const Image& actual, const CompareThresholds& thresholds);
/// One line: "exact" or "max channel diff 12, 34 of 120000 pixels (0.028%) beyond 8, mean 0.01: pass".
std::string DescribeComparison(const CompareResult& r, const CompareThresholds& thresholds);
