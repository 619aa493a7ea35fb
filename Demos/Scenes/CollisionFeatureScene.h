#pragma once
// Collision Features / "SAT Test Demo" scene (docs/book-reference.md §2.2): two boxes and two spheres, the six pair
// manifolds the book computes every frame, and a scripted motion that brings the shapes together so contacts
// appear (headless stand-in for dragging them with the gizmo). GL-free; shared by CollisionFeature and tests.

#include <array>

#include "Demos/Scenes/Parameters.h"
#include "Physics/Geometry/Geometry3D.h"

/// The demo's script and panel values; ranges and labels are in AddCollisionFeatureParameters.
struct CollisionFeatureParams {
    bool script = true;  ///< scripted motion (false: the book's static start, nothing collides)
    float speed = 1.0f;  ///< cycles per kCycleFrames output frames
    int gizmo = 0;       ///< the panel's radio buttons: 0 Translate, 1 Rotate, 2 Scale (no gizmo headless)
    int space = 0;       ///< 0 Local, 1 World
};

/// Registers script and speed (`--set` only) and the panel's radio buttons gizmo (Translate / Rotate / Scale)
/// and space (Local / World), docs/book-reference.md §2.2, bound to *params on *set.
void AddCollisionFeatureParameters(ParameterSet* set, CollisionFeatureParams* params);

class CollisionFeatureScene {
public:
    /// Output frames of one approach-and-retreat cycle at speed 1.
    static constexpr int kCycleFrames = 240;
    /// Shape indices: 0 obb[0], 1 obb[1], 2 sphere[0], 3 sphere[1].
    static constexpr int kShapeCount = 4;
    /// The book's pairs r1..r6 as shape indices: (obb0,obb1), (obb0,s0), (obb1,s0), (s0,s1), (obb0,s1), (obb1,s1).
    static constexpr std::array<std::array<int, 2>, 6> kPairs{
        {{{0, 1}}, {{0, 2}}, {{1, 2}}, {{2, 3}}, {{0, 3}}, {{1, 3}}}};

    std::array<OBB, 2> obb;
    std::array<Sphere, 2> sphere;
    std::array<CollisionManifold, 6> results;  ///< r1..r6 after Compute()

    CollisionFeatureScene();
    /// The book's start: obb0 (4,2,0) identity; obb1 (-4,-2,0) Rotation3x3(30,20,0); s0 (-4,2,0) r 1;
    /// s1 (4,-2,0) r 0.5.
    void Reset();
    /// Poses every shape for output frame `frame`: each centre moves toward the origin and back (at the
    /// closest, 0.15 of its start, where all six pairs overlap); obb0 turns about Y and Z, obb1 about Y.
    /// Frame 0 is the start.
    void Script(int frame, float speed);
    /// The six manifolds of the current poses.
    void Compute();
    /// True if shape `index` is in at least one colliding pair (after Compute).
    bool Colliding(int index) const;
};
