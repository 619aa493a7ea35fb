// ManifoldReuse.cpp: a box-box manifold kept in the boxes' frames (KeepLocal) and re-expressed at later poses
// (ReuseLocal) while the pair has moved less than the reuse distance (docs/soft-solver.md, "Manifold reuse").
#include <gtest/gtest.h>

#include <cmath>

#include "Physics/Geometry/ContactManifold.h"
#include "Physics/Geometry/Geometry3D.h"
#include "tests/support/Approx.h"

namespace {

const OBB kGround(vec3(0, -0.5f, 0), vec3(5, 0.5f, 5));
constexpr float kMargin = 0.02f;

/// A cube of half extent 0.5 tilted 0.3 degree about x and 0.2 about z, its lowest corner 1 mm into the ground:
/// four points of four different separations.
OBB TiltedCube(const vec3& shift = vec3()) {
    OBB cube(vec3(0, 0, 0), vec3(0.5f, 0.5f, 0.5f), XRotation3x3(0.3f) * ZRotation3x3(0.2f));
    float lowest = 0.0f;
    for (const vec3& v : GetVertices(cube)) lowest = std::fmin(lowest, v.y);
    cube.position = vec3(0, -lowest - 0.001f, 0) + shift;
    return cube;
}

/// The point of `m` with feature id `id` (nullptr when none has it).
const ManifoldPoint* WithId(const ContactManifold& m, std::uint32_t id) {
    for (int i = 0; i < m.pointCount; ++i)
        if (m.points[i].id == id) return &m.points[i];
    return nullptr;
}

}  // namespace

TEST(ManifoldReuse, AtTheSamePosesGivesBackTheManifold) {
    const OBB cube = TiltedCube();
    ContactManifold fresh;
    CollideBoxes(kGround, cube, kMargin, &fresh);
    ASSERT_EQ(fresh.pointCount, 4);
    LocalManifold kept;
    KeepLocal(kGround, cube, fresh, &kept);
    ContactManifold reused;
    ASSERT_TRUE(ReuseLocal(kGround, cube, kept, 0.001f, &reused));
    ASSERT_EQ(reused.pointCount, fresh.pointCount);
    EXPECT_TRUE(VecNear(reused.normal, fresh.normal, tol::kExact));
    for (int i = 0; i < fresh.pointCount; ++i) {
        EXPECT_EQ(reused.points[i].id, fresh.points[i].id);
        EXPECT_TRUE(VecNear(reused.points[i].point, fresh.points[i].point, tol::kTight)) << "point " << i;
        EXPECT_NEAR(reused.points[i].separation, fresh.points[i].separation, tol::kTight) << "point " << i;
    }
}

// Sunk 0.4 mm and slid 0.3 mm (0.5 mm in all, under the 1 mm reuse distance): the reused points are the same
// corners, so each separation is what colliding anew gives for the point with the same id (the reference face
// is the ground's, so a corner's height above it is exact at any pose). The swapped pair (the cube as A, its
// normal turned with the cube) agrees to a few micrometres.
TEST(ManifoldReuse, SmallMotionFollowsTheFreshSeparations) {
    const OBB start = TiltedCube();
    const OBB moved = TiltedCube(vec3(0.0003f, -0.0004f, 0.0f));
    for (const bool swap : {false, true}) {
        const OBB& a0 = swap ? start : kGround;
        const OBB& b0 = swap ? kGround : start;
        const OBB& a1 = swap ? moved : kGround;
        const OBB& b1 = swap ? kGround : moved;
        ContactManifold first, fresh, reused;
        CollideBoxes(a0, b0, kMargin, &first);
        CollideBoxes(a1, b1, kMargin, &fresh);
        ASSERT_EQ(first.pointCount, 4);
        ASSERT_EQ(fresh.pointCount, 4);
        LocalManifold kept;
        KeepLocal(a0, b0, first, &kept);
        ASSERT_TRUE(ReuseLocal(a1, b1, kept, 0.001f, &reused)) << "swap " << swap;
        ASSERT_EQ(reused.pointCount, 4);
        EXPECT_TRUE(VecNear(reused.normal, fresh.normal, tol::kExact));
        for (int i = 0; i < 4; ++i) {
            const ManifoldPoint* match = WithId(fresh, reused.points[i].id);
            ASSERT_NE(match, nullptr) << "swap " << swap << " point " << i;
            EXPECT_NEAR(reused.points[i].separation, match->separation, swap ? 5e-6f : tol::kTight);
            EXPECT_NEAR(reused.points[i].separation, first.points[i].separation - 0.0004f, 5e-6f);
            EXPECT_TRUE(VecNear(reused.points[i].point, match->point, 5e-6f));
        }
    }
}

// 1.2 mm of slide, or a turn of 0.1 degree (the bound on the motion, sqrt(2) x 0.1 degree x the cube's bounding
// radius of 0.87 m, is 2.1 mm), is past the 1 mm reuse distance: refused, and the output is left alone; within 3 mm
// both are reused. A kept manifold without points is never reused.
TEST(ManifoldReuse, MotionPastTheDistanceIsRefused) {
    const OBB start = TiltedCube();
    ContactManifold first;
    CollideBoxes(kGround, start, kMargin, &first);
    LocalManifold kept;
    KeepLocal(kGround, start, first, &kept);
    OBB turned = start;
    turned.orientation = start.orientation * YRotation3x3(0.1f);
    for (const OBB& cube : {TiltedCube(vec3(0.0012f, 0, 0)), turned}) {
        ContactManifold out;
        out.pointCount = -1;
        EXPECT_FALSE(ReuseLocal(kGround, cube, kept, 0.001f, &out));
        EXPECT_EQ(out.pointCount, -1);
        EXPECT_TRUE(ReuseLocal(kGround, cube, kept, 0.003f, &out)) << "within a 3 mm distance";
    }
    LocalManifold empty;
    ContactManifold out;
    EXPECT_FALSE(ReuseLocal(kGround, start, empty, 1.0f, &out));
}
