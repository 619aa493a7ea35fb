// PROVISIONAL adapter (replaced by the feature-id clipper of issue 12 before it is called done): builds a solver
// manifold from the book's manifold, so the soft solver can be developed against ContactManifold.h. No margin,
// no feature ids (index order), no reduction beyond the first four points.
#include "Physics/Geometry/ContactManifold.h"

namespace {

void FromBook(const CollisionManifold& m, ContactManifold* out) {
    out->pointCount = 0;
    if (!m.colliding) return;
    out->normal = m.normal;
    for (const vec3& p : m.contacts) {
        if (out->pointCount == kMaxManifoldPoints) break;
        ManifoldPoint& q = out->points[out->pointCount];
        q.point = p;
        q.separation = -m.depth;
        q.id = static_cast<std::uint32_t>(out->pointCount);
        ++out->pointCount;
    }
}

}  // namespace

void CollideBoxes(const OBB& A, const OBB& B, float /*margin*/, ContactManifold* out) {
    CollisionManifold m;
    FindCollisionFeatures(A, B, &m);
    FromBook(m, out);
}

void CollideBoxSphere(const OBB& A, const Sphere& B, float /*margin*/, ContactManifold* out) {
    CollisionManifold m;
    FindCollisionFeatures(A, B, &m);
    FromBook(m, out);
}

void CollideSpheres(const Sphere& A, const Sphere& B, float /*margin*/, ContactManifold* out) {
    CollisionManifold m;
    FindCollisionFeatures(A, B, &m);
    FromBook(m, out);
}
