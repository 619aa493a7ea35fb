// mat2 / mat3 / mat4 (Math/matrices.cpp): row-major, row vectors on the left, left-handed, degrees.
#include "Math/matrices.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "tests/support/Approx.h"

namespace {

constexpr float kPi = 3.14159265358979f;

mat3 Diag3(float a, float b, float c) { return mat3(a, 0, 0, 0, b, 0, 0, 0, c); }
mat4 Diag4(float a, float b, float c, float d) { return mat4(a, 0, 0, 0, 0, b, 0, 0, 0, 0, c, 0, 0, 0, 0, d); }

/// Row i of a mat3 compared with the values the book prints (5 decimals).
void ExpectRows(const mat3& m, const vec3& r0, const vec3& r1, const vec3& r2) {
    EXPECT_TRUE(VecNear(GetRow(m, 0), r0, tol::kBook));
    EXPECT_TRUE(VecNear(GetRow(m, 1), r1, tol::kBook));
    EXPECT_TRUE(VecNear(GetRow(m, 2), r2, tol::kBook));
}

float U(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
mat3 RandomRotation(std::mt19937& rng) { return Rotation3x3(U(rng, -180, 180), U(rng, -180, 180), U(rng, -180, 180)); }

}  // namespace

// ---- Layout, transpose, multiply ---------------------------------------------------------------------

TEST(Matrices, DefaultIsIdentityAndIndexingIsRowMajor) {
    const mat3 m;
    EXPECT_TRUE(MatNear(m, Diag3(1, 1, 1), 0.0f));
    const mat4 t(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16);
    EXPECT_FLOAT_EQ(t[1][2], 7.0f);  // the book's _23
    EXPECT_FLOAT_EQ(t[3][0], 13.0f);
    EXPECT_TRUE(MatNear(ZeroMat3(), Diag3(0, 0, 0), 0.0f));
}

TEST(Matrices, Transpose) {
    EXPECT_TRUE(MatNear(Transpose(mat2(1, 2, 3, 4)), mat2(1, 3, 2, 4), 0.0f));
    EXPECT_TRUE(MatNear(Transpose(mat3(1, 2, 3, 4, 5, 6, 7, 8, 9)), mat3(1, 4, 7, 2, 5, 8, 3, 6, 9), 0.0f));
    const mat4 m(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16);
    EXPECT_TRUE(MatNear(Transpose(m), mat4(1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15, 4, 8, 12, 16), 0.0f));
    // Generic form on a 2x3 array: [[1,2,3],[4,5,6]] -> [[1,4],[2,5],[3,6]].
    const float src[6] = {1, 2, 3, 4, 5, 6};
    float dst[6] = {};
    Transpose(src, dst, 2, 3);
    const float expected[6] = {1, 4, 2, 5, 3, 6};
    for (int i = 0; i < 6; ++i) EXPECT_FLOAT_EQ(dst[i], expected[i]) << i;
}

TEST(Matrices, Multiply) {
    // [[1,2],[3,4]] * [[5,6],[7,8]] = [[19,22],[43,50]]
    EXPECT_TRUE(MatNear(mat2(1, 2, 3, 4) * mat2(5, 6, 7, 8), mat2(19, 22, 43, 50), 0.0f));
    // [[1,2,3],[4,5,6],[7,8,9]] * [[9,8,7],[6,5,4],[3,2,1]] = [[30,24,18],[84,69,54],[138,114,90]]
    EXPECT_TRUE(MatNear(mat3(1, 2, 3, 4, 5, 6, 7, 8, 9) * mat3(9, 8, 7, 6, 5, 4, 3, 2, 1),
                        mat3(30, 24, 18, 84, 69, 54, 138, 114, 90), 0.0f));
    // 1..16 times 17..32 (computed independently with exact integers).
    const mat4 a(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16);
    const mat4 b(17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32);
    EXPECT_TRUE(MatNear(
        a * b, mat4(250, 260, 270, 280, 618, 644, 670, 696, 986, 1028, 1070, 1112, 1354, 1412, 1470, 1528), 0.0f));
    EXPECT_TRUE(MatNear(a * mat4(), a, 0.0f));
    // Generic: (2x3) * (3x2) = [[1,2,3],[4,5,6]] * [[7,8],[9,10],[11,12]] = [[58,64],[139,154]].
    const float l[6] = {1, 2, 3, 4, 5, 6}, r[6] = {7, 8, 9, 10, 11, 12};
    float out[4] = {};
    ASSERT_TRUE(Multiply(out, l, 2, 3, r, 3, 2));
    EXPECT_FLOAT_EQ(out[0], 58);
    EXPECT_FLOAT_EQ(out[1], 64);
    EXPECT_FLOAT_EQ(out[2], 139);
    EXPECT_FLOAT_EQ(out[3], 154);
    EXPECT_FALSE(Multiply(out, l, 2, 3, r, 2, 3));  // inner sizes differ
    EXPECT_TRUE(MatNear(mat3(1, 2, 3, 4, 5, 6, 7, 8, 9) * 2.0f, mat3(2, 4, 6, 8, 10, 12, 14, 16, 18), 0.0f));
}

// ---- Determinant, minors, cofactors, inverse -----------------------------------------------------------

TEST(Matrices, Determinants) {
    EXPECT_FLOAT_EQ(Determinant(mat2(4, 7, 2, 6)), 10.0f);
    // 2(0*5 - (-1)*4) - (-3)(2*5 - (-1)*1) + 1(2*4 - 0*1) = 8 + 33 + 8
    EXPECT_FLOAT_EQ(Determinant(mat3(2, -3, 1, 2, 0, -1, 1, 4, 5)), 49.0f);
    // Laplace expansion along column 2 (only one nonzero entry): 30.
    EXPECT_FLOAT_EQ(Determinant(mat4(1, 0, 2, -1, 3, 0, 0, 5, 2, 1, 4, -3, 1, 0, 5, 0)), 30.0f);
    EXPECT_FLOAT_EQ(Determinant(Diag4(2, 3, 4, 5)), 120.0f);
    EXPECT_FLOAT_EQ(Determinant(mat3(1, 2, 3, 4, 5, 6, 7, 8, 9)), 0.0f);
}

TEST(Matrices, CutMinorCofactorAdjugate) {
    const mat3 m(2, -3, 1, 2, 0, -1, 1, 4, 5);
    EXPECT_TRUE(MatNear(Cut(m, 0, 1), mat2(2, -1, 1, 5), 0.0f));
    EXPECT_TRUE(MatNear(Minor(m), mat3(4, 11, 8, -19, 9, 11, 3, -4, 6), 0.0f));
    EXPECT_TRUE(MatNear(Cofactor(m), mat3(4, -11, 8, 19, 9, -11, 3, 4, 6), 0.0f));
    EXPECT_TRUE(MatNear(Adjugate(m), mat3(4, 19, 3, -11, 9, 4, 8, -11, 6), 0.0f));
    EXPECT_TRUE(MatNear(Cofactor(mat2(4, 7, 2, 6)), mat2(6, -2, -7, 4), 0.0f));
    const mat4 m4(1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16);
    EXPECT_TRUE(MatNear(Cut(m4, 1, 2), mat3(1, 2, 4, 9, 10, 12, 13, 14, 16), 0.0f));
    // Cofactor(i, j) of a diagonal matrix: the product of the other diagonal entries on the diagonal.
    EXPECT_TRUE(MatNear(Cofactor(Diag4(2, 3, 4, 5)), Diag4(60, 40, 30, 24), 0.0f));
}

TEST(Matrices, InverseHandComputed) {
    EXPECT_TRUE(MatNear(Inverse(mat2(4, 7, 2, 6)), mat2(0.6f, -0.7f, -0.2f, 0.4f), tol::kExact));
    const mat3 inv = Inverse(mat3(2, -3, 1, 2, 0, -1, 1, 4, 5));
    EXPECT_TRUE(MatNear(inv, mat3(4, 19, 3, -11, 9, 4, 8, -11, 6) * (1.0f / 49.0f), tol::kExact));
    // (Scale(2,4,8) * Translation(1,2,3))^-1 = Translation(-1,-2,-3) * Scale(1/2, 1/4, 1/8).
    const mat4 m = Scale(2, 4, 8) * Translation(1, 2, 3);
    EXPECT_TRUE(MatNear(Inverse(m), Translation(-1, -2, -3) * Scale(0.5f, 0.25f, 0.125f), tol::kExact));
}

TEST(Matrices, InverseOfSmallWellConditionedMatrix) {
    // Erratum 5.2-10: det = (1/6)^3 = 0.00463 <= 0.005, so the book returns identity for both. This is the
    // inverse inertia of a 0.5 half-size, mass-1 box: it must be diag(6, 6, 6).
    const float s = 1.0f / 6.0f;
    EXPECT_TRUE(MatNear(Inverse(Diag4(s, s, s, 1)), Diag4(6, 6, 6, 1), tol::kLoose));
    EXPECT_TRUE(MatNear(Inverse(Diag3(s, s, s)), Diag3(6, 6, 6), tol::kLoose));
    // A sphere of radius 0.5, mass 1: I = 2/5 m r^2 = 0.1, det 0.001.
    EXPECT_TRUE(MatNear(Inverse(Diag3(0.1f, 0.1f, 0.1f)), Diag3(10, 10, 10), tol::kLoose));
    EXPECT_FALSE(IsSingular(Diag4(s, s, s, 1)));
    EXPECT_TRUE(MatNear(Inverse(mat2(0.05f, 0, 0, 0.05f)), mat2(20, 0, 0, 20), tol::kLoose));
}

TEST(Matrices, SingularMatricesReturnIdentity) {
    EXPECT_TRUE(IsSingular(mat3(1, 2, 3, 4, 5, 6, 7, 8, 9)));
    EXPECT_TRUE(MatNear(Inverse(mat3(1, 2, 3, 4, 5, 6, 7, 8, 9)), mat3(), 0.0f));
    EXPECT_TRUE(MatNear(Inverse(mat3(1, 2, 3, 2, 4, 6, 0, 0, 1)), mat3(), 0.0f));  // two parallel rows
    EXPECT_TRUE(MatNear(Inverse(Diag4(1, 1, 0, 1)), mat4(), 0.0f));                // a zero row
    EXPECT_TRUE(MatNear(Inverse(ZeroMat4()), mat4(), 0.0f));
    EXPECT_TRUE(MatNear(Inverse(mat2(1, 2, 2, 4)), mat2(), 0.0f));
}

TEST(MatricesProperty, InverseTimesMatrixIsIdentity) {
    // Well-conditioned random matrices: rotation * diag(scales in [0.2, 5]) * rotation (condition <= 25),
    // plus a translation for mat4.
    std::mt19937 rng(42);
    for (int n = 0; n < 500; ++n) {
        const mat3 m =
            RandomRotation(rng) * Diag3(U(rng, 0.2f, 5), U(rng, 0.2f, 5), U(rng, 0.2f, 5)) * RandomRotation(rng);
        ASSERT_TRUE(MatNear(Inverse(m) * m, mat3(), tol::kLoose)) << "mat3 case " << n;
        ASSERT_TRUE(MatNear(m * Inverse(m), mat3(), tol::kLoose)) << "mat3 case " << n;
        mat4 m4 = FromMat3(m);
        m4[3][0] = U(rng, -10, 10);
        m4[3][1] = U(rng, -10, 10);
        m4[3][2] = U(rng, -10, 10);
        ASSERT_TRUE(MatNear(Inverse(m4) * m4, mat4(), tol::kLoose)) << "mat4 case " << n;
        // A general 4x4 (projective column too): identity plus a perturbation small enough to stay strictly
        // diagonally dominant, hence invertible and well conditioned.
        mat4 g;
        for (float& e : g.asArray) e += U(rng, -0.2f, 0.2f);  // diagonally dominant
        ASSERT_TRUE(MatNear(Inverse(g) * g, mat4(), tol::kLoose)) << "general mat4 case " << n;
    }
}

// ---- Rotations ---------------------------------------------------------------------------------------

TEST(Matrices, AxisRotationsMapAxesLeftHanded) {
    // Row vectors: v * X(90) sends +Y to +Z, v * Y(90) sends +Z to +X, v * Z(90) sends +X to +Y.
    EXPECT_TRUE(VecNear(MultiplyVector(vec3(0, 1, 0), XRotation3x3(90)), vec3(0, 0, 1), tol::kTight));
    EXPECT_TRUE(VecNear(MultiplyVector(vec3(0, 0, 1), YRotation3x3(90)), vec3(1, 0, 0), tol::kTight));
    EXPECT_TRUE(VecNear(MultiplyVector(vec3(1, 0, 0), ZRotation3x3(90)), vec3(0, 1, 0), tol::kTight));
    // docs/book-reference.md §0 matrices, c = cos 30, s = sin 30.
    const float c = std::cos(kPi / 6), s = 0.5f;
    EXPECT_TRUE(MatNear(XRotation3x3(30), mat3(1, 0, 0, 0, c, s, 0, -s, c), tol::kTight));
    EXPECT_TRUE(MatNear(YRotation3x3(30), mat3(c, 0, -s, 0, 1, 0, s, 0, c), tol::kTight));
    EXPECT_TRUE(MatNear(ZRotation3x3(30), mat3(c, s, 0, -s, c, 0, 0, 0, 1), tol::kTight));
    EXPECT_TRUE(MatNear(XRotation(30), FromMat3(XRotation3x3(30)), 0.0f));
    EXPECT_TRUE(MatNear(YRotation(30), FromMat3(YRotation3x3(30)), 0.0f));
    EXPECT_TRUE(MatNear(ZRotation(30), FromMat3(ZRotation3x3(30)), 0.0f));
}

TEST(Matrices, RotationOrderIsZThenXThenY) {
    // Rotation3x3(pitch, yaw, roll) = Z(roll) * X(pitch) * Y(yaw).
    const mat3 expected = ZRotation3x3(15) * XRotation3x3(40) * YRotation3x3(-70);
    EXPECT_TRUE(MatNear(Rotation3x3(40, -70, 15), expected, tol::kExact));
    EXPECT_TRUE(MatNear(Rotation(40, -70, 15), FromMat3(expected), tol::kExact));
    EXPECT_TRUE(MatNear(YawPitchRoll(-70, 40, 15), FromMat3(expected), tol::kExact));
}

TEST(Matrices, RotationsPrintedInTheBook) {
    // docs/book-reference.md §2.0, the raycast demo's OBB.
    ExpectRows(Rotation3x3(30, 20, 0), vec3(0.93969f, 0, -0.34202f), vec3(0.17101f, 0.86603f, 0.46985f),
               vec3(0.29620f, -0.5f, 0.81380f));
    // docs/book-reference.md §2.1, CH14 obb1, obb2, obb3.
    ExpectRows(Rotation3x3(30.716f, 0, 0), vec3(1, 0, 0), vec3(0, 0.85971f, 0.51078f), vec3(0, -0.51078f, 0.85971f));
    ExpectRows(Rotation3x3(-33.964f, -24.233f, 9.128f), vec3(0.93671f, 0.13157f, 0.32443f),
               vec3(0.08174f, 0.81889f, -0.56811f), vec3(-0.34042f, 0.55867f, 0.75631f));
    ExpectRows(Rotation3x3(24.702f, 0, 0), vec3(1, 0, 0), vec3(0, 0.90849f, 0.41790f), vec3(0, -0.41790f, 0.90849f));
}

TEST(Matrices, AxisAngleAgreesWithAxisRotations) {
    for (float a : {-135.0f, -30.0f, 0.0f, 10.0f, 90.0f, 200.0f}) {
        EXPECT_TRUE(MatNear(AxisAngle3x3(vec3(1, 0, 0), a), XRotation3x3(a), tol::kTight)) << a;
        EXPECT_TRUE(MatNear(AxisAngle3x3(vec3(0, 2, 0), a), YRotation3x3(a), tol::kTight)) << a;  // normalised
        EXPECT_TRUE(MatNear(AxisAngle3x3(vec3(0, 0, 1), a), ZRotation3x3(a), tol::kTight)) << a;
        EXPECT_TRUE(MatNear(AxisAngle(vec3(0, 0, 1), a), ZRotation(a), tol::kTight)) << a;
    }
    // 120 degrees about (1,1,1) cycles the axes: +X -> +Y -> +Z.
    const mat3 r = AxisAngle3x3(vec3(1, 1, 1), 120);
    EXPECT_TRUE(VecNear(MultiplyVector(vec3(1, 0, 0), r), vec3(0, 1, 0), tol::kTight));
    EXPECT_TRUE(VecNear(MultiplyVector(vec3(0, 1, 0), r), vec3(0, 0, 1), tol::kTight));
    EXPECT_TRUE(MatNear(AxisAngle3x3(vec3(0, 0, 0), 45), mat3(), 0.0f));  // zero axis
}

TEST(Matrices, DecomposeRoundTrip) {
    std::mt19937 rng(3);
    for (int n = 0; n < 200; ++n) {
        const vec3 e(U(rng, -89, 89), U(rng, -179, 179), U(rng, -179, 179));
        const vec3 d = Decompose(Rotation3x3(e.x, e.y, e.z));
        ASSERT_TRUE(VecNear(d, e, 2e-2f)) << "case " << n;  // asin near +-90 amplifies rounding
        ASSERT_TRUE(MatNear(Rotation3x3(d.x, d.y, d.z), Rotation3x3(e.x, e.y, e.z), tol::kLoose)) << "case " << n;
    }
    EXPECT_TRUE(VecNear(Decompose(Rotation3x3(30, 20, 0)), vec3(30, 20, 0), 1e-3f));
}

// ---- Transforms ------------------------------------------------------------------------------------------

TEST(Matrices, TranslationScaleAndMultiplyPointVector) {
    const mat4 t = Translation(1, 2, 3);
    EXPECT_TRUE(VecNear(GetTranslation(t), vec3(1, 2, 3), 0.0f));
    EXPECT_TRUE(VecNear(MultiplyPoint(vec3(1, 0, 0), t), vec3(2, 2, 3), 0.0f));
    EXPECT_TRUE(VecNear(MultiplyVector(vec3(1, 0, 0), t), vec3(1, 0, 0), 0.0f));  // w = 0: no translation
    EXPECT_TRUE(VecNear(GetScale(Scale(2, 3, 4)), vec3(2, 3, 4), 0.0f));
    // world = scale * rotation * translation: (1,0,0) scaled to (2,0,0), Z(90) -> (0,2,0), moved by (1,2,3).
    const mat4 w = Transform(vec3(2, 2, 2), vec3(0, 0, 90), vec3(1, 2, 3));
    EXPECT_TRUE(VecNear(MultiplyPoint(vec3(1, 0, 0), w), vec3(1, 4, 3), tol::kTight));
    EXPECT_TRUE(VecNear(MultiplyVector(vec3(1, 0, 0), w), vec3(0, 2, 0), tol::kTight));
    const mat4 wa = Transform(vec3(1, 1, 1), vec3(0, 0, 1), 90, vec3(1, 2, 3));
    EXPECT_TRUE(VecNear(MultiplyPoint(vec3(1, 0, 0), wa), vec3(1, 3, 3), tol::kTight));
    EXPECT_TRUE(VecNear(MultiplyVector(vec3(0, 1, 0), ZRotation3x3(90)), vec3(-1, 0, 0), tol::kTight));
}

TEST(Matrices, FastInverseEqualsInverseForRigidTransforms) {
    std::mt19937 rng(11);
    for (int n = 0; n < 200; ++n) {
        const mat3 r = RandomRotation(rng);
        const mat4 m = FromMat3(r) * Translation(U(rng, -20, 20), U(rng, -20, 20), U(rng, -20, 20));
        ASSERT_TRUE(MatNear(FastInverse(m), Inverse(m), tol::kLoose)) << "case " << n;
        ASSERT_TRUE(MatNear(FastInverse(m) * m, mat4(), tol::kLoose)) << "case " << n;
        ASSERT_TRUE(MatNear(FastInverse(r), Inverse(r), tol::kTight)) << "case " << n;
    }
}

TEST(Matrices, OrthogonalizeKeepsUpAndRestoresOrthonormality) {
    mat3 m = Rotation3x3(20, 30, 40);
    m[0][0] += 0.05f;  // skew the X row
    const mat3 o = Orthogonalize(m);
    EXPECT_TRUE(MatNear(o * Transpose(o), mat3(), tol::kTight));
    EXPECT_TRUE(VecNear(GetRow(o, 1), Normalized(GetRow(m, 1)), tol::kTight));
}

// ---- Camera matrices (docs/book-reference.md §1.4) ------------------------------------------------------------------

TEST(Matrices, LookAtForTheCh14CameraPreset) {
    // OrbitCamera: orient = Rotation3x3(pitch = rot.y, yaw = rot.x, 0), eye = target + (0,0,-zoom) * orient.
    const vec3 target(3.75622f, 2.98255f, 0);
    const float zoom = 9, yaw = -67.9312f, pitch = 19.8f;
    const vec3 eye = target + MultiplyVector(vec3(0, 0, -zoom), Rotation3x3(pitch, yaw, 0));
    // Closed form of docs/book-reference.md §1.4, and its printed eye.
    const float p = DEG2RAD(pitch), y = DEG2RAD(yaw);
    EXPECT_TRUE(VecNear(eye, target + vec3(-std::cos(p) * std::sin(y), std::sin(p), -std::cos(p) * std::cos(y)) * zoom,
                        tol::kTight));
    EXPECT_TRUE(VecNear(eye, vec3(11.6037f, 6.0312f, -3.1816f), 1e-4f));

    const mat4 view = LookAt(eye, target, vec3(0, 1, 0));
    EXPECT_TRUE(VecNear(MultiplyPoint(eye, view), vec3(0, 0, 0), tol::kLoose));
    EXPECT_TRUE(VecNear(MultiplyPoint(target, view), vec3(0, 0, zoom), tol::kLoose));  // +Z into the screen
    // The rotation part is orthonormal and the camera's up has a positive world-Y component.
    const mat3 r(view[0][0], view[0][1], view[0][2], view[1][0], view[1][1], view[1][2], view[2][0], view[2][1],
                 view[2][2]);
    EXPECT_TRUE(MatNear(r * Transpose(r), mat3(), tol::kTight));
    EXPECT_GT(MultiplyVector(vec3(0, 1, 0), view).y, 0.0f);
    // The Ch15 preset (zoom 12) prints eye (14.2196, 7.0474, -4.2421).
    const vec3 eye12 = target + MultiplyVector(vec3(0, 0, -12), Rotation3x3(pitch, yaw, 0));
    EXPECT_TRUE(VecNear(eye12, vec3(14.2196f, 7.0474f, -4.2421f), 1e-4f));
}

TEST(Matrices, LookAtDefaultCameraAndDegenerateInput) {
    // Default preset: eye (0,0,-10) looking at the origin along +Z; +X stays +X (screen right).
    const mat4 view = LookAt(vec3(0, 0, -10), vec3(0, 0, 0), vec3(0, 1, 0));
    EXPECT_TRUE(MatNear(view, Translation(0, 0, 10), tol::kExact));
    // eye == target, and up parallel to the view direction: finite, orthonormal fallbacks (erratum 5.2-6).
    for (const mat4& v :
         {LookAt(vec3(1, 2, 3), vec3(1, 2, 3), vec3(0, 1, 0)), LookAt(vec3(0, 0, 0), vec3(0, 5, 0), vec3(0, 1, 0))}) {
        for (float e : v.asArray) ASSERT_TRUE(std::isfinite(e));
        const mat3 r(v[0][0], v[0][1], v[0][2], v[1][0], v[1][1], v[1][2], v[2][0], v[2][1], v[2][2]);
        EXPECT_TRUE(MatNear(r * Transpose(r), mat3(), tol::kTight));
    }
}

TEST(Matrices, ProjectionEntries) {
    // docs/book-reference.md §1.4: 60 degrees, 800/600, near 0.01, far 1000.
    const float n = 0.01f, f = 1000.0f, aspect = 800.0f / 600.0f;
    const mat4 p = Projection(60, aspect, n, f);
    const float cot30 = std::sqrt(3.0f);
    const mat4 expected(cot30 / aspect, 0, 0, 0, 0, cot30, 0, 0, 0, 0, f / (f - n), 1, 0, 0, -n * f / (f - n), 0);
    EXPECT_TRUE(MatNear(p, expected, tol::kTight));
    EXPECT_NEAR(p[0][0], 1.2990381f, tol::kTight);
    // View z = near maps to NDC z 0 and z = far to 1 (D3D style).
    const float zn = n * p[2][2] + p[3][2], wn = n * p[2][3];
    const float zf = f * p[2][2] + p[3][2], wf = f * p[2][3];
    EXPECT_NEAR(zn / wn, 0.0f, tol::kLoose);
    EXPECT_NEAR(zf / wf, 1.0f, tol::kLoose);
}

TEST(Matrices, OrthoMapsTheBoxToNdc) {
    const mat4 o = Ortho(-4, 4, -3, 3, 1, 11);
    EXPECT_TRUE(VecNear(MultiplyPoint(vec3(-4, -3, 1), o), vec3(-1, -1, 0), tol::kTight));
    EXPECT_TRUE(VecNear(MultiplyPoint(vec3(4, 3, 11), o), vec3(1, 1, 1), tol::kTight));
}

TEST(Matrices, EqualityUsesTheBooksTolerance) {
    EXPECT_TRUE(mat3() == Diag3(1.004f, 1, 1));
    EXPECT_TRUE(mat3() != Diag3(1.006f, 1, 1));
    EXPECT_TRUE(mat4() == Diag4(1, 1, 1, 0.996f));
    EXPECT_TRUE(mat2() != mat2(1, 0.01f, 0, 1));
}
