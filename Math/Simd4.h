#pragma once
// Four float lanes, the two shapes the soft contact solver works in (Physics/SoftContactKernel.h):
//  - V4: one vec3 and a fourth float (x, y, z, pad), SSE2 where the compiler has it, plain floats otherwise;
//  - Float4 / Vec4x3: one float (one vec3) per lane of four independent items, by the GCC/Clang vector extension.
// Every operation is lane-wise, and every dot product sums (x + y) + z, the order of Dot in Math/vectors.h, so a
// lane carries the same bits as plain float and vec3 arithmetic (the build has -ffp-contract=off: no fused
// multiply-add). No GL, no state.
#include <cmath>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "Math/vectors.h"

namespace simd4 {

// ---- V4: one vec3 in four lanes (the fourth lane never reaches a result) ----

#if defined(__SSE2__)
struct V4 {
    __m128 m;
};
/// The 16 bytes at a 16-aligned vec3 and its padding float.
inline V4 Load(const vec3& v) { return {_mm_load_ps(&v.x)}; }
inline V4 Load(const float* f) { return {_mm_load_ps(f)}; }
/// Writes all four lanes: the float after v (its padding) is overwritten.
inline void Store(vec3& v, V4 a) { _mm_store_ps(&v.x, a.m); }
inline V4 Splat(float f) { return {_mm_set1_ps(f)}; }
/// (v.x, v.y, v.z, 0).
inline V4 Make(const vec3& v) { return {_mm_set_ps(0.0f, v.z, v.y, v.x)}; }
/// Lane i of a in every lane.
template <int i>
inline V4 Broadcast(V4 a) {
    return {_mm_shuffle_ps(a.m, a.m, _MM_SHUFFLE(i, i, i, i))};
}
/// Lane-wise Cross: (l.y r.z - l.z r.y, l.z r.x - l.x r.z, l.x r.y - l.y r.x).
inline V4 Cross(V4 l, V4 r) {
    const __m128 lYZX = _mm_shuffle_ps(l.m, l.m, _MM_SHUFFLE(3, 0, 2, 1));
    const __m128 lZXY = _mm_shuffle_ps(l.m, l.m, _MM_SHUFFLE(3, 1, 0, 2));
    const __m128 rYZX = _mm_shuffle_ps(r.m, r.m, _MM_SHUFFLE(3, 0, 2, 1));
    const __m128 rZXY = _mm_shuffle_ps(r.m, r.m, _MM_SHUFFLE(3, 1, 0, 2));
    return {_mm_sub_ps(_mm_mul_ps(lYZX, rZXY), _mm_mul_ps(lZXY, rYZX))};
}
inline V4 operator+(V4 a, V4 b) { return {_mm_add_ps(a.m, b.m)}; }
inline V4 operator-(V4 a, V4 b) { return {_mm_sub_ps(a.m, b.m)}; }
inline V4 operator*(V4 a, V4 b) { return {_mm_mul_ps(a.m, b.m)}; }
/// Lane i of the result is Dot(a_i, b_i) for i < 3, summed as (x + y) + z; lane 3 is 0.
inline V4 Dot3(V4 a0, V4 b0, V4 a1, V4 b1, V4 a2, V4 b2) {
    __m128 p0 = _mm_mul_ps(a0.m, b0.m), p1 = _mm_mul_ps(a1.m, b1.m), p2 = _mm_mul_ps(a2.m, b2.m);
    __m128 p3 = _mm_setzero_ps();
    _MM_TRANSPOSE4_PS(p0, p1, p2, p3);
    return {_mm_add_ps(_mm_add_ps(p0, p1), p2)};
}
/// Lane i of a.
template <int i>
inline float Get(V4 a) {
    return _mm_cvtss_f32(_mm_shuffle_ps(a.m, a.m, _MM_SHUFFLE(i, i, i, i)));
}
/// Dot(a0, b0), Dot(a1, b1), Dot(a2, b2) and Dot(a3, b3), each (x + y) + z, sharing one transpose.
inline V4 Dot4(V4 a0, V4 b0, V4 a1, V4 b1, V4 a2, V4 b2, V4 a3, V4 b3) {
    __m128 p0 = _mm_mul_ps(a0.m, b0.m), p1 = _mm_mul_ps(a1.m, b1.m);
    __m128 p2 = _mm_mul_ps(a2.m, b2.m), p3 = _mm_mul_ps(a3.m, b3.m);
    _MM_TRANSPOSE4_PS(p0, p1, p2, p3);
    return {_mm_add_ps(_mm_add_ps(p0, p1), p2)};
}
/// (x + y) + z of a's lanes times b's.
inline float Dot(V4 a, V4 b) {
    const __m128 p = _mm_mul_ps(a.m, b.m);
    return (_mm_cvtss_f32(p) + _mm_cvtss_f32(_mm_shuffle_ps(p, p, 1))) + _mm_cvtss_f32(_mm_shuffle_ps(p, p, 2));
}
#else
struct V4 {
    float f[4];
};
inline V4 Load(const float* f) { return {{f[0], f[1], f[2], f[3]}}; }
inline V4 Load(const vec3& v) { return Load(&v.x); }
inline void Store(vec3& v, V4 a) { std::memcpy(&v.x, a.f, sizeof(a.f)); }
inline V4 Splat(float x) { return {{x, x, x, x}}; }
inline V4 Make(const vec3& v) { return {{v.x, v.y, v.z, 0.0f}}; }
template <int i>
inline V4 Broadcast(V4 a) {
    return Splat(a.f[i]);
}
inline V4 Cross(V4 l, V4 r) {
    return {{l.f[1] * r.f[2] - l.f[2] * r.f[1], l.f[2] * r.f[0] - l.f[0] * r.f[2], l.f[0] * r.f[1] - l.f[1] * r.f[0],
             0.0f}};
}
inline V4 operator+(V4 a, V4 b) { return {{a.f[0] + b.f[0], a.f[1] + b.f[1], a.f[2] + b.f[2], a.f[3] + b.f[3]}}; }
inline V4 operator-(V4 a, V4 b) { return {{a.f[0] - b.f[0], a.f[1] - b.f[1], a.f[2] - b.f[2], a.f[3] - b.f[3]}}; }
inline V4 operator*(V4 a, V4 b) { return {{a.f[0] * b.f[0], a.f[1] * b.f[1], a.f[2] * b.f[2], a.f[3] * b.f[3]}}; }
inline float Dot(V4 a, V4 b) { return (a.f[0] * b.f[0] + a.f[1] * b.f[1]) + a.f[2] * b.f[2]; }
template <int i>
inline float Get(V4 a) {
    return a.f[i];
}
inline V4 Dot3(V4 a0, V4 b0, V4 a1, V4 b1, V4 a2, V4 b2) { return {{Dot(a0, b0), Dot(a1, b1), Dot(a2, b2), 0.0f}}; }
inline V4 Dot4(V4 a0, V4 b0, V4 a1, V4 b1, V4 a2, V4 b2, V4 a3, V4 b3) {
    return {{Dot(a0, b0), Dot(a1, b1), Dot(a2, b2), Dot(a3, b3)}};
}
#endif

/// v M for a matrix stored as three rows of four floats: (v.x row0 + v.y row1) + v.z row2 (MultiplyVector's order).
inline V4 MulRows(V4 v, const float (*m)[4]) {
    return Broadcast<0>(v) * Load(m[0]) + Broadcast<1>(v) * Load(m[1]) + Broadcast<2>(v) * Load(m[2]);
}

// ---- Float4 / Vec4x3: one item per lane ----

/// Four floats, one per lane (element-wise arithmetic and comparisons).
typedef float Float4 __attribute__((vector_size(16)));
/// A comparison's result: all bits set in a lane where it holds.
using Mask4 = decltype(Float4{} < Float4{});
/// Three Float4: a vector per lane.
struct Vec4x3 {
    Float4 x, y, z;
};

inline Float4 Wide(float v) { return Float4{v, v, v, v}; }

inline Vec4x3 Sub(const Vec4x3& l, const Vec4x3& r) { return {l.x - r.x, l.y - r.y, l.z - r.z}; }
inline Vec4x3 Add(const Vec4x3& l, const Vec4x3& r) { return {l.x + r.x, l.y + r.y, l.z + r.z}; }
inline Vec4x3 Scale(const Vec4x3& v, Float4 s) { return {v.x * s, v.y * s, v.z * s}; }
/// Dot(l, r) lane by lane, in Dot's order (x, then y, then z).
inline Float4 Dot(const Vec4x3& l, const Vec4x3& r) { return l.x * r.x + l.y * r.y + l.z * r.z; }
/// Cross(l, r) lane by lane, in Cross's order.
inline Vec4x3 Cross(const Vec4x3& l, const Vec4x3& r) {
    return {l.y * r.z - l.z * r.y, l.z * r.x - l.x * r.z, l.x * r.y - l.y * r.x};
}
/// v M lane by lane (row-vector convention), M given by its rows m[0..2].
inline Vec4x3 Mul(const Vec4x3& v, const Vec4x3 (&m)[3]) {
    return {v.x * m[0].x + v.y * m[1].x + v.z * m[2].x, v.x * m[0].y + v.y * m[1].y + v.z * m[2].y,
            v.x * m[0].z + v.y * m[1].z + v.z * m[2].z};
}
inline void SetLane(Vec4x3* v, int lane, const vec3& value) {
    v->x[lane] = value.x;
    v->y[lane] = value.y;
    v->z[lane] = value.z;
}
inline vec3 Lane(const Vec4x3& v, int lane) { return vec3(v.x[lane], v.y[lane], v.z[lane]); }

/// A 16-aligned vec3 with its padding float as one Float4.
inline Float4 Load4(const vec3& v) {
    Float4 r;
    std::memcpy(&r, &v.x, sizeof(r));
    return r;
}

/// Four rows (x, y, z, pad) of lanes 0..3 turned into the lanes' x, y and z (a 4x4 transpose: data moves only).
inline Vec4x3 Transpose(Float4 r0, Float4 r1, Float4 r2, Float4 r3) {
    const Float4 xy01 = __builtin_shufflevector(r0, r1, 0, 4, 1, 5);  // x0 x1 y0 y1
    const Float4 xy23 = __builtin_shufflevector(r2, r3, 0, 4, 1, 5);
    const Float4 zp01 = __builtin_shufflevector(r0, r1, 2, 6, 3, 7);  // z0 z1 p0 p1
    const Float4 zp23 = __builtin_shufflevector(r2, r3, 2, 6, 3, 7);
    return {__builtin_shufflevector(xy01, xy23, 0, 1, 4, 5), __builtin_shufflevector(xy01, xy23, 2, 3, 6, 7),
            __builtin_shufflevector(zp01, zp23, 0, 1, 4, 5)};
}

/// The inverse: lane l's (x, y, z, 0) as row l.
inline void Untranspose(const Vec4x3& v, Float4 (&row)[4]) {
    const Float4 zero = {0.0f, 0.0f, 0.0f, 0.0f};
    const Float4 xy01 = __builtin_shufflevector(v.x, v.y, 0, 4, 1, 5);  // x0 y0 x1 y1
    const Float4 xy23 = __builtin_shufflevector(v.x, v.y, 2, 6, 3, 7);
    const Float4 z01 = __builtin_shufflevector(v.z, zero, 0, 4, 1, 5);  // z0 0 z1 0
    const Float4 z23 = __builtin_shufflevector(v.z, zero, 2, 6, 3, 7);
    row[0] = __builtin_shufflevector(xy01, z01, 0, 1, 4, 5);
    row[1] = __builtin_shufflevector(xy01, z01, 2, 3, 6, 7);
    row[2] = __builtin_shufflevector(xy23, z23, 0, 1, 4, 5);
    row[3] = __builtin_shufflevector(xy23, z23, 2, 3, 6, 7);
}

// ---- Lane-generic pieces, so one template serves float and Float4 ----

/// x in every lane of R (float or Float4).
template <class R>
inline R Fill(float x);
template <>
inline float Fill<float>(float x) {
    return x;
}
template <>
inline Float4 Fill<Float4>(float x) {
    return Wide(x);
}
/// std::max and std::min lane by lane ((a < b) ? b : a and (b < a) ? b : a).
inline float Max(float a, float b) { return a < b ? b : a; }
inline float Min(float a, float b) { return b < a ? b : a; }
inline Float4 Max(Float4 a, Float4 b) { return a < b ? b : a; }
inline Float4 Min(Float4 a, Float4 b) { return b < a ? b : a; }
/// Both masks, lane by lane; whether any lane of a mask is set.
inline bool And(bool a, bool b) { return a && b; }
inline Mask4 And(Mask4 a, Mask4 b) { return a & b; }
inline bool Any(bool a) { return a; }
inline bool Any(Mask4 a) { return (a[0] | a[1] | a[2] | a[3]) != 0; }
/// Square root lane by lane (correctly rounded, as std::sqrt).
inline Float4 Sqrt(Float4 x) {
#if defined(__SSE2__)
    return _mm_sqrt_ps(x);
#else
    for (int lane = 0; lane < 4; ++lane) x[lane] = std::sqrt(x[lane]);
    return x;
#endif
}
/// mask ? a : b lane by lane.
inline float Select(bool mask, float a, float b) { return mask ? a : b; }
inline Float4 Select(Mask4 mask, Float4 a, Float4 b) { return mask ? a : b; }
}  // namespace simd4
