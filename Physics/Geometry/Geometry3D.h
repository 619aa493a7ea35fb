#pragma once
// The book's 3D primitives and the geometric queries chapters 14-16 and the demos use. GL-free.
// Conventions: left-handed world, row-vector math (Math/), OBB axes are the ROWS of `orientation`,
// AABB/OBB `size` is the HALF extent. Comparisons inside raycasts/clipping use CMP_EPS (book Geometry3D.cpp).
// Implementation is split by topic: Primitives.cpp, PointTests.cpp, Intersections.cpp (SAT), Raycast.cpp,
// Linetest.cpp, BoxFeatures.cpp (vertices/edges/planes/clipping), Manifolds.cpp, Mesh.cpp (BVH), Picking.cpp.

#include <array>
#include <memory>
#include <vector>

#include "Math/matrices.h"
#include "Math/vectors.h"

typedef vec3 Point;

struct Line {
    Point start, end;
    Line() = default;
    Line(const Point& s, const Point& e) : start(s), end(e) {}
};
float Length(const Line& line);
float LengthSq(const Line& line);

struct Ray {
    Point origin;
    vec3 direction{0, 0, 1};
    Ray() = default;
    /// Normalises the direction (a zero direction stays zero; raycasts then miss).
    Ray(const Point& o, const vec3& d) : origin(o), direction(d) { NormalizeDirection(); }
    void NormalizeDirection() { Normalize(direction); }
};
/// Ray from `from` through `to`.
Ray FromPoints(const Point& from, const Point& to);

struct Sphere {
    Point position;
    float radius = 1.0f;
    Sphere() = default;
    Sphere(const Point& p, float r) : position(p), radius(r) {}
};

struct AABB {
    Point position;
    vec3 size{1, 1, 1};  ///< half extents
    AABB() = default;
    AABB(const Point& p, const vec3& s) : position(p), size(s) {}
};
vec3 GetMin(const AABB& aabb);
vec3 GetMax(const AABB& aabb);
AABB FromMinMax(const vec3& min, const vec3& max);

struct OBB {
    Point position;
    vec3 size{1, 1, 1};  ///< half extents along the local axes
    mat3 orientation;    ///< rows are the local X, Y, Z axes in world space
    OBB() = default;
    OBB(const Point& p, const vec3& s) : position(p), size(s) {}
    OBB(const Point& p, const vec3& s, const mat3& o) : position(p), size(s), orientation(o) {}
};

struct Plane {
    vec3 normal{1, 0, 0};
    float distance = 0.0f;  ///< the plane is Dot(normal, p) = distance
    Plane() = default;
    Plane(const vec3& n, float d) : normal(n), distance(d) {}
};
/// Signed value Dot(p, normal) - distance: > 0 in front, < 0 behind, 0 on the plane.
float PlaneEquation(const Point& point, const Plane& plane);

/// Standard-C++ triangle (the book's anonymous union is rejected by GCC, erratum 5.2-30).
struct Triangle {
    Point a, b, c;
    Triangle() = default;
    Triangle(const Point& p1, const Point& p2, const Point& p3) : a(p1), b(p2), c(p3) {}
    Point& operator[](int i) { return i == 0 ? a : (i == 1 ? b : c); }
    const Point& operator[](int i) const { return i == 0 ? a : (i == 1 ? b : c); }
};

struct Interval {
    float min = 0.0f;
    float max = 0.0f;
};

struct RaycastResult {
    vec3 point;
    vec3 normal{0, 0, 1};
    float t = -1.0f;
    bool hit = false;
};
/// t = -1, hit = false, normal (0,0,1), point 0.
void ResetRaycastResult(RaycastResult* outResult);

/// Contact information for a colliding pair. `normal` points FROM A TO B.
struct CollisionManifold {
    bool colliding = false;
    vec3 normal{0, 0, 1};
    /// m: how far B must move along `normal` to stop touching A, the whole penetration for every pair type.
    float depth = 3.402823466e+38f;
    std::vector<vec3> contacts;  ///< reused across calls: Reset clears without freeing
};
/// colliding false, normal (0,0,1), depth FLT_MAX, contacts cleared (capacity kept).
void ResetCollisionManifold(CollisionManifold* result);

// ---- Point tests and closest points (PointTests.cpp) -------------------------------------------------
bool PointInSphere(const Point& point, const Sphere& sphere);
bool PointOnPlane(const Point& point, const Plane& plane);
bool PointInAABB(const Point& point, const AABB& aabb);
/// Exact (no epsilon) test |dot(p - C, axis_i)| <= size_i, as the book.
bool PointInOBB(const Point& point, const OBB& obb);
bool PointOnLine(const Point& point, const Line& line);
bool PointOnRay(const Point& point, const Ray& ray);
bool PointInTriangle(const Point& p, const Triangle& t);
Point ClosestPoint(const Sphere& sphere, const Point& point);
/// Per-axis clamp (erratum 5.2-9: the book clamps y and z against min.x / max.x).
Point ClosestPoint(const AABB& aabb, const Point& point);
Point ClosestPoint(const OBB& obb, const Point& point);
Point ClosestPoint(const Plane& plane, const Point& point);
Point ClosestPoint(const Line& line, const Point& point);
Point ClosestPoint(const Ray& ray, const Point& point);
Point ClosestPoint(const Triangle& t, const Point& p);

// ---- Shape-pair intersection tests, chapters 9 and 11 (Intersections.cpp) ---------------------------
bool SphereSphere(const Sphere& s1, const Sphere& s2);  ///< strict <, touching is not overlapping
bool SphereAABB(const Sphere& sphere, const AABB& aabb);
bool SphereOBB(const Sphere& sphere, const OBB& obb);
bool SpherePlane(const Sphere& sphere, const Plane& plane);
bool AABBAABB(const AABB& aabb1, const AABB& aabb2);
/// SAT over the 15 axes; edge axes are A x B (erratum 5.2-2).
bool AABBOBB(const AABB& aabb, const OBB& obb);
bool AABBPlane(const AABB& aabb, const Plane& plane);
/// SAT over the 15 axes, both boxes projected (erratum 5.2-8).
bool OBBOBB(const OBB& obb1, const OBB& obb2);
bool OBBPlane(const OBB& obb, const Plane& plane);
bool PlanePlane(const Plane& plane1, const Plane& plane2);
Interval GetInterval(const AABB& aabb, const vec3& axis);
/// Min and max of Dot(corner, axis) over the 8 corners; the axis is not normalised inside.
Interval GetInterval(const OBB& obb, const vec3& axis);
Interval GetInterval(const Triangle& triangle, const vec3& axis);
bool OverlapOnAxis(const AABB& aabb, const OBB& obb, const vec3& axis);
bool OverlapOnAxis(const OBB& obb1, const OBB& obb2, const vec3& axis);
bool OverlapOnAxis(const AABB& aabb, const Triangle& triangle, const vec3& axis);
bool OverlapOnAxis(const OBB& obb, const Triangle& triangle, const vec3& axis);
bool OverlapOnAxis(const Triangle& t1, const Triangle& t2, const vec3& axis);
bool TriangleSphere(const Triangle& t, const Sphere& s);
bool TriangleAABB(const Triangle& t, const AABB& a);
bool TriangleOBB(const Triangle& t, const OBB& o);
bool TrianglePlane(const Triangle& t, const Plane& p);
bool TriangleTriangle(const Triangle& t1, const Triangle& t2);

// ---- Raycasts (Raycast.cpp). Each returns hit; outResult (optional) gets point, unit normal, t >= 0. ---
/// Rejects spheres behind the origin (erratum 5.2-7).
bool Raycast(const Sphere& sphere, const Ray& ray, RaycastResult* outResult);
/// Slab test; zero direction components handled without inf/NaN, origin exactly on a slab plane included.
bool Raycast(const AABB& aabb, const Ray& ray, RaycastResult* outResult);
bool Raycast(const OBB& obb, const Ray& ray, RaycastResult* outResult);
/// One-sided: rays travelling along the normal (Dot(d, n) >= 0) miss.
bool Raycast(const Plane& plane, const Ray& ray, RaycastResult* outResult);
bool Raycast(const Triangle& triangle, const Ray& ray, RaycastResult* outResult);
vec3 Barycentric(const Point& p, const Triangle& t);
Plane FromTriangle(const Triangle& t);

// ---- Line tests (Linetest.cpp): does the segment touch the shape? ------------------------------------
bool Linetest(const Sphere& sphere, const Line& line);
bool Linetest(const AABB& aabb, const Line& line);
/// A zero-length segment tests its start point (erratum 5.1-5).
bool Linetest(const OBB& obb, const Line& line);
bool Linetest(const Plane& plane, const Line& line);
bool Linetest(const Triangle& triangle, const Line& line);

// ---- Box features used by SAT and manifolds (BoxFeatures.cpp). Fixed-size arrays: no allocation. ----
/// 8 corners in the book's order v0 = C+X+Y+Z, v1 = C-X+Y+Z, v2 = C+X-Y+Z, v3 = C+X+Y-Z, v4 = C-X-Y-Z,
/// v5 = C+X-Y-Z, v6 = C-X+Y-Z, v7 = C-X-Y+Z (X = axis0 * size.x ...).
std::array<Point, 8> GetVertices(const OBB& obb);
/// The 12 edges as the book's index pairs {6,1},{6,3},{6,4},{2,7},{2,5},{2,0},{0,1},{0,3},{7,1},{7,4},{4,5},{5,3}.
std::array<Line, 12> GetEdges(const OBB& obb);
/// The 6 face planes, outward normals: +X, -X, +Y, -Y, +Z, -Z.
std::array<Plane, 6> GetPlanes(const OBB& obb);
/// Segment-plane intersection with t in [0, 1]; a segment parallel to the plane is rejected.
bool ClipToPlane(const Plane& plane, const Line& line, Point* outPoint);
/// Appends to `out` every intersection of the edges with obb's face planes that lies in the obb (within
/// 1e-4 * max(1, largest half extent), erratum 5.2-5). Allocates only when `out` runs out of capacity.
void ClipEdgesToOBB(const std::array<Line, 12>& edges, const OBB& obb, std::vector<Point>* out);
/// Overlap of the two boxes' projections on `axis` (normalised inside), 0 if they do not overlap.
/// *outShouldFlip is set when B's interval starts before A's (the axis must be negated to point A->B).
float PenetrationDepth(const OBB& o1, const OBB& o2, const vec3& axis, bool* outShouldFlip);

// ---- Collision manifolds, chapter 15 (Manifolds.cpp). Normal from A to B. ----------------------------
/// depth = the whole overlap rA + rB - |AB| (m; the book's is half), contact at A + n*(rA - depth/2), the middle
/// of the overlap (erratum 5.2-1 fixed).
CollisionManifold FindCollisionFeatures(const Sphere& A, const Sphere& B);
/// Normal from the box surface to the sphere centre (centre inside: nearest face, erratum 5.2-32); depth = the
/// whole penetration (m; the book's is half); one contact, halfway between the box surface and the sphere's
/// deepest point.
CollisionManifold FindCollisionFeatures(const OBB& A, const Sphere& B);
/// SAT with A x B edge axes (5.2-2), no sign-losing zeroing (5.2-3); contacts from edge clipping projected
/// onto the mid plane, duplicates removed. Coincident centres and deep overlaps give a finite manifold.
CollisionManifold FindCollisionFeatures(const OBB& A, const OBB& B);
/// Allocation-free forms for the physics step: overwrite *out, reusing its contact storage.
void FindCollisionFeatures(const Sphere& A, const Sphere& B, CollisionManifold* out);
void FindCollisionFeatures(const OBB& A, const Sphere& B, CollisionManifold* out);
void FindCollisionFeatures(const OBB& A, const OBB& B, CollisionManifold* out);

// ---- Meshes with a BVH accelerator (Mesh.cpp) ---------------------------------------------------------
struct BVHNode {
    AABB bounds;
    std::vector<BVHNode> children;  ///< 0 (leaf) or 8
    std::vector<int> triangles;     ///< triangle indices, leaves only
};
struct Mesh {
    std::vector<Triangle> triangles;
    std::unique_ptr<BVHNode> accelerator;  ///< built by AccelerateMesh; null means brute force
};
/// Builds the BVH: root AABB of all vertices, split into 8 children down to `maxDepth` (book: 3).
void AccelerateMesh(Mesh& mesh, int maxDepth = 3);
/// Nearest hit t >= 0, or -1 on a miss (the book's MeshRay).
float MeshRay(const Mesh& mesh, const Ray& ray);
bool Raycast(const Mesh& mesh, const Ray& ray, RaycastResult* outResult);
bool Linetest(const Mesh& mesh, const Line& line);
bool MeshSphere(const Mesh& mesh, const Sphere& sphere);
bool MeshAABB(const Mesh& mesh, const AABB& aabb);
bool MeshOBB(const Mesh& mesh, const OBB& obb);

/// A mesh placed in the world: position, rotation (degrees, pitch/yaw/roll), optional parent.
struct Model {
    const Mesh* content = nullptr;
    vec3 position;
    vec3 rotation;
    const Model* parent = nullptr;
};
mat4 GetWorldMatrix(const Model& model);
/// OBB around the model's mesh bounds in world space.
OBB GetOBB(const Model& model);
/// Raycast in model space; t and point/normal returned in world space.
bool Raycast(const Model& model, const Ray& ray, RaycastResult* outResult);

// ---- Picking (Picking.cpp) ----------------------------------------------------------------------------
/// Screen point (pixels, y down) with depth in [0,1] (0 near) back to world space.
vec3 Unproject(const vec3& viewportPoint, const vec2& viewportOrigin, const vec2& viewportSize, const mat4& view,
               const mat4& projection);
/// Ray from the near plane through the far plane under the screen point.
Ray GetPickRay(const vec2& viewportPoint, const vec2& viewportOrigin, const vec2& viewportSize, const mat4& view,
               const mat4& projection);
