// Raycast.cpp: hand-computed raycasts for every shape (edge cases spelled out) and seeded property tests.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "Physics/Geometry/Geometry3D.h"
#include "tests/support/Approx.h"

namespace {

/// Builds a ray without going through the normalising constructor (direction already unit in the tests).
Ray MakeRay(const vec3& origin, const vec3& direction) { return Ray(origin, direction); }

bool AllFinite(const RaycastResult& r) { return IsFinite(r.point) && IsFinite(r.normal) && std::isfinite(r.t); }

}  // namespace

// ---- OBB ----------------------------------------------------------------------------------------------

TEST(RaycastOBB, IdentityBoxAlongX) {
    // Box [-1,1]^3 at (5,0,0) -> spans x in [4,6]. Ray from origin along +X enters the -X face at t = 4.
    OBB box(vec3(5, 0, 0), vec3(1, 1, 1));
    RaycastResult r;
    ASSERT_TRUE(Raycast(box, MakeRay(vec3(0, 0, 0), vec3(1, 0, 0)), &r));
    EXPECT_TRUE(r.hit);
    EXPECT_NEAR(r.t, 4.0f, tol::kExact);
    EXPECT_TRUE(VecNear(r.point, vec3(4, 0, 0), tol::kExact));
    EXPECT_TRUE(VecNear(r.normal, vec3(-1, 0, 0), tol::kExact));
}

TEST(RaycastOBB, RotatedBoxHitsCornerFaceWithRotatedNormal) {
    // Box rotated 45 degrees about Y (yaw): local X = (c,0,-s), local Z = (s,0,c). A ray along +Z from
    // (0,0,-5) hits the vertex edge at the point where the local +-X and -Z faces meet: that edge lies at
    // distance sqrt(2) (half-diagonal of the unit-half-size square) from the centre on the -Z side.
    OBB box(vec3(0, 0, 0), vec3(1, 1, 1), Rotation3x3(0, 45, 0));
    RaycastResult r;
    ASSERT_TRUE(Raycast(box, MakeRay(vec3(0, 0, -5), vec3(0, 0, 1)), &r));
    EXPECT_NEAR(r.t, 5.0f - std::sqrt(2.0f), tol::kTight);
    EXPECT_NEAR(Magnitude(r.normal), 1.0f, tol::kTight);
    EXPECT_LE(Dot(r.normal, vec3(0, 0, 1)), 0.0f);
    // Offset the ray so it clearly enters one face. Point (0.5, 0, z): local x = 0.5c - zs (3.89 at z = -5,
    // outside the +X face) and local z = 0.5s + zc. It reaches local x = 1 at z = (0.5c - 1)/s = -0.914 and
    // local z = -1 earlier, at z = -1.914, so the +X face is the one entered: normal = +local X.
    ASSERT_TRUE(Raycast(box, MakeRay(vec3(0.5f, 0, -5), vec3(0, 0, 1)), &r));
    const float c = std::cos(DEG2RAD(45.0f)), s = std::sin(DEG2RAD(45.0f));
    const float zHit = (0.5f * c - 1.0f) / s;
    EXPECT_NEAR(r.point.z, zHit, tol::kTight);
    EXPECT_NEAR(r.t, zHit + 5.0f, tol::kTight);
    EXPECT_TRUE(VecNear(r.normal, vec3(c, 0, -s), tol::kTight));
}

TEST(RaycastOBB, ParallelToSlabInsideAndOutside) {
    // Rotated box; a ray parallel to the local Y slab. Inside the slab it hits, outside it misses - per axis
    // (erratum 5.1-3: the book tested the X offset e.x for every slab, so a ray parallel to Y and Z with a
    // small X offset but a large Y offset was accepted).
    const mat3 rot = Rotation3x3(0, 30, 0);  // yaw only: local Y stays world Y
    OBB box(vec3(0, 0, 0), vec3(1, 1, 1), rot);
    RaycastResult r;
    EXPECT_TRUE(Raycast(box, MakeRay(vec3(0, 0.5f, -5), vec3(0, 0, 1)), &r));
    EXPECT_FALSE(Raycast(box, MakeRay(vec3(0, 1.5f, -5), vec3(0, 0, 1)), &r));
    EXPECT_FALSE(Raycast(box, MakeRay(vec3(0, -1.5f, -5), vec3(0, 0, 1)), &r));
    // Identity box, ray along +X (parallel to the Y and Z slabs), X offset 0 but Y offset 3: the book's
    // e.x typo compares the X offset (0, inside) for the Y slab and would not reject here.
    OBB unit(vec3(0, 0, 0), vec3(1, 1, 1));
    EXPECT_FALSE(Raycast(unit, MakeRay(vec3(-5, 3, 0), vec3(1, 0, 0)), &r));
    EXPECT_FALSE(Raycast(unit, MakeRay(vec3(-5, 0, 3), vec3(1, 0, 0)), &r));
    EXPECT_TRUE(AllFinite(r));
}

TEST(RaycastOBB, OriginOnSlabPlaneParallelGrazesBothFaces) {
    // erratum 5.1-2/5.1-3: ray along +X lying exactly in the +Y face plane, and in the -Y face plane. Both
    // touch the closed box at x = -1 (t = 4). The repo's 1e-5 substitute gives t3 = -2e5, t4 = 0 for the +Y
    // plane, so tmax = 0 < tmin = 4 and it misses on +Y while hitting on -Y; the printed book divides 0/0.
    OBB box(vec3(0, 0, 0), vec3(1, 1, 1));
    for (float y : {1.0f, -1.0f}) {
        RaycastResult r;
        ASSERT_TRUE(Raycast(box, MakeRay(vec3(-5, y, 0), vec3(1, 0, 0)), &r)) << "y = " << y;
        EXPECT_NEAR(r.t, 4.0f, tol::kExact);
        EXPECT_TRUE(VecNear(r.normal, vec3(-1, 0, 0), tol::kExact));
        EXPECT_TRUE(AllFinite(r));
    }
}

TEST(RaycastOBB, StartingInsideReportsExitWithOutwardNormal) {
    OBB box(vec3(0, 0, 0), vec3(2, 1, 1));
    RaycastResult r;
    ASSERT_TRUE(Raycast(box, MakeRay(vec3(0.5f, 0, 0), vec3(1, 0, 0)), &r));
    EXPECT_NEAR(r.t, 1.5f, tol::kExact);
    EXPECT_TRUE(VecNear(r.normal, vec3(1, 0, 0), tol::kExact));
}

TEST(RaycastOBB, StartingOnFaceAndPointingAway) {
    OBB box(vec3(0, 0, 0), vec3(1, 1, 1));
    RaycastResult r;
    // On the -X face looking in: t = 0, normal -X.
    ASSERT_TRUE(Raycast(box, MakeRay(vec3(-1, 0, 0), vec3(1, 0, 0)), &r));
    EXPECT_NEAR(r.t, 0.0f, tol::kExact);
    EXPECT_TRUE(VecNear(r.normal, vec3(-1, 0, 0), tol::kExact));
    // Outside, pointing away: miss.
    EXPECT_FALSE(Raycast(box, MakeRay(vec3(-3, 0, 0), vec3(-1, 0, 0)), &r));
    EXPECT_FALSE(r.hit);
    EXPECT_FLOAT_EQ(r.t, -1.0f);
}

TEST(RaycastOBB, ZeroDirectionNeverHits) {
    OBB box(vec3(0, 0, 0), vec3(1, 1, 1));
    Ray ray;
    ray.origin = vec3(0, 0, 0);
    ray.direction = vec3(0, 0, 0);
    RaycastResult r;
    EXPECT_FALSE(Raycast(box, ray, &r));
    EXPECT_FALSE(Raycast(box, ray, nullptr));
}

// ---- AABB ---------------------------------------------------------------------------------------------

TEST(RaycastAABB, EveryFaceNormalIncludingPlusXAndPlusY) {
    // erratum 5.1-1: the book's +X and +Y normals are the comma expression (1,0,0) == 0, i.e. zero vectors.
    AABB box(vec3(4, 2, 0), vec3(1, 1, 1));
    struct Case {
        vec3 origin, dir, normal;
        float t;
    };
    const Case cases[] = {
        {vec3(0, 2, 0), vec3(1, 0, 0), vec3(-1, 0, 0), 3},  {vec3(9, 2, 0), vec3(-1, 0, 0), vec3(1, 0, 0), 4},
        {vec3(4, -3, 0), vec3(0, 1, 0), vec3(0, -1, 0), 4}, {vec3(4, 6, 0), vec3(0, -1, 0), vec3(0, 1, 0), 3},
        {vec3(4, 2, -5), vec3(0, 0, 1), vec3(0, 0, -1), 4}, {vec3(4, 2, 5), vec3(0, 0, -1), vec3(0, 0, 1), 4},
    };
    for (const Case& c : cases) {
        RaycastResult r;
        ASSERT_TRUE(Raycast(box, MakeRay(c.origin, c.dir), &r));
        EXPECT_NEAR(r.t, c.t, tol::kExact);
        EXPECT_TRUE(VecNear(r.normal, c.normal, tol::kExact));
        EXPECT_TRUE(VecNear(r.point, c.origin + c.dir * c.t, tol::kExact));
    }
}

TEST(RaycastAABB, ParallelToFaceInsideOutsideAndOnThePlane) {
    // erratum 5.1-2: zero direction components. The book divides by 0 (inf; NaN for an origin on the plane).
    AABB box(vec3(0, 0, 0), vec3(1, 1, 1));
    RaycastResult r;
    EXPECT_TRUE(Raycast(box, MakeRay(vec3(-5, 0.5f, 0.5f), vec3(1, 0, 0)), &r));  // inside the Y and Z slabs
    EXPECT_FALSE(Raycast(box, MakeRay(vec3(-5, 1.5f, 0), vec3(1, 0, 0)), &r));    // outside the Y slab
    EXPECT_FALSE(Raycast(box, MakeRay(vec3(-5, 0, -1.01f), vec3(1, 0, 0)), &r));  // outside the Z slab
    // Exactly on the +Y, -Y, +Z planes: grazing the closed box, hit at the -X face. The repo's 1e-5
    // substitute misses the +Y and +Z cases (tmax = 0 < tmin = 4) and hits the -Y one.
    for (const vec3& o : {vec3(-5, 1, 0), vec3(-5, -1, 0), vec3(-5, 0, 1), vec3(-5, 1, 1)}) {
        ASSERT_TRUE(Raycast(box, MakeRay(o, vec3(1, 0, 0)), &r)) << o.y << " " << o.z;
        EXPECT_NEAR(r.t, 4.0f, tol::kExact);
        EXPECT_TRUE(VecNear(r.normal, vec3(-1, 0, 0), tol::kExact));
        EXPECT_TRUE(AllFinite(r));
    }
}

TEST(RaycastAABB, InsideOnFaceAwayAndGrazingEdge) {
    AABB box(vec3(0, 0, 0), vec3(1, 2, 3));
    RaycastResult r;
    ASSERT_TRUE(Raycast(box, MakeRay(vec3(0, 0, 0), vec3(0, 1, 0)), &r));  // inside: exit through +Y
    EXPECT_NEAR(r.t, 2.0f, tol::kExact);
    EXPECT_TRUE(VecNear(r.normal, vec3(0, 1, 0), tol::kExact));
    ASSERT_TRUE(Raycast(box, MakeRay(vec3(0, 0, -3), vec3(0, 0, 1)), &r));  // on the -Z face, looking in
    EXPECT_NEAR(r.t, 0.0f, tol::kExact);
    EXPECT_TRUE(VecNear(r.normal, vec3(0, 0, -1), tol::kExact));
    EXPECT_FALSE(Raycast(box, MakeRay(vec3(0, 0, -4), vec3(0, 0, -1)), &r));  // pointing away
    // Diagonal ray in the XY plane through the edge x = 1, y = 2 only: from (0, 3) along (1,-1)/sqrt2 it
    // touches the corner edge at (1, 2) at t = sqrt2, where the X and Y slabs open and close together.
    ASSERT_TRUE(Raycast(box, MakeRay(vec3(0, 3, 0), Normalized(vec3(1, -1, 0))), &r));
    EXPECT_NEAR(r.t, std::sqrt(2.0f), tol::kTight);
    EXPECT_TRUE(VecNear(r.point, vec3(1, 2, 0), tol::kTight));
    // Shifted outward by 0.01 it misses.
    EXPECT_FALSE(Raycast(box, MakeRay(vec3(0.01f, 3.01f, 0), Normalized(vec3(1, -1, 0))), &r));
}

// ---- Sphere -------------------------------------------------------------------------------------------

TEST(RaycastSphere, FrontInsideTangentAndBehind) {
    Sphere sphere(vec3(0, 0, 5), 2);
    RaycastResult r;
    ASSERT_TRUE(Raycast(sphere, MakeRay(vec3(0, 0, 0), vec3(0, 0, 1)), &r));
    EXPECT_NEAR(r.t, 3.0f, tol::kExact);
    EXPECT_TRUE(VecNear(r.normal, vec3(0, 0, -1), tol::kExact));
    ASSERT_TRUE(Raycast(sphere, MakeRay(vec3(0, 0, 5), vec3(0, 1, 0)), &r));  // from the centre: exit
    EXPECT_NEAR(r.t, 2.0f, tol::kExact);
    EXPECT_TRUE(VecNear(r.normal, vec3(0, 1, 0), tol::kExact));
    ASSERT_TRUE(Raycast(sphere, MakeRay(vec3(2, -5, 5), vec3(0, 1, 0)), &r));  // tangent at (2,0,5)
    EXPECT_NEAR(r.t, 5.0f, tol::kTight);
    EXPECT_TRUE(VecNear(r.normal, vec3(1, 0, 0), tol::kTight));
    EXPECT_FALSE(Raycast(sphere, MakeRay(vec3(2.01f, -5, 5), vec3(0, 1, 0)), &r));  // just past tangent
}

TEST(RaycastSphere, SphereBehindOriginIsAMiss) {
    // erratum 5.2-7: the book returns hit with t = a - f = -5 - 2 = -7 for this sphere behind the origin.
    Sphere sphere(vec3(0, 0, -5), 2);
    RaycastResult r;
    EXPECT_FALSE(Raycast(sphere, MakeRay(vec3(0, 0, 0), vec3(0, 0, 1)), &r));
    EXPECT_FALSE(r.hit);
    EXPECT_FLOAT_EQ(r.t, -1.0f);
}

// ---- Plane and triangle ----------------------------------------------------------------------------------

TEST(RaycastPlane, OneSidedAsTheBook) {
    Plane plane(vec3(0, 1, 0), 2);  // y = 2, facing +Y
    RaycastResult r;
    ASSERT_TRUE(Raycast(plane, MakeRay(vec3(1, 5, 1), vec3(0, -1, 0)), &r));
    EXPECT_NEAR(r.t, 3.0f, tol::kExact);
    EXPECT_TRUE(VecNear(r.point, vec3(1, 2, 1), tol::kExact));
    EXPECT_TRUE(VecNear(r.normal, vec3(0, 1, 0), tol::kExact));
    EXPECT_FALSE(Raycast(plane, MakeRay(vec3(1, -5, 1), vec3(0, 1, 0)), &r));  // from behind
    EXPECT_FALSE(Raycast(plane, MakeRay(vec3(1, 5, 1), vec3(1, 0, 0)), &r));   // parallel
    EXPECT_FALSE(Raycast(plane, MakeRay(vec3(1, 1, 1), vec3(0, -1, 0)), &r));  // plane behind the origin
    // Un-normalised plane normal: t is still a distance and the normal comes back unit.
    ASSERT_TRUE(Raycast(Plane(vec3(0, 2, 0), 4), MakeRay(vec3(0, 5, 0), vec3(0, -1, 0)), &r));
    EXPECT_NEAR(r.t, 3.0f, tol::kExact);
    EXPECT_TRUE(VecNear(r.normal, vec3(0, 1, 0), tol::kExact));
}

TEST(RaycastTriangle, DemoTriangleIsOneSided) {
    // docs/book-reference.md §2.0: a (0,3,0), b (-1,1,0), c (1,1,0) has normal +Z, so +Z rays from the camera miss it.
    Triangle tri(vec3(0, 3, 0), vec3(-1, 1, 0), vec3(1, 1, 0));
    const Plane plane = FromTriangle(tri);
    EXPECT_TRUE(VecNear(plane.normal, vec3(0, 0, 1), tol::kExact));
    RaycastResult r;
    EXPECT_FALSE(Raycast(tri, MakeRay(vec3(0, 2, -10), vec3(0, 0, 1)), &r));
    ASSERT_TRUE(Raycast(tri, MakeRay(vec3(0, 2, 10), vec3(0, 0, -1)), &r));
    EXPECT_NEAR(r.t, 10.0f, tol::kExact);
    EXPECT_TRUE(VecNear(r.normal, vec3(0, 0, 1), tol::kExact));
    EXPECT_FALSE(Raycast(tri, MakeRay(vec3(0.9f, 2.5f, 10), vec3(0, 0, -1)), &r));  // in the plane, outside
    ASSERT_TRUE(Raycast(tri, MakeRay(vec3(0, 3, 10), vec3(0, 0, -1)), &r));         // exactly on vertex a
    EXPECT_FALSE(Raycast(Triangle(vec3(0, 0, 0), vec3(1, 1, 1), vec3(2, 2, 2)), MakeRay(vec3(1, 1, -5), vec3(0, 0, 1)),
                         &r));  // degenerate triangle: no plane, no hit
}

TEST(RaycastTriangle, BarycentricWeights) {
    Triangle tri(vec3(0, 0, 0), vec3(4, 0, 0), vec3(0, 4, 0));
    EXPECT_TRUE(VecNear(Barycentric(vec3(0, 0, 0), tri), vec3(1, 0, 0), tol::kExact));
    EXPECT_TRUE(VecNear(Barycentric(vec3(4, 0, 0), tri), vec3(0, 1, 0), tol::kExact));
    EXPECT_TRUE(VecNear(Barycentric(vec3(1, 2, 0), tri), vec3(0.25f, 0.25f, 0.5f), tol::kExact));
    EXPECT_TRUE(VecNear(Barycentric(vec3(1, 2, 7), tri), vec3(0.25f, 0.25f, 0.5f), tol::kExact));  // projected
    EXPECT_LT(Barycentric(vec3(5, 5, 0), tri).x, 0.0f);
}

// ---- Properties over seeded random rays ------------------------------------------------------------------

namespace {

/// Checks a hit: t >= 0 is the distance to the point, the point lies on the surface (signed distance from
/// `surfaceDistance` within 1e-4 for shapes of size ~1..3 at distances up to ~20), the normal is unit and
/// faces the ray unless the origin is inside.
template <typename SurfaceDistance>
::testing::AssertionResult GoodHit(const Ray& ray, const RaycastResult& r, bool originInside,
                                   SurfaceDistance surfaceDistance) {
    if (!r.hit || !(r.t >= 0.0f)) return ::testing::AssertionFailure() << "t " << r.t;
    if (std::fabs(Distance(ray.origin, r.point) - r.t) > 1e-4f) return ::testing::AssertionFailure() << "t != |p-o|";
    if (std::fabs(surfaceDistance(r.point)) > 1e-4f)
        return ::testing::AssertionFailure() << "off surface by " << surfaceDistance(r.point);
    if (std::fabs(Magnitude(r.normal) - 1.0f) > 1e-5f) return ::testing::AssertionFailure() << "normal not unit";
    if (!originInside && Dot(r.normal, ray.direction) > 1e-6f)
        return ::testing::AssertionFailure() << "normal faces away from the ray";
    return ::testing::AssertionSuccess();
}

/// Signed distance to an OBB surface along its axes (max of |local_i| - size_i): 0 on the surface.
float BoxSurface(const OBB& box, const Point& p) {
    float d = -1e30f;
    for (int i = 0; i < 3; ++i) {
        const vec3 axis = Normalized(GetRow(box.orientation, i));
        d = std::fmax(d, std::fabs(Dot(p - box.position, axis)) - box.size[i]);
    }
    return d;
}

}  // namespace

TEST(RaycastProperties, RandomRaysAgainstAllShapes) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<float> u(-1, 1), pos(-8, 8), half(0.3f, 3), ang(-180, 180);
    int hits[4] = {0, 0, 0, 0};
    for (int i = 0; i < 4000; ++i) {
        const vec3 origin(pos(rng), pos(rng), pos(rng));
        vec3 dir(u(rng), u(rng), u(rng));
        if (i % 5 == 0) dir[i % 3] = 0.0f;  // a fifth of the rays lie parallel to a slab
        if (MagnitudeSq(dir) < 1e-4f) continue;
        // Aim most rays near the shapes so that hits are common.
        const Ray ray = MakeRay(origin, i % 2 ? dir : Normalized(vec3(u(rng), u(rng), u(rng)) - origin));
        if (MagnitudeSq(ray.direction) == 0.0f) continue;

        const Sphere sphere(vec3(u(rng), u(rng), u(rng)), half(rng));
        const AABB aabb(vec3(u(rng), u(rng), u(rng)), vec3(half(rng), half(rng), half(rng)));
        const OBB obb(vec3(u(rng), u(rng), u(rng)), vec3(half(rng), half(rng), half(rng)),
                      Rotation3x3(ang(rng), ang(rng), ang(rng)));
        const Triangle tri(vec3(pos(rng), pos(rng), pos(rng)) * 0.3f, vec3(pos(rng), pos(rng), pos(rng)) * 0.3f,
                           vec3(pos(rng), pos(rng), pos(rng)) * 0.3f);
        RaycastResult r;
        if (Raycast(sphere, ray, &r)) {
            ++hits[0];
            ASSERT_TRUE(GoodHit(ray, r, PointInSphere(ray.origin, sphere), [&](const Point& p) {
                return Distance(p, sphere.position) - sphere.radius;
            })) << i;
        } else {
            // Miss: the closest approach of the ray (t >= 0) is outside the sphere.
            const float t = std::fmax(Dot(sphere.position - ray.origin, ray.direction), 0.0f);
            ASSERT_GT(Distance(ray.origin + ray.direction * t, sphere.position), sphere.radius * (1 - 1e-5f)) << i;
        }
        EXPECT_TRUE(AllFinite(r));
        const OBB aabbAsObb(aabb.position, aabb.size);
        if (Raycast(aabb, ray, &r)) {
            ++hits[1];
            ASSERT_TRUE(GoodHit(ray, r, PointInAABB(ray.origin, aabb), [&](const Point& p) {
                return BoxSurface(aabbAsObb, p);
            })) << i;
        }
        EXPECT_TRUE(AllFinite(r));
        // The AABB and the identity OBB of the same box agree.
        RaycastResult rObb;
        ASSERT_EQ(Raycast(aabb, ray, &r), Raycast(aabbAsObb, ray, &rObb)) << i;
        if (r.hit) {
            ASSERT_NEAR(r.t, rObb.t, 1e-5f) << i;
        }
        if (Raycast(obb, ray, &r)) {
            ++hits[2];
            ASSERT_TRUE(GoodHit(ray, r, PointInOBB(ray.origin, obb), [&](const Point& p) {
                return BoxSurface(obb, p);
            })) << i;
        } else {
            // Miss: no sampled point along the ray lies strictly inside the box (shrunk by 1e-4).
            OBB shrunk = obb;
            shrunk.size = obb.size - vec3(1e-4f, 1e-4f, 1e-4f);
            for (float t = 0; t < 30; t += 0.01f) ASSERT_FALSE(PointInOBB(ray.origin + ray.direction * t, shrunk)) << i;
        }
        EXPECT_TRUE(AllFinite(r));
        if (Raycast(tri, ray, &r)) {
            ++hits[3];
            const Plane plane = FromTriangle(tri);
            ASSERT_TRUE(GoodHit(ray, r, false, [&](const Point& p) { return PlaneEquation(p, plane); })) << i;
            const vec3 bc = Barycentric(r.point, tri);
            ASSERT_TRUE(bc.x >= 0 && bc.y >= 0 && bc.z >= 0) << i;
        }
    }
    // The sample must actually exercise hits.
    for (int k = 0; k < 4; ++k) EXPECT_GT(hits[k], 100) << "shape " << k;
}
