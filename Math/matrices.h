#pragma once
// mat2 / mat3 / mat4 with the book's conventions: row-major storage, row vectors multiplied on the left
// (v * M), transforms concatenated left to right (scale * rotation * translation), translation in row 4,
// left-handed, rotation helpers in degrees. Element (row r, column c) is m[r][c] (the book's _rc, 1-based).
// Default-constructed matrices are identity.

#include "Math/vectors.h"

struct mat2 {
    float asArray[4] = {1, 0, 0, 1};
    constexpr mat2() = default;
    constexpr mat2(float f11, float f12, float f21, float f22) : asArray{f11, f12, f21, f22} {}
    float* operator[](int row) { return asArray + row * 2; }
    const float* operator[](int row) const { return asArray + row * 2; }
};

struct mat3 {
    float asArray[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    constexpr mat3() = default;
    constexpr mat3(float f11, float f12, float f13, float f21, float f22, float f23, float f31, float f32, float f33)
        : asArray{f11, f12, f13, f21, f22, f23, f31, f32, f33} {}
    float* operator[](int row) { return asArray + row * 3; }
    const float* operator[](int row) const { return asArray + row * 3; }
};

struct mat4 {
    float asArray[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    constexpr mat4() = default;
    constexpr mat4(float f11, float f12, float f13, float f14, float f21, float f22, float f23, float f24, float f31,
                   float f32, float f33, float f34, float f41, float f42, float f43, float f44)
        : asArray{f11, f12, f13, f14, f21, f22, f23, f24, f31, f32, f33, f34, f41, f42, f43, f44} {}
    float* operator[](int row) { return asArray + row * 4; }
    const float* operator[](int row) const { return asArray + row * 4; }
};

/// A matrix of all zeros (default construction gives identity).
mat3 ZeroMat3();
mat4 ZeroMat4();

/// Row i of an orientation matrix: the local axis i expressed in world space.
vec3 GetRow(const mat3& m, int row);

bool operator==(const mat2& l, const mat2& r);  ///< element-wise CMP (absolute 0.005)
bool operator==(const mat3& l, const mat3& r);
bool operator==(const mat4& l, const mat4& r);
bool operator!=(const mat2& l, const mat2& r);
bool operator!=(const mat3& l, const mat3& r);
bool operator!=(const mat4& l, const mat4& r);

/// Generic row-major product out = A(aRows x aCols) * B(bRows x bCols); false if aCols != bRows.
bool Multiply(float* out, const float* matA, int aRows, int aCols, const float* matB, int bRows, int bCols);
/// Generic transpose of a srcRows x srcCols row-major array.
void Transpose(const float* srcMat, float* dstMat, int srcRows, int srcCols);

mat2 Transpose(const mat2& m);
mat3 Transpose(const mat3& m);
mat4 Transpose(const mat4& m);
mat2 operator*(const mat2& m, float s);
mat3 operator*(const mat3& m, float s);
mat4 operator*(const mat4& m, float s);
mat2 operator*(const mat2& a, const mat2& b);
mat3 operator*(const mat3& a, const mat3& b);
mat4 operator*(const mat4& a, const mat4& b);
mat3 operator+(const mat3& a, const mat3& b);

float Determinant(const mat2& m);
float Determinant(const mat3& m);
float Determinant(const mat4& m);
/// The (rows-1)x(cols-1) matrix left after removing `row` and `col`.
mat2 Cut(const mat3& m, int row, int col);
mat3 Cut(const mat4& m, int row, int col);
mat2 Minor(const mat2& m);
mat3 Minor(const mat3& m);
mat4 Minor(const mat4& m);
mat2 Cofactor(const mat2& m);
mat3 Cofactor(const mat3& m);
mat4 Cofactor(const mat4& m);
mat2 Adjugate(const mat2& m);
mat3 Adjugate(const mat3& m);
mat4 Adjugate(const mat4& m);

/// True if |det| is too small, relative to the size of the rows, for an inverse to be meaningful
/// (|det| <= 1e-7 * product of row lengths). Erratum 5.2-10: the book tests |det| <= 0.005 absolutely.
bool IsSingular(const mat2& m);
bool IsSingular(const mat3& m);
bool IsSingular(const mat4& m);
/// Inverse; a singular matrix (IsSingular) returns identity, as the book does, but small well-conditioned
/// matrices (a 0.5 m box's inertia tensor, det 0.0046) invert correctly (erratum 5.2-10).
mat2 Inverse(const mat2& m);
mat3 Inverse(const mat3& m);
mat4 Inverse(const mat4& m);

mat4 ToColumnMajor(const mat4& m);
mat3 ToColumnMajor(const mat3& m);
mat4 FromColumnMajor(const mat4& m);
mat4 FromColumnMajor(const float* input);

mat4 Translation(float x, float y, float z);
mat4 Translation(const vec3& pos);
vec3 GetTranslation(const mat4& m);
mat4 Translate(float x, float y, float z);
mat4 Translate(const vec3& pos);
/// Embeds a rotation (or any 3x3) in the upper-left of an identity mat4.
mat4 FromMat3(const mat3& m);
mat4 Scale(float x, float y, float z);
mat4 Scale(const vec3& s);
vec3 GetScale(const mat4& m);

/// Rotation(pitch, yaw, roll) in degrees = Z(roll) * X(pitch) * Y(yaw): roll acts first on a row vector.
mat4 Rotation(float pitch, float yaw, float roll);
mat3 Rotation3x3(float pitch, float yaw, float roll);
mat4 ZRotation(float angle);
mat3 ZRotation3x3(float angle);
mat4 XRotation(float angle);
mat3 XRotation3x3(float angle);
mat4 YRotation(float angle);
mat3 YRotation3x3(float angle);
/// The book's YawPitchRoll(yaw, pitch, roll), degrees, the D3D convention (roll, then pitch, then yaw).
mat4 YawPitchRoll(float yaw, float pitch, float roll);
/// Rotation of `angle` degrees about `axis` (normalised inside; a zero axis gives identity).
mat4 AxisAngle(const vec3& axis, float angle);
mat3 AxisAngle3x3(const vec3& axis, float angle);

/// Row vector times matrix with w = 1: the point transformed, translation included.
vec3 MultiplyPoint(const vec3& vec, const mat4& mat);
/// Row vector times matrix with w = 0: rotation and scale only.
vec3 MultiplyVector(const vec3& vec, const mat4& mat);
vec3 MultiplyVector(const vec3& vec, const mat3& mat);

/// world = scale * rotation(euler degrees: pitch, yaw, roll) * translation.
mat4 Transform(const vec3& scale, const vec3& eulerRotation, const vec3& translate);
mat4 Transform(const vec3& scale, const vec3& rotationAxis, float rotationAngle, const vec3& translate);
/// Left-handed view matrix: forward = target - eye, right = up x forward. eye == target, or up parallel
/// to forward, picks a defined fallback basis instead of NaN (erratum 5.2-6).
mat4 LookAt(const vec3& position, const vec3& target, const vec3& up);
/// D3D-style perspective, vertical fov in degrees, view z in [near, far] -> NDC z in [0, 1].
mat4 Projection(float fov, float aspect, float zNear, float zFar);
/// D3D-style orthographic projection.
mat4 Ortho(float left, float right, float bottom, float top, float zNear, float zFar);
/// Inverse of a pure rotation (its transpose).
mat3 FastInverse(const mat3& mat);
/// Inverse of a rigid transform: transposed rotation, translation = -dot(axis_i, position).
mat4 FastInverse(const mat4& mat);
/// Re-orthonormalises the rows of a rotation, keeping the direction of row 2 (up).
mat3 Orthogonalize(const mat3& mat);
/// Pitch/yaw/roll in degrees of a rotation built with Rotation3x3 (inverse of it for |pitch| < 90).
vec3 Decompose(const mat3& rot);
