// Linetest.cpp: hand-computed segments for every shape, and agreement with Raycast over seeded random segments.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "Physics/Geometry/Geometry3D.h"
#include "tests/support/Approx.h"

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
    // erratum R-1 (docs/ERRATA.md, Raycasts): the book raycasts from start and compares the exit t = 1.9 with
    // the length 0.2, returning false for a segment wholly inside the box.
    OBB box(vec3(0, 0, 0), vec3(2, 2, 2));
    EXPECT_TRUE(Linetest(box, Line(vec3(0.1f, 0, 0), vec3(0.3f, 0, 0))));
}

TEST(LinetestAABB, HandComputedSegments) {
    AABB box(vec3(0, 0, 0), vec3(1, 1, 1));
    EXPECT_TRUE(Linetest(box, Line(vec3(-3, 0, 0), vec3(-1, 0, 0))));                  // ends exactly on the face
    EXPECT_FALSE(Linetest(box, Line(vec3(-3, 0, 0), vec3(-1.01f, 0, 0))));             // stops short
    EXPECT_TRUE(Linetest(box, Line(vec3(-3, 1, 0), vec3(3, 1, 0))));                   // lies in the +Y face plane
    EXPECT_TRUE(Linetest(box, Line(vec3(0.5f, 0.5f, 0.5f), vec3(0.6f, 0.5f, 0.5f))));  // wholly inside
    EXPECT_TRUE(Linetest(box, Line(vec3(0.5f, 0, 0), vec3(0.5f, 0, 0))));              // zero length, inside
    EXPECT_FALSE(Linetest(box, Line(vec3(2, 0, 0), vec3(2, 0, 0))));                   // zero length, outside
}

TEST(LinetestSphere, ClosestPointWithinRadius) {
    Sphere sphere(vec3(0, 0, 0), 1);
    EXPECT_TRUE(Linetest(sphere, Line(vec3(-2, 0.5f, 0), vec3(2, 0.5f, 0))));
    EXPECT_TRUE(Linetest(sphere, Line(vec3(-2, 1, 0), vec3(2, 1, 0))));  // tangent
    EXPECT_FALSE(Linetest(sphere, Line(vec3(-2, 1.01f, 0), vec3(2, 1.01f, 0))));
    EXPECT_FALSE(Linetest(sphere, Line(vec3(-5, 0, 0), vec3(-2, 0, 0))));     // on the line, but short
    EXPECT_TRUE(Linetest(sphere, Line(vec3(0.1f, 0, 0), vec3(0.2f, 0, 0))));  // inside
}

TEST(LinetestPlane, CrossingParallelAndInPlane) {
    Plane plane(vec3(0, 1, 0), 1);  // y = 1
    EXPECT_TRUE(Linetest(plane, Line(vec3(0, 0, 0), vec3(0, 2, 0))));
    EXPECT_TRUE(Linetest(plane, Line(vec3(0, 2, 0), vec3(0, 0, 0))));  // two-sided
    EXPECT_TRUE(Linetest(plane, Line(vec3(0, 0, 0), vec3(0, 1, 0))));  // ends on it
    EXPECT_FALSE(Linetest(plane, Line(vec3(0, 0, 0), vec3(0, 0.99f, 0))));
    EXPECT_FALSE(Linetest(plane, Line(vec3(0, 0, 0), vec3(5, 0, 0))));  // parallel, off the plane
    // Lying in the plane: touches (the book's parallel rule returns false).
    EXPECT_TRUE(Linetest(plane, Line(vec3(0, 1, 0), vec3(5, 1, 0))));
}

TEST(LinetestTriangle, BothSidesEdgesAndCoplanar) {
    Triangle tri(vec3(0, 0, 0), vec3(4, 0, 0), vec3(0, 4, 0));        // normal +Z
    EXPECT_TRUE(Linetest(tri, Line(vec3(1, 1, 5), vec3(1, 1, -5))));  // against the normal
    // erratum R-2: from behind. The book raycasts the one-sided triangle and returns false.
    EXPECT_TRUE(Linetest(tri, Line(vec3(1, 1, -5), vec3(1, 1, 5))));
    EXPECT_FALSE(Linetest(tri, Line(vec3(1, 1, 5), vec3(1, 1, 0.1f))));  // stops short
    EXPECT_FALSE(Linetest(tri, Line(vec3(3, 3, 5), vec3(3, 3, -5))));    // crosses the plane outside
    EXPECT_TRUE(Linetest(tri, Line(vec3(2, 0, 5), vec3(2, 0, -5))));     // through an edge
    // Coplanar segments: crossing the triangle, wholly outside, and touching only at a vertex.
    EXPECT_TRUE(Linetest(tri, Line(vec3(-1, 1, 0), vec3(5, 1, 0))));
    EXPECT_FALSE(Linetest(tri, Line(vec3(3, 3, 0), vec3(5, 5, 0))));
    EXPECT_TRUE(Linetest(tri, Line(vec3(4, 0, 0), vec3(6, 0, 0))));
    EXPECT_TRUE(Linetest(tri, Line(vec3(1, 1, 0), vec3(1, 1, 0))));   // zero length, on the triangle
    EXPECT_FALSE(Linetest(tri, Line(vec3(1, 1, 1), vec3(1, 1, 1))));  // zero length, off it
}

TEST(LinetestProperties, AgreesWithRaycastWithinLength) {
    // For a start point outside the shape, Linetest == (Raycast hits with t <= length). Seeded.
    std::mt19937 rng(777);
    std::uniform_real_distribution<float> u(-1, 1), pos(-6, 6), half(0.3f, 2.5f), ang(-180, 180), len(0.1f, 12);
    int agreeHits = 0;
    for (int i = 0; i < 5000; ++i) {
        const vec3 start(pos(rng), pos(rng), pos(rng));
        vec3 dir = Normalized(vec3(u(rng), u(rng), u(rng)) - start);
        if (MagnitudeSq(dir) == 0.0f) continue;
        const Line line(start, start + dir * len(rng));
        const Ray ray(line.start, line.end - line.start);
        const float length = Length(line);
        const Sphere sphere(vec3(u(rng), u(rng), u(rng)), half(rng));
        const AABB aabb(vec3(u(rng), u(rng), u(rng)), vec3(half(rng), half(rng), half(rng)));
        const OBB obb(vec3(u(rng), u(rng), u(rng)), vec3(half(rng), half(rng), half(rng)),
                      Rotation3x3(ang(rng), ang(rng), ang(rng)));
        RaycastResult r;
        // Skip the measure-zero band where t ~ length (rounding may fall either way).
        auto check = [&](bool linetest, bool raycast, const char* what) {
            if (raycast && std::fabs(r.t - length) < 1e-4f) return;
            ASSERT_EQ(linetest, raycast && r.t <= length) << what << " case " << i;
            agreeHits += linetest ? 1 : 0;
        };
        if (!PointInSphere(start, sphere)) check(Linetest(sphere, line), Raycast(sphere, ray, &r), "sphere");
        if (!PointInAABB(start, aabb)) check(Linetest(aabb, line), Raycast(aabb, ray, &r), "aabb");
        if (!PointInOBB(start, obb)) check(Linetest(obb, line), Raycast(obb, ray, &r), "obb");
    }
    EXPECT_GT(agreeHits, 1000);
}
