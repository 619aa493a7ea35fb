// Manifolds.cpp: hand-computed manifolds for sphere-sphere, OBB-sphere and every OBB-OBB feature pairing
// (face-face, edge-face, edge-edge, vertex-face), the degenerate cases (coincident centres, touching
// faces, identical boxes, a box inside a box), the errata 5.2-1/-2/-3/-32 cases and a seeded property test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "Math/Random.h"
#include "Physics/Geometry/Geometry3D.h"
#include "tests/support/Approx.h"

namespace {

bool AllFinite(const CollisionManifold& m) {
    if (!IsFinite(m.normal) || !std::isfinite(m.depth)) return false;
    return std::all_of(m.contacts.begin(), m.contacts.end(), [](const vec3& c) { return IsFinite(c); });
}

bool Contains(const std::vector<vec3>& points, const vec3& p, float eps) {
    return std::any_of(points.begin(), points.end(), [&](const vec3& q) { return VecNear(q, p, eps); });
}

/// Every expected point is matched by a contact and every contact by an expected point.
::testing::AssertionResult SameContacts(const std::vector<vec3>& contacts, const std::vector<vec3>& expected,
                                        float eps) {
    for (const vec3& e : expected)
        if (!Contains(contacts, e, eps))
            return ::testing::AssertionFailure() << "missing contact (" << e.x << ", " << e.y << ", " << e.z << ")";
    for (const vec3& c : contacts)
        if (!Contains(expected, c, eps))
            return ::testing::AssertionFailure() << "unexpected contact (" << c.x << ", " << c.y << ", " << c.z << ")";
    return ::testing::AssertionSuccess();
}

/// Distance by which p lies outside the box (0 inside), measured per local axis (max over axes).
float OutsideBy(const OBB& box, const vec3& p) {
    const vec3 d = p - box.position;
    float worst = 0.0f;
    for (int i = 0; i < 3; ++i) worst = std::max(worst, std::fabs(Dot(d, GetRow(box.orientation, i))) - box.size[i]);
    return worst;
}

/// World point of local coordinates (x, y, z) in the box's frame.
vec3 FromLocal(const OBB& box, float x, float y, float z) {
    return box.position + GetRow(box.orientation, 0) * x + GetRow(box.orientation, 1) * y +
           GetRow(box.orientation, 2) * z;
}

/// CH15's red box orientation: roll 0.4 rad, rows (c, s, 0), (-s, c, 0), (0, 0, 1).
mat3 Ch15Roll() {
    const float c = std::cos(0.4f), s = std::sin(0.4f);
    return mat3(c, s, 0, -s, c, 0, 0, 0, 1);
}

mat3 RandomRotation(MsvcRand& rng) {
    return Rotation3x3(rng.Range(-180, 180), rng.Range(-180, 180), rng.Range(-180, 180));
}

/// Checks the swapped pair gives the opposite normal and the same depth.
void ExpectSwapFlipsNormal(const OBB& a, const OBB& b) {
    const CollisionManifold ab = FindCollisionFeatures(a, b);
    const CollisionManifold ba = FindCollisionFeatures(b, a);
    ASSERT_TRUE(ab.colliding);
    ASSERT_TRUE(ba.colliding);
    EXPECT_TRUE(VecNear(ba.normal, -ab.normal, tol::kTight));
    EXPECT_NEAR(ba.depth, ab.depth, tol::kTight);
}

}  // namespace

// ---- Sphere-sphere ------------------------------------------------------------------------------------

TEST(ManifoldSphereSphere, Erratum5_2_1_DepthAndContactFromTheRealDistance) {
    // Unit spheres 1.5 apart: penetration 0.5 = depth (the whole penetration; the book reports half of it,
    // docs/STYLE.md, "Renames in the engine"); the contact is the middle of the overlap [0.5, 1] on X. The book
    // normalises first, so it returns half-depth |1 - 2|/2 = 0.5 (a penetration of 1) and contact (0.5,0,0).
    const CollisionManifold m = FindCollisionFeatures(Sphere(vec3(0, 0, 0), 1), Sphere(vec3(1.5f, 0, 0), 1));
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(VecNear(m.normal, vec3(1, 0, 0), tol::kExact));
    EXPECT_NEAR(m.depth, 0.5f, tol::kExact);
    ASSERT_EQ(m.contacts.size(), 1u);
    EXPECT_TRUE(VecNear(m.contacts[0], vec3(0.75f, 0, 0), tol::kExact));
}

TEST(ManifoldSphereSphere, DiagonalOverlapWithDifferentRadii) {
    // A r = 2 at (1,2,3); B r = 1 at A + 2.5*(0.6, 0.8, 0) = (2.5, 4, 3). Penetration 3 - 2.5 = 0.5 = depth;
    // contact A + n*(2 - 0.5/2) = (2.05, 3.4, 3). (Book: depth |1 - 3|/2 = 1.)
    const CollisionManifold m = FindCollisionFeatures(Sphere(vec3(1, 2, 3), 2), Sphere(vec3(2.5f, 4, 3), 1));
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(VecNear(m.normal, vec3(0.6f, 0.8f, 0), tol::kTight));
    EXPECT_NEAR(m.depth, 0.5f, tol::kTight);
    ASSERT_EQ(m.contacts.size(), 1u);
    EXPECT_TRUE(VecNear(m.contacts[0], vec3(2.05f, 3.4f, 3), tol::kTight));
}

TEST(ManifoldSphereSphere, SeparatedTouchingAndSwapped) {
    // Separated: nothing, contacts empty, the reset values.
    CollisionManifold m = FindCollisionFeatures(Sphere(vec3(0, 0, 0), 1), Sphere(vec3(2.1f, 0, 0), 1));
    EXPECT_FALSE(m.colliding);
    EXPECT_TRUE(m.contacts.empty());
    // Touching exactly (distance 2 = rA + rB) collides with depth 0, as in the book; contact on the surface.
    m = FindCollisionFeatures(Sphere(vec3(0, 0, 0), 1), Sphere(vec3(0, 0, 2), 1));
    ASSERT_TRUE(m.colliding);
    EXPECT_EQ(m.depth, 0.0f);
    EXPECT_TRUE(VecNear(m.contacts[0], vec3(0, 0, 1), tol::kExact));
    // Swapping A and B flips the normal; depth and contact stay.
    const Sphere a(vec3(0, 0, 0), 1), b(vec3(0.3f, -1.2f, 0.4f), 0.5f);
    const CollisionManifold ab = FindCollisionFeatures(a, b), ba = FindCollisionFeatures(b, a);
    ASSERT_TRUE(ab.colliding && ba.colliding);
    EXPECT_TRUE(VecNear(ba.normal, -ab.normal, tol::kExact));
    EXPECT_NEAR(ab.depth, ba.depth, tol::kExact);
    EXPECT_TRUE(VecNear(ab.contacts[0], ba.contacts[0], tol::kTight));
}

TEST(ManifoldSphereSphere, CoincidentCentresUsePlusYAndFullRadiiHalved) {
    // Book: no collision. Here normal +Y, depth 1 + 0.5 = 1.5, contact A + Y*(1 - 1.5/2).
    const CollisionManifold m = FindCollisionFeatures(Sphere(vec3(1, 2, 3), 1), Sphere(vec3(1, 2, 3), 0.5f));
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(AllFinite(m));
    EXPECT_TRUE(VecNear(m.normal, vec3(0, 1, 0), tol::kExact));
    EXPECT_NEAR(m.depth, 1.5f, tol::kExact);
    ASSERT_EQ(m.contacts.size(), 1u);
    EXPECT_TRUE(VecNear(m.contacts[0], vec3(1, 2.25f, 3), tol::kExact));
}

TEST(ManifoldSphereSphere, ReusesContactStorage) {
    CollisionManifold m;
    FindCollisionFeatures(Sphere(vec3(0, 0, 0), 1), Sphere(vec3(1, 0, 0), 1), &m);
    ASSERT_TRUE(m.colliding);
    const vec3* data = m.contacts.data();
    const std::size_t capacity = m.contacts.capacity();
    FindCollisionFeatures(Sphere(vec3(0, 0, 0), 1), Sphere(vec3(5, 0, 0), 1), &m);
    EXPECT_FALSE(m.colliding);
    EXPECT_TRUE(m.contacts.empty());
    EXPECT_EQ(m.contacts.capacity(), capacity);
    FindCollisionFeatures(Sphere(vec3(0, 0, 0), 1), Sphere(vec3(0, 1, 0), 1), &m);
    EXPECT_EQ(m.contacts.data(), data);
    FindCollisionFeatures(Sphere(), Sphere(), nullptr);  // ignored
}

// ---- OBB-sphere ---------------------------------------------------------------------------------------

TEST(ManifoldOBBSphere, FaceRegion) {
    // Unit box; sphere r 1 at (1.5, 0.2, -0.3): closest (1, 0.2, -0.3), distance 0.5, penetration 0.5.
    // Contact halfway between the face point and the sphere's deepest point (0.5, 0.2, -0.3).
    const CollisionManifold m =
        FindCollisionFeatures(OBB(vec3(0, 0, 0), vec3(1, 1, 1)), Sphere(vec3(1.5f, 0.2f, -0.3f), 1));
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(VecNear(m.normal, vec3(1, 0, 0), tol::kExact));
    EXPECT_NEAR(m.depth, 0.5f, tol::kExact);
    ASSERT_EQ(m.contacts.size(), 1u);
    EXPECT_TRUE(VecNear(m.contacts[0], vec3(0.75f, 0.2f, -0.3f), tol::kExact));
}

TEST(ManifoldOBBSphere, EdgeRegion) {
    // Sphere r 0.8 at (1.3, 1.4, 0.5): closest point on the edge (1, 1, 0.5); offset (0.3, 0.4, 0), distance
    // 0.5, normal (0.6, 0.8, 0), penetration 0.3 = depth. Deepest point (0.82, 0.76, 0.5);
    // contact ((1,1,0.5) + (0.82,0.76,0.5))/2 = (0.91, 0.88, 0.5).
    const CollisionManifold m =
        FindCollisionFeatures(OBB(vec3(0, 0, 0), vec3(1, 1, 1)), Sphere(vec3(1.3f, 1.4f, 0.5f), 0.8f));
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(VecNear(m.normal, vec3(0.6f, 0.8f, 0), tol::kTight));
    EXPECT_NEAR(m.depth, 0.3f, tol::kTight);
    ASSERT_EQ(m.contacts.size(), 1u);
    EXPECT_TRUE(VecNear(m.contacts[0], vec3(0.91f, 0.88f, 0.5f), tol::kTight));
}

TEST(ManifoldOBBSphere, CornerRegion) {
    // Sphere r 1 at (1.4, 1.4, 1.2): closest corner (1,1,1), offset (0.4,0.4,0.2), distance 0.6, normal
    // (2,2,1)/3, penetration 0.4 = depth; contact = corner + n*(0.6 - 1)/2... = corner - n*0.2.
    const CollisionManifold m =
        FindCollisionFeatures(OBB(vec3(0, 0, 0), vec3(1, 1, 1)), Sphere(vec3(1.4f, 1.4f, 1.2f), 1));
    ASSERT_TRUE(m.colliding);
    const vec3 n(2.0f / 3, 2.0f / 3, 1.0f / 3);
    EXPECT_TRUE(VecNear(m.normal, n, tol::kTight));
    EXPECT_NEAR(m.depth, 0.4f, tol::kTight);
    ASSERT_EQ(m.contacts.size(), 1u);
    EXPECT_TRUE(VecNear(m.contacts[0], vec3(1, 1, 1) - n * 0.2f, tol::kTight));
}

TEST(ManifoldOBBSphere, SeparatedAndRotatedBox) {
    EXPECT_FALSE(FindCollisionFeatures(OBB(vec3(0, 0, 0), vec3(1, 1, 1)), Sphere(vec3(2.5f, 0, 0), 1)).colliding);
    // Roll 30 degrees: the sphere sits 1.5 along the box's local X from its centre: normal = that row.
    const OBB box(vec3(1, 2, 3), vec3(1, 1, 1), Rotation3x3(0, 0, 30));
    const vec3 x = GetRow(box.orientation, 0);
    const CollisionManifold m = FindCollisionFeatures(box, Sphere(box.position + x * 1.5f, 1));
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(VecNear(m.normal, x, tol::kTight));
    EXPECT_NEAR(m.depth, 0.5f, tol::kTight);
    EXPECT_TRUE(VecNear(m.contacts[0], box.position + x * 0.75f, tol::kTight));
}

TEST(ManifoldOBBSphere, Erratum5_2_32_CentreInsideUsesTheNearestFace) {
    // Box half (2,1,3); sphere r 0.5 centred inside at (0.5, 0.7, -1). Distances to the faces: x 1.5,
    // y 0.3, z 2 -> leaves through +Y. Penetration 0.3 + 0.5 = 0.8 = depth; face point (0.5, 1, -1),
    // deepest point (0.5, 0.2, -1), contact (0.5, 0.6, -1). The book returns normal
    // normalize(0.5, 0.7, -1) and depth r/2 = 0.25.
    const OBB box(vec3(0, 0, 0), vec3(2, 1, 3));
    CollisionManifold m = FindCollisionFeatures(box, Sphere(vec3(0.5f, 0.7f, -1), 0.5f));
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(VecNear(m.normal, vec3(0, 1, 0), tol::kExact));
    EXPECT_NEAR(m.depth, 0.8f, tol::kTight);
    ASSERT_EQ(m.contacts.size(), 1u);
    EXPECT_TRUE(VecNear(m.contacts[0], vec3(0.5f, 0.6f, -1), tol::kTight));
    // Nearest face on the negative side: centre (-1.8, 0.2, 0.5): x gap 0.2 -> normal -X, depth 0.2 + 0.5 = 0.7.
    m = FindCollisionFeatures(box, Sphere(vec3(-1.8f, 0.2f, 0.5f), 0.5f));
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(VecNear(m.normal, vec3(-1, 0, 0), tol::kExact));
    EXPECT_NEAR(m.depth, 0.7f, tol::kTight);
}

TEST(ManifoldOBBSphere, CentreAtTheBoxCentreIsFinite) {
    // Book: "no collision". Here the nearest face is +Y (gap 1 < 2 < 3): depth 1 + 0.5, contact midway
    // between the face point (0,1,0) and the deepest point (0,-0.5,0).
    const CollisionManifold m = FindCollisionFeatures(OBB(vec3(0, 0, 0), vec3(2, 1, 3)), Sphere(vec3(0, 0, 0), 0.5f));
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(AllFinite(m));
    EXPECT_TRUE(VecNear(m.normal, vec3(0, 1, 0), tol::kExact));
    EXPECT_NEAR(m.depth, 1.5f, tol::kExact);
    EXPECT_TRUE(VecNear(m.contacts[0], vec3(0, 0.25f, 0), tol::kExact));
}

// ---- OBB-OBB: the four feature pairings ---------------------------------------------------------------

TEST(ManifoldOBBOBB, FaceFaceBoxOnAWiderBox) {
    // A = half (3,1,3) at the origin (top y = 1); B = unit box at (0.5, 1.9, 0.2) (bottom y = 0.9): overlap
    // 0.1 on Y. B's 4 vertical edges cross A's top at x = 0.5 +- 1, z = 0.2 +- 1; A's edges miss B. The
    // contacts are projected onto the middle of the overlap, y = 0.95.
    const OBB a(vec3(0, 0, 0), vec3(3, 1, 3));
    const OBB b(vec3(0.5f, 1.9f, 0.2f), vec3(1, 1, 1));
    const CollisionManifold m = FindCollisionFeatures(a, b);
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(VecNear(m.normal, vec3(0, 1, 0), tol::kExact));
    EXPECT_NEAR(m.depth, 0.1f, tol::kTight);
    EXPECT_TRUE(SameContacts(
        m.contacts,
        {vec3(-0.5f, 0.95f, -0.8f), vec3(1.5f, 0.95f, -0.8f), vec3(-0.5f, 0.95f, 1.2f), vec3(1.5f, 0.95f, 1.2f)},
        tol::kTight));
    // B first: the normal points from B to A (down), same depth and contacts.
    const CollisionManifold r = FindCollisionFeatures(b, a);
    ASSERT_TRUE(r.colliding);
    EXPECT_TRUE(VecNear(r.normal, vec3(0, -1, 0), tol::kExact));
    EXPECT_NEAR(r.depth, 0.1f, tol::kTight);
    EXPECT_TRUE(SameContacts(r.contacts, m.contacts, tol::kTight));
}

TEST(ManifoldOBBOBB, FaceFaceOffsetCubesWithParallelEdges) {
    // Two unit cubes, B at (0.5, 1.5, 0.5): every edge of B is parallel to one of A (edge axes are zero and
    // skipped). Overlap on Y is 0.5 (1.5 on X and Z). The overlap region's footprint is x, z in [-0.5, 1];
    // its 4 corners, projected to y = 0.75, are the contacts.
    const OBB a(vec3(0, 0, 0), vec3(1, 1, 1));
    const OBB b(vec3(0.5f, 1.5f, 0.5f), vec3(1, 1, 1));
    const CollisionManifold m = FindCollisionFeatures(a, b);
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(VecNear(m.normal, vec3(0, 1, 0), tol::kExact));
    EXPECT_NEAR(m.depth, 0.5f, tol::kExact);
    EXPECT_TRUE(SameContacts(
        m.contacts, {vec3(-0.5f, 0.75f, -0.5f), vec3(1, 0.75f, -0.5f), vec3(-0.5f, 0.75f, 1), vec3(1, 0.75f, 1)},
        tol::kTight));
    ExpectSwapFlipsNormal(a, b);
}

TEST(ManifoldOBBOBB, EdgeFaceRidgeOnAFace) {
    // B = unit cube rolled 45 degrees: its lowest edge is a ridge along Z, sqrt(2) below its centre. With B
    // at (0.4, 1 + sqrt(2) - 0.004, 0.3) the ridge sinks 0.004 into A's top face. The two faces beside the
    // ridge (at 45 degrees) cross y = 1 at x = 0.4 +- 0.004 near each end z = 0.3 +- 1; projected to
    // y = 0.998 the pairs are 0.008 apart, under the 0.01 duplicate distance, so one contact per ridge end.
    const OBB a(vec3(0, 0, 0), vec3(3, 1, 3));
    const OBB b(vec3(0.4f, 1 + std::sqrt(2.0f) - 0.004f, 0.3f), vec3(1, 1, 1), Rotation3x3(0, 0, 45));
    const CollisionManifold m = FindCollisionFeatures(a, b);
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(VecNear(m.normal, vec3(0, 1, 0), tol::kExact));
    EXPECT_NEAR(m.depth, 0.004f, 2e-5f);
    EXPECT_TRUE(SameContacts(m.contacts, {vec3(0.4f, 0.998f, 1.3f), vec3(0.4f, 0.998f, -0.7f)}, 0.005f));
    ExpectSwapFlipsNormal(a, b);
}

TEST(ManifoldOBBOBB, Erratum5_2_2_EdgeEdgeCrossedRidges) {
    // A = unit cube pitched 45 degrees: top ridge along X at height sqrt(2). B = unit cube rolled 45 degrees
    // at (0, 2.8, 0): bottom ridge along Z at 2.8 - sqrt(2). The ridges cross at x = z = 0 and overlap by
    // 2*sqrt(2) - 2.8 = 0.0284 along Y, which is the edge axis A_x x B_z = (0,-1,0), flipped to point A->B.
    // Every face axis overlaps far more (>= 0.7). The book, with A x A "edge" axes, can only answer with a
    // face axis: normal (0, 0.707, 0.707)-like, depth ~0.73.
    const OBB a(vec3(0, 0, 0), vec3(1, 1, 1), Rotation3x3(45, 0, 0));
    const OBB b(vec3(0, 2.8f, 0), vec3(1, 1, 1), Rotation3x3(0, 0, 45));
    const CollisionManifold m = FindCollisionFeatures(a, b);
    ASSERT_TRUE(m.colliding);
    const float depth = 2 * std::sqrt(2.0f) - 2.8f;
    EXPECT_TRUE(VecNear(m.normal, vec3(0, 1, 0), tol::kTight));
    EXPECT_NEAR(m.depth, depth, 2e-5f);
    for (int i = 0; i < 3; ++i) {  // not a face axis of either box
        EXPECT_LT(std::fabs(Dot(m.normal, GetRow(a.orientation, i))), 0.9f);
        EXPECT_LT(std::fabs(Dot(m.normal, GetRow(b.orientation, i))), 0.9f);
    }
    // Contacts: the ridge ends clipped inside the other box, all within 0.05 of the crossing on the mid plane.
    ASSERT_GE(m.contacts.size(), 1u);
    for (const vec3& c : m.contacts) {
        EXPECT_NEAR(c.y, std::sqrt(2.0f) - depth / 2, 2e-5f);
        EXPECT_LT(Distance(c, vec3(0, std::sqrt(2.0f) - depth / 2, 0)), 0.05f);
    }
    ExpectSwapFlipsNormal(a, b);
    // Raised to 2.9 the ridges are 0.07 apart: only the edge axis separates them. (Book: colliding.)
    EXPECT_FALSE(FindCollisionFeatures(a, OBB(vec3(0, 2.9f, 0), vec3(1, 1, 1), Rotation3x3(0, 0, 45))).colliding);
}

TEST(ManifoldOBBOBB, VertexFaceCornerPokingIntoAFace) {
    // B's body diagonal is vertical: rows u_k = (sqrt(2/3) cos phi_k, 1/sqrt(3), sqrt(2/3) sin phi_k) for
    // phi = 0, 240, 120 degrees (orthonormal, right-handed). Its lowest corner v4 = C - (u0+u1+u2) = C -
    // sqrt(3)*Y sits 0.003 below A's top face. The 3 edges from that corner rise at 54.7 degrees from the
    // vertical and cross y = 1 within 0.003*sqrt(2) = 0.0042 of the corner: one contact after duplicate
    // removal, on the mid plane y = 0.9985.
    const float a2 = std::sqrt(2.0f / 3.0f), b1 = 1.0f / std::sqrt(3.0f);
    const float pi = 3.14159265f;
    const float phi[3] = {0.0f, 240.0f * pi / 180.0f, 120.0f * pi / 180.0f};
    mat3 rot;
    for (int k = 0; k < 3; ++k) {
        rot[k][0] = a2 * std::cos(phi[k]);
        rot[k][1] = b1;
        rot[k][2] = a2 * std::sin(phi[k]);
    }
    ASSERT_TRUE(VecNear(Cross(GetRow(rot, 0), GetRow(rot, 1)), GetRow(rot, 2), tol::kTight));
    const OBB a(vec3(0, 0, 0), vec3(3, 1, 3));
    const OBB b(vec3(0.3f, 1 + std::sqrt(3.0f) - 0.003f, -0.2f), vec3(1, 1, 1), rot);
    const CollisionManifold m = FindCollisionFeatures(a, b);
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(VecNear(m.normal, vec3(0, 1, 0), tol::kExact));
    EXPECT_NEAR(m.depth, 0.003f, 2e-5f);
    ASSERT_EQ(m.contacts.size(), 1u);
    EXPECT_TRUE(VecNear(m.contacts[0], vec3(0.3f, 0.9985f, -0.2f), 0.005f));
    ExpectSwapFlipsNormal(a, b);
}

// ---- OBB-OBB: CH15's rotated box (erratum 5.2-3) -----------------------------------------------------

TEST(ManifoldOBBOBB, Ch15RedBoxEdgeOnBlueBoxHasNoSpuriousNormalComponents) {
    // CH15 pairs (red, blue) in body order, so A = red (roll 0.4 rad), B = blue (unit, at (0,1,0), top y=2).
    // Red's lowest edge (-X -Y corners, along Z) is (c + s) below its centre and (c - s) to its left; red
    // is placed so that edge is 0.05 into blue's top: normal red->blue = (0,-1,0) exactly, depth 0.05.
    // The overlap is a prism under y = 2: the edge at x0 = 0.5 - (c - s), y = 1.95, and the points where
    // red's two lower faces reach y = 2: x0 + c*(0.05/s) and x0 - s*(0.05/c). Its 6 corners (z = +-1)
    // projected to y = 1.975 are the contacts.
    const float c = std::cos(0.4f), s = std::sin(0.4f);
    const OBB red(vec3(0.5f, 2 + (c + s) - 0.05f, 0), vec3(1, 1, 1), Ch15Roll());
    EXPECT_TRUE(VecNear(GetRow(red.orientation, 0), vec3(0.92106f, 0.38942f, 0), tol::kBook));
    EXPECT_TRUE(VecNear(GetRow(red.orientation, 1), vec3(-0.38942f, 0.92106f, 0), tol::kBook));
    const OBB blue(vec3(0, 1, 0), vec3(1, 1, 1));
    const CollisionManifold m = FindCollisionFeatures(red, blue);
    ASSERT_TRUE(m.colliding);
    EXPECT_NEAR(m.normal.x, 0.0f, tol::kExact);
    EXPECT_NEAR(m.normal.y, -1.0f, tol::kExact);
    EXPECT_NEAR(m.normal.z, 0.0f, tol::kExact);
    EXPECT_NEAR(m.depth, 0.05f, tol::kLoose);
    const float x0 = 0.5f - (c - s);
    std::vector<vec3> expected;
    for (float z : {-1.0f, 1.0f})
        for (float x : {x0, x0 + c * (0.05f / s), x0 - s * (0.05f / c)}) expected.push_back(vec3(x, 1.975f, z));
    EXPECT_TRUE(SameContacts(m.contacts, expected, tol::kLoose));
    ExpectSwapFlipsNormal(red, blue);
}

TEST(ManifoldOBBOBB, Erratum5_2_3_RotatedBoxStackedOnAnEquallyRotatedBox) {
    // Both boxes have CH15's roll; B sits 1.95 along the shared local Y: face-face overlap 0.05 along
    // Y' = (-0.38942, 0.92106, 0). The repo zeroes every negative component, turning every candidate along
    // Y' into world Y (or X), and returns normal (0,1,0) with depth ~0.825 here.
    const OBB a(vec3(0, 0, 0), vec3(1, 1, 1), Ch15Roll());
    const vec3 up = GetRow(a.orientation, 1);
    const OBB b(up * 1.95f, vec3(1, 1, 1), Ch15Roll());
    const CollisionManifold m = FindCollisionFeatures(a, b);
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(VecNear(m.normal, vec3(-0.38942f, 0.92106f, 0), tol::kBook));
    EXPECT_NEAR(m.depth, 0.05f, tol::kLoose);
    // Identical footprints: the 4 corners of A's top face, projected to local y = 0.975.
    std::vector<vec3> expected;
    for (float x : {-1.0f, 1.0f})
        for (float z : {-1.0f, 1.0f}) expected.push_back(FromLocal(a, x, 0.975f, z));
    EXPECT_TRUE(SameContacts(m.contacts, expected, tol::kLoose));
    ExpectSwapFlipsNormal(a, b);
}

// ---- OBB-OBB: degenerate cases ------------------------------------------------------------------------

TEST(ManifoldOBBOBB, TouchingFacesDoNotCollide) {
    // Depth exactly 0 is no collision (book). CH15's ground (top y = 0) under the blue box (bottom y = 0).
    CollisionManifold m =
        FindCollisionFeatures(OBB(vec3(0, -0.25f, 0), vec3(12.5f, 0.25f, 12.5f)), OBB(vec3(0, 1, 0), vec3(1, 1, 1)));
    EXPECT_FALSE(m.colliding);
    EXPECT_TRUE(m.contacts.empty());
    m = FindCollisionFeatures(OBB(vec3(0, 0, 0), vec3(1, 1, 1)), OBB(vec3(2, 0.5f, 0), vec3(1, 1, 1)));
    EXPECT_FALSE(m.colliding);
    // Far apart: the bounding-sphere early out.
    EXPECT_FALSE(
        FindCollisionFeatures(OBB(vec3(0, 0, 0), vec3(1, 1, 1)), OBB(vec3(10, 0, 0), vec3(1, 1, 1))).colliding);
}

TEST(ManifoldOBBOBB, IdenticalBoxesGiveAFiniteManifold) {
    // Same box twice: every face axis overlaps by 2, the first (A's X) wins without a flip. The 8 corners
    // (from the edges) are projected onto x = 1 (centre of the overlap [0, 2]): 4 contacts.
    const OBB box(vec3(1, 2, 3), vec3(1, 1, 1));
    const CollisionManifold m = FindCollisionFeatures(box, box);
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(AllFinite(m));
    EXPECT_TRUE(VecNear(m.normal, vec3(1, 0, 0), tol::kExact));
    EXPECT_NEAR(m.depth, 2.0f, tol::kExact);
    EXPECT_TRUE(SameContacts(m.contacts, {vec3(1, 1, 2), vec3(1, 3, 2), vec3(1, 1, 4), vec3(1, 3, 4)}, tol::kTight));
}

TEST(ManifoldOBBOBB, CoincidentCentresDifferentBoxesAreFinite) {
    const OBB a(vec3(1, 1, 1), vec3(1, 1, 1));
    const OBB b(vec3(1, 1, 1), vec3(2, 0.5f, 0.5f), Rotation3x3(0, 30, 0));
    const CollisionManifold m = FindCollisionFeatures(a, b);
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(AllFinite(m));
    EXPECT_NEAR(Magnitude(m.normal), 1.0f, tol::kTight);
    EXPECT_GT(m.depth, 0.0f);
    ASSERT_GE(m.contacts.size(), 1u);
    for (const vec3& c : m.contacts) {
        EXPECT_LE(OutsideBy(a, c), m.depth / 2 + 1e-4f);
        EXPECT_LE(OutsideBy(b, c), m.depth / 2 + 1e-4f);
    }
}

TEST(ManifoldOBBOBB, SmallBoxInsideABigBoxUsesItsCorners) {
    // No edge of either box crosses a face of the other, so clipping finds nothing; the fallback takes B's
    // corners inside A, projected onto the middle of B on the normal: 4 contacts, B's mid cross-section.
    // (The book's plane A.pos + axis*(3 - 0.5) would put them 2 units outside B.) B leaves A fastest through
    // A's -Y face: it spans y in [-1.5, -0.5], so 2.5 down, against x 3 (B in [0, 1]) and z 3.25 (B in
    // [-0.25, 0.75]). The book's depth is B's width 1 on every axis, a tie that can pick a sideways normal.
    const OBB a(vec3(0, 0, 0), vec3(3, 3, 3));
    const OBB b(vec3(0.5f, -1, 0.25f), vec3(0.5f, 0.5f, 0.5f));
    const CollisionManifold m = FindCollisionFeatures(a, b);
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(AllFinite(m));
    EXPECT_NEAR(m.depth, 2.5f, tol::kExact);
    EXPECT_TRUE(VecNear(m.normal, vec3(0, -1, 0), tol::kExact));
    ASSERT_EQ(m.contacts.size(), 4u);
    for (const vec3& c : m.contacts) {
        EXPECT_LE(OutsideBy(b, c), 1e-5f);
        EXPECT_NEAR(Dot(c - b.position, m.normal), 0.0f, tol::kTight);
    }
}

TEST(ManifoldOBBOBB, DeepOverlapStaysFiniteAndInsideBothBoxes) {
    const OBB a(vec3(0, 0, 0), vec3(1, 1, 1));
    const OBB b(vec3(0.1f, 0.2f, 0), vec3(1, 1, 1), Rotation3x3(0, 0, 30));
    const CollisionManifold m = FindCollisionFeatures(a, b);
    ASSERT_TRUE(m.colliding);
    EXPECT_TRUE(AllFinite(m));
    ASSERT_GE(m.contacts.size(), 1u);
    for (const vec3& c : m.contacts) {
        EXPECT_LE(OutsideBy(a, c), m.depth / 2 + 1e-4f);
        EXPECT_LE(OutsideBy(b, c), m.depth / 2 + 1e-4f);
    }
}

TEST(ManifoldOBBOBB, ReusesContactStorage) {
    const OBB a(vec3(0, 0, 0), vec3(3, 1, 3));
    const OBB b(vec3(0.5f, 1.9f, 0.2f), vec3(1, 1, 1));
    CollisionManifold m;
    FindCollisionFeatures(a, b, &m);
    ASSERT_TRUE(m.colliding);
    const vec3* data = m.contacts.data();
    const std::size_t capacity = m.contacts.capacity();
    FindCollisionFeatures(a, OBB(vec3(0, 5, 0), vec3(1, 1, 1)), &m);
    EXPECT_FALSE(m.colliding);
    EXPECT_EQ(m.contacts.capacity(), capacity);
    FindCollisionFeatures(a, b, &m);
    EXPECT_TRUE(m.colliding);
    EXPECT_EQ(m.contacts.data(), data);  // same pair again: no reallocation
}

// ---- OBB-OBB: seeded property test --------------------------------------------------------------------

TEST(ManifoldOBBOBB, RandomPairsAgreeWithSatAndStayInsideBothBoxes) {
    // Colliding iff OBBOBB, except (counted, and required to be rare) where they legitimately differ:
    // OBBOBB counts touching as overlap and tests nearly parallel edge axes that the manifold skips
    // (|A_i x B_j|^2 < 0.001), so pairs whose smallest separation or overlap is under 0.05 are not compared.
    // Every colliding manifold: finite, unit normal, depth > 0, >= 1 contact, contacts on one plane
    // perpendicular to the normal that cuts the overlap of the projections, within depth/2 of both boxes,
    // and the swapped pair gives the opposite normal.
    MsvcRand rng(15);
    int colliding = 0, compared = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const OBB a(vec3(rng.Range(-1.5f, 1.5f), rng.Range(-1.5f, 1.5f), rng.Range(-1.5f, 1.5f)),
                    vec3(rng.Range(0.2f, 1.5f), rng.Range(0.2f, 1.5f), rng.Range(0.2f, 1.5f)), RandomRotation(rng));
        const OBB b(vec3(rng.Range(-1.5f, 1.5f), rng.Range(-1.5f, 1.5f), rng.Range(-1.5f, 1.5f)),
                    vec3(rng.Range(0.2f, 1.5f), rng.Range(0.2f, 1.5f), rng.Range(0.2f, 1.5f)), RandomRotation(rng));
        const CollisionManifold m = FindCollisionFeatures(a, b);

        // Signed SAT margin over all 15 axes (only exactly parallel edges skipped): the smallest overlap of
        // the projections, negative when an axis separates the boxes.
        vec3 axes[15];
        for (int i = 0; i < 3; ++i) {
            axes[i] = GetRow(a.orientation, i);
            axes[3 + i] = GetRow(b.orientation, i);
            for (int j = 0; j < 3; ++j) axes[6 + 3 * i + j] = Cross(GetRow(a.orientation, i), GetRow(b.orientation, j));
        }
        float margin = 1e30f;
        for (const vec3& axis : axes) {
            if (MagnitudeSq(axis) < 1e-10f) continue;
            const vec3 n = Normalized(axis);
            const Interval ia = GetInterval(a, n), ib = GetInterval(b, n);
            margin = std::min(margin, std::min(ia.max, ib.max) - std::max(ia.min, ib.min));
        }
        if (std::fabs(margin) > 0.05f) {
            ++compared;
            EXPECT_EQ(m.colliding, OBBOBB(a, b)) << "trial " << trial << " margin " << margin;
        }
        if (!m.colliding) {
            EXPECT_TRUE(m.contacts.empty());
            continue;
        }
        ++colliding;
        ASSERT_TRUE(AllFinite(m)) << "trial " << trial;
        EXPECT_NEAR(Magnitude(m.normal), 1.0f, tol::kTight);
        EXPECT_GT(m.depth, 0.0f);
        ASSERT_GE(m.contacts.size(), 1u) << "trial " << trial;
        const Interval ia = GetInterval(a, m.normal), ib = GetInterval(b, m.normal);
        const float lo = std::max(ia.min, ib.min), hi = std::min(ia.max, ib.max);
        const float plane = Dot(m.contacts[0], m.normal);
        EXPECT_GE(plane, lo - 1e-4f);
        EXPECT_LE(plane, hi + 1e-4f);
        for (const vec3& c : m.contacts) {
            EXPECT_NEAR(Dot(c, m.normal), plane, tol::kLoose) << "trial " << trial;
            EXPECT_LE(OutsideBy(a, c), m.depth / 2 + 1e-3f) << "trial " << trial;
            EXPECT_LE(OutsideBy(b, c), m.depth / 2 + 1e-3f) << "trial " << trial;
        }
        const CollisionManifold swapped = FindCollisionFeatures(b, a);
        ASSERT_TRUE(swapped.colliding) << "trial " << trial;
        EXPECT_TRUE(VecNear(swapped.normal, -m.normal, tol::kLoose)) << "trial " << trial;
        EXPECT_NEAR(swapped.depth, m.depth, tol::kLoose) << "trial " << trial;
    }
    // The distribution must exercise both outcomes and leave few pairs uncompared.
    EXPECT_GT(colliding, 600);
    EXPECT_LT(colliding, 2700);
    EXPECT_GT(compared, 2700);
}
