// Manifold reuse (docs/soft-solver.md, "Manifold reuse"): a box-box manifold kept in the boxes' frames and
// re-expressed at the present poses while the pair's relative pose has barely changed since it was made.
#include <cmath>

#include "Math/Simd4.h"
#include "Physics/Geometry/ContactManifold.h"

namespace {

/// Row i of the orientation: box axis i in world coordinates.
inline vec3 Axis(const OBB& o, int i) { return vec3(o.orientation[i][0], o.orientation[i][1], o.orientation[i][2]); }

/// v in the frame with world axes `axis` (components along each).
inline vec3 ToLocal(const vec3& v, const vec3 axis[3]) {
    return vec3(Dot(v, axis[0]), Dot(v, axis[1]), Dot(v, axis[2]));
}

/// Local v with the frame's world axes back to world coordinates, in four lanes: (axis0 v.x + axis1 v.y) + axis2 v.z,
/// lane by lane.
inline simd4::V4 ToWorld4(simd4::V4 v, const simd4::V4 axis[3]) {
    return axis[0] * simd4::Broadcast<0>(v) + axis[1] * simd4::Broadcast<1>(v) + axis[2] * simd4::Broadcast<2>(v);
}

inline vec3 ToVec3(simd4::V4 v) { return vec3(simd4::Get<0>(v), simd4::Get<1>(v), simd4::Get<2>(v)); }

/// Half diagonal of a box: the radius of its bounding sphere, m.
inline float Radius(const OBB& o) { return std::sqrt(MagnitudeSq(o.size)); }

}  // namespace

void KeepLocal(const OBB& A, const OBB& B, const ContactManifold& m, LocalManifold* out) {
    const vec3 a[3] = {Axis(A, 0), Axis(A, 1), Axis(A, 2)};
    const vec3 b[3] = {Axis(B, 0), Axis(B, 1), Axis(B, 2)};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out->R[i][j] = Dot(a[i], b[j]);
    out->t = ToLocal(B.position - A.position, a);
    out->normal = ToLocal(m.normal, a);
    out->pointCount = m.pointCount < kMaxManifoldPoints ? m.pointCount : kMaxManifoldPoints;
    for (int k = 0; k < out->pointCount; ++k) {
        const ManifoldPoint& p = m.points[k];
        // The point is midway between the two surfaces along the normal: A's surface half a separation behind it.
        const vec3 half = m.normal * (0.5f * p.separation);
        out->onA[k] = ToLocal(p.point - half - A.position, a);
        out->onB[k] = ToLocal(p.point + half - B.position, b);
        out->id[k] = p.id;
    }
}

bool ReuseLocal(const OBB& A, const OBB& B, const LocalManifold& kept, float maxMotion, ContactManifold* out) {
    if (kept.pointCount <= 0) return false;
    const vec3 a[3] = {Axis(A, 0), Axis(A, 1), Axis(A, 2)};
    const vec3 b[3] = {Axis(B, 0), Axis(B, 1), Axis(B, 2)};
    // A point x of B (|x| <= its radius) sits at t + R x in A's frame, so it has moved by at most
    // |t - t0| + ||R - R0|| |x| since the manifold was made (the Frobenius norm bounds the spectral one).
    float turnSq = 0.0f;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const float d = Dot(a[i], b[j]) - kept.R[i][j];
            turnSq += d * d;
        }
    const vec3 shift = ToLocal(B.position - A.position, a) - kept.t;
    const float motion = std::sqrt(MagnitudeSq(shift)) + std::sqrt(turnSq) * Radius(B);
    if (!(motion <= maxMotion)) return false;
    // The points in four lanes (Math/Simd4.h): each lane does the vec3 operations above in their order, so the
    // bits are theirs (a fifth fewer instructions in a resting tower's reuse, callgrind).
    using simd4::V4;
    const V4 a4[3] = {simd4::Make(a[0]), simd4::Make(a[1]), simd4::Make(a[2])};
    const V4 b4[3] = {simd4::Make(b[0]), simd4::Make(b[1]), simd4::Make(b[2])};
    const V4 n = ToWorld4(simd4::Make(kept.normal), a4);
    const V4 pA = simd4::Make(A.position), pB = simd4::Make(B.position);
    out->normal = ToVec3(n);
    out->pointCount = kept.pointCount;
    for (int k = 0; k < kept.pointCount; ++k) {
        const V4 onA = pA + ToWorld4(simd4::Make(kept.onA[k]), a4);
        const V4 onB = pB + ToWorld4(simd4::Make(kept.onB[k]), b4);
        ManifoldPoint& p = out->points[k];
        p.separation = simd4::Dot(onB - onA, n);
        // A corner (of either box) is where the fresh point would be: the other surface point is only its
        // projection as it was when kept, so the point goes half a separation from the corner. Otherwise midway.
        const std::uint32_t id = kept.id[k];
        if ((id >> 8 & 0xF0u) == kFeatureVertex)
            p.point = ToVec3(onA + n * simd4::Splat(0.5f * p.separation));
        else if ((id & 0xF0u) == kFeatureVertex)
            p.point = ToVec3(onB - n * simd4::Splat(0.5f * p.separation));
        else
            p.point = ToVec3((onA + onB) * simd4::Splat(0.5f));
        p.id = id;
    }
    return true;
}
