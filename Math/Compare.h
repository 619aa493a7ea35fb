#pragma once
// Float comparison helpers. The book uses two different CMP macros; both are kept, under distinct names.

#include <cfloat>
#include <cmath>

/// True if |a-b| <= maxDiff (absolute) or |a-b| <= max(|a|,|b|)*maxRelDiff (relative).
inline bool AlmostEqualRelativeAndAbs(float a, float b, float maxDiff, float maxRelDiff = FLT_EPSILON) {
    const float diff = std::fabs(a - b);
    if (diff <= maxDiff) return true;
    const float largest = std::fmax(std::fabs(a), std::fabs(b));
    return diff <= largest * maxRelDiff;
}

/// The book's Compare.h CMP: an absolute tolerance of 0.005 (used by vector ==, matrix ==, camera code).
inline bool CMP(float a, float b) { return AlmostEqualRelativeAndAbs(a, b, 0.005f); }

/// The book's Geometry3D.cpp CMP: |a-b| <= FLT_EPSILON * max(1, |a|, |b|) (raycasts, clipping, manifolds).
inline bool CMP_EPS(float a, float b) {
    return std::fabs(a - b) <= FLT_EPSILON * std::fmax(1.0f, std::fmax(std::fabs(a), std::fabs(b)));
}
