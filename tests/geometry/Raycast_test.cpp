// Raycast.cpp: hand-computed raycasts for every shape (edge cases spelled out) and seeded property tests.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "Approx.h"
#include "Geometry3D.h"

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

TEST(LinetestOBB, HandComputedSegments) {
    OBB box(vec3(0, 0, 0), vec3(1, 1, 1), Rotation3x3(30, 20, 0));
    EXPECT_TRUE(Linetest(box, Line(vec3(-5, 0, 0), vec3(5, 0, 0))));    // through the centre
    EXPECT_FALSE(Linetest(box, Line(vec3(-5, 0, 0), vec3(-3, 0, 0))));  // stops short
    EXPECT_FALSE(Linetest(box, Line(vec3(-5, 5, 0), vec3(5, 5, 0))));   // passes above
    EXPECT_TRUE(Linetest(box, Line(vec3(-5, 0, 0), vec3(0, 0, 0))));    // ends inside
}

TEST(LinetestOBB, ZeroLengthSegmentTestsItsPoint) {
    // erratum 5.1-5: the book normalises a zero segment into a NaN ray and always misses.
    OBB box(vec3(1, 2, 3), vec3(1, 1, 1));
    EXPECT_TRUE(Linetest(box, Line(vec3(1.5f, 2, 3), vec3(1.5f, 2, 3))));
    EXPECT_FALSE(Linetest(box, Line(vec3(5, 2, 3), vec3(5, 2, 3))));
}

TEST(LinetestOBB, SegmentWhollyInsideTouches) {
    // erratum R-1 (docs/errata/raycast.md): the book raycasts from start and compares the exit t = 1.9 with
    // the length 0.2, returning false for a segment wholly inside the box.
    OBB box(vec3(0, 0, 0), vec3(2, 2, 2));
    EXPECT_TRUE(Linetest(box, Line(vec3(0.1f, 0, 0), vec3(0.3f, 0, 0))));
}
