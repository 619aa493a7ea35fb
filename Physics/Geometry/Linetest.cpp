// Segment tests: does the closed segment [start, end] touch the (closed, solid) shape? (book ch. 10,
// docs/book-reference.md §4.2). Boxes and spheres are solids: a segment wholly inside touches them.
#include <cmath>

#include "Math/Compare.h"
#include "Physics/Geometry/Geometry3D.h"

/// Defined in Raycast.cpp: the barycentric inside test shared by the triangle raycast and line test.
bool InsideBarycentric(const vec3& weights);

namespace {

/// Below this squared length (the repo's Linetest(OBB) guard) a segment is tested as its start point.
constexpr float kPointSegmentSq = 1e-7f;

/// Segment against a solid box through its raycast. An origin inside (or on) the box touches it even when the
/// exit lies beyond the end, which the book's "t <= length" rule misses (see docs/ERRATA.md, Raycasts R-1).
template <typename Box>
bool SegmentTouchesBox(const Box& box, const Line& line, bool (*pointInside)(const Point&, const Box&)) {
    const float lenSq = LengthSq(line);
    if (lenSq < kPointSegmentSq) return pointInside(line.start, box);
    if (pointInside(line.start, box)) return true;
    RaycastResult result;
    if (!Raycast(box, Ray(line.start, line.end - line.start), &result)) return false;
    return result.t >= 0.0f && result.t * result.t <= lenSq;
}

/// 2D cross product of (b - a) and (c - a).
float Orient2D(const vec2& a, const vec2& b, const vec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// Closed 2D segment intersection through orientation signs (collinear overlaps included).
bool Segments2DTouch(const vec2& p1, const vec2& p2, const vec2& q1, const vec2& q2) {
    const float d1 = Orient2D(q1, q2, p1), d2 = Orient2D(q1, q2, p2);
    const float d3 = Orient2D(p1, p2, q1), d4 = Orient2D(p1, p2, q2);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    auto onSegment = [](const vec2& a, const vec2& b, const vec2& p) {
        return std::fmin(a.x, b.x) <= p.x && p.x <= std::fmax(a.x, b.x) && std::fmin(a.y, b.y) <= p.y &&
               p.y <= std::fmax(a.y, b.y);
    };
    return (d1 == 0 && onSegment(q1, q2, p1)) || (d2 == 0 && onSegment(q1, q2, p2)) ||
           (d3 == 0 && onSegment(p1, p2, q1)) || (d4 == 0 && onSegment(p1, p2, q2));
}

/// A segment lying in the triangle's plane: an end inside the triangle, or a crossing with an edge.
bool CoplanarSegmentTouchesTriangle(const Triangle& triangle, const vec3& normal, const Line& line) {
    int drop = 0;
    if (std::fabs(normal.y) > std::fabs(normal[drop])) drop = 1;
    if (std::fabs(normal.z) > std::fabs(normal[drop])) drop = 2;
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;
    auto flat = [u, v](const Point& p) { return vec2(p[u], p[v]); };
    const vec2 a = flat(triangle.a), b = flat(triangle.b), c = flat(triangle.c);
    const vec2 s = flat(line.start), e = flat(line.end);
    const float area = Orient2D(a, b, c);
    auto inside = [&](const vec2& p) {
        const float w0 = Orient2D(b, c, p), w1 = Orient2D(c, a, p), w2 = Orient2D(a, b, p);
        return area > 0 ? (w0 >= 0 && w1 >= 0 && w2 >= 0) : (w0 <= 0 && w1 <= 0 && w2 <= 0);
    };
    if (inside(s) || inside(e)) return true;
    return Segments2DTouch(s, e, a, b) || Segments2DTouch(s, e, b, c) || Segments2DTouch(s, e, c, a);
}

}  // namespace

/// Closest point on the segment within the radius (book).
bool Linetest(const Sphere& sphere, const Line& line) {
    const Point closest = ClosestPoint(line, sphere.position);
    return DistanceSq(sphere.position, closest) <= sphere.radius * sphere.radius;
}

/// Raycast from start toward end, t <= length; a zero-length segment (or a start inside) tests PointInAABB.
bool Linetest(const AABB& aabb, const Line& line) { return SegmentTouchesBox<AABB>(aabb, line, &PointInAABB); }

/// erratum 5.1-5: a zero-length segment tests PointInOBB(start) instead of raycasting a NaN direction.
bool Linetest(const OBB& obb, const Line& line) { return SegmentTouchesBox<OBB>(obb, line, &PointInOBB); }

/// Parametric segment-plane crossing with t in [0, 1] (book). A segment parallel to the plane touches it only
/// when it lies in it (the book returns false for every parallel segment).
bool Linetest(const Plane& plane, const Line& line) {
    const vec3 ab = line.end - line.start;
    const float nA = Dot(plane.normal, line.start);
    const float nAB = Dot(plane.normal, ab);
    if (CMP_EPS(nAB, 0.0f)) return CMP_EPS(nA, plane.distance);
    const float t = (plane.distance - nA) / nAB;
    return t >= 0.0f && t <= 1.0f;
}

/// Two-sided: the segment crosses (or touches) the triangle's plane inside the triangle. A degenerate
/// triangle is never touched. (The book raycasts the one-sided triangle, so a segment crossing from behind
/// misses; see docs/ERRATA.md, Raycasts R-2.)
bool Linetest(const Triangle& triangle, const Line& line) {
    const Plane plane = FromTriangle(triangle);
    if (MagnitudeSq(plane.normal) == 0.0f) return false;
    const vec3 ab = line.end - line.start;
    const float startSide = PlaneEquation(line.start, plane);
    const float nAB = Dot(plane.normal, ab);
    if (CMP_EPS(nAB, 0.0f)) {
        // Parallel: touches only if it lies in the plane; then a 2D segment-triangle overlap test in the plane
        // coordinates that drop the normal's largest component.
        if (!CMP_EPS(startSide, 0.0f)) return false;
        return CoplanarSegmentTouchesTriangle(triangle, plane.normal, line);
    }
    const float t = -startSide / nAB;
    if (!(t >= 0.0f && t <= 1.0f)) return false;
    const Point crossing = line.start + ab * t;
    return InsideBarycentric(Barycentric(crossing, triangle));
}
