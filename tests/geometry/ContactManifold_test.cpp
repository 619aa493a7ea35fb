// ContactManifold.cpp: solver manifolds (docs/soft-solver.md, "Solver manifolds"): face contacts with corner points and
// stable feature ids, speculative points within the margin, edge-on-face and edge-edge contacts, the reduction to
// four points, a seeded comparison with the book's manifolds, and the sphere pairs.
#include "Physics/Geometry/ContactManifold.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "Math/Random.h"
#include "Physics/Geometry/Geometry3D.h"
#include "tests/support/Approx.h"
#include "tests/support/BoxPoses.h"

namespace {

const OBB kGround(vec3(0, -0.5f, 0), vec3(5, 0.5f, 5));

OBB UnitCube(const vec3& centre, const mat3& orientation = mat3()) {
    return OBB(centre, vec3(0.5f, 0.5f, 0.5f), orientation);
}

bool HasPoint(const ContactManifold& m, const vec3& p, float eps) {
    for (int i = 0; i < m.pointCount; ++i)
        if (VecNear(m.points[i].point, p, eps)) return true;
    return false;
}

std::vector<std::uint32_t> SortedIds(const ContactManifold& m) {
    std::vector<std::uint32_t> ids;
    for (int i = 0; i < m.pointCount; ++i) ids.push_back(m.points[i].id);
    std::sort(ids.begin(), ids.end());
    return ids;
}

float MinSeparation(const ContactManifold& m) {
    float s = 3.4e38f;
    for (int i = 0; i < m.pointCount; ++i) s = std::min(s, m.points[i].separation);
    return s;
}

/// Every point lies midway between the surfaces: inside or on both boxes grown by |separation| / 2 + eps.
bool PointsBetweenSurfaces(const ContactManifold& m, const OBB& a, const OBB& b, float eps) {
    for (int i = 0; i < m.pointCount; ++i) {
        const float slack = std::fabs(m.points[i].separation) * 0.5f + eps;
        for (const OBB* box : {&a, &b}) {
            const vec3 d = m.points[i].point - box->position;
            for (int k = 0; k < 3; ++k)
                if (std::fabs(Dot(d, GetRow(box->orientation, k))) > box->size[k] + slack) return false;
        }
    }
    return true;
}

/// How far p lies from the surface of `box` (0 on it, > 0 off it, inside or outside).
float OffSurface(const OBB& box, const vec3& p) {
    const vec3 d = p - box.position;
    float outside = 0.0f, inside = 3.4e38f;
    for (int k = 0; k < 3; ++k) {
        const float over = std::fabs(Dot(d, GetRow(box.orientation, k))) - box.size[k];
        outside = std::max(outside, over);
        inside = std::min(inside, -over);
    }
    return outside > 0.0f ? outside : std::max(inside, 0.0f);
}

/// Each point sits midway: half its separation back along the normal lies on A's surface, half forward on B's.
bool EndsOnSurfaces(const ContactManifold& m, const OBB& a, const OBB& b, float eps) {
    for (int i = 0; i < m.pointCount; ++i) {
        const vec3 half = m.normal * (0.5f * m.points[i].separation);
        if (OffSurface(a, m.points[i].point - half) > eps || OffSurface(b, m.points[i].point + half) > eps)
            return false;
    }
    return true;
}

}  // namespace

// ---- Face contacts --------------------------------------------------------------------------------------

TEST(SolverManifoldBoxBox, RestingCubeGivesFourCornersAndSwapFlipsTheNormal) {
    const OBB cube = UnitCube(vec3(0, 0.5f, 0));
    ContactManifold m;
    CollideBoxes(kGround, cube, 0.02f, &m);
    ASSERT_EQ(m.pointCount, 4);
    EXPECT_TRUE(VecNear(m.normal, vec3(0, 1, 0), tol::kExact));
    for (const vec3& corner : {vec3(0.5f, 0, 0.5f), vec3(-0.5f, 0, 0.5f), vec3(-0.5f, 0, -0.5f), vec3(0.5f, 0, -0.5f)})
        EXPECT_TRUE(HasPoint(m, corner, tol::kTight));
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(m.points[i].separation, 0.0f, tol::kTight);
    const std::vector<std::uint32_t> ids = SortedIds(m);
    EXPECT_TRUE(std::adjacent_find(ids.begin(), ids.end()) == ids.end()) << "ids must be distinct";

    ContactManifold swapped;
    CollideBoxes(cube, kGround, 0.02f, &swapped);
    ASSERT_EQ(swapped.pointCount, 4);
    EXPECT_TRUE(VecNear(swapped.normal, vec3(0, -1, 0), tol::kExact));
    for (const vec3& corner : {vec3(0.5f, 0, 0.5f), vec3(-0.5f, 0, 0.5f), vec3(-0.5f, 0, -0.5f), vec3(0.5f, 0, -0.5f)})
        EXPECT_TRUE(HasPoint(swapped, corner, tol::kTight));
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(swapped.points[i].separation, 0.0f, tol::kTight);
}

TEST(SolverManifoldBoxBox, SmallMotionKeepsTheIds) {
    ContactManifold rest;
    CollideBoxes(kGround, UnitCube(vec3(0, 0.5f, 0)), 0.02f, &rest);
    ASSERT_EQ(rest.pointCount, 4);
    const std::vector<std::uint32_t> ids = SortedIds(rest);
    // Each id names the ground's top face (A, bits 8-15: face 2 * axis y + 0) and one bottom corner of the cube
    // (B, bits 0-7: a vertex on the negative side of y); swapping A and B swaps the two bytes.
    ContactManifold swappedRest;
    CollideBoxes(UnitCube(vec3(0, 0.5f, 0)), kGround, 0.02f, &swappedRest);
    ASSERT_EQ(swappedRest.pointCount, 4);
    std::vector<std::uint32_t> byteSwapped;
    for (std::uint32_t id : ids) {
        EXPECT_EQ(id >> 8, kFeatureFace | 2u);
        EXPECT_EQ(id & 0xF0u, kFeatureVertex);
        EXPECT_EQ(id & 2u, 2u);
        byteSwapped.push_back((id & 0xFFu) << 8 | id >> 8);
    }
    std::sort(byteSwapped.begin(), byteSwapped.end());
    EXPECT_EQ(SortedIds(swappedRest), byteSwapped);

    const OBB moved[] = {
        UnitCube(vec3(0.001f, 0.5f, 0)),                            // slid 1 mm along x
        UnitCube(vec3(0, 0.5f, -0.001f)),                           // slid 1 mm along z
        UnitCube(vec3(0, 0.499f, 0)),                               // sunk 1 mm
        UnitCube(vec3(0, 0.5f, 0), YRotation3x3(0.5f)),             // turned 0.5 degree about the normal
        UnitCube(vec3(0, 0.5f + 0.0044f, 0), XRotation3x3(0.5f)),   // tilted 0.5 degree (one edge lifts)
        UnitCube(vec3(0, 0.5f + 0.0044f, 0), ZRotation3x3(-0.5f)),  // tilted the other way about z
    };
    for (const OBB& cube : moved) {
        ContactManifold m;
        CollideBoxes(kGround, cube, 0.02f, &m);
        ASSERT_EQ(m.pointCount, 4);
        EXPECT_EQ(SortedIds(m), ids);
        // Swapped, the tilted cubes take the ground's face as the reference instead of the cube's (the flat cube
        // ties and keeps A's): the ids stay.
        ContactManifold swapped;
        CollideBoxes(cube, kGround, 0.02f, &swapped);
        ASSERT_EQ(swapped.pointCount, 4);
        EXPECT_EQ(SortedIds(swapped), SortedIds(swappedRest));
    }
}

TEST(SolverManifoldBoxBox, TiltedCubeSeparationsFollowTheCorners) {
    // Tilted 0.5 degree about x, resting on its -z edge: the +z corners are lifted by sin(0.5 deg) = 0.0087 m.
    const float lift = std::sin(DEG2RAD(0.5f));
    const mat3 tilt = XRotation3x3(0.5f);
    OBB cube = UnitCube(vec3(0, 0, 0), tilt);
    // Place the lowest corner on y = 0.
    float lowest = 0.0f;
    for (const vec3& v : GetVertices(cube)) lowest = std::min(lowest, v.y);
    cube.position.y -= lowest;
    ContactManifold m;
    CollideBoxes(kGround, cube, 0.02f, &m);
    ASSERT_EQ(m.pointCount, 4);
    int low = 0, high = 0;
    for (int i = 0; i < 4; ++i) {
        if (std::fabs(m.points[i].separation) < tol::kLoose) ++low;
        if (std::fabs(m.points[i].separation - lift) < tol::kLoose) ++high;
        // The point is midway: half the separation above the ground.
        EXPECT_NEAR(m.points[i].point.y, 0.5f * m.points[i].separation, tol::kTight);
    }
    EXPECT_EQ(low, 2);
    EXPECT_EQ(high, 2);
}

TEST(SolverManifoldBoxBox, SpeculativePointsWithinTheMarginOnly) {
    const OBB lifted = UnitCube(vec3(0, 0.51f, 0));
    ContactManifold m;
    CollideBoxes(kGround, lifted, 0.02f, &m);
    ASSERT_EQ(m.pointCount, 4);
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(m.points[i].separation, 0.01f, tol::kLoose);
        EXPECT_NEAR(m.points[i].point.y, 0.005f, tol::kLoose);
    }
    CollideBoxes(kGround, lifted, 0.005f, &m);
    EXPECT_EQ(m.pointCount, 0);
    // Margin 0: touching counts, a gap does not.
    CollideBoxes(kGround, UnitCube(vec3(0, 0.5f, 0)), 0.0f, &m);
    EXPECT_EQ(m.pointCount, 4);
    CollideBoxes(kGround, UnitCube(vec3(0, 0.5001f, 0)), 0.0f, &m);
    EXPECT_EQ(m.pointCount, 0);
    // Far away along a diagonal (the early outs): nothing.
    CollideBoxes(UnitCube(vec3(0, 0, 0)), UnitCube(vec3(3, 3, 3)), 0.02f, &m);
    EXPECT_EQ(m.pointCount, 0);
}

TEST(SolverManifoldBoxBox, CubeOnItsEdgeGivesTwoPoints) {
    // Rolled 40 degrees about z, resting on the edge between two faces: the edge's two ends touch.
    OBB cube = UnitCube(vec3(0, 0, 0), ZRotation3x3(40.0f));
    float lowest = 0.0f;
    for (const vec3& v : GetVertices(cube)) lowest = std::min(lowest, v.y);
    cube.position.y = -lowest - 0.003f;  // 3 mm into the ground
    ContactManifold m;
    CollideBoxes(kGround, cube, 0.01f, &m);
    ASSERT_EQ(m.pointCount, 2);
    EXPECT_TRUE(VecNear(m.normal, vec3(0, 1, 0), tol::kExact));
    for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(m.points[i].separation, -0.003f, tol::kLoose);
        EXPECT_NEAR(std::fabs(m.points[i].point.z), 0.5f, tol::kLoose);
    }
    EXPECT_NE(m.points[0].id, m.points[1].id);
}

TEST(SolverManifoldBoxBox, CrossedEdgesGiveOnePoint) {
    // A rolled 45 degrees about z (top edge along z at y = sqrt(1/2)); B rolled 45 degrees about x (bottom edge
    // along x), lowered so the edges cross 0.05 m deep.
    const float h = std::sqrt(0.5f);
    const OBB a = UnitCube(vec3(0, 0, 0), ZRotation3x3(45.0f));
    const OBB b = UnitCube(vec3(0, 2 * h - 0.05f, 0), XRotation3x3(45.0f));
    ContactManifold m;
    CollideBoxes(a, b, 0.02f, &m);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_TRUE(VecNear(m.normal, vec3(0, 1, 0), tol::kLoose));
    EXPECT_NEAR(m.points[0].separation, -0.05f, tol::kLoose);
    EXPECT_TRUE(VecNear(m.points[0].point, vec3(0, h - 0.025f, 0), tol::kLoose));
    EXPECT_EQ((m.points[0].id >> 8) & 0x30u, kFeatureEdge);
    EXPECT_EQ(m.points[0].id & 0x30u, kFeatureEdge);

    // Swapped: normal down, same point and separation.
    ContactManifold s;
    CollideBoxes(b, a, 0.02f, &s);
    ASSERT_EQ(s.pointCount, 1);
    EXPECT_TRUE(VecNear(s.normal, vec3(0, -1, 0), tol::kLoose));
    EXPECT_NEAR(s.points[0].separation, -0.05f, tol::kLoose);
    EXPECT_TRUE(VecNear(s.points[0].point, m.points[0].point, tol::kLoose));

    // 0.01 m apart: speculative with margin 0.02, nothing with margin 0.005.
    const OBB apart = UnitCube(vec3(0, 2 * h + 0.01f, 0), XRotation3x3(45.0f));
    CollideBoxes(a, apart, 0.02f, &m);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_NEAR(m.points[0].separation, 0.01f, tol::kLoose);
    CollideBoxes(a, apart, 0.005f, &m);
    EXPECT_EQ(m.pointCount, 0);
}

TEST(SolverManifoldBoxBox, OctagonIsReducedToFourIncludingTheDeepest) {
    // B turned 45 degrees about y over A's top face: the clip is an octagon (8 points). B is also tilted a little
    // so one side of the octagon is deeper.
    const OBB a = UnitCube(vec3(0, 0, 0));
    const OBB b = UnitCube(vec3(0, 0.99f, 0), XRotation3x3(1.0f) * YRotation3x3(45.0f) * ZRotation3x3(0.4f));
    ContactManifold m;
    CollideBoxes(a, b, 0.02f, &m);
    ASSERT_EQ(m.pointCount, 4);
    EXPECT_TRUE(VecNear(m.normal, vec3(0, 1, 0), tol::kExact));

    // The deepest point of B's bottom face over A's top face, by brute force on a grid of A's top face.
    const vec3 n = -GetRow(b.orientation, 1);  // B's face toward A
    const vec3 faceCentre = b.position + n * 0.5f;
    float deepest = 3.4e38f;
    for (int ix = 0; ix <= 400; ++ix)
        for (int iz = 0; iz <= 400; ++iz) {
            const float x = -0.5f + ix / 400.0f, z = -0.5f + iz / 400.0f;
            // Height of B's bottom face plane above (x, z): Dot(n, p - faceCentre) = 0.
            const float y = faceCentre.y - (n.x * (x - faceCentre.x) + n.z * (z - faceCentre.z)) / n.y;
            const vec3 p(x, y, z);
            const vec3 d = p - b.position;
            if (std::fabs(Dot(d, GetRow(b.orientation, 0))) > 0.5f ||
                std::fabs(Dot(d, GetRow(b.orientation, 2))) > 0.5f)
                continue;
            deepest = std::min(deepest, y - 0.5f);
        }
    EXPECT_NEAR(MinSeparation(m), deepest, 2e-4f);
    EXPECT_NEAR(m.points[0].separation, MinSeparation(m), 0.0f) << "the deepest point comes first";
    // The four kept points are octagon corners (on the rim of A's top face) spanning most of its area
    // (octagon 0.83 m^2; the best quad of its corners 0.586 m^2).
    for (int i = 0; i < 4; ++i) {
        const vec3& p = m.points[i].point;
        EXPECT_NEAR(std::max(std::fabs(p.x), std::fabs(p.z)), 0.5f, tol::kLoose);
    }
    const vec3 p0 = m.points[0].point, p1 = m.points[1].point, p2 = m.points[2].point, p3 = m.points[3].point;
    // Area of the quad: the hull of four points in a plane, as the larger of the two diagonal splits.
    const float area =
        0.5f * std::max(Magnitude(Cross(p2 - p0, p3 - p1)),
                        std::max(Magnitude(Cross(p1 - p0, p3 - p2)), Magnitude(Cross(p3 - p0, p2 - p1))));
    EXPECT_GT(area, 0.58f);
    const std::vector<std::uint32_t> ids = SortedIds(m);
    EXPECT_TRUE(std::adjacent_find(ids.begin(), ids.end()) == ids.end());
}

TEST(SolverManifoldBoxBox, TurnedStackKeepsItsFourIdsUnderNoise) {
    // Two equal cubes face on face, the top one turned 2 degrees about y: its corners overhang, so the clip is an
    // octagon of pairs of nearby points, all equally deep. Noise of a resting stack (0.01 degree tilts, 0.1 mm
    // sinking) must not change which four are kept.
    const OBB a = UnitCube(vec3(0, 0, 0));
    ContactManifold rest;
    CollideBoxes(a, UnitCube(vec3(0, 0.999f, 0), YRotation3x3(2.0f)), 0.02f, &rest);
    ASSERT_EQ(rest.pointCount, 4);
    const std::vector<std::uint32_t> ids = SortedIds(rest);
    const mat3 noise[] = {XRotation3x3(0.01f),
                          XRotation3x3(-0.01f),
                          ZRotation3x3(0.01f),
                          ZRotation3x3(-0.01f),
                          XRotation3x3(0.01f) * ZRotation3x3(0.01f),
                          XRotation3x3(-0.01f) * ZRotation3x3(-0.01f)};
    for (const mat3& tilt : noise)
        for (float sink : {0.0f, 0.0001f}) {
            ContactManifold m;
            CollideBoxes(a, UnitCube(vec3(0, 0.999f - sink, 0), tilt * YRotation3x3(2.0f)), 0.02f, &m);
            ASSERT_EQ(m.pointCount, 4);
            EXPECT_EQ(SortedIds(m), ids);
        }
}

TEST(SolverManifoldBoxBox, CoincidentAndFlatBoxesStayFinite) {
    ContactManifold m;
    CollideBoxes(UnitCube(vec3(1, 2, 3)), UnitCube(vec3(1, 2, 3)), 0.02f, &m);
    ASSERT_EQ(m.pointCount, 4);
    EXPECT_NEAR(Magnitude(m.normal), 1.0f, tol::kTight);
    for (int i = 0; i < 4; ++i) {
        EXPECT_TRUE(IsFinite(m.points[i].point));
        EXPECT_NEAR(m.points[i].separation, -1.0f, tol::kTight);
    }
    // A zero-thickness plate crossing a rotated cube's edge.
    const OBB plate(vec3(0, 0, 0), vec3(1, 0, 1), ZRotation3x3(30.0f));
    CollideBoxes(plate, UnitCube(vec3(0.2f, 0.6f, 0), Rotation3x3(20, 30, 40)), 0.02f, &m);
    for (int i = 0; i < m.pointCount; ++i) {
        EXPECT_TRUE(IsFinite(m.points[i].point));
        EXPECT_TRUE(std::isfinite(m.points[i].separation));
    }
    EXPECT_TRUE(IsFinite(m.normal));
}

TEST(SolverManifoldBoxBox, RandomPosesAgreeWithTheBook) {
    // Seeded random pairs near touching. Whenever the book's manifold collides, ours has points; its deepest
    // separation is the book's depth, except that the face preference may take a face axis up to 5 % + 5 mm deeper
    // than the book's least-overlap axis (and never shallower by more than 1 mm on these poses);
    // normals agree in sign, and every point lies between the two surfaces with its ends (half the separation
    // either way along the normal) on A's and B's surfaces. Every pose, touching or not: swapping A and B negates
    // the normal and swaps the two bytes of every id.
    MsvcRand rng(12345);
    int colliding = 0, close = 0, swapMismatch = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        // Touching by the book's SAT, then pushed in by up to 5 cm (or 1 cm apart).
        const TouchingBoxes pose = RandomTouchingBoxes(rng);
        const OBB& a = pose.a;
        const OBB b = pose.B(rng.Range(-0.01f, 0.05f));
        const CollisionManifold book = FindCollisionFeatures(a, b);
        ContactManifold m, swapped;
        CollideBoxes(a, b, 0.02f, &m);
        CollideBoxes(b, a, 0.02f, &swapped);
        {
            std::vector<std::uint32_t> back;
            for (std::uint32_t id : SortedIds(swapped)) back.push_back((id & 0xFFu) << 8 | id >> 8);
            std::sort(back.begin(), back.end());
            if (back != SortedIds(m) || (m.pointCount > 0 && !VecNear(swapped.normal, -m.normal, tol::kLoose)))
                ++swapMismatch;
        }
        if (!book.colliding) {
            // Separated by more than the margin: nothing; within it only speculative points.
            // (Apart, an edge pair's closest points can sit at an edge's end, off the axis by a fraction of a mm.)
            for (int i = 0; i < m.pointCount; ++i) EXPECT_GT(m.points[i].separation, -tol::kLoose);
            EXPECT_TRUE(EndsOnSurfaces(m, a, b, 1e-3f)) << "trial " << trial;
            continue;
        }
        ++colliding;
        ASSERT_GT(m.pointCount, 0) << "trial " << trial;
        ASSERT_LE(m.pointCount, kMaxManifoldPoints);
        EXPECT_GT(Dot(m.normal, book.normal), 0.0f) << "trial " << trial;
        EXPECT_NEAR(Magnitude(m.normal), 1.0f, tol::kLoose);
        const float minSep = MinSeparation(m);
        EXPECT_GE(minSep, -1.05f * book.depth - 0.005f - 1e-4f) << "trial " << trial;
        EXPECT_LE(minSep, -book.depth + 1e-3f) << "trial " << trial;
        if (std::fabs(minSep + book.depth) < 1e-3f) ++close;
        EXPECT_TRUE(PointsBetweenSurfaces(m, a, b, 2e-3f)) << "trial " << trial;
        EXPECT_TRUE(EndsOnSurfaces(m, a, b, 1e-4f)) << "trial " << trial;
    }
    EXPECT_GT(colliding, 2000);
    EXPECT_EQ(swapMismatch, 0) << "swapping A and B must negate the normal and swap the id bytes";
    EXPECT_GT(close, colliding * 8 / 10) << "most pairs match the book's depth to 1 mm";
}

// ---- Spheres ---------------------------------------------------------------------------------------------

TEST(SolverManifoldSpheres, SeparationPointAndMargin) {
    ContactManifold m;
    CollideSpheres(Sphere(vec3(0, 0, 0), 1), Sphere(vec3(0, 0, 1.7f), 0.5f), 0.02f, &m);
    EXPECT_EQ(m.pointCount, 0) << "0.2 m apart is outside the margin";
    CollideSpheres(Sphere(vec3(0, 0, 0), 1), Sphere(vec3(0, 0, 1.51f), 0.5f), 0.02f, &m);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_TRUE(VecNear(m.normal, vec3(0, 0, 1), tol::kExact));
    EXPECT_NEAR(m.points[0].separation, 0.01f, tol::kTight);
    EXPECT_TRUE(VecNear(m.points[0].point, vec3(0, 0, 1.005f), tol::kTight));
    EXPECT_EQ(m.points[0].id, 0u);
    CollideSpheres(Sphere(vec3(0, 0, 0), 1), Sphere(vec3(0, 0, 1.51f), 0.5f), 0.005f, &m);
    EXPECT_EQ(m.pointCount, 0);
    // Overlapping diagonally: separation = distance - radii, point midway between the surfaces.
    CollideSpheres(Sphere(vec3(1, 2, 3), 2), Sphere(vec3(2.5f, 4, 3), 1), 0.0f, &m);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_TRUE(VecNear(m.normal, vec3(0.6f, 0.8f, 0), tol::kTight));
    EXPECT_NEAR(m.points[0].separation, -0.5f, tol::kTight);
    EXPECT_TRUE(VecNear(m.points[0].point, vec3(1, 2, 3) + vec3(0.6f, 0.8f, 0) * 1.75f, tol::kTight));
}

TEST(SolverManifoldSpheres, BoxSphereOutsideAndInside) {
    const OBB box(vec3(0, 0, 0), vec3(1, 0.5f, 2), YRotation3x3(30.0f));
    const vec3 up = GetRow(box.orientation, 1);
    ContactManifold m;
    // Over the top face, 0.01 m above it.
    CollideBoxSphere(box, Sphere(up * 0.76f, 0.25f), 0.02f, &m);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_TRUE(VecNear(m.normal, up, tol::kTight));
    EXPECT_NEAR(m.points[0].separation, 0.01f, tol::kTight);
    EXPECT_TRUE(VecNear(m.points[0].point, up * 0.505f, tol::kTight));
    CollideBoxSphere(box, Sphere(up * 0.76f, 0.25f), 0.005f, &m);
    EXPECT_EQ(m.pointCount, 0);
    // Off a corner: the normal runs from the corner to the centre.
    const vec3 corner = GetRow(box.orientation, 0) * 1.0f + up * 0.5f + GetRow(box.orientation, 2) * 2.0f;
    const vec3 dir = Normalized(GetRow(box.orientation, 0) + up + GetRow(box.orientation, 2));
    CollideBoxSphere(box, Sphere(corner + dir * 0.3f, 0.4f), 0.0f, &m);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_TRUE(VecNear(m.normal, dir, tol::kLoose));
    EXPECT_NEAR(m.points[0].separation, -0.1f, tol::kLoose);
    // Centre inside, nearest the top face (0.1 below it): leaves through the top, separation -(0.1 + r).
    CollideBoxSphere(box, Sphere(up * 0.4f, 0.25f), 0.0f, &m);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_TRUE(VecNear(m.normal, up, tol::kTight));
    EXPECT_NEAR(m.points[0].separation, -0.35f, tol::kTight);
    EXPECT_TRUE(VecNear(m.points[0].point, up * (0.5f + 0.15f) * 0.5f, tol::kTight));
    // The book agrees on normal and depth for the penetrating cases.
    const CollisionManifold book = FindCollisionFeatures(box, Sphere(up * 0.4f, 0.25f));
    ASSERT_TRUE(book.colliding);
    EXPECT_TRUE(VecNear(book.normal, m.normal, tol::kTight));
    EXPECT_NEAR(book.depth, -m.points[0].separation, tol::kTight);
}
