#pragma once
// Unit quaternions for rigid-body orientation (the book's author names the lack of one as his main regret).
// Convention: q = (x, y, z, w), w the scalar part. ToMat3 gives the book-style orientation matrix whose ROWS
// are the rotated local axes, so MultiplyVector(v, ToMat3(q)) == Rotate(q, v).

#include <cmath>

#include "Math/matrices.h"
#include "Math/vectors.h"

struct quat {
    float x = 0.0f, y = 0.0f, z = 0.0f, w = 1.0f;
    constexpr quat() = default;
    constexpr quat(float x_, float y_, float z_, float w_) : x(x_), y(y_), z(z_), w(w_) {}
};

// The small operations are inline: the solvers call them per body per substep.
/// Hamilton product: (a*b) rotates by b, then by a.
inline quat operator*(const quat& a, const quat& b) {
    return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}
inline quat operator*(const quat& q, float s) { return {q.x * s, q.y * s, q.z * s, q.w * s}; }
inline quat operator+(const quat& a, const quat& b) { return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w}; }
inline float Dot(const quat& a, const quat& b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }
inline float Magnitude(const quat& q) { return std::sqrt(Dot(q, q)); }
/// Unit quaternion; identity for a zero or non-finite input.
quat Normalized(const quat& q);
inline quat Conjugate(const quat& q) { return {-q.x, -q.y, -q.z, q.w}; }
/// Inverse; equals Conjugate for unit quaternions. Identity for a zero quaternion.
quat Inverse(const quat& q);
/// Rotation of `radians` about `axis` (normalised inside; a zero axis gives identity).
quat AngleAxis(const vec3& axis, float radians);
/// Rotates a vector: q v q*.
vec3 Rotate(const quat& q, const vec3& v);
/// Orientation matrix with the rotated local axes as rows (book convention, row vectors).
inline mat3 ToMat3(const quat& q) {
    // Rows are the images of the unit axes: row i = Rotate(q, e_i).
    const float xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    const float xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    const float wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    return mat3(1 - 2 * (yy + zz), 2 * (xy + wz), 2 * (xz - wy),  //
                2 * (xy - wz), 1 - 2 * (xx + zz), 2 * (yz + wx),  //
                2 * (xz + wy), 2 * (yz - wx), 1 - 2 * (xx + yy));
}
/// Inverse of ToMat3 for a rotation matrix (Shepperd's method, numerically safe for every trace).
quat FromMat3ToQuat(const mat3& m);
/// Book Euler angles (pitch, yaw, roll in degrees, Rotation3x3 order) as a quaternion.
quat FromEuler(float pitch, float yaw, float roll);
/// Advances orientation by a world-space angular velocity over dt (exact exponential map, renormalised).
quat Integrate(const quat& q, const vec3& angularVelocity, float dt);
bool IsFinite(const quat& q);
