// Solver manifolds (docs/soft-solver.md, "Solver manifolds"): box-box by SAT over the 15 axes with a face preference,
// reference/incident face clipping in the reference box's frame with feature ids, an edge-edge single point,
// reduction to four points, and speculative points up to `margin`. Fixed-size arrays only: nothing allocates.
#include "Physics/Geometry/ContactManifold.h"

#include <cmath>

namespace {

/// Edge axes A_i x B_j with a squared length below this come from nearly parallel edges and are skipped: their
/// separation is ill-conditioned there and the face axes already cover parallel edges.
constexpr float kMinEdgeAxisSq = 1e-6f;

/// An edge axis replaces the best face axis only when its separation is larger by more than
/// kEdgeRelTolerance * |face separation| + kEdgeAbsTolerance, so resting boxes keep their face contacts (and ids).
constexpr float kEdgeRelTolerance = 0.05f;
constexpr float kEdgeAbsTolerance = 0.005f;  // m
/// B's face is the reference only when its separation beats A's by more than this (m), so the choice does not
/// flicker between the two boxes when both faces are equally good (two boxes stacked face on face).
constexpr float kFaceBTolerance = 0.0005f;  // m

/// Vertices of a clipped polygon: the incident quad gains at most one vertex per side plane.
constexpr int kMaxPolygon = 16;

/// A box with its axes taken out of the matrix once per call.
struct Box {
    vec3 c;
    vec3 axis[3];
    float e[3];
};

Box MakeBox(const OBB& o) {
    Box b;
    b.c = o.position;
    for (int i = 0; i < 3; ++i) {
        b.axis[i] = vec3(o.orientation[i][0], o.orientation[i][1], o.orientation[i][2]);
        b.e[i] = o.size[i];
    }
    return b;
}

inline std::uint32_t Neg(float sign) { return sign < 0.0f ? 1u : 0u; }
/// Face 2 * axis (+1 on the negative side): the order of GetPlanes.
inline std::uint32_t FaceFeature(int axis, float sign) { return kFeatureFace | (2u * axis + Neg(sign)); }
/// Edge 4 * axis + (2 if the next axis is negative) + (1 if the one after is negative), axes in cyclic order.
inline std::uint32_t EdgeFeature(int axis, float s1, float s2) {
    return kFeatureEdge | (4u * axis + 2u * Neg(s1) + Neg(s2));
}
/// Vertex with bit i set when it lies on the negative side of axis i.
inline std::uint32_t VertexFeature(const float s[3]) {
    return kFeatureVertex | (Neg(s[0]) | 2u * Neg(s[1]) | 4u * Neg(s[2]));
}

/// Side plane of the reference box as a polygon-edge tag: bit 7, axis in bits 1-2, bit 0 the negative side.
constexpr std::uint32_t kSideTag = 0x80u;

struct ClipVertex {
    float p[3];                ///< in the reference frame: x, y along the reference face, z along its normal
                               ///< (plain floats: the clip buffers are not zeroed on every call)
    std::uint32_t refFeature;  ///< feature of the reference box that made this point
    std::uint32_t incFeature;  ///< feature of the incident box
    std::uint32_t inEdge;      ///< the polygon edge ending here: an incident box edge feature, or kSideTag | side
};

/// The reference box's face: axis r with outward sign; sides run along axes u and v.
struct RefFace {
    int r;
    float sign;
    std::uint32_t incFace;  ///< incident face feature
};

/// Clips `in` (count n) against the side plane  sideSign * p[k] <= extent, k = 0 for the reference axis
/// `sideAxis` along x, 1 along y.
int ClipSide(const ClipVertex* in, int n, int k, int sideAxis, float sideSign, float extent, const RefFace& face,
             ClipVertex* out) {
    if (n == 0) return 0;
    int m = 0;
    const std::uint32_t sideTag = kSideTag | (2u * sideAxis + Neg(sideSign));
    const ClipVertex* prev = &in[n - 1];
    float dPrev = sideSign * prev->p[k] - extent;
    for (int i = 0; i < n && m + 2 <= kMaxPolygon; ++i) {
        const ClipVertex* cur = &in[i];
        const float dCur = sideSign * cur->p[k] - extent;
        const bool prevIn = dPrev <= 0.0f;
        const bool curIn = dCur <= 0.0f;
        if (prevIn != curIn) {
            // Leaving: the crossing ends the edge that came from inside (skipped if prev lies on the plane).
            // Entering: the polygon runs along the side plane up to the crossing (none if cur lies on the plane),
            // then on along the edge. The crossing is written in place: a vertex built on the stack and then
            // copied is read back in wider pieces than it was written, which stalls.
            if (prevIn ? dPrev < 0.0f : dCur < 0.0f) {
                ClipVertex& x = out[m++];
                const float t = dPrev / (dPrev - dCur);
                for (int c = 0; c < 3; ++c) x.p[c] = prev->p[c] + (cur->p[c] - prev->p[c]) * t;
                x.p[k] = sideSign * extent;  // exactly on the side plane
                if (cur->inEdge & kSideTag) {
                    // Along another side plane into this one: a corner of the reference face, on the incident face.
                    float signs[3];
                    signs[face.r] = face.sign;
                    signs[sideAxis] = sideSign;
                    const int other = static_cast<int>((cur->inEdge >> 1) & 3u);
                    signs[other] = (cur->inEdge & 1u) ? -1.0f : 1.0f;
                    x.refFeature = VertexFeature(signs);
                    x.incFeature = face.incFace;
                } else {
                    // An incident edge through a side plane: that edge against the reference face's rim edge.
                    const int w = 3 - face.r - sideAxis;  // the rim edge runs along the third axis
                    const float sw1 = ((w + 1) % 3 == face.r) ? face.sign : sideSign;
                    const float sw2 = ((w + 2) % 3 == face.r) ? face.sign : sideSign;
                    x.refFeature = EdgeFeature(w, sw1, sw2);
                    x.incFeature = cur->inEdge;
                }
                x.inEdge = prevIn ? cur->inEdge : sideTag;
                if (!prevIn) out[m++] = *cur;
            } else if (!prevIn) {
                out[m] = *cur;
                out[m].inEdge = sideTag;
                ++m;
            }
        } else if (curIn) {
            out[m++] = *cur;
        }
        prev = cur;
        dPrev = dCur;
    }
    return m;
}

/// Keeps the deepest point, the one farthest from it, the one making the largest triangle and the one adding the
/// largest area to that triangle (in that order). `n` > kMaxManifoldPoints. A later candidate replaces the best so
/// far only when it is better by the slops below, so near ties (a flat stack: every point equally deep) go to the
/// first in id order (CollideFaces sorts them), and the kept ids do not flip with noise from step to step.
/// The id's two feature bytes, smaller first: unchanged when A and B swap.
inline std::uint32_t SymmetricKey(std::uint32_t id) {
    const std::uint32_t a = id >> 8, b = id & 0xFFu;
    return a < b ? (a << 8 | b) : (b << 8 | a);
}

constexpr float kReduceDepthSlop = 0.001f;  // m
constexpr float kReduceRelSlop = 1.02f;     // on squared distances and areas: about 1 % in length

int ReducePoints(const ManifoldPoint* in, int n, ManifoldPoint* out) {
    int i0 = 0;
    for (int i = 1; i < n; ++i)
        if (in[i].separation < in[i0].separation - kReduceDepthSlop) i0 = i;
    const vec3 p0 = in[i0].point;
    int i1 = -1;
    float best = 0.0f;
    for (int i = 0; i < n; ++i) {
        const float d = MagnitudeSq(in[i].point - p0);
        if (i != i0 && (i1 < 0 || d > best * kReduceRelSlop)) {
            best = d;
            i1 = i;
        }
    }
    const vec3 p1 = in[i1].point;
    int i2 = -1;
    best = 0.0f;
    for (int i = 0; i < n; ++i) {
        if (i == i0 || i == i1) continue;
        const float a = MagnitudeSq(Cross(p1 - p0, in[i].point - p0));
        if (i2 < 0 || a > best * kReduceRelSlop) {
            best = a;
            i2 = i;
        }
    }
    const vec3 p2 = in[i2].point;
    const vec3 normal = Cross(p1 - p0, p2 - p0);
    // The fourth point: the one lying farthest outside any edge of the triangle (the largest added area).
    int i3 = -1;
    best = 0.0f;
    const vec3 tri[3] = {p0, p1, p2};
    for (int i = 0; i < n; ++i) {
        if (i == i0 || i == i1 || i == i2) continue;
        float added = 0.0f;
        for (int e = 0; e < 3; ++e) {
            const vec3& a = tri[e];
            const vec3& b = tri[(e + 1) % 3];
            const float s = -Dot(Cross(b - a, in[i].point - a), normal);
            if (s > added) added = s;
        }
        if (added > best * kReduceRelSlop) {
            best = added;
            i3 = i;
        }
    }
    out[0] = in[i0];
    out[1] = in[i1];
    out[2] = in[i2];
    if (i3 < 0) return 3;
    out[3] = in[i3];
    return 4;
}

/// Writes the incident quad into `quad` (4 vertices, in the reference frame of `face`: x along axis u, y along axis
/// v, z = height above the reference face): the face of `inc` whose outward normal is most anti-parallel to n, with
/// its corners' and edges' feature ids. Sets face.incFace.
void IncidentQuad(const Box& ref, const Box& inc, const vec3& n, int u, int v, RefFace* face, ClipVertex* quad) {
    int k = 0;
    float dk = Dot(inc.axis[0], n);
    for (int i = 1; i < 3; ++i) {
        const float d = Dot(inc.axis[i], n);
        if (std::fabs(d) > std::fabs(dk)) {
            k = i;
            dk = d;
        }
    }
    const float incSign = dk > 0.0f ? -1.0f : 1.0f;
    const int ku = (k + 1) % 3;
    const int kv = (k + 2) % 3;
    const vec3 faceCentre = inc.c + inc.axis[k] * (incSign * inc.e[k]);
    const vec3 du = inc.axis[ku] * inc.e[ku];
    const vec3 dv = inc.axis[kv] * inc.e[kv];

    const vec3 rel = faceCentre - ref.c;
    const vec3 cl(Dot(rel, ref.axis[u]), Dot(rel, ref.axis[v]), Dot(rel, n) - ref.e[face->r]);
    const vec3 ul(Dot(du, ref.axis[u]), Dot(du, ref.axis[v]), Dot(du, n));
    const vec3 vl(Dot(dv, ref.axis[u]), Dot(dv, ref.axis[v]), Dot(dv, n));
    face->incFace = FaceFeature(k, incSign);
    const std::uint32_t refFace = FaceFeature(face->r, face->sign);
    // Vertex q runs around the face with signs (su, sv) on axes ku, kv; edge q goes from vertex q to q + 1.
    static constexpr float kSu[4] = {1.0f, -1.0f, -1.0f, 1.0f};
    static constexpr float kSv[4] = {1.0f, 1.0f, -1.0f, -1.0f};
    for (int q = 0; q < 4; ++q) {
        float signs[3];
        signs[k] = incSign;
        signs[ku] = kSu[q];
        signs[kv] = kSv[q];
        const vec3 corner = cl + ul * kSu[q] + vl * kSv[q];
        quad[q].p[0] = corner.x;
        quad[q].p[1] = corner.y;
        quad[q].p[2] = corner.z;
        quad[q].refFeature = refFace;
        quad[q].incFeature = VertexFeature(signs);
    }
    // Edge 0 (v0 -> v1) and edge 2 (v2 -> v3) run along ku at sv = +1 / -1; edges 1 and 3 along kv at su = -1 / +1.
    // fixedSign is the sign on the face axis the edge does not run along (not k).
    auto incEdge = [&](int axis, float fixedSign) {
        const float s1 = ((axis + 1) % 3 == k) ? incSign : fixedSign;
        const float s2 = ((axis + 2) % 3 == k) ? incSign : fixedSign;
        return EdgeFeature(axis, s1, s2);
    };
    quad[1].inEdge = incEdge(ku, 1.0f);
    quad[2].inEdge = incEdge(kv, -1.0f);
    quad[3].inEdge = incEdge(ku, -1.0f);
    quad[0].inEdge = incEdge(kv, 1.0f);
}

/// The clipped points within `margin` of the reference face (count of them in `clipped`) as manifold points of
/// `out`, reduced to four when there are more. Returns the point count.
int EmitPoints(const Box& ref, const RefFace& face, int u, int v, bool refIsB, float margin, ClipVertex* clipped,
               int count, ContactManifold* out) {
    const vec3 n = ref.axis[face.r] * face.sign;
    const vec3 origin = ref.c + n * ref.e[face.r];
    int m = 0;
    for (int i = 0; i < count; ++i)
        if (clipped[i].p[2] <= margin) {
            if (m != i) clipped[m] = clipped[i];
            ++m;
        }
    // Few enough points go straight out; more go through a scratch array to the reduction (declared only on that
    // path: its points are zeroed on construction).
    auto emit = [&](ManifoldPoint* kept) {
        for (int i = 0; i < m; ++i) {
            const ClipVertex& c = clipped[i];
            ManifoldPoint& p = kept[i];
            // Midway between the reference plane (z = 0) and the incident point.
            p.point = origin + ref.axis[u] * c.p[0] + ref.axis[v] * c.p[1] + n * (0.5f * c.p[2]);
            p.separation = c.p[2];
            p.id = refIsB ? (c.incFeature << 8 | c.refFeature) : (c.refFeature << 8 | c.incFeature);
        }
    };
    if (m <= kMaxManifoldPoints) {
        emit(out->points);
        return m;
    }
    ManifoldPoint kept[kMaxPolygon];
    emit(kept);
    // Near ties in the reduction go to the first candidate: order by id (its two feature bytes as a set, the same
    // whichever box is A), not by clip order, which depends on which box gave the reference face.
    for (int i = 1; i < m; ++i) {
        const ManifoldPoint p = kept[i];
        const std::uint32_t key = SymmetricKey(p.id);
        int j = i;
        for (; j > 0 && SymmetricKey(kept[j - 1].id) > key; --j) kept[j] = kept[j - 1];
        kept[j] = p;
    }
    return ReducePoints(kept, m, out->points);
}

/// Face contact: `ref` owns the face with outward normal sign * ref.axis[r] (toward `inc`). Returns the point
/// count written to `out` (normal from A to B is set by the caller). `refIsB` only enters the ids.
int CollideFaces(const Box& ref, const Box& inc, int r, float sign, bool refIsB, float margin, ContactManifold* out) {
    const int u = (r + 1) % 3;
    const int v = (r + 2) % 3;
    const vec3 n = ref.axis[r] * sign;
    RefFace face{r, sign, 0u};
    ClipVertex bufA[kMaxPolygon];
    ClipVertex bufB[kMaxPolygon];
    IncidentQuad(ref, inc, n, u, v, &face, bufA);
    int count = 4;
    count = ClipSide(bufA, count, 0, u, 1.0f, ref.e[u], face, bufB);
    count = ClipSide(bufB, count, 0, u, -1.0f, ref.e[u], face, bufA);
    count = ClipSide(bufA, count, 1, v, 1.0f, ref.e[v], face, bufB);
    count = ClipSide(bufB, count, 1, v, -1.0f, ref.e[v], face, bufA);
    return EmitPoints(ref, face, u, v, refIsB, margin, bufA, count, out);
}

/// x clamped to [lo, hi] (plain compares: std::fmax/fmin are library calls without fast-math).
inline float Clamp(float x, float lo, float hi) { return x < lo ? lo : (x > hi ? hi : x); }

/// Closest points of segments P0 + s*d1 and Q0 + t*d2 (s, t clamped to [-1, 1]; d1, d2 are half edges).
void ClosestOnEdges(const vec3& p0, const vec3& d1, const vec3& q0, const vec3& d2, vec3* onP, vec3* onQ) {
    const vec3 r = p0 - q0;
    const float a = Dot(d1, d1);
    const float e = Dot(d2, d2);
    const float b = Dot(d1, d2);
    const float c = Dot(d1, r);
    const float f = Dot(d2, r);
    const float denom = a * e - b * b;
    // Parallel edges (denom 0) take the middle of P; zero-length edges (flat boxes) stay at their centres.
    float s = denom > 1e-12f ? (b * f - c * e) / denom : 0.0f;
    s = Clamp(s, -1.0f, 1.0f);
    float t = e > 1e-12f ? (b * s + f) / e : 0.0f;
    if (t < -1.0f || t > 1.0f) {
        t = Clamp(t, -1.0f, 1.0f);
        s = a > 1e-12f ? Clamp((b * t - c) / a, -1.0f, 1.0f) : 0.0f;
    }
    *onP = p0 + d1 * s;
    *onQ = q0 + d2 * t;
}

/// Edge-edge contact on axis n (unit, from A to B) built from A's axis i and B's axis j.
void CollideEdges(const Box& a, const Box& b, int i, int j, const vec3& n, float separation, ContactManifold* out) {
    // A's edge parallel to axis i that lies farthest along n; B's edge parallel to axis j farthest along -n.
    const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
    const float sa1 = Dot(a.axis[i1], n) >= 0.0f ? 1.0f : -1.0f;
    const float sa2 = Dot(a.axis[i2], n) >= 0.0f ? 1.0f : -1.0f;
    const float sb1 = Dot(b.axis[j1], n) <= 0.0f ? 1.0f : -1.0f;
    const float sb2 = Dot(b.axis[j2], n) <= 0.0f ? 1.0f : -1.0f;
    const vec3 pa = a.c + a.axis[i1] * (sa1 * a.e[i1]) + a.axis[i2] * (sa2 * a.e[i2]);
    const vec3 pb = b.c + b.axis[j1] * (sb1 * b.e[j1]) + b.axis[j2] * (sb2 * b.e[j2]);
    vec3 onA, onB;
    ClosestOnEdges(pa, a.axis[i] * a.e[i], pb, b.axis[j] * b.e[j], &onA, &onB);
    out->pointCount = 1;
    out->points[0].point = (onA + onB) * 0.5f;
    out->points[0].separation = separation;
    out->points[0].id = EdgeFeature(i, sa1, sa2) << 8 | EdgeFeature(j, sb1, sb2);
}

}  // namespace

namespace {

/// The SAT's outcome: the best face axis of each box, the best edge pair, and the centre offset in both frames.
struct Axes {
    float tA[3], tB[3];  // B's centre from A's, along A's and B's axes, m
    float sepA, sepB, sepE;
    int axisA, axisB, edgeI, edgeJ;  // edgeI -1: every edge pair nearly parallel
};

/// SAT over A's 3 face axes, B's 3 and the 9 edge axes (d: B's centre from A's). False as soon as one separates the
/// boxes by more than `margin`.
bool FindAxes(const Box& A, const Box& B, const vec3& d, float margin, Axes* out) {
    float R[3][3], absR[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            R[i][j] = Dot(A.axis[i], B.axis[j]);
            absR[i][j] = std::fabs(R[i][j]);
        }
    float* tA = out->tA;
    float* tB = out->tB;
    for (int i = 0; i < 3; ++i) {
        tA[i] = Dot(d, A.axis[i]);
        tB[i] = Dot(d, B.axis[i]);
    }

    // Face axes of A, then of B: separation = centre distance minus the two projected radii.
    out->sepA = -3.4e38f;
    out->axisA = 0;
    for (int i = 0; i < 3; ++i) {
        const float s = std::fabs(tA[i]) - (A.e[i] + B.e[0] * absR[i][0] + B.e[1] * absR[i][1] + B.e[2] * absR[i][2]);
        if (s > margin) return false;
        if (s > out->sepA) {
            out->sepA = s;
            out->axisA = i;
        }
    }
    out->sepB = -3.4e38f;
    out->axisB = 0;
    for (int j = 0; j < 3; ++j) {
        const float s = std::fabs(tB[j]) - (B.e[j] + A.e[0] * absR[0][j] + A.e[1] * absR[1][j] + A.e[2] * absR[2][j]);
        if (s > margin) return false;
        if (s > out->sepB) {
            out->sepB = s;
            out->axisB = j;
        }
    }
    // Edge axes A_i x B_j, written in A's frame: (A_i x B_j) = R[i1][j] A_i2 - R[i2][j] A_i1. All nine are
    // computed before any is tested, so their square roots and divisions overlap instead of waiting in turn.
    float edgeSep[9];
    for (int i = 0; i < 3; ++i) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        for (int j = 0; j < 3; ++j) {
            const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            const float lenSq = R[i1][j] * R[i1][j] + R[i2][j] * R[i2][j];
            const float dist = std::fabs(tA[i2] * R[i1][j] - tA[i1] * R[i2][j]);
            const float ra = A.e[i1] * absR[i2][j] + A.e[i2] * absR[i1][j];
            const float rb = B.e[j1] * absR[i][j2] + B.e[j2] * absR[i][j1];
            // Nearly parallel edges get -inf: never separating, never chosen.
            edgeSep[3 * i + j] = lenSq < kMinEdgeAxisSq
                                     ? -3.4e38f
                                     : (dist - ra - rb) / std::sqrt(lenSq > kMinEdgeAxisSq ? lenSq : kMinEdgeAxisSq);
        }
    }
    out->sepE = -3.4e38f;
    out->edgeI = -1;
    out->edgeJ = -1;
    for (int k = 0; k < 9; ++k) {
        if (edgeSep[k] > margin) return false;
        if (edgeSep[k] > out->sepE) {
            out->sepE = edgeSep[k];
            out->edgeI = k / 3;
            out->edgeJ = k % 3;
        }
    }
    return true;
}

}  // namespace

void CollideBoxes(const OBB& obbA, const OBB& obbB, float margin, ContactManifold* out) {
    out->pointCount = 0;
    const vec3 d = obbB.position - obbA.position;
    const float reach = std::sqrt(MagnitudeSq(obbA.size)) + std::sqrt(MagnitudeSq(obbB.size)) + margin;
    if (MagnitudeSq(d) > reach * reach) return;

    const Box A = MakeBox(obbA);
    const Box B = MakeBox(obbB);
    Axes x;
    if (!FindAxes(A, B, d, margin, &x)) return;

    const bool useB = x.sepB > x.sepA + kFaceBTolerance;
    const float sepFace = useB ? x.sepB : x.sepA;
    const bool useEdge = x.edgeI >= 0 && x.sepE > sepFace + kEdgeRelTolerance * std::fabs(sepFace) + kEdgeAbsTolerance;
    if (!useEdge) {
        if (!useB) {
            const float sign = x.tA[x.axisA] >= 0.0f ? 1.0f : -1.0f;
            out->normal = A.axis[x.axisA] * sign;
            out->pointCount = CollideFaces(A, B, x.axisA, sign, false, margin, out);
        } else {
            // B's face toward A is the reference; the normal still points from A to B.
            const float sign = x.tB[x.axisB] >= 0.0f ? -1.0f : 1.0f;
            out->normal = B.axis[x.axisB] * -sign;
            out->pointCount = CollideFaces(B, A, x.axisB, sign, true, margin, out);
        }
        // A face within margin whose clipped incident face keeps no point (edges crossing near the face's rim):
        // fall back to the best edge pair so the contact is not lost.
        if (out->pointCount > 0 || x.edgeI < 0 || x.sepE > margin) return;
    }
    vec3 n = Cross(A.axis[x.edgeI], B.axis[x.edgeJ]);
    n = n * (1.0f / std::sqrt(MagnitudeSq(n)));
    if (Dot(n, d) < 0.0f) n = -n;
    out->normal = n;
    CollideEdges(A, B, x.edgeI, x.edgeJ, n, x.sepE, out);
}

void CollideBoxSphere(const OBB& box, const Sphere& sphere, float margin, ContactManifold* out) {
    out->pointCount = 0;
    const Box A = MakeBox(box);
    const vec3 rel = sphere.position - A.c;
    float local[3];
    bool inside = true;
    vec3 closest = A.c;
    for (int i = 0; i < 3; ++i) {
        local[i] = Dot(rel, A.axis[i]);
        const float clamped = Clamp(local[i], -A.e[i], A.e[i]);
        if (clamped != local[i]) inside = false;
        closest += A.axis[i] * clamped;
    }
    vec3 normal;
    float separation;
    vec3 onBox;
    if (!inside) {
        const vec3 d = sphere.position - closest;
        const float distSq = MagnitudeSq(d);
        const float reach = sphere.radius + margin;
        if (distSq > reach * reach) return;
        const float dist = std::sqrt(distSq);
        normal = d * (1.0f / dist);
        separation = dist - sphere.radius;
        onBox = closest;
    } else {
        // Centre inside the box: leave through the face of least penetration.
        int best = 0;
        float gap = A.e[0] - std::fabs(local[0]);
        for (int i = 1; i < 3; ++i) {
            const float g = A.e[i] - std::fabs(local[i]);
            if (g < gap) {
                gap = g;
                best = i;
            }
        }
        normal = A.axis[best] * (local[best] < 0.0f ? -1.0f : 1.0f);
        separation = -(gap + sphere.radius);
        onBox = sphere.position + normal * gap;
    }
    const vec3 onSphere = sphere.position - normal * sphere.radius;
    out->normal = normal;
    out->pointCount = 1;
    out->points[0].point = (onBox + onSphere) * 0.5f;
    out->points[0].separation = separation;
    out->points[0].id = 0;
}

void CollideSpheres(const Sphere& A, const Sphere& B, float margin, ContactManifold* out) {
    out->pointCount = 0;
    const vec3 d = B.position - A.position;
    const float distSq = MagnitudeSq(d);
    const float reach = A.radius + B.radius + margin;
    if (distSq > reach * reach) return;
    const float dist = std::sqrt(distSq);
    // Coincident centres: any direction separates them; +Y as the book's manifolds choose.
    const vec3 normal = dist > 1e-6f ? d * (1.0f / dist) : vec3(0.0f, 1.0f, 0.0f);
    out->normal = normal;
    out->pointCount = 1;
    const vec3 onA = A.position + normal * A.radius;
    const vec3 onB = B.position - normal * B.radius;
    out->points[0].point = (onA + onB) * 0.5f;
    out->points[0].separation = dist - A.radius - B.radius;
    out->points[0].id = 0;
}
