// Collision manifolds of book ch.15 (sphere-sphere, OBB-sphere, OBB-OBB). World space; the normal is a unit
// vector pointing from A to B. `depth` is the whole penetration for every pair: how far B must move along the
// normal to stop touching A (the book reports half of it for sphere pairs and the whole for boxes; docs/STYLE.md,
// "Renames in the engine"). Every colliding manifold has at least one
// contact and only finite numbers, including for coincident centres and boxes inside boxes.
#include <algorithm>
#include <cmath>

#include "Math/Compare.h"
#include "Physics/Geometry/Geometry3D.h"

namespace {

/// Normal used when the centres coincide and no direction can be derived from the geometry.
const vec3 kFallbackNormal(0, 1, 0);

/// Cross products of edge axes with |A_i x B_j|^2 below this are nearly parallel edges and are skipped
/// (book threshold; the face axes cover parallel edges).
constexpr float kMinAxisSq = 0.001f;

/// Contacts closer than this (squared) are one contact (book value 0.0001, i.e. 1 cm).
constexpr float kDuplicateSq = 0.0001f;

/// Removes near-duplicates in place, keeping the first of each cluster; keeps the vector's capacity.
void RemoveDuplicates(std::vector<vec3>* points) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < points->size(); ++i) {
        const vec3 p = (*points)[i];
        bool duplicate = false;
        for (std::size_t j = 0; j < kept && !duplicate; ++j) duplicate = DistanceSq(p, (*points)[j]) < kDuplicateSq;
        if (!duplicate) (*points)[kept++] = p;
    }
    points->resize(kept);
}

/// Appends the corners of `box` that lie inside `other` (slack 1e-4 per half extent).
void AppendCornersInside(const OBB& box, const OBB& other, std::vector<vec3>* out) {
    for (const Point& v : GetVertices(box)) {
        const vec3 d = v - other.position;
        bool inside = true;
        for (int i = 0; i < 3 && inside; ++i)
            inside = std::fabs(Dot(d, GetRow(other.orientation, i))) <= other.size[i] + 1e-4f;
        if (inside) out->push_back(v);
    }
}

/// The corner of `box` furthest along `direction`.
Point SupportVertex(const OBB& box, const vec3& direction) {
    Point p = box.position;
    for (int i = 0; i < 3; ++i) {
        const vec3 axis = GetRow(box.orientation, i);
        p += axis * (Dot(axis, direction) >= 0.0f ? box.size[i] : -box.size[i]);
    }
    return p;
}

}  // namespace

void FindCollisionFeatures(const Sphere& A, const Sphere& B, CollisionManifold* out) {
    if (out == nullptr) return;
    ResetCollisionManifold(out);
    const float r = A.radius + B.radius;
    const vec3 d = B.position - A.position;
    const float distSq = MagnitudeSq(d);
    if (distSq > r * r) return;  // touching (distSq == r^2) collides with depth 0, as in the book

    // Erratum 5.2-1: the book normalises d first and then takes |d| (always 1) as the distance, so its depth
    // is |1 - r|/2 whatever the overlap. The distance is taken before normalising.
    const float dist = std::sqrt(distSq);
    // Coincident centres: the book reports no collision; any direction separates them, +Y is chosen.
    const vec3 normal = dist > 1e-6f ? d * (1.0f / dist) : kFallbackNormal;
    out->colliding = true;
    out->normal = normal;
    out->depth = r - dist;
    // Middle of the overlap along the normal: A's surface point minus half the penetration.
    out->contacts.push_back(A.position + normal * (A.radius - out->depth * 0.5f));
}

void FindCollisionFeatures(const OBB& A, const Sphere& B, CollisionManifold* out) {
    if (out == nullptr) return;
    ResetCollisionManifold(out);
    const Point closest = ClosestPoint(A, B.position);
    const float distSq = DistanceSq(closest, B.position);
    const float rSq = B.radius * B.radius;
    if (distSq > rSq) return;

    vec3 normal;
    float penetration;  // how far B must move along `normal` to stop touching A
    Point surface;      // A's surface point facing B
    if (CMP_EPS(distSq, 0.0f)) {
        // Erratum 5.2-32: the book uses normalize(closest - A.centre) (NaN or "no collision" at the exact
        // centre) and depth r/2. Here the sphere leaves through the nearest face: normal = that face's
        // outward normal, penetration = distance from the centre to the face plus the radius.
        const vec3 local = B.position - A.position;
        int best = 0;
        float bestGap = 0.0f;
        float bestSign = 1.0f;
        for (int i = 0; i < 3; ++i) {
            const float along = Dot(local, GetRow(A.orientation, i));
            const float gap = A.size[i] - std::fabs(along);  // distance to the nearer face on axis i
            if (i == 0 || gap < bestGap) {
                best = i;
                bestGap = gap;
                bestSign = along < 0.0f ? -1.0f : 1.0f;  // the exact centre picks the + face
            }
        }
        normal = GetRow(A.orientation, best) * bestSign;
        penetration = bestGap + B.radius;
        surface = B.position + normal * bestGap;
    } else {
        const float dist = std::sqrt(distSq);
        normal = (B.position - closest) * (1.0f / dist);
        penetration = B.radius - dist;
        surface = closest;
    }
    // Book: contact halfway between A's surface point and B's deepest point (its depth is half the penetration).
    const Point deepest = B.position - normal * B.radius;
    out->colliding = true;
    out->normal = normal;
    out->depth = penetration;
    out->contacts.push_back((surface + deepest) * 0.5f);
}

void FindCollisionFeatures(const OBB& A, const OBB& B, CollisionManifold* out) {
    if (out == nullptr) return;
    ResetCollisionManifold(out);

    // Repo-only early out (erratum 5.1-10): bounding spheres must overlap strictly.
    const float reach = Magnitude(A.size) + Magnitude(B.size);
    if (DistanceSq(A.position, B.position) >= reach * reach) return;

    vec3 test[15];
    for (int i = 0; i < 3; ++i) {
        test[i] = GetRow(A.orientation, i);
        test[3 + i] = GetRow(B.orientation, i);
    }
    // Erratum 5.2-2: the edge-edge axes are A_i x B_j (the book crosses A's axes with themselves).
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) test[6 + i * 3 + j] = Cross(test[i], test[3 + j]);

    // Erratum 5.2-3: the repo zeroes every component < 1e-6 (so every negative one); no zeroing here,
    // near-zero axes are skipped on their length alone.
    vec3 axis;
    float depth = 3.402823466e+38f;
    bool found = false;
    for (const vec3& candidate : test) {
        if (MagnitudeSq(candidate) < kMinAxisSq) continue;
        bool flip = false;
        const float d = PenetrationDepth(A, B, candidate, &flip);
        if (d <= 0.0f) return;  // separating axis, or touching (depth 0 is no collision)
        if (d < depth) {
            depth = d;
            axis = flip ? -candidate : candidate;
            found = true;
        }
    }
    if (!found) return;
    axis = Normalized(axis);

    std::vector<vec3>& contacts = out->contacts;
    ClipEdgesToOBB(GetEdges(B), A, &contacts);
    ClipEdgesToOBB(GetEdges(A), B, &contacts);
    // Fallbacks so a colliding pair always has a contact (documented in docs/ERRATA.md, Manifolds): a box
    // inside the other box has no edge crossing any face, so use the corners inside the other box; if the
    // boxes only overlap on every tested axis without touching (skipped near-parallel edge axes), B's corner
    // deepest toward A, clamped into A.
    if (contacts.empty()) {
        AppendCornersInside(B, A, &contacts);
        AppendCornersInside(A, B, &contacts);
    }
    if (contacts.empty()) contacts.push_back(ClosestPoint(A, SupportVertex(B, -axis)));

    // Project onto the plane through the middle of the overlap on the axis. The book's plane point
    // A.pos + axis*(lenA/2 - depth/2) is the same plane whenever B sticks out of A's far side; the overlap
    // centre also stays inside both boxes when one box's projection contains the other's.
    const Interval iA = GetInterval(A, axis);
    const Interval iB = GetInterval(B, axis);
    const float mid = 0.5f * (std::max(iA.min, iB.min) + std::min(iA.max, iB.max));
    for (vec3& c : contacts) c += axis * (mid - Dot(axis, c));
    RemoveDuplicates(&contacts);

    out->colliding = true;
    out->normal = axis;
    out->depth = depth;
}

CollisionManifold FindCollisionFeatures(const Sphere& A, const Sphere& B) {
    CollisionManifold result;
    FindCollisionFeatures(A, B, &result);
    return result;
}

CollisionManifold FindCollisionFeatures(const OBB& A, const Sphere& B) {
    CollisionManifold result;
    FindCollisionFeatures(A, B, &result);
    return result;
}

CollisionManifold FindCollisionFeatures(const OBB& A, const OBB& B) {
    CollisionManifold result;
    FindCollisionFeatures(A, B, &result);
    return result;
}
