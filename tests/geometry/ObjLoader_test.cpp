// ObjLoader.cpp: fixtures in tests/geometry/data (hand-written OBJ files, including malformed ones).
#include "Physics/Geometry/ObjLoader.h"

#include <gtest/gtest.h>

#include <string>

#include "tests/support/Approx.h"

namespace {

std::string Fixture(const std::string& name) { return std::string(PSB_SOURCE_DIR) + "/tests/geometry/data/" + name; }

bool Contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

}  // namespace

TEST(ObjLoader, CubeQuadsBecomeTwelveTrianglesWithBVH) {
    Mesh mesh;
    std::string error = "stale";
    ASSERT_TRUE(LoadMesh(Fixture("cube.obj"), &mesh, &error)) << error;
    EXPECT_TRUE(error.empty());
    EXPECT_EQ(mesh.triangles.size(), 12u);  // 6 quads, 2 triangles each
    ASSERT_NE(mesh.accelerator, nullptr);
    // Every vertex of the fixture is a corner (+-1, +-1, +-1).
    for (const Triangle& t : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(std::fabs(t[k][c]), 1.0f);
    // The loaded cube answers raycasts: from (0,0,-5) along +Z the -Z face (wound to face outward) at t = 4.
    RaycastResult r;
    ASSERT_TRUE(Raycast(mesh, Ray(vec3(0.1f, 0.2f, -5), vec3(0, 0, 1)), &r));
    EXPECT_NEAR(r.t, 4.0f, tol::kTight);
    EXPECT_TRUE(VecNear(r.normal, vec3(0, 0, -1), tol::kTight));
}

TEST(ObjLoader, GroupsTextureNormalAndNegativeIndices) {
    Mesh mesh;
    std::string error;
    ASSERT_TRUE(LoadMesh(Fixture("triangles.obj"), &mesh, &error)) << error;
    ASSERT_EQ(mesh.triangles.size(), 2u);
    EXPECT_TRUE(VecNear(mesh.triangles[0].b, vec3(1, 0, 0), tol::kExact));
    // "f -3 -2 -1" refers to the last three vertices.
    EXPECT_TRUE(VecNear(mesh.triangles[1].a, vec3(0, 0, 2), tol::kExact));
    EXPECT_TRUE(VecNear(mesh.triangles[1].c, vec3(0, 2, 2), tol::kExact));
}

TEST(ObjLoader, MissingFileErrorNamesTheFile) {
    Mesh mesh;
    mesh.triangles.push_back(Triangle());
    std::string error;
    const std::string path = Fixture("does_not_exist.obj");
    EXPECT_FALSE(LoadMesh(path, &mesh, &error));
    EXPECT_TRUE(Contains(error, path)) << error;
    EXPECT_TRUE(Contains(error, "cannot open")) << error;
    EXPECT_EQ(mesh.triangles.size(), 1u);  // untouched on failure
}

TEST(ObjLoader, DirectoryIsNotAFile) {
    Mesh mesh;
    std::string error;
    const std::string path = std::string(PSB_SOURCE_DIR) + "/tests/geometry/data";
    EXPECT_FALSE(LoadMesh(path, &mesh, &error));
    EXPECT_TRUE(Contains(error, path)) << error;
}

TEST(ObjLoader, NoFacesIsAnError) {
    Mesh mesh;
    std::string error;
    EXPECT_FALSE(LoadMesh(Fixture("no_faces.obj"), &mesh, &error));
    EXPECT_TRUE(Contains(error, "no_faces.obj")) << error;
    EXPECT_TRUE(Contains(error, "no faces")) << error;
}

TEST(ObjLoader, MalformedFilesAreErrorsNamingFileAndProblem) {
    struct Case {
        const char* file;
        const char* problem;
    };
    const Case cases[] = {
        {"bad_index.obj", "vertex 9"},                    // out of range triangle index
        {"bad_quad_index.obj", "malformed"},              // tinyobjloader only warns and drops the face
        {"two_vertex_face.obj", "line 5"},                // a face must have 3 vertices (tinyobjloader drops it)
        {"zero_index.obj", "zero value for face index"},  // OBJ indices are 1-based (tinyobjloader's message)
    };
    for (const Case& c : cases) {
        Mesh mesh;
        std::string error;
        EXPECT_FALSE(LoadMesh(Fixture(c.file), &mesh, &error)) << c.file;
        EXPECT_TRUE(Contains(error, c.file)) << error;
        EXPECT_TRUE(Contains(error, c.problem)) << c.file << ": " << error;
        EXPECT_TRUE(mesh.triangles.empty());
    }
}

TEST(ObjLoader, NullErrorPointerIsAllowed) {
    Mesh mesh;
    EXPECT_FALSE(LoadMesh(Fixture("no_faces.obj"), &mesh, nullptr));
    EXPECT_TRUE(LoadMesh(Fixture("cube.obj"), &mesh, nullptr));
}
