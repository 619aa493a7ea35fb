#include "Math/quaternion.h"

#include <cmath>

quat Normalized(const quat& q) {
    const float len = Magnitude(q);
    if (!(len > 0.0f) || !std::isfinite(len)) return quat();
    return q * (1.0f / len);
}
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
