// Point containment and closest-point queries (Physics/Geometry/PointTests.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "Physics/Geometry/Geometry3D.h"
#include "tests/support/Approx.h"

namespace {

constexpr float kSqrt2 = 1.41421356f;

OBB Rotated45AboutZ() { return OBB(vec3(0, 0, 0), vec3(1, 1, 1), ZRotation3x3(45.0f)); }

/// Local coordinates of p in the box frame (the rows of the orientation are the axes).
vec3 LocalCoords(const OBB& obb, const Point& p) {
    const vec3 d = p - obb.position;
    return {Dot(d, GetRow(obb.orientation, 0)), Dot(d, GetRow(obb.orientation, 1)), Dot(d, GetRow(obb.orientation, 2))};
}

}  // namespace

// ---- Containment ------------------------------------------------------------------------------------

TEST(PointTests, PointInSphereInsideSurfaceOutside) {
    const Sphere s(vec3(1, 2, 3), 2.0f);
    EXPECT_TRUE(PointInSphere(vec3(1, 2, 3), s));        // centre
    EXPECT_TRUE(PointInSphere(vec3(2, 2, 3), s));        // inside
    EXPECT_TRUE(PointInSphere(vec3(3, 2, 3), s));        // exactly on the surface counts as inside
    EXPECT_FALSE(PointInSphere(vec3(3.001f, 2, 3), s));  // just outside
    EXPECT_FALSE(PointInSphere(vec3(-10, 2, 3), s));
}

TEST(PointTests, PointInSphereZeroRadiusContainsOnlyItsCentre) {
    const Sphere s(vec3(1, 1, 1), 0.0f);
    EXPECT_TRUE(PointInSphere(vec3(1, 1, 1), s));
    EXPECT_FALSE(PointInSphere(vec3(1, 1, 1.0001f), s));
}

TEST(PointTests, PointOnPlane) {
    const Plane p(Normalized(vec3(1, 1, 0)), kSqrt2);  // x + y = 2
    EXPECT_TRUE(PointOnPlane(vec3(1, 1, 0), p));
    EXPECT_TRUE(PointOnPlane(vec3(2, 0, 7), p));
    EXPECT_FALSE(PointOnPlane(vec3(1, 1, 0.0f) + Normalized(vec3(1, 1, 0)) * 0.001f, p));
    EXPECT_FALSE(PointOnPlane(vec3(0, 0, 0), p));
}

TEST(PointTests, PointInAABBFacesEdgesCornersAndOutside) {
    const AABB box(vec3(1, 2, 3), vec3(1, 2, 3));  // min (0,0,0), max (2,4,6)
    EXPECT_TRUE(PointInAABB(vec3(1, 2, 3), box));
    EXPECT_TRUE(PointInAABB(vec3(2, 2, 3), box));  // on the +X face
    EXPECT_TRUE(PointInAABB(vec3(0, 4, 3), box));  // on an edge
    EXPECT_TRUE(PointInAABB(vec3(2, 4, 6), box));  // max corner
    EXPECT_TRUE(PointInAABB(vec3(0, 0, 0), box));  // min corner
    EXPECT_FALSE(PointInAABB(vec3(2.001f, 2, 3), box));
    EXPECT_FALSE(PointInAABB(vec3(1, -0.001f, 3), box));
    EXPECT_FALSE(PointInAABB(vec3(1, 2, 6.001f), box));
}

TEST(PointTests, PointInAABBNegativeSizeIsTreatedAsItsMirror) {
    // GetMin/GetMax sort the corners, so a negative half size describes the same box.
    const AABB box(vec3(0, 0, 0), vec3(-1, -1, -1));
    EXPECT_TRUE(PointInAABB(vec3(0.5f, -0.5f, 0.9f), box));
    EXPECT_FALSE(PointInAABB(vec3(1.5f, 0, 0), box));
}

TEST(PointTests, PointInAABBZeroSizeIsAPoint) {
    const AABB box(vec3(1, 1, 1), vec3(0, 0, 0));
    EXPECT_TRUE(PointInAABB(vec3(1, 1, 1), box));
    EXPECT_FALSE(PointInAABB(vec3(1, 1, 1.001f), box));
}

TEST(PointTests, PointInOBBIsExactOnTheFace) {
    // Identity orientation, all values exactly representable: the face itself is in, the next float is out.
    const OBB box(vec3(0, 0, 0), vec3(1, 2, 3));
    EXPECT_TRUE(PointInOBB(vec3(1, 0, 0), box));
    EXPECT_TRUE(PointInOBB(vec3(-1, -2, -3), box));  // corner
    EXPECT_FALSE(PointInOBB(vec3(std::nextafter(1.0f, 2.0f), 0, 0), box));
    EXPECT_FALSE(PointInOBB(vec3(0, 0, std::nextafter(-3.0f, -4.0f)), box));
}

TEST(PointTests, PointInOBBRotated) {
    const OBB box = Rotated45AboutZ();  // a diamond in XY: corners at distance sqrt(2) along X and Y
    EXPECT_TRUE(PointInOBB(vec3(1.4f, 0, 0), box));
    EXPECT_FALSE(PointInOBB(vec3(1.42f, 0, 0), box));
    EXPECT_FALSE(PointInOBB(vec3(0.9f, 0.9f, 0), box));  // inside the AABB of the same size, outside the OBB
    EXPECT_TRUE(PointInOBB(vec3(0.7f, 0.7f, 1.0f), box));
    EXPECT_FALSE(PointInOBB(vec3(0, 0, 1.01f), box));
}

TEST(PointTests, PointOnLine) {
    const Line l(vec3(0, 0, 0), vec3(2, 4, 6));
    EXPECT_TRUE(PointOnLine(vec3(1, 2, 3), l));
    EXPECT_TRUE(PointOnLine(vec3(0, 0, 0), l));      // start
    EXPECT_TRUE(PointOnLine(vec3(2, 4, 6), l));      // end
    EXPECT_FALSE(PointOnLine(vec3(3, 6, 9), l));     // on the infinite line, beyond the end
    EXPECT_FALSE(PointOnLine(vec3(-1, -2, -3), l));  // before the start
    EXPECT_FALSE(PointOnLine(vec3(1, 2, 3.01f), l));
}

TEST(PointTests, PointOnZeroLengthLineIsItsPoint) {
    const Line l(vec3(1, 1, 1), vec3(1, 1, 1));
    EXPECT_TRUE(PointOnLine(vec3(1, 1, 1), l));
    EXPECT_FALSE(PointOnLine(vec3(1, 1, 1.01f), l));
}

TEST(PointTests, PointOnRay) {
    const Ray r(vec3(1, 0, 0), vec3(0, 2, 0));  // normalised to +Y
    EXPECT_TRUE(PointOnRay(vec3(1, 0, 0), r));  // origin
    EXPECT_TRUE(PointOnRay(vec3(1, 5, 0), r));
    EXPECT_TRUE(PointOnRay(vec3(1, 1000, 0), r));
    EXPECT_FALSE(PointOnRay(vec3(1, -1, 0), r));  // behind the origin
    EXPECT_FALSE(PointOnRay(vec3(1.01f, 5, 0), r));
}

TEST(PointTests, PointInTriangleInteriorEdgesCornersOutside) {
    const Triangle t(vec3(0, 0, 0), vec3(4, 0, 0), vec3(0, 4, 0));
    EXPECT_TRUE(PointInTriangle(vec3(1, 1, 0), t));
    EXPECT_TRUE(PointInTriangle(vec3(2, 0, 0), t));  // on edge ab
    EXPECT_TRUE(PointInTriangle(vec3(2, 2, 0), t));  // on the hypotenuse
    EXPECT_TRUE(PointInTriangle(vec3(4, 0, 0), t));  // corner
    EXPECT_FALSE(PointInTriangle(vec3(2.1f, 2.1f, 0), t));
    EXPECT_FALSE(PointInTriangle(vec3(-0.1f, 1, 0), t));
    EXPECT_FALSE(PointInTriangle(vec3(5, 0, 0), t));  // on the line of ab, past b
}

TEST(PointTests, PointAboveTriangleIsNotInIt) {
    // The book's cross-product test never looks at the plane and returns true for (1,1,1) here.
    const Triangle t(vec3(0, 0, 0), vec3(4, 0, 0), vec3(0, 4, 0));
    EXPECT_FALSE(PointInTriangle(vec3(1, 1, 1), t));
    EXPECT_FALSE(PointInTriangle(vec3(1, 1, -0.01f), t));
}

TEST(PointTests, PointInDegenerateTriangleIsOnItsSegment) {
    const Triangle t(vec3(0, 0, 0), vec3(1, 1, 1), vec3(2, 2, 2));  // collinear corners
    EXPECT_TRUE(PointInTriangle(vec3(1.5f, 1.5f, 1.5f), t));
    EXPECT_FALSE(PointInTriangle(vec3(3, 3, 3), t));
    EXPECT_FALSE(PointInTriangle(vec3(1, 1, 0), t));  // off the segment; the book's test returns true here
    const Triangle point(vec3(1, 2, 3), vec3(1, 2, 3), vec3(1, 2, 3));
    EXPECT_TRUE(PointInTriangle(vec3(1, 2, 3), point));
    EXPECT_FALSE(PointInTriangle(vec3(1, 2, 3.1f), point));
}

// ---- Closest points ----------------------------------------------------------------------------------

TEST(ClosestPointTest, SphereOutsideInsideAndCentre) {
    const Sphere s(vec3(1, 0, 0), 2.0f);
    EXPECT_TRUE(VecNear(ClosestPoint(s, vec3(1, 10, 0)), vec3(1, 2, 0), tol::kExact));
    EXPECT_TRUE(VecNear(ClosestPoint(s, vec3(1, 0, -0.5f)), vec3(1, 0, -2), tol::kExact));  // inside: surface
    // Coincident with the centre: a defined surface point (+X), never NaN.
    EXPECT_TRUE(VecNear(ClosestPoint(s, vec3(1, 0, 0)), vec3(3, 0, 0), tol::kExact));
}

TEST(ClosestPointTest, AABBClampsEachAxisToItsOwnRange) {
    // Erratum 5.2-9. The box spans y in [9, 11] and z in [-6, -4]; the book clamps y and z against x's
    // range [-1, 1] and returns (0, 1, -1) for the first query instead of (0, 11, -4).
    const AABB box(vec3(0, 10, -5), vec3(1, 1, 1));
    EXPECT_TRUE(VecNear(ClosestPoint(box, vec3(0, 20, 0)), vec3(0, 11, -4), tol::kExact));
    EXPECT_TRUE(VecNear(ClosestPoint(box, vec3(-3, 0, -9)), vec3(-1, 9, -6), tol::kExact));  // corner region
    EXPECT_TRUE(VecNear(ClosestPoint(box, vec3(0.5f, 10.5f, -5.5f)), vec3(0.5f, 10.5f, -5.5f), tol::kExact));
    EXPECT_TRUE(VecNear(ClosestPoint(box, vec3(0.5f, 12, -5.5f)), vec3(0.5f, 11, -5.5f), tol::kExact));  // face
}

TEST(ClosestPointTest, OBBFaceEdgeCornerInside) {
    const OBB box = Rotated45AboutZ();
    // Along world +X the nearest feature is the corner (sqrt2, 0, z) between the +X and -Y local faces.
    EXPECT_TRUE(VecNear(ClosestPoint(box, vec3(5, 0, 0)), vec3(kSqrt2, 0, 0), tol::kTight));
    // Along the local +X axis (1,1,0)/sqrt2 the nearest point is the face centre.
    EXPECT_TRUE(VecNear(ClosestPoint(box, vec3(3, 3, 0)), vec3(0.5f * kSqrt2, 0.5f * kSqrt2, 0), tol::kTight));
    // Above the top face (local z = world z).
    EXPECT_TRUE(VecNear(ClosestPoint(box, vec3(0.1f, 0.2f, 4)), vec3(0.1f, 0.2f, 1), tol::kTight));
    // Inside: the point itself.
    EXPECT_TRUE(VecNear(ClosestPoint(box, vec3(0.3f, -0.2f, 0.5f)), vec3(0.3f, -0.2f, 0.5f), tol::kTight));
    // Corner region: clamp on all three axes.
    EXPECT_TRUE(VecNear(ClosestPoint(box, vec3(5, 0, 5)), vec3(kSqrt2, 0, 1), tol::kTight));
}

TEST(ClosestPointTest, OBBZeroSizeIsItsCentre) {
    const OBB box(vec3(1, 2, 3), vec3(0, 0, 0), Rotation3x3(10, 20, 30));
    EXPECT_TRUE(VecNear(ClosestPoint(box, vec3(-5, 7, 1)), vec3(1, 2, 3), tol::kExact));
}

TEST(ClosestPointTest, PlaneWithUnitAndNonUnitNormal) {
    const Plane unit(vec3(0, 1, 0), 2.0f);
    EXPECT_TRUE(VecNear(ClosestPoint(unit, vec3(3, 7, -1)), vec3(3, 2, -1), tol::kExact));
    EXPECT_TRUE(VecNear(ClosestPoint(unit, vec3(3, -7, -1)), vec3(3, 2, -1), tol::kExact));
    const Plane scaled(vec3(0, 2, 0), 4.0f);  // the same plane y = 2, equation not normalised
    EXPECT_TRUE(VecNear(ClosestPoint(scaled, vec3(3, 7, -1)), vec3(3, 2, -1), tol::kExact));
}

TEST(ClosestPointTest, LineClampsToEnds) {
    const Line l(vec3(0, 0, 0), vec3(4, 0, 0));
    EXPECT_TRUE(VecNear(ClosestPoint(l, vec3(1, 5, 0)), vec3(1, 0, 0), tol::kExact));
    EXPECT_TRUE(VecNear(ClosestPoint(l, vec3(-3, 1, 0)), vec3(0, 0, 0), tol::kExact));
    EXPECT_TRUE(VecNear(ClosestPoint(l, vec3(9, 0, 1)), vec3(4, 0, 0), tol::kExact));
    const Line degenerate(vec3(1, 1, 1), vec3(1, 1, 1));
    EXPECT_TRUE(VecNear(ClosestPoint(degenerate, vec3(5, 5, 5)), vec3(1, 1, 1), tol::kExact));
}

TEST(ClosestPointTest, RayClampsBehindOrigin) {
    const Ray r(vec3(1, 1, 0), vec3(1, 0, 0));
    EXPECT_TRUE(VecNear(ClosestPoint(r, vec3(5, 3, 0)), vec3(5, 1, 0), tol::kExact));
    EXPECT_TRUE(VecNear(ClosestPoint(r, vec3(-5, 3, 0)), vec3(1, 1, 0), tol::kExact));
}

TEST(ClosestPointTest, TriangleRegions) {
    const Triangle t(vec3(0, 0, 0), vec3(4, 0, 0), vec3(0, 4, 0));
    EXPECT_TRUE(VecNear(ClosestPoint(t, vec3(1, 1, 5)), vec3(1, 1, 0), tol::kExact));              // face
    EXPECT_TRUE(VecNear(ClosestPoint(t, vec3(2, -3, 2)), vec3(2, 0, 0), tol::kExact));             // edge ab
    EXPECT_TRUE(VecNear(ClosestPoint(t, vec3(3, 3, -1)), vec3(2, 2, 0), tol::kTight));             // hypotenuse
    EXPECT_TRUE(VecNear(ClosestPoint(t, vec3(-2, -2, 1)), vec3(0, 0, 0), tol::kExact));            // corner a
    EXPECT_TRUE(VecNear(ClosestPoint(t, vec3(7, -1, 0)), vec3(4, 0, 0), tol::kExact));             // corner b
    EXPECT_TRUE(VecNear(ClosestPoint(t, vec3(0.5f, 0.5f, 0)), vec3(0.5f, 0.5f, 0), tol::kExact));  // in it
}

TEST(ClosestPointTest, DegenerateTriangleActsAsSegment) {
    const Triangle t(vec3(0, 0, 0), vec3(2, 0, 0), vec3(1, 0, 0));
    EXPECT_TRUE(VecNear(ClosestPoint(t, vec3(1.5f, 3, 0)), vec3(1.5f, 0, 0), tol::kExact));
    EXPECT_TRUE(VecNear(ClosestPoint(t, vec3(5, 1, 1)), vec3(2, 0, 0), tol::kExact));
    EXPECT_TRUE(IsFinite(ClosestPoint(Triangle(vec3(1, 1, 1), vec3(1, 1, 1), vec3(1, 1, 1)), vec3(0, 0, 0))));
}

// ---- Properties over seeded random cases ---------------------------------------------------------------
// The closest point lies in or on the shape, and no sampled point of the shape is nearer the query.

namespace {
constexpr int kCases = 300;
constexpr int kSamples = 60;
constexpr float kSlack = 1e-4f;  // float rounding of positions of magnitude ~10

float U(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }
vec3 RandomVec(std::mt19937& rng, float lo, float hi) { return {U(rng, lo, hi), U(rng, lo, hi), U(rng, lo, hi)}; }
}  // namespace

TEST(ClosestPointProperty, OBB) {
    std::mt19937 rng(1234);
    for (int n = 0; n < kCases; ++n) {
        const OBB box(RandomVec(rng, -3, 3), RandomVec(rng, 0.1f, 2),
                      Rotation3x3(U(rng, -180, 180), U(rng, -180, 180), U(rng, -180, 180)));
        const Point q = RandomVec(rng, -6, 6);
        const Point c = ClosestPoint(box, q);
        const vec3 local = LocalCoords(box, c);
        for (int i = 0; i < 3; ++i) ASSERT_LE(std::fabs(local[i]), box.size[i] + kSlack) << "case " << n;
        if (PointInOBB(q, box)) {
            EXPECT_TRUE(VecNear(c, q, kSlack)) << "case " << n;
        }
        const float best = Distance(q, c);
        for (int s = 0; s < kSamples; ++s) {
            const vec3 l(U(rng, -1, 1) * box.size.x, U(rng, -1, 1) * box.size.y, U(rng, -1, 1) * box.size.z);
            const Point sample = box.position + MultiplyVector(l, box.orientation);
            ASSERT_LE(best, Distance(q, sample) + kSlack) << "case " << n;
        }
    }
}

TEST(ClosestPointProperty, AABB) {
    std::mt19937 rng(99);
    for (int n = 0; n < kCases; ++n) {
        const AABB box(RandomVec(rng, -3, 3), RandomVec(rng, 0, 2));  // includes near-flat boxes
        const Point q = RandomVec(rng, -6, 6);
        const Point c = ClosestPoint(box, q);
        ASSERT_TRUE(PointInAABB(c, box)) << "case " << n;  // clamping is exact
        const float best = Distance(q, c);
        for (int s = 0; s < kSamples; ++s) {
            const Point sample = box.position + box.size * RandomVec(rng, -1, 1);
            ASSERT_LE(best, Distance(q, sample) + kSlack) << "case " << n;
        }
    }
}

TEST(ClosestPointProperty, SphereSurface) {
    std::mt19937 rng(7);
    for (int n = 0; n < kCases; ++n) {
        const Sphere s(RandomVec(rng, -3, 3), U(rng, 0.1f, 3));
        const Point q = RandomVec(rng, -6, 6);
        const Point c = ClosestPoint(s, q);
        ASSERT_NEAR(Distance(c, s.position), s.radius, kSlack) << "case " << n;
        const float best = Distance(q, c);
        for (int k = 0; k < kSamples; ++k) {
            const Point sample = s.position + Normalized(RandomVec(rng, -1, 1)) * s.radius;
            ASSERT_LE(best, Distance(q, sample) + kSlack) << "case " << n;
        }
    }
}

TEST(ClosestPointProperty, Triangle) {
    std::mt19937 rng(2024);
    for (int n = 0; n < kCases; ++n) {
        const Triangle t(RandomVec(rng, -3, 3), RandomVec(rng, -3, 3), RandomVec(rng, -3, 3));
        const Point q = RandomVec(rng, -6, 6);
        const Point c = ClosestPoint(t, q);
        ASSERT_TRUE(PointInTriangle(c, t)) << "case " << n;
        const float best = Distance(q, c);
        for (int k = 0; k < kSamples; ++k) {
            float u = U(rng, 0, 1), v = U(rng, 0, 1);
            if (u + v > 1) u = 1 - u, v = 1 - v;
            const Point sample = t.a + (t.b - t.a) * u + (t.c - t.a) * v;
            ASSERT_LE(best, Distance(q, sample) + kSlack) << "case " << n;
        }
    }
}

TEST(ClosestPointProperty, LineRayPlane) {
    std::mt19937 rng(5);
    for (int n = 0; n < kCases; ++n) {
        const Point a = RandomVec(rng, -3, 3), b = RandomVec(rng, -3, 3), q = RandomVec(rng, -6, 6);
        const Line line(a, b);
        const Ray ray(a, b - a);
        const Plane plane(Normalized(b - a), U(rng, -2, 2));
        const Point cl = ClosestPoint(line, q), cr = ClosestPoint(ray, q), cp = ClosestPoint(plane, q);
        ASSERT_TRUE(PointOnLine(cl, line)) << "case " << n;
        ASSERT_TRUE(PointOnRay(cr, ray)) << "case " << n;
        ASSERT_NEAR(PlaneEquation(cp, plane), 0.0f, kSlack) << "case " << n;
        for (int k = 0; k < kSamples; ++k) {
            const float s = U(rng, 0, 1);
            ASSERT_LE(Distance(q, cl), Distance(q, a + (b - a) * s) + kSlack) << "case " << n;
            ASSERT_LE(Distance(q, cr), Distance(q, a + (b - a) * (4 * s)) + kSlack) << "case " << n;
            // Some point of the plane, built independently of ClosestPoint: the foot n*d plus a tangent offset.
            const vec3 r = RandomVec(rng, -6, 6);
            const Point onPlane = plane.normal * plane.distance + (r - plane.normal * Dot(r, plane.normal));
            ASSERT_LE(Distance(q, cp), Distance(q, onPlane) + kSlack) << "case " << n;
        }
    }
}
