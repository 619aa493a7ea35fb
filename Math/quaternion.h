#pragma once
// Unit quaternions for rigid-body orientation (the book's author names the lack of one as his main regret).
// Convention: q = (x, y, z, w), w the scalar part. ToMat3 gives the book-style orientation matrix whose ROWS
// are the rotated local axes, so MultiplyVector(v, ToMat3(q)) == Rotate(q, v).

#include "Math/matrices.h"
#include "Math/vectors.h"

struct quat {
    float x = 0.0f, y = 0.0f, z = 0.0f, w = 1.0f;
    constexpr quat() = default;
    constexpr quat(float x_, float y_, float z_, float w_) : x(x_), y(y_), z(z_), w(w_) {}
};

quat operator*(const quat& a, const quat& b);  ///< Hamilton product: (a*b) rotates by b, then by a.
quat operator*(const quat& q, float s);
quat operator+(const quat& a, const quat& b);
float Dot(const quat& a, const quat& b);
float Magnitude(const quat& q);
/// Unit quaternion; identity for a zero or non-finite input.
quat Normalized(const quat& q);
quat Conjugate(const quat& q);
/// Inverse; equals Conjugate for unit quaternions. Identity for a zero quaternion.
quat Inverse(const quat& q);
/// Rotation of `radians` about `axis` (normalised inside; a zero axis gives identity).
quat AngleAxis(const vec3& axis, float radians);
/// Rotates a vector: q v q*.
vec3 Rotate(const quat& q, const vec3& v);
/// Orientation matrix with the rotated local axes as rows (book convention, row vectors).
mat3 ToMat3(const quat& q);
/// Inverse of ToMat3 for a rotation matrix (Shepperd's method, numerically safe for every trace).
quat FromMat3ToQuat(const mat3& m);
/// Book Euler angles (pitch, yaw, roll in degrees, Rotation3x3 order) as a quaternion.
quat FromEuler(float pitch, float yaw, float roll);
/// Advances orientation by a world-space angular velocity over dt (exact exponential map, renormalised).
quat Integrate(const quat& q, const vec3& angularVelocity, float dt);
bool IsFinite(const quat& q);
