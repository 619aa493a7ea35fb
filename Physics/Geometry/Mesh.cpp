// Triangle meshes with the book's octree-style BVH (book ch. 10/14 "Mesh", "AccelerateMesh", "MeshRay"),
// mesh queries, and Model (a mesh placed in the world).
#include <cfloat>
#include <cmath>
#include <utility>

#include "Physics/Geometry/Geometry3D.h"

namespace {

/// Node boxes are grown by this fraction of the root's largest half extent (plus an absolute floor), so a
/// triangle lying exactly on a split plane, or a zero-thickness mesh, is never lost to rounding. Growing
/// only adds triangles to nodes; queries stay exact because leaves test the triangles themselves.
constexpr float kMarginFraction = 1e-4f;
constexpr float kMarginFloor = 1e-6f;

AABB Inflate(const AABB& box, float margin) {
    const vec3 m(margin, margin, margin);
    return AABB(box.position, vec3(std::fabs(box.size.x), std::fabs(box.size.y), std::fabs(box.size.z)) + m);
}

/// Splits a node holding triangles into 8 octants of its (un-inflated) box and hands each triangle to every
/// octant it overlaps (TriangleAABB), down to `depth` more levels (book SplitBVHNode).
void SplitBVHNode(BVHNode& node, const std::vector<Triangle>& triangles, const AABB& tightBounds, int depth,
                  float margin) {
    if (depth <= 0 || node.triangles.empty()) return;
    const vec3 c = tightBounds.position;
    const vec3 e = tightBounds.size * 0.5f;
    node.children.resize(8);
    std::vector<AABB> childTight(8);
    for (int i = 0; i < 8; ++i) {
        const vec3 offset((i & 1) ? e.x : -e.x, (i & 2) ? e.y : -e.y, (i & 4) ? e.z : -e.z);
        childTight[i] = AABB(c + offset, e);
        BVHNode& child = node.children[i];
        child.bounds = Inflate(childTight[i], margin);
        for (int index : node.triangles)
            if (TriangleAABB(triangles[index], child.bounds)) child.triangles.push_back(index);
    }
    node.triangles.clear();
    node.triangles.shrink_to_fit();
    for (int i = 0; i < 8; ++i) SplitBVHNode(node.children[i], triangles, childTight[i], depth - 1, margin);
}

bool ComputeBounds(const Mesh& mesh, AABB* out) {
    if (mesh.triangles.empty()) return false;
    vec3 min = mesh.triangles[0].a, max = min;
    for (const Triangle& t : mesh.triangles)
        for (int v = 0; v < 3; ++v)
            for (int k = 0; k < 3; ++k) {
                min[k] = std::fmin(min[k], t[v][k]);
                max[k] = std::fmax(max[k], t[v][k]);
            }
    *out = FromMinMax(min, max);
    return true;
}

/// Visits the triangles whose leaves pass `nodeTest`; `visit` returns true to stop early. Without a BVH every
/// triangle is visited.
template <typename NodeTest, typename Visit>
void ForEachCandidate(const Mesh& mesh, NodeTest nodeTest, Visit visit) {
    if (!mesh.accelerator) {
        for (int i = 0; i < static_cast<int>(mesh.triangles.size()); ++i)
            if (visit(i)) return;
        return;
    }
    std::vector<const BVHNode*> stack{mesh.accelerator.get()};
    while (!stack.empty()) {
        const BVHNode* node = stack.back();
        stack.pop_back();
        if (!nodeTest(node->bounds)) continue;
        for (int index : node->triangles)
            if (visit(index)) return;
        for (const BVHNode& child : node->children) stack.push_back(&child);
    }
}

/// Nearest triangle hit with t >= 0 (BVH nodes whose box entry is beyond the best hit are skipped).
bool NearestHit(const Mesh& mesh, const Ray& ray, RaycastResult* best) {
    ResetRaycastResult(best);
    float bestT = FLT_MAX;
    auto nodeTest = [&](const AABB& bounds) {
        if (PointInAABB(ray.origin, bounds)) return true;
        RaycastResult boxHit;
        return Raycast(bounds, ray, &boxHit) && boxHit.t <= bestT;
    };
    auto visit = [&](int index) {
        RaycastResult r;
        if (Raycast(mesh.triangles[index], ray, &r) && r.t >= 0.0f && r.t < bestT) {
            bestT = r.t;
            *best = r;
        }
        return false;
    };
    ForEachCandidate(mesh, nodeTest, visit);
    return best->hit;
}

}  // namespace

/// Builds the BVH: root box around every vertex, each level split into 8 octants down to maxDepth levels
/// (book: 3), triangles kept in the leaves they overlap. An existing accelerator is replaced; an empty mesh
/// gets none.
void AccelerateMesh(Mesh& mesh, int maxDepth) {
    mesh.accelerator.reset();
    AABB tight;
    if (!ComputeBounds(mesh, &tight)) return;
    const float extent = std::fmax(tight.size.x, std::fmax(tight.size.y, tight.size.z));
    const float margin = extent * kMarginFraction + kMarginFloor;
    auto root = std::make_unique<BVHNode>();
    root->bounds = Inflate(tight, margin);
    root->triangles.resize(mesh.triangles.size());
    for (int i = 0; i < static_cast<int>(mesh.triangles.size()); ++i) root->triangles[i] = i;
    SplitBVHNode(*root, mesh.triangles, tight, maxDepth, margin);
    mesh.accelerator = std::move(root);
}

/// Nearest hit distance t >= 0 over all triangles (one-sided, as Raycast(Triangle)), -1 on a miss.
/// (The book returns the first hit found in traversal order, not the nearest: docs/ERRATA.md, Raycasts R-3.)
float MeshRay(const Mesh& mesh, const Ray& ray) {
    RaycastResult r;
    return NearestHit(mesh, ray, &r) ? r.t : -1.0f;
}

/// Nearest triangle hit: world point, that triangle's unit normal, t.
bool Raycast(const Mesh& mesh, const Ray& ray, RaycastResult* outResult) {
    RaycastResult r;
    const bool hit = NearestHit(mesh, ray, &r);
    if (outResult != nullptr) *outResult = r;
    return hit;
}

/// True if the segment touches any triangle (two-sided Linetest(Triangle)).
bool Linetest(const Mesh& mesh, const Line& line) {
    bool found = false;
    ForEachCandidate(
        mesh, [&](const AABB& b) { return Linetest(b, line); },
        [&](int i) { return found = Linetest(mesh.triangles[i], line); });
    return found;
}

/// True if any triangle overlaps the sphere.
bool MeshSphere(const Mesh& mesh, const Sphere& sphere) {
    bool found = false;
    ForEachCandidate(
        mesh, [&](const AABB& b) { return SphereAABB(sphere, b); },
        [&](int i) { return found = TriangleSphere(mesh.triangles[i], sphere); });
    return found;
}

/// True if any triangle overlaps the box.
bool MeshAABB(const Mesh& mesh, const AABB& aabb) {
    bool found = false;
    ForEachCandidate(
        mesh, [&](const AABB& b) { return AABBAABB(aabb, b); },
        [&](int i) { return found = TriangleAABB(mesh.triangles[i], aabb); });
    return found;
}

/// True if any triangle overlaps the oriented box.
bool MeshOBB(const Mesh& mesh, const OBB& obb) {
    bool found = false;
    ForEachCandidate(
        mesh, [&](const AABB& b) { return AABBOBB(b, obb); },
        [&](int i) { return found = TriangleOBB(mesh.triangles[i], obb); });
    return found;
}

/// Local = Rotation(pitch, yaw, roll) * Translation(position); world = local * parent's world (row vectors).
mat4 GetWorldMatrix(const Model& model) {
    const mat4 local = Rotation(model.rotation.x, model.rotation.y, model.rotation.z) * Translation(model.position);
    if (model.parent != nullptr) return local * GetWorldMatrix(*model.parent);
    return local;
}

/// World-space OBB of the mesh's model-space bounds (a zero-size box at the model origin without content).
OBB GetOBB(const Model& model) {
    const mat4 world = GetWorldMatrix(model);
    AABB bounds(vec3(0, 0, 0), vec3(0, 0, 0));
    if (model.content != nullptr) ComputeBounds(*model.content, &bounds);
    return OBB(MultiplyPoint(bounds.position, world), bounds.size, Cut(world, 3, 3));
}

/// The ray goes into model space through the inverse world matrix; the hit comes back to world space. The
/// model transform is rigid (rotation and translation), so t is the same in both spaces.
bool Raycast(const Model& model, const Ray& ray, RaycastResult* outResult) {
    ResetRaycastResult(outResult);
    if (model.content == nullptr) return false;
    const mat4 world = GetWorldMatrix(model);
    const mat4 inverse = Inverse(world);
    const Ray local(MultiplyPoint(ray.origin, inverse), MultiplyVector(ray.direction, inverse));
    RaycastResult r;
    if (!Raycast(*model.content, local, &r)) return false;
    if (outResult != nullptr) {
        outResult->hit = true;
        outResult->t = r.t;
        outResult->point = MultiplyPoint(r.point, world);
        outResult->normal = Normalized(MultiplyVector(r.normal, world));
    }
    return true;
}
