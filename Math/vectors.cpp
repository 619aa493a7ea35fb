#include "Math/vectors.h"

#include <cmath>

#include "Math/Compare.h"

namespace {
constexpr float kPi = 3.14159265358979323846f;
}

vec2 operator+(const vec2& l, const vec2& r) { return {l.x + r.x, l.y + r.y}; }
vec2 operator-(const vec2& l, const vec2& r) { return {l.x - r.x, l.y - r.y}; }
vec2 operator*(const vec2& l, const vec2& r) { return {l.x * r.x, l.y * r.y}; }
vec2 operator*(const vec2& l, float r) { return {l.x * r, l.y * r}; }
vec2 operator/(const vec2& l, const vec2& r) { return {l.x / r.x, l.y / r.y}; }
vec2 operator/(const vec2& l, float r) { return {l.x / r, l.y / r}; }
vec2 operator-(const vec2& v) { return {-v.x, -v.y}; }
vec2& operator+=(vec2& l, const vec2& r) { return l = l + r; }
vec2& operator-=(vec2& l, const vec2& r) { return l = l - r; }
vec2& operator*=(vec2& l, const vec2& r) { return l = l * r; }
vec2& operator*=(vec2& l, float r) { return l = l * r; }
vec2& operator/=(vec2& l, const vec2& r) { return l = l / r; }
vec2& operator/=(vec2& l, float r) { return l = l / r; }
bool operator==(const vec2& l, const vec2& r) { return CMP(l.x, r.x) && CMP(l.y, r.y); }
bool operator!=(const vec2& l, const vec2& r) { return !(l == r); }

bool operator==(const vec3& l, const vec3& r) { return CMP(l.x, r.x) && CMP(l.y, r.y) && CMP(l.z, r.z); }
bool operator!=(const vec3& l, const vec3& r) { return !(l == r); }

float Dot(const vec2& l, const vec2& r) { return l.x * r.x + l.y * r.y; }
float Magnitude(const vec2& v) { return std::sqrt(Dot(v, v)); }
float Magnitude(const vec3& v) { return std::sqrt(Dot(v, v)); }
float MagnitudeSq(const vec2& v) { return Dot(v, v); }
float Distance(const vec2& p1, const vec2& p2) { return Magnitude(p1 - p2); }
float Distance(const vec3& p1, const vec3& p2) { return Magnitude(p1 - p2); }
float DistanceSq(const vec2& p1, const vec2& p2) { return MagnitudeSq(p1 - p2); }
float DistanceSq(const vec3& p1, const vec3& p2) { return MagnitudeSq(p1 - p2); }

vec2 Normalized(const vec2& v) {
    const float len = Magnitude(v);
    // Erratum 5.2-6: the book multiplies by 1/|v| unguarded and returns NaN for a zero vector.
    if (!(len > 0.0f) || !std::isfinite(len)) return vec2();
    return v * (1.0f / len);
}
vec3 Normalized(const vec3& v) {
    const float len = Magnitude(v);
    if (!(len > 0.0f) || !std::isfinite(len)) return vec3();
    return v * (1.0f / len);
}
void Normalize(vec2& v) {
    if (MagnitudeSq(v) > 0.0f) v = Normalized(v);
}
void Normalize(vec3& v) {
    if (MagnitudeSq(v) > 0.0f) v = Normalized(v);
}

float Angle(const vec2& l, const vec2& r) {
    const float m = std::sqrt(MagnitudeSq(l) * MagnitudeSq(r));
    if (!(m > 0.0f)) return 0.0f;
    return std::acos(std::fmax(-1.0f, std::fmin(1.0f, Dot(l, r) / m)));
}
float Angle(const vec3& l, const vec3& r) {
    const float m = std::sqrt(MagnitudeSq(l) * MagnitudeSq(r));
    if (!(m > 0.0f)) return 0.0f;
    return std::acos(std::fmax(-1.0f, std::fmin(1.0f, Dot(l, r) / m)));
}

vec2 Project(const vec2& length, const vec2& direction) {
    const float d = MagnitudeSq(direction);
    if (!(d > 0.0f)) return vec2();
    return direction * (Dot(length, direction) / d);
}
vec3 Project(const vec3& length, const vec3& direction) {
    const float d = MagnitudeSq(direction);
    if (!(d > 0.0f)) return vec3();
    return direction * (Dot(length, direction) / d);
}
vec2 Perpendicular(const vec2& len, const vec2& dir) { return len - Project(len, dir); }
vec3 Perpendicular(const vec3& len, const vec3& dir) { return len - Project(len, dir); }
vec2 Reflection(const vec2& v, const vec2& n) { return v - n * (2.0f * Dot(v, n)); }
vec3 Reflection(const vec3& v, const vec3& n) { return v - n * (2.0f * Dot(v, n)); }

vec2 RotateVector(const vec2& vector, float degrees) {
    const float a = DEG2RAD(degrees);
    const float c = std::cos(a), s = std::sin(a);
    return {vector.x * c - vector.y * s, vector.x * s + vector.y * c};
}

float CorrectDegrees(float degrees) {
    if (degrees > 360.0f || degrees < -360.0f) return std::fmod(degrees, 360.0f);
    return degrees;
}
float DEG2RAD(float degrees) { return CorrectDegrees(degrees) * (kPi / 180.0f); }
float RAD2DEG(float radians) { return CorrectDegrees(radians * (180.0f / kPi)); }

bool IsFinite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
