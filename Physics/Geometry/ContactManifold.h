#pragma once
// Solver manifolds for ContactSolver::Soft (docs/soft-solver.md, "The soft-step solver"): at most four points per pair,
// each with its separation (negative when penetrating, up to +margin for a speculative contact) and a feature id
// that names the pair of features that made it, so a solver can match contacts across steps by id instead of
// by distance. The book's manifolds (CollisionManifold, Manifolds.cpp) are unchanged and still drive the Book and
// Accumulated solvers.

#include <cstdint>

#include "Physics/Geometry/Geometry3D.h"

/// Most points a solver manifold keeps (deepest first, then the ones that span the largest area).
constexpr int kMaxManifoldPoints = 4;

struct ManifoldPoint {
    vec3 point;               ///< world, midway between the two surfaces along the normal
    float separation = 0.0f;  ///< m along the normal; < 0 penetrating, in (0, margin] speculative
    std::uint32_t id = 0;     ///< feature id: the same two features give the same id from step to step
};

/// One pair's contact: a normal from A to B and up to four points. pointCount 0 means further apart than margin.
struct ContactManifold {
    vec3 normal{0.0f, 1.0f, 0.0f};
    int pointCount = 0;
    ManifoldPoint points[kMaxManifoldPoints];
};

// Feature ids (docs/soft-solver.md, "Solver manifolds"). A box-box point's id names the feature of A (bits 8-15) and
// the feature of B (bits 0-7) that made it, whichever box gave the reference face, so the same corner keeps its id when
// the reference face changes sides. A feature byte is a kind (bits 4-5) and an index (bits 0-3):
//   vertex: bit i set when the corner is on the negative side of local axis i (0-7);
//   edge:   4 * axis + 2 (next axis negative) + 1 (the axis after negative), axes in cyclic order (0-11);
//   face:   2 * axis + 1 on the negative side (0-5, the order of GetPlanes).
// As (reference box's feature, incident box's feature): (face, vertex) an incident corner on the reference face,
// (edge, edge) crossing edges (a clipped rim crossing, or the edge-edge case), (vertex, face) a reference corner
// over the incident face. Sphere pairs use id 0.
constexpr std::uint32_t kFeatureVertex = 1u << 4;
constexpr std::uint32_t kFeatureEdge = 2u << 4;
constexpr std::uint32_t kFeatureFace = 3u << 4;

/// Box A against box B. Points are reported while the boxes are within `margin` (m) of touching.
void CollideBoxes(const OBB& A, const OBB& B, float margin, ContactManifold* out);
/// Box A against sphere B (normal from the box to the sphere); one point, id 0.
void CollideBoxSphere(const OBB& A, const Sphere& B, float margin, ContactManifold* out);
/// Sphere A against sphere B; one point, id 0.
void CollideSpheres(const Sphere& A, const Sphere& B, float margin, ContactManifold* out);

/// A box-box manifold kept in the two boxes' frames (docs/soft-solver.md, "Manifold reuse"), so that it can be
/// re-expressed at later poses instead of colliding the boxes again: the relative pose it was made at, the normal
/// in A's frame, and each point's two surface points (on A in A's frame, on B in B's frame, from the centres).
struct LocalManifold {
    float R[3][3] = {};  ///< A.axis[i] . B.axis[j] when made
    vec3 t;              ///< B's centre from A's, A's frame, m
    vec3 normal;         ///< from A to B, A's frame
    int pointCount = 0;  ///< 0: nothing kept
    vec3 onA[kMaxManifoldPoints];
    vec3 onB[kMaxManifoldPoints];
    std::uint32_t id[kMaxManifoldPoints] = {};
};

/// Keeps `m`, a manifold of boxes A and B at their present poses (CollideBoxes), in their frames.
void KeepLocal(const OBB& A, const OBB& B, const ContactManifold& m, LocalManifold* out);
/// When no point of B within its bounding sphere has moved by more than `maxMotion` (m) relative to A since `kept`
/// was made (and kept has points): writes `kept` at the present poses to `out` (same ids, the normal turned with
/// A, each point half its separation from its corner, or midway between its two surface points when neither box gives a
/// corner, separation measured anew along the normal) and returns true. Otherwise returns false and leaves `out` alone.
bool ReuseLocal(const OBB& A, const OBB& B, const LocalManifold& kept, float maxMotion, ContactManifold* out);
