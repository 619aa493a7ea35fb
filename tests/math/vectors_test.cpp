// vec2 / vec3 operations (Math/vectors.cpp). Expected values are worked out by hand in the comments.
#include "Math/vectors.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/Approx.h"

namespace {
constexpr float kPi = 3.14159265358979f;
}

TEST(Vectors, Vec3Arithmetic) {
    const vec3 a(1, 2, 3), b(4, -5, 6);
    EXPECT_TRUE(VecNear(a + b, vec3(5, -3, 9), tol::kExact));
    EXPECT_TRUE(VecNear(a - b, vec3(-3, 7, -3), tol::kExact));
    EXPECT_TRUE(VecNear(a * b, vec3(4, -10, 18), tol::kExact));  // component-wise
    EXPECT_TRUE(VecNear(a * 2.0f, vec3(2, 4, 6), tol::kExact));
    EXPECT_TRUE(VecNear(2.0f * a, vec3(2, 4, 6), tol::kExact));
    EXPECT_TRUE(VecNear(b / a, vec3(4, -2.5f, 2), tol::kExact));
    EXPECT_TRUE(VecNear(b / 2.0f, vec3(2, -2.5f, 3), tol::kExact));
    EXPECT_TRUE(VecNear(-a, vec3(-1, -2, -3), tol::kExact));
    vec3 c = a;
    c += b;
    EXPECT_TRUE(VecNear(c, vec3(5, -3, 9), tol::kExact));
    c -= b;
    EXPECT_TRUE(VecNear(c, a, tol::kExact));
    c *= 3.0f;
    EXPECT_TRUE(VecNear(c, vec3(3, 6, 9), tol::kExact));
    c /= vec3(3, 3, 9);
    EXPECT_TRUE(VecNear(c, vec3(1, 2, 1), tol::kExact));
    EXPECT_FLOAT_EQ(a[0], 1.0f);
    EXPECT_FLOAT_EQ(a[2], 3.0f);
}

TEST(Vectors, Vec2Arithmetic) {
    const vec2 a(3, 4), b(1, -2);
    EXPECT_TRUE(Vec2Near(a + b, vec2(4, 2), tol::kExact));
    EXPECT_TRUE(Vec2Near(a - b, vec2(2, 6), tol::kExact));
    EXPECT_TRUE(Vec2Near(a * b, vec2(3, -8), tol::kExact));
    EXPECT_TRUE(Vec2Near(a / 2.0f, vec2(1.5f, 2), tol::kExact));
    EXPECT_FLOAT_EQ(Dot(a, b), -5.0f);
    EXPECT_FLOAT_EQ(Magnitude(a), 5.0f);
    EXPECT_FLOAT_EQ(MagnitudeSq(a), 25.0f);
    EXPECT_FLOAT_EQ(Distance(a, b), std::sqrt(40.0f));
}

TEST(Vectors, Vec2MinusEqualsSubtractsEachComponent) {
    // Erratum 5.2-31: the book's operator-= computes x -= r.y; it would give (3, 5) here.
    vec2 a(5, 7);
    a -= vec2(1, 2);
    EXPECT_FLOAT_EQ(a.x, 4.0f);
    EXPECT_FLOAT_EQ(a.y, 5.0f);
}

TEST(Vectors, EqualityUsesTheBooksAbsoluteTolerance) {
    // Compare.h CMP: |x - y| <= 0.005.
    EXPECT_TRUE(vec3(1, 2, 3) == vec3(1.004f, 2, 3));
    EXPECT_FALSE(vec3(1, 2, 3) == vec3(1.006f, 2, 3));
    EXPECT_TRUE(vec3(1, 2, 3) != vec3(1, 2, 3.01f));
    EXPECT_TRUE(vec2(1, 2) == vec2(1, 2.004f));
}

TEST(Vectors, DotMagnitudeDistance) {
    const vec3 a(1, 2, 2), b(-2, 0, 1);
    EXPECT_FLOAT_EQ(Dot(a, b), 0.0f);  // perpendicular
    EXPECT_FLOAT_EQ(Dot(a, a), 9.0f);
    EXPECT_FLOAT_EQ(Magnitude(a), 3.0f);
    EXPECT_FLOAT_EQ(MagnitudeSq(b), 5.0f);
    EXPECT_FLOAT_EQ(DistanceSq(a, b), 9 + 4 + 1);
    EXPECT_FLOAT_EQ(Distance(a, b), std::sqrt(14.0f));
}

TEST(Vectors, CrossFollowsTheDeterminantFormula) {
    EXPECT_TRUE(VecNear(Cross(vec3(1, 0, 0), vec3(0, 1, 0)), vec3(0, 0, 1), tol::kExact));
    EXPECT_TRUE(VecNear(Cross(vec3(0, 1, 0), vec3(0, 0, 1)), vec3(1, 0, 0), tol::kExact));
    EXPECT_TRUE(VecNear(Cross(vec3(0, 1, 0), vec3(1, 0, 0)), vec3(0, 0, -1), tol::kExact));  // anti-commutative
    // (1,2,3) x (4,5,6) = (2*6-3*5, 3*4-1*6, 1*5-2*4) = (-3, 6, -3)
    EXPECT_TRUE(VecNear(Cross(vec3(1, 2, 3), vec3(4, 5, 6)), vec3(-3, 6, -3), tol::kExact));
    EXPECT_TRUE(VecNear(Cross(vec3(1, 2, 3), vec3(2, 4, 6)), vec3(0, 0, 0), tol::kExact));  // parallel
}

TEST(Vectors, NormalizeUnitLength) {
    EXPECT_TRUE(VecNear(Normalized(vec3(3, 0, 4)), vec3(0.6f, 0, 0.8f), tol::kExact));
    vec3 v(0, -2, 0);
    Normalize(v);
    EXPECT_TRUE(VecNear(v, vec3(0, -1, 0), tol::kExact));
    EXPECT_TRUE(Vec2Near(Normalized(vec2(3, 4)), vec2(0.6f, 0.8f), tol::kExact));
    EXPECT_NEAR(Magnitude(Normalized(vec3(1e-15f, 0, 0))), 1.0f, tol::kExact);  // tiny but nonzero
}

TEST(Vectors, NormalizeZeroVectorGivesZeroNotNaN) {
    // Erratum 5.2-6: the book multiplies by 1/|v| and returns (NaN, NaN, NaN) here.
    const vec3 n = Normalized(vec3(0, 0, 0));
    EXPECT_TRUE(IsFinite(n));
    EXPECT_TRUE(VecNear(n, vec3(0, 0, 0), 0.0f));
    vec3 v;
    Normalize(v);
    EXPECT_TRUE(VecNear(v, vec3(0, 0, 0), 0.0f));
    const vec2 n2 = Normalized(vec2(0, 0));
    EXPECT_EQ(n2.x, 0.0f);
    EXPECT_EQ(n2.y, 0.0f);
    vec2 v2;
    Normalize(v2);
    EXPECT_EQ(v2.x, 0.0f);
    EXPECT_EQ(v2.y, 0.0f);
}

TEST(Vectors, AngleInRadians) {
    EXPECT_NEAR(Angle(vec3(1, 0, 0), vec3(0, 5, 0)), kPi / 2, tol::kExact);
    EXPECT_NEAR(Angle(vec3(1, 1, 0), vec3(2, 0, 0)), kPi / 4, tol::kExact);
    EXPECT_NEAR(Angle(vec3(1, 0, 0), vec3(-3, 0, 0)), kPi, tol::kExact);
    EXPECT_NEAR(Angle(vec3(1, 2, 3), vec3(2, 4, 6)), 0.0f, 1e-3f);  // acos near 1 is ill-conditioned
    EXPECT_FLOAT_EQ(Angle(vec3(0, 0, 0), vec3(1, 0, 0)), 0.0f);     // zero vector: 0, not NaN
    EXPECT_NEAR(Angle(vec2(1, 0), vec2(0, -1)), kPi / 2, tol::kExact);
}

TEST(Vectors, ProjectPerpendicularReflection) {
    // Project (3,4,5) onto (2,0,0): only the x part survives.
    EXPECT_TRUE(VecNear(Project(vec3(3, 4, 5), vec3(2, 0, 0)), vec3(3, 0, 0), tol::kExact));
    // Onto (1,1,0): dot 7, |d|^2 2 -> 3.5 (1,1,0).
    EXPECT_TRUE(VecNear(Project(vec3(3, 4, 5), vec3(1, 1, 0)), vec3(3.5f, 3.5f, 0), tol::kExact));
    EXPECT_TRUE(VecNear(Perpendicular(vec3(3, 4, 5), vec3(1, 1, 0)), vec3(-0.5f, 0.5f, 5), tol::kExact));
    EXPECT_TRUE(VecNear(Project(vec3(3, 4, 5), vec3(0, 0, 0)), vec3(0, 0, 0), 0.0f));  // zero direction
    EXPECT_TRUE(Vec2Near(Project(vec2(2, 3), vec2(0, 5)), vec2(0, 3), tol::kExact));
    // Reflection about a unit normal: v - 2 (v.n) n.
    EXPECT_TRUE(VecNear(Reflection(vec3(1, -1, 0), vec3(0, 1, 0)), vec3(1, 1, 0), tol::kExact));
    const vec3 n = Normalized(vec3(1, 1, 0));
    EXPECT_TRUE(VecNear(Reflection(vec3(1, 0, 0), n), vec3(0, -1, 0), tol::kExact));
    EXPECT_TRUE(Vec2Near(Reflection(vec2(2, -3), vec2(0, 1)), vec2(2, 3), tol::kExact));
}

TEST(Vectors, RotateVector2D) {
    EXPECT_TRUE(Vec2Near(RotateVector(vec2(1, 0), 90), vec2(0, 1), tol::kTight));
    EXPECT_TRUE(Vec2Near(RotateVector(vec2(0, 2), 90), vec2(-2, 0), tol::kTight));
    EXPECT_TRUE(Vec2Near(RotateVector(vec2(1, 0), 450), vec2(0, 1), tol::kTight));  // wrapped
}

TEST(Vectors, DegreeConversions) {
    EXPECT_NEAR(DEG2RAD(180.0f), kPi, tol::kExact);
    EXPECT_NEAR(DEG2RAD(-90.0f), -kPi / 2, tol::kExact);
    EXPECT_NEAR(DEG2RAD(450.0f), kPi / 2, tol::kExact);  // wrapped to 90 first
    EXPECT_FLOAT_EQ(CorrectDegrees(370.0f), 10.0f);
    EXPECT_FLOAT_EQ(CorrectDegrees(-370.0f), -10.0f);
    EXPECT_FLOAT_EQ(CorrectDegrees(360.0f), 360.0f);  // the book keeps [-360, 360]
}

TEST(Vectors, RAD2DEGUsesTheExactConstant) {
    // Erratum 5.2-33: the book multiplies by 57.295754, giving 57.295754 and 179.99992 below (off by 2.6e-5
    // and 7.6e-5, several float ULPs); the exact factor is 180/pi = 57.2957795.
    EXPECT_NEAR(RAD2DEG(1.0f), 57.2957795f, 8e-6f);
    EXPECT_NEAR(RAD2DEG(kPi), 180.0f, 2e-5f);
    EXPECT_NEAR(RAD2DEG(DEG2RAD(123.456f)), 123.456f, 2e-5f);
    EXPECT_NEAR(RAD2DEG(3 * kPi), 180.0f, 1e-3f);  // 540 wrapped to [-360, 360]
}
