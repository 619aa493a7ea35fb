#pragma once
// The soft solver's rows and per-body velocity state (SoftSolver.h), on their own so that the contact kernel
// (SoftContactKernel.h) and the solver (SoftSolver.h) both build on them without including each other.
//
// The solver's hot data keeps every vec3 on a 16-byte boundary followed by a fourth float, so the inner loops work on
// four lanes at once (the fourth lane never reaches a result); each lane does the scalar operations in the scalar
// order, so results are the same bits as plain vec3 arithmetic.

#include "Math/Simd4.h"
#include "Math/vectors.h"

/// One row of a contact (normal or tangent direction d): the angular Jacobians and their images under the
/// world inverse inertias, so solving needs no matrix product.
struct alignas(16) SoftRow {
    vec3 rAxD;             // rA x d
    float mass = 0.0f;     // 1 / effective inverse mass along d, kg
    vec3 rBxD;             // rB x d
    float impulse = 0.0f;  // accumulated this substep, N s
    vec3 iArAxD;           // IA^-1 (rA x d)
    float padA = 0.0f;
    vec3 iBrBxD;  // IB^-1 (rB x d)
    float padB = 0.0f;
};

/// One row of a point in every lane (SoftRow, four wide).
struct SoftWideRow {
    simd4::Vec4x3 rAxD, rBxD, iArAxD, iBrBxD;
    simd4::Float4 mass, impulse;
};

/// Per-body solver state of the step (hot: read and written every pass).
struct alignas(16) SoftBodyState {
    vec3 v;  // linear velocity, world, m/s
    float padV = 0.0f;
    vec3 w;  // angular velocity, world, rad/s
    float padW = 0.0f;
    vec3 dp;  // position change since the step began, m
    float padP = 0.0f;
    // Rotation since the step began (row-vector form), rows padded to four floats.
    float dR[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    // v and w as this substep's IntegrateVelocities left them, before any contact impulse: v - v0 and w - w0 at
    // the substep's end are what its contacts gave (the next substep's warm start, IntegrateVelocities).
    vec3 v0;
    float padV0 = 0.0f;
    vec3 w0;
    float padW0 = 0.0f;
};
