#pragma once
// Shared approximate-equality helpers with named tolerances for vectors, matrices and quaternions.

#include <gtest/gtest.h>

#include <cmath>

#include "Math/matrices.h"
#include "Math/quaternion.h"
#include "Math/vectors.h"

namespace tol {
constexpr float kExact = 1e-6f;  ///< hand-computed values that should agree to float rounding
constexpr float kTight = 1e-5f;  ///< a few float operations of rounding
constexpr float kLoose = 1e-4f;  ///< long chains (matrix inverse, trig round trips)
constexpr float kBook = 5e-5f;   ///< values the book prints to 5 decimals
}  // namespace tol

inline ::testing::AssertionResult VecNear(const vec3& a, const vec3& b, float eps) {
    for (int i = 0; i < 3; ++i)
        if (!(std::fabs(a[i] - b[i]) <= eps))
            return ::testing::AssertionFailure()
                   << "(" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", " << b.y << ", " << b.z
                   << "), component " << i << " differs by more than " << eps;
    return ::testing::AssertionSuccess();
}

inline ::testing::AssertionResult Vec2Near(const vec2& a, const vec2& b, float eps) {
    if (std::fabs(a.x - b.x) <= eps && std::fabs(a.y - b.y) <= eps) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "(" << a.x << ", " << a.y << ") vs (" << b.x << ", " << b.y << ")";
}

template <typename M, int N>
inline ::testing::AssertionResult MatNearImpl(const M& a, const M& b, float eps) {
    for (int i = 0; i < N * N; ++i)
        if (!(std::fabs(a.asArray[i] - b.asArray[i]) <= eps))
            return ::testing::AssertionFailure()
                   << "element " << i << ": " << a.asArray[i] << " vs " << b.asArray[i] << " (tolerance " << eps << ")";
    return ::testing::AssertionSuccess();
}
inline ::testing::AssertionResult MatNear(const mat2& a, const mat2& b, float eps) {
    return MatNearImpl<mat2, 2>(a, b, eps);
}
inline ::testing::AssertionResult MatNear(const mat3& a, const mat3& b, float eps) {
    return MatNearImpl<mat3, 3>(a, b, eps);
}
inline ::testing::AssertionResult MatNear(const mat4& a, const mat4& b, float eps) {
    return MatNearImpl<mat4, 4>(a, b, eps);
}
