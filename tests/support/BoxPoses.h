#pragma once
// Seeded box-box poses shared by the solver-manifold tests and psb-manifold-bench (docs/soft-solver.md, "Solver
// manifolds"): box A at the origin, box B of random size and rotation along a random direction, placed where the
// book's SAT (OBBOBB) says the two just touch. The caller then moves B in or out along that direction.

#include "Math/Random.h"
#include "Physics/Geometry/Geometry3D.h"

/// A random pair that touches: A (random half extents 0.2..1.2 m, random rotation, at the origin), B's half extents
/// and rotation, the unit direction from A to B, and the distance along it at which the two just touch (bisection on
/// OBBOBB, 40 halvings). Draws from rng in a fixed order, so a seed gives the same poses everywhere.
struct TouchingBoxes {
    OBB a;
    vec3 size;
    mat3 rotation;
    vec3 direction;
    float touching = 0.0f;
    /// B moved `push` m into A along the direction (negative: apart).
    OBB B(float push) const { return OBB(direction * (touching - push), size, rotation); }
};

inline TouchingBoxes RandomTouchingBoxes(MsvcRand& rng) {
    TouchingBoxes t;
    t.a = OBB(vec3(0, 0, 0), vec3(rng.Range(0.2f, 1.2f), rng.Range(0.2f, 1.2f), rng.Range(0.2f, 1.2f)),
              Rotation3x3(rng.Range(-180, 180), rng.Range(-180, 180), rng.Range(-180, 180)));
    t.size = vec3(rng.Range(0.2f, 1.2f), rng.Range(0.2f, 1.2f), rng.Range(0.2f, 1.2f));
    t.rotation = Rotation3x3(rng.Range(-180, 180), rng.Range(-180, 180), rng.Range(-180, 180));
    t.direction = Normalized(vec3(rng.Range(-1, 1), rng.Range(-1, 1), rng.Range(-1, 1)) + vec3(0, 1e-3f, 0));
    float lo = 0.0f, hi = Magnitude(t.a.size) + Magnitude(t.size) + 0.1f;
    for (int it = 0; it < 40; ++it) {
        const float mid = 0.5f * (lo + hi);
        (OBBOBB(t.a, OBB(t.direction * mid, t.size, t.rotation)) ? lo : hi) = mid;
    }
    t.touching = lo;
    return t;
}
