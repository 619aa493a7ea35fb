// Shape-pair intersection tests of book chapters 9 (spheres, boxes, planes) and 11 (triangles).
// Boolean queries in world space; touching shapes count as intersecting except where noted (sphere tests
// use the book's strict <). Box and triangle pairs use the separating axis test (SAT).
#include <cmath>

#include "Math/Compare.h"
#include "Physics/Geometry/Geometry3D.h"

namespace {

/// Cross products shorter than this (squared, relative to the inputs' squared lengths) are parallel edges:
/// their axis is skipped. Exactly parallel edges need no axis of their own (the face axes cover that case);
/// a very short but nonzero cross product is still a valid test axis, so the threshold can be tiny.
constexpr float kParallelSq = 1e-12f;

bool UsableAxis(const vec3& axis, float scaleSq) { return MagnitudeSq(axis) > kParallelSq * scaleSq; }

/// The three orientation rows (local axes in world space).
void Axes(const mat3& m, vec3 out[3]) {
    for (int i = 0; i < 3; ++i) out[i] = GetRow(m, i);
}

bool Overlap(const Interval& a, const Interval& b) { return b.min <= a.max && a.min <= b.max; }

/// Interval of a box given by centre, half sizes and unit axes: centre +- sum |size_i (axis_i . axis)|.
/// Equal to the min/max over the 8 corners (each corner picks the sign that extends the projection).
Interval BoxInterval(const vec3& centre, const vec3& size, const vec3 axes[3], const vec3& axis) {
    const float c = Dot(centre, axis);
    const float r = std::fabs(size.x * Dot(axes[0], axis)) + std::fabs(size.y * Dot(axes[1], axis)) +
                    std::fabs(size.z * Dot(axes[2], axis));
    return {c - r, c + r};
}

/// SAT between two boxes: 3 face axes of each and the 9 edge-edge axes A_i x B_j (erratum 5.2-2: the book
/// crosses A's axes with A's own axes, so edge-edge separations are never found).
bool BoxBox(const vec3& ca, const vec3& sa, const vec3 a[3], const vec3& cb, const vec3& sb, const vec3 b[3]) {
    vec3 test[15];
    int count = 0;
    for (int i = 0; i < 3; ++i) test[count++] = a[i];
    for (int i = 0; i < 3; ++i) test[count++] = b[i];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const vec3 axis = Cross(a[i], b[j]);
            if (UsableAxis(axis, MagnitudeSq(a[i]) * MagnitudeSq(b[j]))) test[count++] = axis;
        }
    for (int k = 0; k < count; ++k)
        if (!Overlap(BoxInterval(ca, sa, a, test[k]), BoxInterval(cb, sb, b, test[k]))) return false;
    return true;
}

/// SAT between a triangle and a box: the box's 3 face axes, the triangle normal, and the 9 crosses of box
/// axes with triangle edges. Degenerate (zero) axes are skipped: a collinear triangle is then tested as a
/// segment, which the box axes and edge crosses cover.
bool TriangleBox(const Triangle& t, const vec3& centre, const vec3& size, const vec3 axes[3]) {
    const vec3 e[3] = {t.b - t.a, t.c - t.b, t.a - t.c};
    vec3 test[13];
    int count = 0;
    for (int i = 0; i < 3; ++i) test[count++] = axes[i];
    const vec3 n = Cross(e[0], e[1]);
    if (UsableAxis(n, MagnitudeSq(e[0]) * MagnitudeSq(e[1]))) test[count++] = n;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const vec3 axis = Cross(axes[i], e[j]);
            if (UsableAxis(axis, MagnitudeSq(axes[i]) * MagnitudeSq(e[j]))) test[count++] = axis;
        }
    for (int k = 0; k < count; ++k)
        if (!Overlap(GetInterval(t, test[k]), BoxInterval(centre, size, axes, test[k]))) return false;
    return true;
}

}  // namespace

/// True if the spheres overlap; touching (distance == r1 + r2) is not overlapping.
bool SphereSphere(const Sphere& s1, const Sphere& s2) {
    const float radii = s1.radius + s2.radius;
    return DistanceSq(s1.position, s2.position) < radii * radii;
}

/// True if the box comes strictly closer than the radius to the centre (touching is false).
bool SphereAABB(const Sphere& sphere, const AABB& aabb) {
    const Point closest = ClosestPoint(aabb, sphere.position);
    return DistanceSq(sphere.position, closest) < sphere.radius * sphere.radius;
}

/// True if the box comes strictly closer than the radius to the centre (touching is false).
bool SphereOBB(const Sphere& sphere, const OBB& obb) {
    const Point closest = ClosestPoint(obb, sphere.position);
    return DistanceSq(sphere.position, closest) < sphere.radius * sphere.radius;
}

/// True if the centre is strictly closer than the radius to the plane (unit normal assumed).
bool SpherePlane(const Sphere& sphere, const Plane& plane) {
    const Point closest = ClosestPoint(plane, sphere.position);
    return DistanceSq(sphere.position, closest) < sphere.radius * sphere.radius;
}

/// True if the boxes overlap or touch on every world axis.
bool AABBAABB(const AABB& aabb1, const AABB& aabb2) {
    const vec3 aMin = GetMin(aabb1), aMax = GetMax(aabb1);
    const vec3 bMin = GetMin(aabb2), bMax = GetMax(aabb2);
    return aMin.x <= bMax.x && aMax.x >= bMin.x && aMin.y <= bMax.y && aMax.y >= bMin.y && aMin.z <= bMax.z &&
           aMax.z >= bMin.z;
}

/// SAT over 15 axes (3 + 3 face axes, 9 edge crosses A x B); touching counts as intersecting.
bool AABBOBB(const AABB& aabb, const OBB& obb) {
    const vec3 a[3] = {vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1)};
    vec3 b[3];
    Axes(obb.orientation, b);
    return BoxBox(aabb.position, aabb.size, a, obb.position, obb.size, b);
}

/// True if the plane passes through or touches the box (unit normal assumed).
bool AABBPlane(const AABB& aabb, const Plane& plane) {
    // Book: the box's projected half length on the normal against the centre's signed plane distance.
    const float pLen = aabb.size.x * std::fabs(plane.normal.x) + aabb.size.y * std::fabs(plane.normal.y) +
                       aabb.size.z * std::fabs(plane.normal.z);
    return std::fabs(Dot(plane.normal, aabb.position) - plane.distance) <= pLen;
}

/// SAT over 15 axes (3 + 3 face axes, 9 edge crosses A x B); touching counts as intersecting.
bool OBBOBB(const OBB& obb1, const OBB& obb2) {
    vec3 a[3], b[3];
    Axes(obb1.orientation, a);
    Axes(obb2.orientation, b);
    return BoxBox(obb1.position, obb1.size, a, obb2.position, obb2.size, b);
}

/// True if the plane passes through or touches the box (unit normal assumed).
bool OBBPlane(const OBB& obb, const Plane& plane) {
    vec3 a[3];
    Axes(obb.orientation, a);
    const float pLen = obb.size.x * std::fabs(Dot(plane.normal, a[0])) +
                       obb.size.y * std::fabs(Dot(plane.normal, a[1])) +
                       obb.size.z * std::fabs(Dot(plane.normal, a[2]));
    return std::fabs(Dot(plane.normal, obb.position) - plane.distance) <= pLen;
}

/// True unless the planes are parallel and distinct (coincident planes intersect).
bool PlanePlane(const Plane& plane1, const Plane& plane2) {
    const vec3 d = Cross(plane1.normal, plane2.normal);
    const float scaleSq = MagnitudeSq(plane1.normal) * MagnitudeSq(plane2.normal);
    if (UsableAxis(d, scaleSq)) return true;  // not parallel: they meet in a line
    // Parallel. The book returns false here; coincident planes do intersect, so compare the offsets of the
    // normalised equations (normals may point opposite ways).
    const float l1 = Magnitude(plane1.normal), l2 = Magnitude(plane2.normal);
    if (!(l1 > 0.0f) || !(l2 > 0.0f)) return false;
    const float sign = Dot(plane1.normal, plane2.normal) < 0.0f ? -1.0f : 1.0f;
    return CMP_EPS(plane1.distance / l1, sign * plane2.distance / l2);
}

/// Min and max of Dot(corner, axis) over the 8 corners (axis not normalised).
Interval GetInterval(const AABB& aabb, const vec3& axis) {
    const vec3 a[3] = {vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1)};
    return BoxInterval(aabb.position, aabb.size, a, axis);
}

/// Min and max of Dot(corner, axis) over the 8 corners (axis not normalised).
Interval GetInterval(const OBB& obb, const vec3& axis) {
    vec3 a[3];
    Axes(obb.orientation, a);
    return BoxInterval(obb.position, obb.size, a, axis);
}

/// Min and max of Dot(vertex, axis) over the 3 vertices (axis not normalised).
Interval GetInterval(const Triangle& triangle, const vec3& axis) {
    Interval r;
    r.min = r.max = Dot(triangle.a, axis);
    for (const Point* p : {&triangle.b, &triangle.c}) {
        const float v = Dot(*p, axis);
        r.min = std::fmin(r.min, v);
        r.max = std::fmax(r.max, v);
    }
    return r;
}

/// True if the two projections onto axis overlap or touch.
bool OverlapOnAxis(const AABB& aabb, const OBB& obb, const vec3& axis) {
    return Overlap(GetInterval(aabb, axis), GetInterval(obb, axis));
}

/// True if the two boxes' projections onto axis overlap or touch (erratum 5.2-8).
bool OverlapOnAxis(const OBB& obb1, const OBB& obb2, const vec3& axis) {
    // Erratum 5.2-8: the book projects obb1 twice, so every axis overlaps and OBBOBB is always true.
    return Overlap(GetInterval(obb1, axis), GetInterval(obb2, axis));
}

/// True if the two projections onto axis overlap or touch.
bool OverlapOnAxis(const AABB& aabb, const Triangle& triangle, const vec3& axis) {
    return Overlap(GetInterval(aabb, axis), GetInterval(triangle, axis));
}

/// True if the two projections onto axis overlap or touch.
bool OverlapOnAxis(const OBB& obb, const Triangle& triangle, const vec3& axis) {
    return Overlap(GetInterval(obb, axis), GetInterval(triangle, axis));
}

/// True if the two projections onto axis overlap or touch.
bool OverlapOnAxis(const Triangle& t1, const Triangle& t2, const vec3& axis) {
    return Overlap(GetInterval(t1, axis), GetInterval(t2, axis));
}

/// True if the triangle comes within the radius of the centre (touching included, as the book).
bool TriangleSphere(const Triangle& t, const Sphere& s) {
    const Point closest = ClosestPoint(t, s.position);
    return DistanceSq(closest, s.position) <= s.radius * s.radius;
}

/// SAT over 13 axes (box axes, triangle normal, box axis x edge); degenerate axes skipped.
bool TriangleAABB(const Triangle& t, const AABB& a) {
    const vec3 axes[3] = {vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1)};
    return TriangleBox(t, a.position, a.size, axes);
}

/// SAT over 13 axes (box axes, triangle normal, box axis x edge); degenerate axes skipped.
bool TriangleOBB(const Triangle& t, const OBB& o) {
    vec3 axes[3];
    Axes(o.orientation, axes);
    return TriangleBox(t, o.position, o.size, axes);
}

/// True if the triangle touches or crosses the plane (or lies in it).
bool TrianglePlane(const Triangle& t, const Plane& p) {
    const float s1 = PlaneEquation(t.a, p), s2 = PlaneEquation(t.b, p), s3 = PlaneEquation(t.c, p);
    if (CMP_EPS(s1, 0.0f) && CMP_EPS(s2, 0.0f) && CMP_EPS(s3, 0.0f)) return true;  // lies in the plane
    if (s1 > 0.0f && s2 > 0.0f && s3 > 0.0f) return false;
    if (s1 < 0.0f && s2 < 0.0f && s3 < 0.0f) return false;
    return true;
}

/// SAT over normals, edge crosses and in-plane edge normals; coplanar and degenerate safe.
bool TriangleTriangle(const Triangle& t1, const Triangle& t2) {
    // Book axes: both normals and the 9 edge crosses. Coplanar triangles make every edge cross parallel to
    // the shared normal, so the book misses in-plane separations; the in-plane edge normals n x e of both
    // triangles (with either normal, which also covers a degenerate triangle) are added. Extra axes can
    // only find real separations, never invent them.
    const vec3 e1[3] = {t1.b - t1.a, t1.c - t1.b, t1.a - t1.c};
    const vec3 e2[3] = {t2.b - t2.a, t2.c - t2.b, t2.a - t2.c};
    const vec3 n1 = Cross(e1[0], e1[1]);
    const vec3 n2 = Cross(e2[0], e2[1]);
    vec3 test[23];
    int count = 0;
    auto add = [&](const vec3& axis, float scaleSq) {
        if (UsableAxis(axis, scaleSq)) test[count++] = axis;
    };
    add(n1, MagnitudeSq(e1[0]) * MagnitudeSq(e1[1]));
    add(n2, MagnitudeSq(e2[0]) * MagnitudeSq(e2[1]));
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) add(Cross(e1[i], e2[j]), MagnitudeSq(e1[i]) * MagnitudeSq(e2[j]));
    for (const vec3& n : {n1, n2})
        for (int i = 0; i < 3; ++i) {
            add(Cross(n, e1[i]), MagnitudeSq(n) * MagnitudeSq(e1[i]));
            add(Cross(n, e2[i]), MagnitudeSq(n) * MagnitudeSq(e2[i]));
        }
    for (int k = 0; k < count; ++k)
        if (!OverlapOnAxis(t1, t2, test[k])) return false;
    return true;
}
