// Shape-pair intersection tests (Physics/Geometry/Intersections.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "Physics/Geometry/Geometry3D.h"
#include "tests/support/Approx.h"

namespace {

constexpr float kSqrt2 = 1.41421356f;

/// Edge-on-edge pair separated only by an edge-edge axis (hand-built):
/// A is the unit box at the origin; its +X+Y edge runs along Z through (1, 1, z).
/// B is a unit box whose axes are e = (1,-1,0)/sqrt2, (u+z)/sqrt2, (u-z)/sqrt2 with u = (1,1,0)/sqrt2, so
/// its ridge along e points at A. B's centre is c*u; the ridge lies at (c - sqrt2) along u, A's edge at
/// sqrt2. With c = 2.9 the gap along u = Cross(A_z, B_e) is 0.072. The other 6 face axes all overlap:
/// on X and Y, B spans [0.343, 3.757] against A's [-1, 1]; on Z, B is centred at 0; on e both are centred
/// at 0; on (u +- z)/sqrt2, B spans [1.051, 3.051] against A's [-1.707, 1.707].
constexpr float kEdgeGapCentre = 2.9f;
mat3 EdgeOnEdgeOrientation() {
    const vec3 u = Normalized(vec3(1, 1, 0)), z(0, 0, 1);
    const vec3 e = Normalized(vec3(1, -1, 0));
    const vec3 b1 = (u + z) * (1.0f / kSqrt2), b2 = (u - z) * (1.0f / kSqrt2);
    return mat3(e.x, e.y, e.z, b1.x, b1.y, b1.z, b2.x, b2.y, b2.z);
}
OBB EdgeOnEdgeB(float centre) {
    return OBB(Normalized(vec3(1, 1, 0)) * centre, vec3(1, 1, 1), EdgeOnEdgeOrientation());
}

/// Applies a rigid motion to a whole configuration (used to check invariance).
OBB Moved(const OBB& o, const mat3& r, const vec3& t) {
    return OBB(MultiplyVector(o.position, r) + t, o.size, o.orientation * r);
}
Triangle Moved(const Triangle& tr, const mat3& r, const vec3& t) {
    return Triangle(MultiplyVector(tr.a, r) + t, MultiplyVector(tr.b, r) + t, MultiplyVector(tr.c, r) + t);
}

}  // namespace

// ---- Spheres -------------------------------------------------------------------------------------------

TEST(Intersections, SphereSphereTouchingIsNotOverlapping) {
    EXPECT_FALSE(SphereSphere(Sphere(vec3(0, 0, 0), 1), Sphere(vec3(2, 0, 0), 1)));  // touching: strict <
    EXPECT_TRUE(SphereSphere(Sphere(vec3(0, 0, 0), 1), Sphere(vec3(1.99f, 0, 0), 1)));
    EXPECT_FALSE(SphereSphere(Sphere(vec3(0, 0, 0), 1), Sphere(vec3(0, 3, 0), 1.5f)));
    EXPECT_TRUE(SphereSphere(Sphere(vec3(1, 1, 1), 1), Sphere(vec3(1, 1, 1), 0.5f)));  // coincident centres
    EXPECT_TRUE(SphereSphere(Sphere(vec3(0, 0, 0), 5), Sphere(vec3(1, 0, 0), 0.1f)));  // one inside the other
    // Two zero-radius spheres at one point: 0 < 0 is false (strict, like touching).
    EXPECT_FALSE(SphereSphere(Sphere(vec3(1, 1, 1), 0), Sphere(vec3(1, 1, 1), 0)));
}

TEST(Intersections, SphereAABBUsesPerAxisClosestPoint) {
    // Box spans y in [9, 11]. Erratum 5.2-9: the book's ClosestPoint clamps y into x's range [-1, 1],
    // finds (0, 1, 0) at distance 9.5 and reports no intersection.
    const AABB box(vec3(0, 10, 0), vec3(1, 1, 1));
    EXPECT_TRUE(SphereAABB(Sphere(vec3(0, 10.5f, 0), 1), box));      // centre inside
    EXPECT_TRUE(SphereAABB(Sphere(vec3(0, 11.5f, 0), 1), box));      // overlapping the top face
    EXPECT_FALSE(SphereAABB(Sphere(vec3(0, 12, 0), 1), box));        // touching the top face (strict)
    EXPECT_FALSE(SphereAABB(Sphere(vec3(1.8f, 11.8f, 0), 1), box));  // edge region: distance 1.131
    EXPECT_TRUE(SphereAABB(Sphere(vec3(1.7f, 11.7f, 0), 1), box));   // edge region: distance 0.990
}

TEST(Intersections, SphereOBBNearARotatedCorner) {
    const OBB box(vec3(0, 0, 0), vec3(1, 1, 1), ZRotation3x3(45.0f));  // corner at (sqrt2, 0, z)
    EXPECT_TRUE(SphereOBB(Sphere(vec3(2.4f, 0, 0), 1), box));          // distance 0.986
    EXPECT_FALSE(SphereOBB(Sphere(vec3(2.5f, 0, 0), 1), box));         // distance 1.086
    EXPECT_TRUE(SphereOBB(Sphere(vec3(0, 0, 0), 0.1f), box));          // coincident centres
    EXPECT_FALSE(SphereOBB(Sphere(vec3(0, 0, 3), 2), box));            // touching the top face (strict)
}

TEST(Intersections, SpherePlane) {
    const Plane p(vec3(0, 1, 0), 1);
    EXPECT_TRUE(SpherePlane(Sphere(vec3(5, 1.5f, 5), 1), p));
    EXPECT_TRUE(SpherePlane(Sphere(vec3(5, 0.5f, 5), 1), p));  // from behind
    EXPECT_FALSE(SpherePlane(Sphere(vec3(5, 2, 5), 1), p));    // touching (strict)
    EXPECT_FALSE(SpherePlane(Sphere(vec3(5, -3, 5), 1), p));
}

// ---- Boxes ---------------------------------------------------------------------------------------------

TEST(Intersections, AABBAABBTouchingCounts) {
    const AABB a(vec3(0, 0, 0), vec3(1, 1, 1));
    EXPECT_TRUE(AABBAABB(a, AABB(vec3(2, 0, 0), vec3(1, 1, 1))));  // sharing a face
    EXPECT_TRUE(AABBAABB(a, AABB(vec3(2, 2, 2), vec3(1, 1, 1))));  // sharing a corner
    EXPECT_FALSE(AABBAABB(a, AABB(vec3(2.01f, 0, 0), vec3(1, 1, 1))));
    EXPECT_FALSE(AABBAABB(a, AABB(vec3(0, 0, -2.5f), vec3(1, 1, 1))));
    EXPECT_TRUE(AABBAABB(a, AABB(vec3(0, 0, 0), vec3(0, 0, 0))));  // zero-size box at the centre
    EXPECT_TRUE(AABBAABB(a, a));                                   // coincident
}

TEST(Intersections, OBBOBBEdgeOnEdgeSeparatedOnlyByCrossAxis) {
    // Erratum 5.2-2: the book crosses A's axes with A's own, never tests Cross(A_z, B_e), and reports a
    // collision for this separated pair (all 6 face axes overlap, see EdgeOnEdgeB).
    const OBB a(vec3(0, 0, 0), vec3(1, 1, 1));
    EXPECT_FALSE(OBBOBB(a, EdgeOnEdgeB(kEdgeGapCentre)));
    EXPECT_FALSE(OBBOBB(EdgeOnEdgeB(kEdgeGapCentre), a));  // symmetric
    // Slide B in until the ridge crosses A's edge: gap 2.9 - 2*sqrt2 = 0.072 along u; at 2.8 they overlap.
    EXPECT_TRUE(OBBOBB(a, EdgeOnEdgeB(2.8f)));
    // Every face axis overlaps, so only an edge-edge axis can have separated the first pair.
    const OBB b = EdgeOnEdgeB(kEdgeGapCentre);
    for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(OverlapOnAxis(a, b, GetRow(a.orientation, i))) << "A axis " << i;
        EXPECT_TRUE(OverlapOnAxis(a, b, GetRow(b.orientation, i))) << "B axis " << i;
    }
}

TEST(Intersections, OBBOBBEdgeOnEdgeIsInvariantUnderRigidMotion) {
    const mat3 r = Rotation3x3(17, -63, 41);
    const vec3 t(3, -2, 5);
    const OBB a = Moved(OBB(vec3(0, 0, 0), vec3(1, 1, 1)), r, t);
    EXPECT_FALSE(OBBOBB(a, Moved(EdgeOnEdgeB(kEdgeGapCentre), r, t)));
    EXPECT_TRUE(OBBOBB(a, Moved(EdgeOnEdgeB(2.8f), r, t)));
}

TEST(Intersections, AABBOBBEdgeOnEdgeSeparatedOnlyByCrossAxis) {
    // Erratum 5.2-2 in AABBOBB: the book reports this separated pair as colliding.
    const AABB a(vec3(0, 0, 0), vec3(1, 1, 1));
    EXPECT_FALSE(AABBOBB(a, EdgeOnEdgeB(kEdgeGapCentre)));
    EXPECT_TRUE(AABBOBB(a, EdgeOnEdgeB(2.8f)));
}

TEST(Intersections, OverlapOnAxisProjectsBothBoxes) {
    // Erratum 5.2-8: the book projects obb1 twice, so this far-apart pair overlaps on every axis and
    // OBBOBB always returns true.
    const OBB a(vec3(0, 0, 0), vec3(1, 1, 1));
    const OBB b(vec3(10, 0, 0), vec3(1, 1, 1), Rotation3x3(10, 20, 30));
    EXPECT_FALSE(OverlapOnAxis(a, b, vec3(1, 0, 0)));
    EXPECT_TRUE(OverlapOnAxis(a, b, vec3(0, 1, 0)));
    EXPECT_FALSE(OBBOBB(a, b));
}

TEST(Intersections, OBBOBBFaceCasesCoincidentAndDegenerate) {
    const OBB a(vec3(0, 0, 0), vec3(1, 1, 1));
    EXPECT_TRUE(OBBOBB(a, OBB(vec3(2, 0, 0), vec3(1, 1, 1))));        // face to face, touching
    EXPECT_FALSE(OBBOBB(a, OBB(vec3(2.001f, 0, 0), vec3(1, 1, 1))));  // just apart
    // Rotated 45 degrees about Z: its corner reaches sqrt2 along X.
    const mat3 r45 = ZRotation3x3(45.0f);
    EXPECT_TRUE(OBBOBB(a, OBB(vec3(2.4f, 0, 0), vec3(1, 1, 1), r45)));
    EXPECT_FALSE(OBBOBB(a, OBB(vec3(2.45f, 0, 0), vec3(1, 1, 1), r45)));
    EXPECT_TRUE(OBBOBB(a, OBB(vec3(0, 0, 0), vec3(0.5f, 3, 0.5f), Rotation3x3(10, 20, 30))));  // coincident
    // Zero-thickness box (a square) crossing A, and a zero-size box (a point) inside and outside A.
    EXPECT_TRUE(OBBOBB(a, OBB(vec3(0, 1.5f, 0), vec3(2, 0, 2), XRotation3x3(60))));
    EXPECT_TRUE(OBBOBB(a, OBB(vec3(0.5f, 0.5f, 0.5f), vec3(0, 0, 0), r45)));
    EXPECT_FALSE(OBBOBB(a, OBB(vec3(1.5f, 0.5f, 0.5f), vec3(0, 0, 0), r45)));
}

TEST(Intersections, GetIntervalOfRotatedOBBMatchesItsCorners) {
    // Hand-computed: the 45-degree box's corners project onto X at +-sqrt2 (and its centre 3 is added).
    const OBB box(vec3(3, 0, 0), vec3(1, 1, 1), ZRotation3x3(45.0f));
    const Interval ix = GetInterval(box, vec3(1, 0, 0));
    EXPECT_NEAR(ix.min, 3 - kSqrt2, tol::kTight);
    EXPECT_NEAR(ix.max, 3 + kSqrt2, tol::kTight);
    // The axis is not normalised: scaling it by 2 scales the interval.
    const Interval i2 = GetInterval(box, vec3(2, 0, 0));
    EXPECT_NEAR(i2.min, 2 * (3 - kSqrt2), tol::kTight);
    EXPECT_NEAR(i2.max, 2 * (3 + kSqrt2), tol::kTight);
    const Interval ia = GetInterval(AABB(vec3(1, 2, 3), vec3(1, 2, 3)), vec3(0, 1, 1));  // corners y+z
    EXPECT_NEAR(ia.min, 0.0f, tol::kExact);
    EXPECT_NEAR(ia.max, 10.0f, tol::kExact);
    const Interval it = GetInterval(Triangle(vec3(1, 0, 0), vec3(0, 2, 0), vec3(0, 0, -3)), vec3(1, 1, 1));
    EXPECT_FLOAT_EQ(it.min, -3.0f);
    EXPECT_FLOAT_EQ(it.max, 2.0f);
}

TEST(Intersections, AABBPlaneAndOBBPlane) {
    const Plane p(vec3(0, 1, 0), 2);
    EXPECT_TRUE(AABBPlane(AABB(vec3(0, 1, 0), vec3(1, 1, 1)), p));  // touching from below
    EXPECT_FALSE(AABBPlane(AABB(vec3(0, 0.9f, 0), vec3(1, 1, 1)), p));
    EXPECT_TRUE(AABBPlane(AABB(vec3(0, 2.5f, 0), vec3(1, 1, 1)), p));
    // The 45-degree box reaches sqrt2 along Y.
    const mat3 r45 = ZRotation3x3(45.0f);
    EXPECT_TRUE(OBBPlane(OBB(vec3(0, 0.6f, 0), vec3(1, 1, 1), r45), p));
    EXPECT_FALSE(OBBPlane(OBB(vec3(0, 0.5f, 0), vec3(1, 1, 1), r45), p));
    EXPECT_TRUE(OBBPlane(OBB(vec3(0, 2, 0), vec3(0, 0, 0)), p));  // zero-size box on the plane
}

TEST(Intersections, PlanePlane) {
    const Plane a(vec3(0, 1, 0), 1);
    EXPECT_TRUE(PlanePlane(a, Plane(vec3(1, 0, 0), 5)));
    EXPECT_FALSE(PlanePlane(a, Plane(vec3(0, 1, 0), 2)));  // parallel, distinct
    // Coincident planes intersect everywhere; the book returns false for every parallel pair.
    EXPECT_TRUE(PlanePlane(a, Plane(vec3(0, 1, 0), 1)));
    EXPECT_TRUE(PlanePlane(a, Plane(vec3(0, -2, 0), -2)));  // same plane, flipped and scaled equation
    EXPECT_FALSE(PlanePlane(a, Plane(vec3(0, -1, 0), 1)));  // y = -1
}

// ---- Triangles -----------------------------------------------------------------------------------------

namespace {
/// A sliver whose edge ab runs along (1,-1,0) at distance 0.1 beyond the unit box's +X+Y edge, tilted so
/// that its normal (3.6, 3.6, -2.28) is no separating axis. On X, Y and Z it overlaps the box; only
/// Cross(Z, ab) ~ (1,1,0) separates: the triangle starts at 2.1, the box ends at 2.
Triangle EdgeSliver(float offset) {
    const vec3 u(1, 1, 0);
    return Triangle(vec3(1.65f, 0.45f, 0) + u * offset, vec3(0.45f, 1.65f, 0) + u * offset, vec3(2, 2, 3) + u * offset);
}
}  // namespace

TEST(Intersections, TriangleAABBAndOBBEdgeCrossAxis) {
    const AABB box(vec3(0, 0, 0), vec3(1, 1, 1));
    EXPECT_FALSE(TriangleAABB(EdgeSliver(0), box));
    EXPECT_TRUE(TriangleAABB(EdgeSliver(-0.1f), box));  // slid 0.1*2 = 0.2 along (1,1,0) inward: overlap
    const OBB obb(vec3(0, 0, 0), vec3(1, 1, 1));
    EXPECT_FALSE(TriangleOBB(EdgeSliver(0), obb));
    EXPECT_TRUE(TriangleOBB(EdgeSliver(-0.1f), obb));
    const mat3 r = Rotation3x3(33, -12, 75);
    const vec3 t(-4, 1, 2);
    EXPECT_FALSE(TriangleOBB(Moved(EdgeSliver(0), r, t), Moved(obb, r, t)));
    EXPECT_TRUE(TriangleOBB(Moved(EdgeSliver(-0.1f), r, t), Moved(obb, r, t)));
}

TEST(Intersections, TriangleBoxFaceCasesAndDegenerate) {
    const AABB box(vec3(0, 0, 0), vec3(1, 1, 1));
    EXPECT_TRUE(TriangleAABB(Triangle(vec3(-5, 1, -5), vec3(5, 1, -5), vec3(0, 1, 5)), box));  // in the top face
    EXPECT_FALSE(TriangleAABB(Triangle(vec3(-5, 1.01f, -5), vec3(5, 1.01f, -5), vec3(0, 1.01f, 5)), box));
    EXPECT_TRUE(TriangleAABB(Triangle(vec3(-0.1f, 0, 0), vec3(0.1f, 0, 0), vec3(0, 0.1f, 0)), box));  // inside
    // A large triangle around the box, cutting through it: no vertex inside.
    EXPECT_TRUE(TriangleAABB(Triangle(vec3(-10, -10, 0.5f), vec3(10, -10, 0.5f), vec3(0, 10, 0.5f)), box));
    // Tilted plane x + y + z = 3.2 passes the (1,1,1) corner at distance 0.115: no intersection.
    EXPECT_FALSE(TriangleAABB(Triangle(vec3(3.2f, 0, 0), vec3(0, 3.2f, 0), vec3(0, 0, 3.2f)), box));
    EXPECT_TRUE(TriangleAABB(Triangle(vec3(2.9f, 0, 0), vec3(0, 2.9f, 0), vec3(0, 0, 2.9f)), box));
    // Degenerate triangles (segments, zero normal): one pierces the box; the other runs along (1,-1,0)
    // 0.05*sqrt2 beyond the +X+Y edge, where only Cross(Z, (1,-1,0)) separates (2.1 against 2).
    EXPECT_TRUE(TriangleAABB(Triangle(vec3(-3, 0, 0), vec3(3, 0, 0), vec3(0, 0, 0)), box));
    EXPECT_FALSE(TriangleAABB(Triangle(vec3(3.05f, -0.95f, 0), vec3(-0.95f, 3.05f, 0), vec3(1.05f, 1.05f, 0)), box));
    EXPECT_TRUE(TriangleAABB(Triangle(vec3(2.95f, -1.05f, 0), vec3(-1.05f, 2.95f, 0), vec3(0.95f, 0.95f, 0)), box));
}

TEST(Intersections, TriangleSphereAndPlane) {
    const Triangle t(vec3(0, 0, 0), vec3(4, 0, 0), vec3(0, 4, 0));
    EXPECT_TRUE(TriangleSphere(t, Sphere(vec3(1, 1, 0.5f), 1)));
    EXPECT_TRUE(TriangleSphere(t, Sphere(vec3(1, 1, 1), 1)));     // touching the face (the book's <=)
    EXPECT_FALSE(TriangleSphere(t, Sphere(vec3(-2, -2, 0), 2)));  // corner at distance 2.83
    EXPECT_FALSE(TriangleSphere(t, Sphere(vec3(3, 3, 0), 1)));    // hypotenuse at distance sqrt2
    EXPECT_TRUE(TriangleSphere(t, Sphere(vec3(3, 3, 0), 1.5f)));
    EXPECT_TRUE(TriangleSphere(t, Sphere(vec3(1, 1, 0), 0.1f)));  // centre in the triangle

    const Plane p(vec3(0, 0, 1), 1);                                                           // z = 1
    EXPECT_TRUE(TrianglePlane(Triangle(vec3(0, 0, 0), vec3(1, 0, 2), vec3(0, 1, 0)), p));      // crossing
    EXPECT_FALSE(TrianglePlane(Triangle(vec3(0, 0, 2), vec3(1, 0, 3), vec3(0, 1, 1.5f)), p));  // all in front
    EXPECT_FALSE(TrianglePlane(Triangle(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0.5f)), p));  // all behind
    EXPECT_TRUE(TrianglePlane(Triangle(vec3(0, 0, 1), vec3(1, 0, 1), vec3(0, 1, 1)), p));      // in the plane
    EXPECT_TRUE(TrianglePlane(Triangle(vec3(0, 0, 1), vec3(1, 0, 2), vec3(0, 1, 2)), p));      // vertex on it
}

TEST(Intersections, TriangleTriangleCoplanarSeparatedInPlane) {
    // Coplanar triangles separated along (1,1,0) within their plane. The book's 11 axes (both normals and
    // the edge crosses, all parallel to Z here) overlap on every axis, so the book reports a collision.
    const Triangle t1(vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0));
    EXPECT_FALSE(TriangleTriangle(t1, Triangle(vec3(1, 1, 0), vec3(2, 1, 0), vec3(1, 2, 0))));
    EXPECT_TRUE(TriangleTriangle(t1, Triangle(vec3(0.4f, 0.4f, 0), vec3(2, 1, 0), vec3(1, 2, 0))));
    EXPECT_TRUE(TriangleTriangle(t1, Triangle(vec3(1, 0, 0), vec3(0, 1, 0), vec3(1, 1, 0))));  // shared edge
}

TEST(Intersections, TriangleTriangleSpatialCases) {
    const Triangle t1(vec3(0, 0, 0), vec3(2, 0, 0), vec3(0, 2, 0));
    // Vertical triangle piercing t1's interior, and the same moved beyond t1's hypotenuse.
    EXPECT_TRUE(TriangleTriangle(t1, Triangle(vec3(0.5f, 0.5f, -1), vec3(0.5f, 0.5f, 1), vec3(3, 3, 0.2f))));
    EXPECT_FALSE(TriangleTriangle(t1, Triangle(vec3(1.5f, 1.5f, -1), vec3(1.5f, 1.5f, 1), vec3(3, 3, 0.2f))));
    // Parallel planes.
    EXPECT_FALSE(TriangleTriangle(t1, Triangle(vec3(0, 0, 1), vec3(2, 0, 1), vec3(0, 2, 1))));
    // Segment (degenerate triangle) in t1's plane, beside it and across it.
    EXPECT_FALSE(TriangleTriangle(t1, Triangle(vec3(3, 0, 0), vec3(0, 3, 0), vec3(1.5f, 1.5f, 0))));
    EXPECT_TRUE(TriangleTriangle(t1, Triangle(vec3(1.5f, 0, 0), vec3(0, 1.5f, 0), vec3(0.75f, 0.75f, 0))));
}

// ---- SAT against an exact brute force over seeded random pairs ------------------------------------------
//
// Brute force for two convex polytopes P, Q: they intersect iff an edge of P meets Q or an edge of Q meets P.
// Proof: if P and Q intersect, P ∩ Q is a non-empty bounded convex polytope and has a vertex v. v lies on at
// least three bounding planes with independent normals, each a face plane of P or of Q, so at least two
// come from the same shape, say P. Two non-parallel face planes of a box meet in the line of the edge they
// share, and v lies in P, so v is on that edge; v also lies in Q. The converse is immediate.
// For a triangle T against a box B the same argument holds with T as the intersection of its plane and its
// three edge half-planes: v is on an edge of T, or in T's interior and on two face planes of B (an edge of
// B meeting T). Segment-against-box uses slab clipping in the box frame (Liang-Barsky) and segment-against-
// triangle a plane crossing plus a barycentric test: no sampling anywhere.
// Float rounding decides cases that touch within rounding, so a case counts only when the brute force
// gives the same answer with every box grown and shrunk by a margin (well-posed cases).

namespace {

struct Box {
    vec3 c, s, ax[3];
};
Box FromOBB(const OBB& o) {
    return {o.position, o.size, {GetRow(o.orientation, 0), GetRow(o.orientation, 1), GetRow(o.orientation, 2)}};
}

bool SegmentMeetsBox(const Point& p0, const Point& p1, const Box& b) {
    float t0 = 0.0f, t1 = 1.0f;
    for (int i = 0; i < 3; ++i) {
        const float s = Dot(p0 - b.c, b.ax[i]), d = Dot(p1 - p0, b.ax[i]);
        if (d == 0.0f) {
            if (std::fabs(s) > b.s[i]) return false;
            continue;
        }
        float ta = (-b.s[i] - s) / d, tb = (b.s[i] - s) / d;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::fmax(t0, ta);
        t1 = std::fmin(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

std::array<Line, 12> BoxEdges(const Box& b) {
    std::array<Line, 12> edges;
    int n = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (int su = -1; su <= 1; su += 2)
            for (int sv = -1; sv <= 1; sv += 2) {
                const vec3 mid = b.c + b.ax[u] * (su * b.s[u]) + b.ax[v] * (sv * b.s[v]);
                edges[n++] = Line(mid - b.ax[axis] * b.s[axis], mid + b.ax[axis] * b.s[axis]);
            }
    }
    return edges;
}

bool BruteBoxBox(const Box& a, const Box& b) {
    for (const Line& e : BoxEdges(a))
        if (SegmentMeetsBox(e.start, e.end, b)) return true;
    for (const Line& e : BoxEdges(b))
        if (SegmentMeetsBox(e.start, e.end, a)) return true;
    return false;
}

bool SegmentMeetsTriangle(const Point& p0, const Point& p1, const Triangle& t) {
    const vec3 n = Cross(t.b - t.a, t.c - t.a);
    const float d0 = Dot(p0 - t.a, n), d1 = Dot(p1 - t.a, n);
    if ((d0 > 0 && d1 > 0) || (d0 < 0 && d1 < 0) || d0 == d1) return false;  // coplanar: measure zero
    const Point x = p0 + (p1 - p0) * (d0 / (d0 - d1));
    const float u = Dot(Cross(t.b - x, t.c - x), n), v = Dot(Cross(t.c - x, t.a - x), n),
                w = Dot(Cross(t.a - x, t.b - x), n);
    return u >= 0 && v >= 0 && w >= 0;
}

bool BruteTriangleBox(const Triangle& t, const Box& b) {
    for (int i = 0; i < 3; ++i)
        if (SegmentMeetsBox(t[i], t[(i + 1) % 3], b)) return true;
    for (const Line& e : BoxEdges(b))
        if (SegmentMeetsTriangle(e.start, e.end, t)) return true;
    return false;
}

Box Grown(Box b, float margin) {
    for (int i = 0; i < 3; ++i) b.s[i] = std::fmax(0.0f, b.s[i] + margin);
    return b;
}

float Uf(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
OBB RandomOBB(std::mt19937& rng, float spread) {
    return OBB(vec3(Uf(rng, -spread, spread), Uf(rng, -spread, spread), Uf(rng, -spread, spread)),
               vec3(Uf(rng, 0.1f, 1.5f), Uf(rng, 0.1f, 1.5f), Uf(rng, 0.1f, 1.5f)),
               Rotation3x3(Uf(rng, -180, 180), Uf(rng, -180, 180), Uf(rng, -180, 180)));
}

/// True if all six face axes overlap: the pair can then be separated only by an edge-edge axis.
bool FaceAxesOverlap(const OBB& a, const OBB& b) {
    for (int i = 0; i < 3; ++i)
        if (!OverlapOnAxis(a, b, GetRow(a.orientation, i)) || !OverlapOnAxis(a, b, GetRow(b.orientation, i)))
            return false;
    return true;
}

constexpr float kMargin = 1e-3f;

}  // namespace

/// The brute-force answer for a box pair, or false in *wellPosed when growing and shrinking by the margin
/// disagree.
bool BoxTruth(const OBB& a, const OBB& b, bool* wellPosed) {
    const bool big = BruteBoxBox(Grown(FromOBB(a), kMargin), Grown(FromOBB(b), kMargin));
    const bool small = BruteBoxBox(Grown(FromOBB(a), -kMargin), Grown(FromOBB(b), -kMargin));
    *wellPosed = big == small;
    return big;
}

TEST(IntersectionsProperty, OBBOBBAgreesWithBruteForce) {
    std::mt19937 rng(20240611);
    int checked = 0, hits = 0, edgeOnly = 0;
    for (int n = 0; n < 20000; ++n) {
        const OBB a = RandomOBB(rng, 2.5f), b = RandomOBB(rng, 2.5f);
        bool wellPosed = false;
        const bool truth = BoxTruth(a, b, &wellPosed);
        if (!wellPosed) continue;
        ++checked;
        hits += truth;
        if (!truth && FaceAxesOverlap(a, b)) ++edgeOnly;
        ASSERT_EQ(OBBOBB(a, b), truth) << "case " << n;
        ASSERT_EQ(OBBOBB(b, a), truth) << "case " << n;
    }
    // The sample exercises both answers and the pairs that only edge-edge axes separate (the A x A bug).
    EXPECT_GT(checked, 19000);
    EXPECT_GT(hits, 2000);
    EXPECT_GT(checked - hits, 2000);
    EXPECT_GT(edgeOnly, 50);
}

TEST(IntersectionsProperty, AABBOBBAgreesWithBruteForce) {
    std::mt19937 rng(31337);
    int checked = 0, hits = 0;
    for (int n = 0; n < 20000; ++n) {
        const OBB r = RandomOBB(rng, 2.5f), b = RandomOBB(rng, 2.5f);
        const AABB a(r.position, r.size);
        bool wellPosed = false;
        const bool truth = BoxTruth(OBB(a.position, a.size), b, &wellPosed);
        if (!wellPosed) continue;
        ++checked;
        hits += truth;
        ASSERT_EQ(AABBOBB(a, b), truth) << "case " << n;
    }
    EXPECT_GT(checked, 19000);
    EXPECT_GT(hits, 2000);
    EXPECT_GT(checked - hits, 2000);
}

TEST(IntersectionsProperty, TriangleOBBAgreesWithBruteForce) {
    std::mt19937 rng(77);
    int checked = 0, hits = 0;
    for (int n = 0; n < 20000; ++n) {
        const OBB b = RandomOBB(rng, 0.5f);
        const vec3 c(Uf(rng, -2.5f, 2.5f), Uf(rng, -2.5f, 2.5f), Uf(rng, -2.5f, 2.5f));
        const Triangle t(c + vec3(Uf(rng, -1.5f, 1.5f), Uf(rng, -1.5f, 1.5f), Uf(rng, -1.5f, 1.5f)),
                         c + vec3(Uf(rng, -1.5f, 1.5f), Uf(rng, -1.5f, 1.5f), Uf(rng, -1.5f, 1.5f)),
                         c + vec3(Uf(rng, -1.5f, 1.5f), Uf(rng, -1.5f, 1.5f), Uf(rng, -1.5f, 1.5f)));
        const bool big = BruteTriangleBox(t, Grown(FromOBB(b), kMargin));
        const bool small = BruteTriangleBox(t, Grown(FromOBB(b), -kMargin));
        if (big != small) continue;
        ++checked;
        hits += big;
        ASSERT_EQ(TriangleOBB(t, b), big) << "case " << n;
    }
    EXPECT_GT(checked, 19000);
    EXPECT_GT(hits, 2000);
    EXPECT_GT(checked - hits, 2000);
}
