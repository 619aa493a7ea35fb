#include "Math/quaternion.h"

#include <cmath>

quat operator*(const quat& a, const quat& b) {
    return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y, a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w, a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}
quat operator*(const quat& q, float s) { return {q.x * s, q.y * s, q.z * s, q.w * s}; }
quat operator+(const quat& a, const quat& b) { return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w}; }
float Dot(const quat& a, const quat& b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }
float Magnitude(const quat& q) { return std::sqrt(Dot(q, q)); }

quat Normalized(const quat& q) {
    const float len = Magnitude(q);
    if (!(len > 0.0f) || !std::isfinite(len)) return quat();
    return q * (1.0f / len);
}
quat Conjugate(const quat& q) { return {-q.x, -q.y, -q.z, q.w}; }
quat Inverse(const quat& q) {
    const float lenSq = Dot(q, q);
    if (!(lenSq > 0.0f)) return quat();
    return Conjugate(q) * (1.0f / lenSq);
}

quat AngleAxis(const vec3& axis, float radians) {
    const vec3 n = Normalized(axis);
    if (MagnitudeSq(n) == 0.0f) return quat();
    const float s = std::sin(radians * 0.5f);
    return {n.x * s, n.y * s, n.z * s, std::cos(radians * 0.5f)};
}

vec3 Rotate(const quat& q, const vec3& v) {
    // v' = v + 2w(u x v) + 2 u x (u x v), u = vector part.
    const vec3 u(q.x, q.y, q.z);
    const vec3 t = Cross(u, v) * 2.0f;
    return v + t * q.w + Cross(u, t);
}

mat3 ToMat3(const quat& q) {
    // Rows are the images of the unit axes: row i = Rotate(q, e_i).
    const float xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
    const float xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
    const float wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
    return mat3(1 - 2 * (yy + zz), 2 * (xy + wz), 2 * (xz - wy),  //
                2 * (xy - wz), 1 - 2 * (xx + zz), 2 * (yz + wx),  //
                2 * (xz + wy), 2 * (yz - wx), 1 - 2 * (xx + yy));
}

quat FromMat3ToQuat(const mat3& m) {
    // m is the transpose of the column-vector rotation matrix C: C[i][j] = m[j][i].
    auto c = [&m](int i, int j) { return m[j][i]; };
    const float trace = c(0, 0) + c(1, 1) + c(2, 2);
    quat q;
    if (trace > 0.0f) {
        const float s = std::sqrt(trace + 1.0f) * 2.0f;
        q = {(c(2, 1) - c(1, 2)) / s, (c(0, 2) - c(2, 0)) / s, (c(1, 0) - c(0, 1)) / s, 0.25f * s};
    } else if (c(0, 0) > c(1, 1) && c(0, 0) > c(2, 2)) {
        const float s = std::sqrt(1.0f + c(0, 0) - c(1, 1) - c(2, 2)) * 2.0f;
        q = {0.25f * s, (c(0, 1) + c(1, 0)) / s, (c(0, 2) + c(2, 0)) / s, (c(2, 1) - c(1, 2)) / s};
    } else if (c(1, 1) > c(2, 2)) {
        const float s = std::sqrt(1.0f + c(1, 1) - c(0, 0) - c(2, 2)) * 2.0f;
        q = {(c(0, 1) + c(1, 0)) / s, 0.25f * s, (c(1, 2) + c(2, 1)) / s, (c(0, 2) - c(2, 0)) / s};
    } else {
        const float s = std::sqrt(1.0f + c(2, 2) - c(0, 0) - c(1, 1)) * 2.0f;
        q = {(c(0, 2) + c(2, 0)) / s, (c(1, 2) + c(2, 1)) / s, 0.25f * s, (c(1, 0) - c(0, 1)) / s};
    }
    return Normalized(q);
}

quat FromEuler(float pitch, float yaw, float roll) { return FromMat3ToQuat(Rotation3x3(pitch, yaw, roll)); }

quat Integrate(const quat& q, const vec3& w, float dt) {
    const float speed = Magnitude(w);
    if (!(speed > 0.0f)) return q;
    // World-space angular velocity: q' = exp(w dt / 2) * q.
    return Normalized(AngleAxis(w, speed * dt) * q);
}

bool IsFinite(const quat& q) {
    return std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w);
}
