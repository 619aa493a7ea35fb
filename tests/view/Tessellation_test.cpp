// Tessellation.h: triangle counts, unit outward normals and the front-face winding the GL layer relies on.
#include "Application/View/Tessellation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/Approx.h"

namespace {

/// True if the triangle's front side (Cross(c - a, b - a), see Tessellation.h) faces along `outward`.
bool FrontFaces(const TriangleList& list, int t, const vec3& outward) {
    const vec3& a = list.positions[3 * t];
    const vec3& b = list.positions[3 * t + 1];
    const vec3& c = list.positions[3 * t + 2];
    return Dot(Cross(c - a, b - a), outward) > 0.0f;
}

}  // namespace

TEST(Icosphere, CountIsTwentyTimesFourToTheDivisions) {
    for (int divs = 0; divs <= 3; ++divs) {
        const TriangleList s = Icosphere(divs, 1.0f);
        const int expected = 20 * (1 << (2 * divs));
        EXPECT_EQ(s.TriangleCount(), expected) << "divisions " << divs;
        EXPECT_EQ(s.positions.size(), s.normals.size());
    }
    EXPECT_EQ(Icosphere(2, 1.0f).TriangleCount(), 320);  // the book's sphere
}

TEST(Icosphere, NegativeDivisionsGiveTheIcosahedron) { EXPECT_EQ(Icosphere(-1, 1.0f).TriangleCount(), 20); }

TEST(Icosphere, NormalsAreUnitPositionsAndVerticesScaleWithRadius) {
    const float r = 0.1f;
    const TriangleList s = Icosphere(2, r);
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
        EXPECT_NEAR(Magnitude(s.normals[i]), 1.0f, tol::kTight) << "vertex " << i;
        EXPECT_NEAR(Magnitude(s.positions[i]), r, tol::kTight) << "vertex " << i;
        EXPECT_TRUE(VecNear(s.normals[i] * r, s.positions[i], tol::kTight)) << "vertex " << i;
    }
}

TEST(Icosphere, EveryTriangleFacesOutward) {
    const TriangleList s = Icosphere(2, 1.0f);
    for (int t = 0; t < s.TriangleCount(); ++t) {
        const vec3 centroid = s.positions[3 * t] + s.positions[3 * t + 1] + s.positions[3 * t + 2];
        EXPECT_TRUE(FrontFaces(s, t, centroid)) << "triangle " << t;
    }
}

TEST(Icosphere, BaseVerticesUseTheBookConstants) {
    const TriangleList s = Icosphere(0, 1.0f);
    bool found = false;
    for (const vec3& p : s.positions)
        if (VecNear(p, vec3(0.525731112119133606f, 0.0f, 0.850650808352039932f), tol::kExact)) found = true;
    EXPECT_TRUE(found);
}

TEST(Cube, TwelveTrianglesInTheBookFaceOrder) {
    const TriangleList c = Cube(1, 1, 1);
    ASSERT_EQ(c.TriangleCount(), 12);
    const vec3 order[6] = {{0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}, {1, 0, 0}};
    for (int t = 0; t < 12; ++t)
        for (int k = 0; k < 3; ++k) EXPECT_TRUE(VecNear(c.normals[3 * t + k], order[t / 2], tol::kExact)) << t;
}

TEST(Cube, FacesAreFlatOutwardAndOnTheExtents) {
    const vec3 e(2.0f, 0.15f, 0.5f);
    const TriangleList c = Cube(e.x, e.y, e.z);
    for (int t = 0; t < c.TriangleCount(); ++t) {
        const vec3 n = c.normals[3 * t];
        EXPECT_TRUE(FrontFaces(c, t, n)) << "triangle " << t;
        for (int k = 0; k < 3; ++k) {
            const vec3& p = c.positions[3 * t + k];
            // On the face: the coordinate along the normal equals that half extent.
            EXPECT_NEAR(Dot(p, n), Dot(e, vec3(std::fabs(n.x), std::fabs(n.y), std::fabs(n.z))), tol::kExact);
            EXPECT_NEAR(std::fabs(p.x), e.x, tol::kExact);
            EXPECT_NEAR(std::fabs(p.y), e.y, tol::kExact);
            EXPECT_NEAR(std::fabs(p.z), e.z, tol::kExact);
        }
    }
}

TEST(Cube, EachFaceCoversItsSquare) {
    // The two triangles of a face have total area 4 * (product of the other two half extents).
    const TriangleList c = Cube(1, 2, 3);
    const float expected[6] = {4 * 1 * 3, 4 * 1 * 2, 4 * 2 * 3, 4 * 1 * 3, 4 * 1 * 2, 4 * 2 * 3};
    for (int f = 0; f < 6; ++f) {
        float area = 0.0f;
        for (int t = 2 * f; t < 2 * f + 2; ++t)
            area += 0.5f * Magnitude(Cross(c.positions[3 * t + 1] - c.positions[3 * t],
                                           c.positions[3 * t + 2] - c.positions[3 * t]));
        EXPECT_NEAR(area, expected[f], tol::kTight) << "face " << f;
    }
}

TEST(FrontNormal, IsTheBookOneSidedNormal) {
    // The cloth's flat cell (tl, br, bl) on y = 0 faces +Y (docs/book-reference.md §3.7).
    EXPECT_TRUE(VecNear(FrontNormal({0, 0, 0}, {1, 0, 1}, {0, 0, 1}), vec3(0, 1, 0), tol::kExact));
    EXPECT_TRUE(VecNear(FrontNormal({0, 0, 0}, {0, 0, 0}, {0, 0, 1}), vec3(), tol::kExact));  // degenerate
}

TEST(PlaneQuad, CentredOnThePlaneAndFacingItsNormal) {
    const Plane p(Normalized(vec3(-0.8944f, 0.4472f, 0.0f)), -4.025f);
    const auto q = PlaneQuad(p, 1.0f);
    vec3 centre;
    for (const vec3& c : q) {
        EXPECT_NEAR(PlaneEquation(c, p), 0.0f, tol::kLoose);
        EXPECT_NEAR(Magnitude(c - p.normal * p.distance), std::sqrt(2.0f), tol::kLoose);
        centre += c * 0.25f;
    }
    EXPECT_TRUE(VecNear(centre, p.normal * p.distance, tol::kLoose));
    EXPECT_GT(Dot(Cross(q[2] - q[0], q[1] - q[0]), p.normal), 0.0f);
    // Vertical normal uses the other helper axis and still works.
    const auto up = PlaneQuad(Plane({0, 1, 0}, 2.0f), 0.5f);
    for (const vec3& c : up) EXPECT_NEAR(c.y, 2.0f, tol::kExact);
}
