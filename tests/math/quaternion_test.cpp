// Unit quaternions (Math/quaternion.cpp) against the book-convention rotation matrices.
#include "Math/quaternion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tests/support/Approx.h"

namespace {

constexpr float kPi = 3.14159265358979f;

float U(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
vec3 RandomVec(std::mt19937& rng, float lo, float hi) { return {U(rng, lo, hi), U(rng, lo, hi), U(rng, lo, hi)}; }
quat RandomQuat(std::mt19937& rng) {
    return Normalized(quat(U(rng, -1, 1), U(rng, -1, 1), U(rng, -1, 1), U(rng, -1, 1)));
}

/// q and -q are the same rotation.
::testing::AssertionResult SameRotation(const quat& a, const quat& b, float eps) {
    if (std::fabs(std::fabs(Dot(a, b)) - 1.0f) <= eps) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "(" << a.x << ", " << a.y << ", " << a.z << ", " << a.w << ") vs (" << b.x
                                         << ", " << b.y << ", " << b.z << ", " << b.w << ")";
}

}  // namespace

TEST(Quaternion, HandComputed) {
    // 90 degrees about +Z: (0, 0, sin 45, cos 45); in the book's convention it maps +X to +Y like Z(90).
    const quat q = AngleAxis(vec3(0, 0, 2), kPi / 2);
    EXPECT_NEAR(q.z, std::sqrt(0.5f), tol::kExact);
    EXPECT_NEAR(q.w, std::sqrt(0.5f), tol::kExact);
    EXPECT_TRUE(VecNear(Rotate(q, vec3(1, 0, 0)), vec3(0, 1, 0), tol::kTight));
    EXPECT_TRUE(MatNear(ToMat3(q), ZRotation3x3(90), tol::kTight));
    // Product: two quarter turns about Z make a half turn, which sends +X to -X.
    EXPECT_TRUE(VecNear(Rotate(q * q, vec3(1, 0, 0)), vec3(-1, 0, 0), tol::kTight));
    // (a * b) rotates by b first: X(90) then Z(90) sends +Y -> +Z -> +Z.
    const quat qx = AngleAxis(vec3(1, 0, 0), kPi / 2);
    EXPECT_TRUE(VecNear(Rotate(q * qx, vec3(0, 1, 0)), vec3(0, 0, 1), tol::kTight));
    // The other order: Z(90) sends +Y to -X, which X(90) leaves alone.
    EXPECT_TRUE(VecNear(Rotate(qx * q, vec3(0, 1, 0)), vec3(-1, 0, 0), tol::kTight));
}

TEST(Quaternion, ConjugateInverseNormalize) {
    const quat q(1, 2, 3, 4);
    const quat c = Conjugate(q);
    EXPECT_FLOAT_EQ(c.x, -1);
    EXPECT_FLOAT_EQ(c.w, 4);
    EXPECT_FLOAT_EQ(Magnitude(q), std::sqrt(30.0f));
    const quat i = q * Inverse(q);
    EXPECT_NEAR(i.x, 0, tol::kExact);
    EXPECT_NEAR(i.y, 0, tol::kExact);
    EXPECT_NEAR(i.z, 0, tol::kExact);
    EXPECT_NEAR(i.w, 1, tol::kExact);
    EXPECT_NEAR(Magnitude(Normalized(q)), 1.0f, tol::kExact);
    // Degenerate input gives identity, never NaN.
    EXPECT_TRUE(SameRotation(Normalized(quat(0, 0, 0, 0)), quat(), 0.0f));
    EXPECT_TRUE(SameRotation(Inverse(quat(0, 0, 0, 0)), quat(), 0.0f));
    EXPECT_TRUE(SameRotation(AngleAxis(vec3(0, 0, 0), 1.0f), quat(), 0.0f));
    EXPECT_TRUE(IsFinite(Normalized(quat(0, 0, 0, 0))));
}

TEST(QuaternionProperty, RotateMatchesItsMatrix) {
    std::mt19937 rng(8);
    for (int n = 0; n < 1000; ++n) {
        const quat q = RandomQuat(rng);
        const vec3 v = RandomVec(rng, -10, 10);
        ASSERT_TRUE(VecNear(Rotate(q, v), MultiplyVector(v, ToMat3(q)), tol::kLoose)) << "case " << n;
        const mat3 m = ToMat3(q);
        ASSERT_TRUE(MatNear(m * Transpose(m), mat3(), tol::kTight)) << "case " << n;  // orthonormal
        ASSERT_NEAR(Determinant(m), 1.0f, tol::kTight) << "case " << n;               // proper rotation
    }
}

TEST(QuaternionProperty, MatrixRoundTrip) {
    std::mt19937 rng(9);
    for (int n = 0; n < 1000; ++n) {
        const quat q = RandomQuat(rng);
        ASSERT_TRUE(SameRotation(FromMat3ToQuat(ToMat3(q)), q, tol::kTight)) << "case " << n;
    }
    // All four branches of the conversion (trace > 0, and each diagonal entry largest): half turns.
    for (const vec3& axis : {vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), vec3(1, 1, 0)}) {
        const quat q = AngleAxis(axis, kPi);
        ASSERT_TRUE(SameRotation(FromMat3ToQuat(ToMat3(q)), q, tol::kTight));
    }
}

TEST(QuaternionProperty, FromEulerMatchesRotation3x3) {
    std::mt19937 rng(10);
    for (int n = 0; n < 500; ++n) {
        const vec3 e = RandomVec(rng, -180, 180);
        const mat3 r = Rotation3x3(e.x, e.y, e.z);
        ASSERT_TRUE(MatNear(ToMat3(FromEuler(e.x, e.y, e.z)), r, tol::kLoose)) << "case " << n;
        const vec3 v = RandomVec(rng, -5, 5);
        ASSERT_TRUE(VecNear(Rotate(FromEuler(e.x, e.y, e.z), v), MultiplyVector(v, r), tol::kLoose)) << "case " << n;
    }
    // The book's CH14 obb2 orientation.
    EXPECT_TRUE(
        MatNear(ToMat3(FromEuler(-33.964f, -24.233f, 9.128f)), Rotation3x3(-33.964f, -24.233f, 9.128f), tol::kTight));
}

TEST(QuaternionProperty, AngleAxisMatchesAxisAngleMatrix) {
    std::mt19937 rng(12);
    for (int n = 0; n < 500; ++n) {
        const vec3 axis = RandomVec(rng, -1, 1);
        const float degrees = U(rng, -350, 350);
        ASSERT_TRUE(MatNear(ToMat3(AngleAxis(axis, DEG2RAD(degrees))), AxisAngle3x3(axis, degrees), tol::kLoose))
            << "case " << n;
    }
}

TEST(Quaternion, IntegrateConstantAngularVelocityEqualsAngleAxis) {
    // 120 steps of 1/60 s at 1.5 rad/s about a fixed axis: a rotation of 3 rad about that axis.
    const vec3 w = Normalized(vec3(1, -2, 0.5f)) * 1.5f;
    quat q;
    for (int i = 0; i < 120; ++i) q = Integrate(q, w, 1.0f / 60.0f);
    EXPECT_TRUE(SameRotation(q, AngleAxis(w, 3.0f), tol::kTight));
    EXPECT_NEAR(Magnitude(q), 1.0f, tol::kExact);
    EXPECT_TRUE(SameRotation(Integrate(q, vec3(0, 0, 0), 0.1f), q, tol::kExact));  // no spin: unchanged
}

TEST(Quaternion, IntegrateUsesWorldSpaceAngularVelocity) {
    // From a non-identity orientation, one step applies the world rotation after the current one.
    std::mt19937 rng(13);
    for (int n = 0; n < 100; ++n) {
        const quat q0 = RandomQuat(rng);
        const vec3 w = RandomVec(rng, -3, 3);
        const float dt = 0.03f;
        const quat q1 = Integrate(q0, w, dt);
        const vec3 v = RandomVec(rng, -2, 2);
        const vec3 expected = Rotate(AngleAxis(w, Magnitude(w) * dt), Rotate(q0, v));
        ASSERT_TRUE(VecNear(Rotate(q1, v), expected, tol::kLoose)) << "case " << n;
    }
}
