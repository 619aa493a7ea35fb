// Box features for SAT and contact generation (book ch.15 "Manifold for boxes"): corners, edges, face
// planes, segment/plane clipping and the per-axis penetration depth. World space throughout. Fixed-size
// arrays and a caller-owned output vector, so nothing here allocates on its own.
#include <algorithm>
#include <cmath>

#include "Math/Compare.h"
#include "Physics/Geometry/Geometry3D.h"

namespace {

/// Slack for "is the clipped point inside the box". A point clipped to a face plane lies on that face, and
/// float rounding can put it a hair outside, where an exact test would drop it (erratum 5.2-5). 1e-4 world
/// units for boxes up to unit half size, growing with the largest half extent (rounding grows with it).
float ClipTolerance(const OBB& obb) {
    const float largest = std::max({1.0f, std::fabs(obb.size.x), std::fabs(obb.size.y), std::fabs(obb.size.z)});
    return 1e-4f * largest;
}

/// PointInOBB with every half extent grown by `slack`.
bool PointInOBBWithin(const Point& point, const OBB& obb, float slack) {
    const vec3 dir = point - obb.position;
    for (int i = 0; i < 3; ++i) {
        if (std::fabs(Dot(dir, GetRow(obb.orientation, i))) > obb.size[i] + slack) return false;
    }
    return true;
}

}  // namespace

std::array<Point, 8> GetVertices(const OBB& obb) {
    const vec3 c = obb.position;
    const vec3 x = GetRow(obb.orientation, 0) * obb.size.x;
    const vec3 y = GetRow(obb.orientation, 1) * obb.size.y;
    const vec3 z = GetRow(obb.orientation, 2) * obb.size.z;
    // The book's corner order (section 3.5); GetEdges indexes into it.
    return {c + x + y + z, c - x + y + z, c + x - y + z, c + x + y - z,
            c - x - y - z, c + x - y - z, c - x + y - z, c - x - y + z};
}

std::array<Line, 12> GetEdges(const OBB& obb) {
    static constexpr int kIndex[12][2] = {{6, 1}, {6, 3}, {6, 4}, {2, 7}, {2, 5}, {2, 0},
                                          {0, 1}, {0, 3}, {7, 1}, {7, 4}, {4, 5}, {5, 3}};
    const std::array<Point, 8> v = GetVertices(obb);
    std::array<Line, 12> edges;
    for (int i = 0; i < 12; ++i) edges[i] = Line(v[kIndex[i][0]], v[kIndex[i][1]]);
    return edges;
}

std::array<Plane, 6> GetPlanes(const OBB& obb) {
    std::array<Plane, 6> planes;
    for (int i = 0; i < 3; ++i) {
        const vec3 axis = GetRow(obb.orientation, i);
        const float centre = Dot(axis, obb.position);
        // Face +axis_i passes through C + axis_i*size_i, face -axis_i through C - axis_i*size_i.
        planes[2 * i] = Plane(axis, centre + obb.size[i]);
        planes[2 * i + 1] = Plane(-axis, -centre + obb.size[i]);
    }
    return planes;
}

bool ClipToPlane(const Plane& plane, const Line& line, Point* outPoint) {
    const vec3 ab = line.end - line.start;
    const float nAB = Dot(plane.normal, ab);
    if (CMP_EPS(nAB, 0.0f)) return false;  // parallel to the plane (or zero length)
    const float t = (plane.distance - Dot(plane.normal, line.start)) / nAB;
    if (t < 0.0f || t > 1.0f) return false;
    if (outPoint != nullptr) *outPoint = line.start + ab * t;
    return true;
}

void ClipEdgesToOBB(const std::array<Line, 12>& edges, const OBB& obb, std::vector<Point>* out) {
    if (out == nullptr) return;
    // Erratum 5.2-4: the book binds a non-const reference to the temporary GetPlanes() result; held by value.
    const std::array<Plane, 6> planes = GetPlanes(obb);
    const float slack = ClipTolerance(obb);
    Point intersection;
    for (const Plane& plane : planes) {
        for (const Line& edge : edges) {
            // Erratum 5.2-5: a tolerant PointInOBB keeps points that rounding puts just outside the face.
            if (ClipToPlane(plane, edge, &intersection) && PointInOBBWithin(intersection, obb, slack))
                out->push_back(intersection);
        }
    }
}

float PenetrationDepth(const OBB& o1, const OBB& o2, const vec3& axis, bool* outShouldFlip) {
    const vec3 n = Normalized(axis);
    const Interval i1 = GetInterval(o1, n);
    const Interval i2 = GetInterval(o2, n);
    if (!(i2.min <= i1.max && i1.min <= i2.max)) return 0.0f;  // separated on this axis
    const bool strictlyContained = (i2.min > i1.min && i2.max < i1.max) || (i1.min > i2.min && i1.max < i2.max);
    if (!strictlyContained) {
        // Book: sum of the lengths minus the combined span = width of the overlap; flip when B starts first.
        const float len1 = i1.max - i1.min;
        const float len2 = i2.max - i2.min;
        const float span = std::max(i1.max, i2.max) - std::min(i1.min, i2.min);
        if (outShouldFlip != nullptr) *outShouldFlip = i2.min < i1.min;
        return (len1 + len2) - span;
    }
    // One interval strictly inside the other: the book returns the inner width and a side that can point the
    // long way out, so a small box sunk into a slab gets a sideways normal and falls through it. Use the
    // minimum translation instead: the distance B must move along +n or -n to separate, and that side.
    const float pushPlus = i1.max - i2.min;
    const float pushMinus = i2.max - i1.min;
    if (outShouldFlip != nullptr) *outShouldFlip = pushMinus < pushPlus;
    return std::min(pushPlus, pushMinus);
}
