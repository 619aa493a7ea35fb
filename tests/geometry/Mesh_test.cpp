// Mesh.cpp: BVH structure, mesh queries (BVH == brute force over seeded random queries), Model transforms.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <string>

#include "Physics/Geometry/Geometry3D.h"
#include "Physics/Geometry/ObjLoader.h"
#include "tests/support/Approx.h"

namespace {

/// Closed box [-1,1]^3 of 12 triangles wound with outward normals ((b-a) x (c-a) points out).
Mesh CubeMesh() {
    Mesh mesh;
    const vec3 v[8] = {vec3(-1, -1, -1), vec3(1, -1, -1), vec3(1, 1, -1), vec3(-1, 1, -1),
                       vec3(-1, -1, 1),  vec3(1, -1, 1),  vec3(1, 1, 1),  vec3(-1, 1, 1)};
    const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 7, 6, 2}};
    for (const auto& q : quads) {
        mesh.triangles.emplace_back(v[q[0]], v[q[1]], v[q[2]]);
        mesh.triangles.emplace_back(v[q[0]], v[q[2]], v[q[3]]);
    }
    return mesh;
}

/// A random triangle soup (seeded) of `count` small triangles in [-5,5]^3.
Mesh SoupMesh(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-5, 5), off(-0.8f, 0.8f);
    Mesh mesh;
    for (int i = 0; i < count; ++i) {
        const vec3 c(pos(rng), pos(rng), pos(rng));
        mesh.triangles.emplace_back(c + vec3(off(rng), off(rng), off(rng)), c + vec3(off(rng), off(rng), off(rng)),
                                    c + vec3(off(rng), off(rng), off(rng)));
    }
    return mesh;
}

Mesh Copy(const Mesh& m) {
    Mesh r;
    r.triangles = m.triangles;
    return r;
}

/// Depth of the BVH and the number of leaves.
void Walk(const BVHNode& node, int depth, int* maxDepth, int* leaves) {
    *maxDepth = std::max(*maxDepth, depth);
    if (node.children.empty()) ++*leaves;
    for (const BVHNode& c : node.children) Walk(c, depth + 1, maxDepth, leaves);
}

}  // namespace

TEST(MeshBVH, EightChildrenPerLevelDownToDepthThree) {
    Mesh mesh = SoupMesh(400, 5);
    AccelerateMesh(mesh);
    ASSERT_NE(mesh.accelerator, nullptr);
    const BVHNode& root = *mesh.accelerator;
    ASSERT_EQ(root.children.size(), 8u);
    EXPECT_TRUE(root.triangles.empty());  // only leaves hold triangles
    int depth = 0, leaves = 0;
    Walk(root, 0, &depth, &leaves);
    EXPECT_EQ(depth, 3);
    EXPECT_EQ(leaves, 512);  // 400 triangles spread over the whole volume: every octant is split
    // Every vertex lies in the root box; every triangle sits in at least one leaf that overlaps it.
    for (const Triangle& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) EXPECT_TRUE(PointInAABB(t[k], root.bounds));
    std::vector<int> seen(mesh.triangles.size(), 0);
    std::function<void(const BVHNode&)> count = [&](const BVHNode& n) {
        for (int i : n.triangles) {
            ++seen[i];
            EXPECT_TRUE(TriangleAABB(mesh.triangles[i], n.bounds));
        }
        for (const BVHNode& c : n.children) count(c);
    };
    count(root);
    for (int s : seen) EXPECT_GE(s, 1);
}

TEST(MeshBVH, EmptyMeshHasNoAcceleratorAndNeverHits) {
    Mesh mesh;
    AccelerateMesh(mesh);
    EXPECT_EQ(mesh.accelerator, nullptr);
    EXPECT_FLOAT_EQ(MeshRay(mesh, Ray(vec3(0, 0, -5), vec3(0, 0, 1))), -1.0f);
    EXPECT_FALSE(MeshAABB(mesh, AABB()));
}

TEST(MeshRaycast, CubeHitsNearestFaceWithOutwardNormal) {
    for (bool accelerate : {false, true}) {
        Mesh mesh = CubeMesh();
        if (accelerate) AccelerateMesh(mesh);
        RaycastResult r;
        ASSERT_TRUE(Raycast(mesh, Ray(vec3(0.3f, -0.2f, -6), vec3(0, 0, 1)), &r));
        EXPECT_NEAR(r.t, 5.0f, tol::kExact);
        EXPECT_TRUE(VecNear(r.point, vec3(0.3f, -0.2f, -1), tol::kExact));
        EXPECT_TRUE(VecNear(r.normal, vec3(0, 0, -1), tol::kExact));
        EXPECT_NEAR(MeshRay(mesh, Ray(vec3(6, 0.5f, 0.5f), vec3(-1, 0, 0))), 5.0f, tol::kExact);
        EXPECT_FLOAT_EQ(MeshRay(mesh, Ray(vec3(0, 3, -6), vec3(0, 0, 1))), -1.0f);   // passes above
        EXPECT_FLOAT_EQ(MeshRay(mesh, Ray(vec3(0, 0, -6), vec3(0, 0, -1))), -1.0f);  // pointing away
        // From inside, the one-sided faces all face away: no hit (book behaviour of Raycast(Triangle)).
        EXPECT_FLOAT_EQ(MeshRay(mesh, Ray(vec3(0, 0, 0), vec3(0, 0, 1))), -1.0f);
    }
}

TEST(MeshRaycast, NearestHitNotFirstListed) {
    // erratum R-3: the far triangle is listed first; the book's MeshRay returns the first hit found (t = 10).
    Mesh mesh;
    mesh.triangles.emplace_back(vec3(-1, -1, 10), vec3(-1, 1, 10), vec3(1, 0, 10));
    mesh.triangles.emplace_back(vec3(-1, -1, 2), vec3(-1, 1, 2), vec3(1, 0, 2));
    const Ray ray(vec3(0, 0, 0), vec3(0, 0, 1));
    ASSERT_TRUE(VecNear(FromTriangle(mesh.triangles[0]).normal, vec3(0, 0, -1), tol::kExact));
    EXPECT_NEAR(MeshRay(mesh, ray), 2.0f, tol::kExact);
    AccelerateMesh(mesh);
    EXPECT_NEAR(MeshRay(mesh, ray), 2.0f, tol::kExact);
}

TEST(MeshBVH, QueriesEqualBruteForceForRandomRaysAndShapes) {
    const Mesh brute = SoupMesh(300, 99);
    Mesh fast = Copy(brute);
    AccelerateMesh(fast);
    std::mt19937 rng(4242);
    std::uniform_real_distribution<float> u(-1, 1), pos(-8, 8), half(0.2f, 1.5f), ang(-180, 180);
    int hits = 0;
    for (int i = 0; i < 1000; ++i) {
        const vec3 origin(pos(rng), pos(rng), pos(rng));
        const Ray ray(origin, vec3(u(rng), u(rng), u(rng)) * 5.0f - origin);
        RaycastResult a, b;
        const bool ha = Raycast(brute, ray, &a), hb = Raycast(fast, ray, &b);
        ASSERT_EQ(ha, hb) << i;
        if (ha) {
            ++hits;
            ASSERT_FLOAT_EQ(a.t, b.t) << i;
            ASSERT_TRUE(VecNear(a.point, b.point, tol::kExact)) << i;
        }
        const Line line(origin, vec3(pos(rng), pos(rng), pos(rng)));
        ASSERT_EQ(Linetest(brute, line), Linetest(fast, line)) << i;
        const vec3 c(pos(rng), pos(rng), pos(rng));
        const Sphere sphere(c, half(rng));
        ASSERT_EQ(MeshSphere(brute, sphere), MeshSphere(fast, sphere)) << i;
        const AABB aabb(c, vec3(half(rng), half(rng), half(rng)));
        ASSERT_EQ(MeshAABB(brute, aabb), MeshAABB(fast, aabb)) << i;
        const OBB obb(c, vec3(half(rng), half(rng), half(rng)), Rotation3x3(ang(rng), ang(rng), ang(rng)));
        ASSERT_EQ(MeshOBB(brute, obb), MeshOBB(fast, obb)) << i;
    }
    EXPECT_GT(hits, 100);
}

TEST(MeshQueries, HandComputedShapesAgainstCube) {
    Mesh mesh = CubeMesh();
    AccelerateMesh(mesh);
    // The mesh is a surface: shapes strictly inside the cube, touching no face, do not overlap it.
    EXPECT_FALSE(MeshSphere(mesh, Sphere(vec3(0, 0, 0), 0.5f)));
    EXPECT_TRUE(MeshSphere(mesh, Sphere(vec3(0, 0, 0), 1.01f)));
    EXPECT_TRUE(MeshSphere(mesh, Sphere(vec3(2, 0, 0), 1.0f)));  // touching the +X face
    EXPECT_FALSE(MeshAABB(mesh, AABB(vec3(0, 0, 0), vec3(0.5f, 0.5f, 0.5f))));
    EXPECT_TRUE(MeshAABB(mesh, AABB(vec3(1.5f, 0, 0), vec3(0.6f, 0.2f, 0.2f))));
    EXPECT_FALSE(MeshOBB(mesh, OBB(vec3(3, 0, 0), vec3(1, 1, 1), Rotation3x3(0, 45, 0))));  // corner at 3-1.414
    EXPECT_TRUE(MeshOBB(mesh, OBB(vec3(2.3f, 0, 0), vec3(1, 1, 1), Rotation3x3(0, 45, 0))));
    EXPECT_TRUE(Linetest(mesh, Line(vec3(0, 0, 0), vec3(0, 0, 5))));  // leaving through a face (two-sided)
    EXPECT_FALSE(Linetest(mesh, Line(vec3(0, 0, 0), vec3(0, 0, 0.5f))));
}

TEST(Model, WorldMatrixOBBAndRaycast) {
    Mesh mesh = CubeMesh();
    AccelerateMesh(mesh);
    Model parent;
    parent.position = vec3(10, 0, 0);
    Model model;
    model.content = &mesh;
    model.position = vec3(0, 0, 5);
    model.rotation = vec3(0, 90, 0);  // yaw 90: local +X goes to world -Z (Y(a) row 0 = (c,0,-s))
    model.parent = &parent;
    const mat4 world = GetWorldMatrix(model);
    // Row-vector order: rotate, translate, then the parent's translation.
    EXPECT_TRUE(VecNear(MultiplyPoint(vec3(1, 0, 0), world), vec3(10, 0, 4), tol::kTight));
    const OBB obb = GetOBB(model);
    EXPECT_TRUE(VecNear(obb.position, vec3(10, 0, 5), tol::kTight));
    EXPECT_TRUE(VecNear(obb.size, vec3(1, 1, 1), tol::kTight));
    EXPECT_TRUE(VecNear(GetRow(obb.orientation, 0), vec3(0, 0, -1), tol::kTight));
    // A world ray along +X at z = 5.5 meets the box's world face x = 9 (local +Z face after yaw 90).
    RaycastResult r;
    ASSERT_TRUE(Raycast(model, Ray(vec3(0, 0.2f, 5.5f), vec3(1, 0, 0)), &r));
    EXPECT_NEAR(r.t, 9.0f, tol::kTight);
    EXPECT_TRUE(VecNear(r.point, vec3(9, 0.2f, 5.5f), tol::kTight));
    EXPECT_TRUE(VecNear(r.normal, vec3(-1, 0, 0), tol::kTight));
    Model empty;
    EXPECT_FALSE(Raycast(empty, Ray(vec3(0, 0, 0), vec3(1, 0, 0)), &r));
}

TEST(Model, RandomRigidPlacementsPreserveDistance) {
    Mesh mesh = CubeMesh();
    AccelerateMesh(mesh);
    std::mt19937 rng(31);
    std::uniform_real_distribution<float> u(-1, 1), pos(-5, 5), ang(-180, 180);
    int hits = 0;
    for (int i = 0; i < 500; ++i) {
        Model model;
        model.content = &mesh;
        model.position = vec3(pos(rng), pos(rng), pos(rng));
        model.rotation = vec3(ang(rng), ang(rng), ang(rng));
        const Ray ray(vec3(pos(rng), pos(rng), pos(rng)) * 3.0f, model.position + vec3(u(rng), u(rng), u(rng)));
        const Ray aimed(ray.origin, model.position + vec3(u(rng), u(rng), u(rng)) - ray.origin);
        RaycastResult r;
        const OBB obb = GetOBB(model);
        RaycastResult rb;
        const bool boxHit = Raycast(obb, aimed, &rb);
        if (PointInOBB(aimed.origin, obb)) continue;
        ASSERT_EQ(Raycast(model, aimed, &r), boxHit) << i;  // closed cube mesh == its OBB from outside
        if (!boxHit) continue;
        ++hits;
        ASSERT_NEAR(r.t, rb.t, 1e-3f) << i;
        ASSERT_NEAR(Distance(aimed.origin, r.point), r.t, 1e-3f) << i;
        ASSERT_TRUE(VecNear(r.normal, rb.normal, 1e-3f)) << i;
    }
    EXPECT_GT(hits, 200);
}

TEST(MeshAsset, RaycastDemoModelLoadsWithOutwardNormals) {
    const std::string path = std::string(PSB_SOURCE_DIR) + "/Demos/assets/raycast_model.obj";
    Mesh mesh;
    std::string error;
    ASSERT_TRUE(LoadMesh(path, &mesh, &error)) << error;
    EXPECT_EQ(mesh.triangles.size(), 256u);  // 16 x 8 quads
    // Torus R = 1, r = 0.4 in the XZ plane: each triangle's normal points away from the tube's centre line.
    for (const Triangle& t : mesh.triangles) {
        const vec3 centroid = (t.a + t.b + t.c) * (1.0f / 3.0f);
        const vec3 ring = Normalized(vec3(centroid.x, 0, centroid.z));
        ASSERT_GT(Dot(FromTriangle(t).normal, centroid - ring), 0.0f);
    }
    // Straight down through the tube at x = 1, z = 0: exactly through the shared vertex (1, 0.4, 0) of four
    // triangles, which the exact [0,1] barycentric test of the book can let slip through.
    RaycastResult r;
    ASSERT_TRUE(Raycast(mesh, Ray(vec3(1, 5, 0), vec3(0, -1, 0)), &r));
    EXPECT_NEAR(r.point.y, 0.4f, 0.05f);
    EXPECT_GT(r.normal.y, 0.9f);
    EXPECT_FALSE(Raycast(mesh, Ray(vec3(0, 5, 0), vec3(0, -1, 0)), &r));  // through the hole
}
