// Raycasts against the primitive shapes (book ch. 10, updated to RaycastResult in ch. 14; docs/book-reference.md §4.2).
// Every function returns whether the ray hits; outResult (optional) receives the world-space hit point,
// a unit normal and the distance t >= 0 along the (unit) ray direction. A zero ray direction never hits.
#include <cfloat>
#include <cmath>

#include "Math/Compare.h"
#include "Physics/Geometry/Geometry3D.h"

namespace {

void WriteResult(RaycastResult* outResult, const Ray& ray, float t, const vec3& normal) {
    if (outResult == nullptr) return;
    outResult->t = t;
    outResult->hit = true;
    outResult->point = ray.origin + ray.direction * t;
    outResult->normal = normal;
}

/// One box slab in box-local terms: the origin sits at `origin` along the axis, the ray moves `dir` per unit
/// t, and the slab spans [-half, +half].
struct Slab {
    float origin;
    float dir;
    float half;
};

/// Slab test shared by AABB and OBB (book Raycast(AABB)/Raycast(OBB)). Returns the slab index and side of the
/// face the ray enters (origin outside) or leaves (origin inside, t = exit). outSign is the sign to apply to
/// the slab's axis to get the outward normal of that face.
/// erratum 5.1-2 / 5.1-3: a direction component that is CMP_EPS-zero is not divided by (the book's printed
/// code yields +-inf, or NaN when the origin lies on a slab plane; the repo's 1e-5 substitute turns a ray
/// grazing the +face into a miss while the mirror ray on the -face hits). Such a slab is a pure in/out test
/// on the origin, closed at both planes, checked per axis (the book's e.x typo compared the X offset).
bool SlabTest(const Slab* slabs, float* outT, int* outAxis, float* outSign) {
    float tEnter = -FLT_MAX, tExit = FLT_MAX;
    int enterAxis = -1, exitAxis = -1;
    float enterSign = 0.0f, exitSign = 0.0f;
    for (int i = 0; i < 3; ++i) {
        const Slab& s = slabs[i];
        if (CMP_EPS(s.dir, 0.0f)) {
            if (s.origin < -s.half || s.origin > s.half) return false;
            continue;
        }
        // Local coordinate along the axis: origin + t * dir. Entering plane is -half when moving +.
        const float tNeg = (-s.half - s.origin) / s.dir;
        const float tPos = (s.half - s.origin) / s.dir;
        const bool movingPositive = s.dir > 0.0f;
        const float tIn = movingPositive ? tNeg : tPos;
        const float tOut = movingPositive ? tPos : tNeg;
        // Ties go to the later axis, as the book's "last matching index" rule.
        if (tIn >= tEnter) {
            tEnter = tIn;
            enterAxis = i;
            enterSign = movingPositive ? -1.0f : 1.0f;
        }
        if (tOut <= tExit) {
            tExit = tOut;
            exitAxis = i;
            exitSign = movingPositive ? 1.0f : -1.0f;
        }
    }
    if (enterAxis < 0) return false;  // every component zero: the zero ray never hits
    if (tExit < 0.0f || tEnter > tExit) return false;
    if (tEnter >= 0.0f) {
        *outT = tEnter;
        *outAxis = enterAxis;
        *outSign = enterSign;
    } else {  // origin inside: report where the ray leaves, outward normal of that face (as the book)
        *outT = tExit;
        *outAxis = exitAxis;
        *outSign = exitSign;
    }
    return true;
}

bool IsZero(const vec3& v) { return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f; }

/// Barycentric slack of the triangle tests (dimensionless: a fraction of the triangle's extent).
constexpr float kBarycentricSlack = 1e-6f;

}  // namespace

/// Sphere raycast (book: e = C - o, a = e.d, b^2 = |e|^2 - a^2, f = sqrt(r^2 - b^2)).
bool Raycast(const Sphere& sphere, const Ray& ray, RaycastResult* outResult) {
    ResetRaycastResult(outResult);
    if (IsZero(ray.direction)) return false;
    const vec3 e = sphere.position - ray.origin;
    const float rSq = sphere.radius * sphere.radius;
    const float eSq = MagnitudeSq(e);
    const float a = Dot(e, ray.direction);
    const float bSq = eSq - a * a;
    // erratum 5.1-4: test before the square root (the book takes sqrt of a negative number on a miss).
    if (rSq - bSq < 0.0f) return false;
    const float f = std::sqrt(rSq - bSq);
    const float tFar = a + f;
    // erratum 5.2-7: a sphere wholly behind the origin is a miss (the book returns hit with t < 0).
    if (tFar < 0.0f) return false;
    // Origin strictly inside: the exit point. Otherwise the entry point; an origin on the surface gives 0.
    const float t = eSq < rSq ? tFar : std::fmax(a - f, 0.0f);
    const vec3 point = ray.origin + ray.direction * t;
    WriteResult(outResult, ray, t, Normalized(point - sphere.position));
    return true;
}

/// AABB slab test (book ch. 14 step 4-10) with world axes as the slab normals.
bool Raycast(const AABB& aabb, const Ray& ray, RaycastResult* outResult) {
    ResetRaycastResult(outResult);
    Slab slabs[3];
    for (int i = 0; i < 3; ++i)
        slabs[i] = {ray.origin[i] - aabb.position[i], ray.direction[i], std::fabs(aabb.size[i])};
    float t = 0.0f, sign = 0.0f;
    int axis = 0;
    if (!SlabTest(slabs, &t, &axis, &sign)) return false;
    // erratum 5.1-1: the +X and +Y normals are (1,0,0) and (0,1,0) (the book's bare "(1,0,0)" is int 0).
    vec3 normal;
    normal[axis] = sign;
    WriteResult(outResult, ray, t, normal);
    return true;
}

/// OBB slab test in the box frame (book: e = X_i . (C - o), f = X_i . d).
bool Raycast(const OBB& obb, const Ray& ray, RaycastResult* outResult) {
    ResetRaycastResult(outResult);
    vec3 axes[3];
    Slab slabs[3];
    const vec3 rel = ray.origin - obb.position;
    for (int i = 0; i < 3; ++i) {
        axes[i] = Normalized(GetRow(obb.orientation, i));
        slabs[i] = {Dot(axes[i], rel), Dot(axes[i], ray.direction), std::fabs(obb.size[i])};
    }
    float t = 0.0f, sign = 0.0f;
    int axis = 0;
    if (!SlabTest(slabs, &t, &axis, &sign)) return false;
    WriteResult(outResult, ray, t, axes[axis] * sign);
    return true;
}

/// One-sided plane raycast as the book: only rays travelling against the normal (d.n < 0) can hit.
bool Raycast(const Plane& plane, const Ray& ray, RaycastResult* outResult) {
    ResetRaycastResult(outResult);
    const float nd = Dot(ray.direction, plane.normal);
    if (nd >= 0.0f) return false;
    const float t = (plane.distance - Dot(ray.origin, plane.normal)) / nd;
    if (t < 0.0f) return false;
    WriteResult(outResult, ray, t, Normalized(plane.normal));
    return true;
}

/// Barycentric weights (for a, b, c) of p projected onto the triangle's plane; (-1,-1,-1) for a degenerate
/// triangle, so that callers testing "all in [0,1]" reject it.
vec3 Barycentric(const Point& p, const Triangle& t) {
    // Solve p - a = v*(b - a) + w*(c - a) in the least-squares sense (Gram matrix, Cramer's rule).
    const vec3 ab = t.b - t.a, ac = t.c - t.a, ap = p - t.a;
    const float d00 = Dot(ab, ab), d01 = Dot(ab, ac), d11 = Dot(ac, ac);
    const float d20 = Dot(ap, ab), d21 = Dot(ap, ac);
    const float denom = d00 * d11 - d01 * d01;
    if (!(std::fabs(denom) > 0.0f) || !std::isfinite(denom)) return vec3(-1, -1, -1);
    const float v = (d11 * d20 - d01 * d21) / denom;
    const float w = (d00 * d21 - d01 * d20) / denom;
    return vec3(1.0f - v - w, v, w);
}

/// Plane through the triangle: normal = normalize((b - a) x (c - a)), distance = normal . a (a zero normal for
/// a degenerate triangle).
Plane FromTriangle(const Triangle& t) {
    Plane result;
    result.normal = Normalized(Cross(t.b - t.a, t.c - t.a));
    result.distance = Dot(result.normal, t.a);
    return result;
}

/// True if every weight is >= -kBarycentricSlack (weights sum to 1, so none exceeds 1 + 2 * slack).
bool InsideBarycentric(const vec3& weights) {
    return weights.x >= -kBarycentricSlack && weights.y >= -kBarycentricSlack && weights.z >= -kBarycentricSlack;
}

/// Triangle raycast: one-sided plane raycast, then every barycentric weight in [0, 1] (book), with a slack of
/// 1e-6 so that a ray through a shared vertex or edge of a closed mesh cannot slip between the triangles.
bool Raycast(const Triangle& triangle, const Ray& ray, RaycastResult* outResult) {
    ResetRaycastResult(outResult);
    RaycastResult planeResult;
    if (!Raycast(FromTriangle(triangle), ray, &planeResult)) return false;
    if (!InsideBarycentric(Barycentric(planeResult.point, triangle))) return false;
    if (outResult != nullptr) *outResult = planeResult;
    return true;
}
