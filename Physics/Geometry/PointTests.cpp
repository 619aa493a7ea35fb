// Point containment and closest-point queries (book chapter 10, "Point Tests"). All in world space.
#include <cfloat>
#include <cmath>

#include "Math/Compare.h"
#include "Physics/Geometry/Geometry3D.h"

namespace {

/// Largest of 1 and the absolute coordinates of v: the scale for relative tolerances.
float MagScale(const vec3& v) {
    return std::fmax(1.0f, std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z))));
}

/// Closest point on the segment [a, b] to p; a zero-length segment gives a.
Point ClosestOnSegment(const Point& a, const Point& b, const Point& p) {
    const vec3 ab = b - a;
    const float lenSq = MagnitudeSq(ab);
    if (!(lenSq > 0.0f)) return a;
    float t = Dot(p - a, ab) / lenSq;
    t = std::fmax(0.0f, std::fmin(1.0f, t));
    return a + ab * t;
}

/// Nearest of the three edges' closest points to p (used for degenerate triangles and points outside).
Point ClosestOnTriangleEdges(const Triangle& t, const Point& p) {
    const Point c1 = ClosestOnSegment(t.a, t.b, p);
    const Point c2 = ClosestOnSegment(t.b, t.c, p);
    const Point c3 = ClosestOnSegment(t.c, t.a, p);
    const float d1 = DistanceSq(p, c1), d2 = DistanceSq(p, c2), d3 = DistanceSq(p, c3);
    if (d1 <= d2 && d1 <= d3) return c1;
    return d2 <= d3 ? c2 : c3;
}

/// True when the triangle's area is negligible compared with its edge lengths (collinear or coincident).
bool IsDegenerate(const Triangle& t, const vec3& n) {
    const float e = std::fmax(MagnitudeSq(t.b - t.a), std::fmax(MagnitudeSq(t.c - t.b), MagnitudeSq(t.a - t.c)));
    return !(MagnitudeSq(n) > 1e-12f * e * e);
}

}  // namespace

/// True if the point is inside or on the sphere (world space); a zero radius contains only the centre.
bool PointInSphere(const Point& point, const Sphere& sphere) {
    // The book uses a strict <; the surface counts as inside here, like PointInAABB/PointInOBB.
    return DistanceSq(point, sphere.position) <= sphere.radius * sphere.radius;
}

/// True if Dot(p, n) equals the plane distance within the book's FLT_EPSILON comparison.
bool PointOnPlane(const Point& point, const Plane& plane) {
    // Book: CMP(Dot(p, n) - d, 0) with Geometry3D's FLT_EPSILON comparison, scaled by the magnitudes.
    return CMP_EPS(Dot(point, plane.normal), plane.distance);
}

/// True if the point is inside or on the box; a zero-size box contains only its centre.
bool PointInAABB(const Point& point, const AABB& aabb) {
    const vec3 mn = GetMin(aabb), mx = GetMax(aabb);
    return point.x >= mn.x && point.y >= mn.y && point.z >= mn.z && point.x <= mx.x && point.y <= mx.y &&
           point.z <= mx.z;
}

/// True if |Dot(p - C, axis_i)| <= size_i on all three axes, exact (no epsilon), as the book.
bool PointInOBB(const Point& point, const OBB& obb) {
    const vec3 dir = point - obb.position;
    for (int i = 0; i < 3; ++i) {
        const float distance = Dot(dir, GetRow(obb.orientation, i));
        if (distance > obb.size[i] || distance < -obb.size[i]) return false;
    }
    return true;
}

/// True if the point lies on the segment (squared distance within FLT_EPSILON * scale^2).
bool PointOnLine(const Point& point, const Line& line) {
    const Point closest = ClosestOnSegment(line.start, line.end, point);
    // Squared distance within the book's FLT_EPSILON test, scaled by the coordinates' magnitude.
    const float s = MagScale(point);
    return DistanceSq(closest, point) <= FLT_EPSILON * s * s;
}

/// True if the point lies on the ray at t >= 0; the origin itself counts.
bool PointOnRay(const Point& point, const Ray& ray) {
    if (point.x == ray.origin.x && point.y == ray.origin.y && point.z == ray.origin.z) return true;
    const Point closest = ClosestPoint(ray, point);
    const float s = MagScale(point);
    return DistanceSq(closest, point) <= FLT_EPSILON * s * s;
}

/// True if p lies in the triangle (on its plane, edges included); collinear corners: on a segment.
bool PointInTriangle(const Point& p, const Triangle& t) {
    const vec3 n = Cross(t.b - t.a, t.c - t.a);
    if (IsDegenerate(t, n)) {
        // Collinear corners: the triangle is the union of its edges.
        const float s = MagScale(p);
        return DistanceSq(ClosestOnTriangleEdges(t, p), p) <= FLT_EPSILON * s * s;
    }
    const float nn = MagnitudeSq(n);
    // Off the plane: not in the triangle (the book's version skips this and accepts any point of the prism).
    const float planeDist = Dot(p - t.a, n) / std::sqrt(nn);
    if (std::fabs(planeDist) > 1e-5f * MagScale(p)) return false;
    // Book's construction: the sub-triangles' normals (b-p)x(c-p), (c-p)x(a-p), (a-p)x(b-p) all face like n
    // when p is inside. Their dot products with n are the barycentric weights times |n|^2.
    const vec3 a = t.a - p, b = t.b - p, c = t.c - p;
    const float slack = -1e-6f * nn;  // points rounded onto an edge still count
    return Dot(Cross(b, c), n) >= slack && Dot(Cross(c, a), n) >= slack && Dot(Cross(a, b), n) >= slack;
}

/// Nearest point of the sphere SURFACE; for the centre itself, the +X surface point.
Point ClosestPoint(const Sphere& sphere, const Point& point) {
    vec3 dir = Normalized(point - sphere.position);
    // Coincident with the centre: every surface point is equally close; pick the +X one.
    if (MagnitudeSq(dir) == 0.0f) dir = vec3(1, 0, 0);
    return sphere.position + dir * sphere.radius;
}

/// Nearest point of the solid box: each axis clamped to its own range (erratum 5.2-9).
Point ClosestPoint(const AABB& aabb, const Point& point) {
    // Erratum 5.2-9: the book clamps y and z against min.x / max.x; clamp each axis to its own range.
    const vec3 mn = GetMin(aabb), mx = GetMax(aabb);
    Point r = point;
    for (int i = 0; i < 3; ++i) r[i] = std::fmax(mn[i], std::fmin(mx[i], r[i]));
    return r;
}

/// Nearest point of the solid box: local coordinates clamped to +-size (axes assumed unit).
Point ClosestPoint(const OBB& obb, const Point& point) {
    Point result = obb.position;
    const vec3 dir = point - obb.position;
    for (int i = 0; i < 3; ++i) {
        const vec3 axis = GetRow(obb.orientation, i);
        float distance = Dot(dir, axis);
        distance = std::fmax(-obb.size[i], std::fmin(obb.size[i], distance));
        result += axis * distance;
    }
    return result;
}

/// Orthogonal projection onto the plane (any nonzero normal length); a zero normal returns the point.
Point ClosestPoint(const Plane& plane, const Point& point) {
    // Book: p - n (Dot(n, p) - d) for a unit n; dividing by |n|^2 also serves non-unit normals.
    const float nn = MagnitudeSq(plane.normal);
    if (!(nn > 0.0f)) return point;
    return point - plane.normal * ((Dot(plane.normal, point) - plane.distance) / nn);
}

/// Nearest point of the segment (t clamped to [0, 1]); a zero-length segment gives its start.
Point ClosestPoint(const Line& line, const Point& point) { return ClosestOnSegment(line.start, line.end, point); }

/// Nearest point of the ray (t clamped to >= 0); a zero direction gives the origin.
Point ClosestPoint(const Ray& ray, const Point& point) {
    const float dd = MagnitudeSq(ray.direction);
    if (!(dd > 0.0f)) return ray.origin;
    const float t = std::fmax(0.0f, Dot(point - ray.origin, ray.direction) / dd);
    return ray.origin + ray.direction * t;
}

/// Nearest point of the solid triangle; a degenerate one is treated as its edges.
Point ClosestPoint(const Triangle& t, const Point& p) {
    const vec3 n = Cross(t.b - t.a, t.c - t.a);
    if (IsDegenerate(t, n)) return ClosestOnTriangleEdges(t, p);
    // Book: project onto the plane; inside -> that point, else the nearest of the three edge points.
    const Point onPlane = p - n * (Dot(p - t.a, n) / MagnitudeSq(n));
    if (PointInTriangle(onPlane, t)) return onPlane;
    return ClosestOnTriangleEdges(t, p);
}
