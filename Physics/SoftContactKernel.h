#pragma once
// The soft contact solver's per-contact equations (docs/soft-solver.md, "The soft-step solver"), written once for both
// of its paths: the scalar one (a pair at a time: R = float, a direction is a V4, a point is a Contact) and the
// four-wide one (four pairs of one colour at a time: R = Float4, a direction is a Vec4x3, a point is a WidePoint).
// Each lane of the wide path does the scalar path's operations in the scalar order, so both give the same bits.
// Only SoftSolver.cpp and SoftSolverWide.cpp include this.
#include <cmath>
#include <cstddef>

#include "Math/Simd4.h"
#include "Physics/SoftSolverRows.h"

namespace softkernel {

using namespace simd4;
using Row = SoftRow;
using WideRow = SoftWideRow;

/// A pair's two bodies' velocities while its contacts are solved (scalar path).
struct PairVelocities {
    V4 vA, wA, vB, wB;
};
/// The velocities of the lanes' bodies (four-wide path).
struct WideVelocities {
    Vec4x3 vA, wA, vB, wB;
};

inline PairVelocities LoadVelocities(const SoftBodyState& A, const SoftBodyState& B) {
    return {Load(A.v), Load(A.w), Load(B.v), Load(B.w)};
}
inline void StoreVelocities(const PairVelocities& x, SoftBodyState& A, SoftBodyState& B) {
    Store(A.v, x.vA);
    Store(A.w, x.wA);
    Store(B.v, x.vB);
    Store(B.w, x.wB);
}

// ---- A row's two primitives, per lane type: its relative speed and applying an impulse along it ----

/// Relative speed along a row: Dot(vB - vA, d) + Dot(wB, rB x d) - Dot(wA, rA x d), left to right.
inline float RowSpeed(const PairVelocities& x, V4 d, const Row& row) {
    const V4 dots = Dot3(x.vB - x.vA, d, x.wB, Load(row.rBxD), x.wA, Load(row.rAxD));
    return (Get<0>(dots) + Get<1>(dots)) - Get<2>(dots);
}
inline Float4 RowSpeed(const WideVelocities& x, const Vec4x3& d, const WideRow& row) {
    return Dot(Sub(x.vB, x.vA), d) + Dot(x.wB, row.rBxD) - Dot(x.wA, row.rAxD);
}
/// RowSpeed of the two friction rows from the same velocities (the scalar path shares the lane transposes).
inline void RowSpeeds(const PairVelocities& x, V4 d1, const Row& r1, V4 d2, const Row& r2, float* s1, float* s2) {
    const V4 dv = x.vB - x.vA;
    const V4 a = Dot4(dv, d1, x.wB, Load(r1.rBxD), x.wA, Load(r1.rAxD), dv, d2);  // dv.d1, wB.rB1, wA.rA1, dv.d2
    const V4 b = Dot3(x.wB, Load(r2.rBxD), x.wA, Load(r2.rAxD), Splat(0.0f), Splat(0.0f));
    *s1 = (Get<0>(a) + Get<1>(a)) - Get<2>(a);
    *s2 = (Get<3>(a) + Get<0>(b)) - Get<1>(b);
}
inline void RowSpeeds(const WideVelocities& x, const Vec4x3& d1, const WideRow& r1, const Vec4x3& d2, const WideRow& r2,
                      Float4* s1, Float4* s2) {
    *s1 = RowSpeed(x, d1, r1);
    *s2 = RowSpeed(x, d2, r2);
}
/// Impulse j along the row to B, -j to A.
inline void ApplyRow(PairVelocities& x, float invA, float invB, V4 d, const Row& row, float j) {
    x.vA = x.vA - d * Splat(invA * j);
    x.vB = x.vB + d * Splat(invB * j);
    x.wA = x.wA - Load(row.iArAxD) * Splat(j);
    x.wB = x.wB + Load(row.iBrBxD) * Splat(j);
}
inline void ApplyRow(WideVelocities& x, Float4 invA, Float4 invB, const Vec4x3& d, const WideRow& row, Float4 j) {
    x.vA = Sub(x.vA, Scale(d, invA * j));
    x.vB = Add(x.vB, Scale(d, invB * j));
    x.wA = Sub(x.wA, Scale(row.iArAxD, j));
    x.wB = Add(x.wB, Scale(row.iBrBxD, j));
}

/// Fills a row along d: Jacobians rA x d and rB x d, their images under the inverse inertias (rows of four floats)
/// and the effective mass 1 / (invSum + (rA x d) . IA^-1 (rA x d) + (rB x d) . IB^-1 (rB x d)), 0 when that is 0.
inline void MakeRow(V4 rA, V4 rB, V4 d, float invSum, const float (*iA)[4], const float (*iB)[4], Row* row) {
    const V4 rAxD = Cross(rA, d), rBxD = Cross(rB, d);
    const V4 iArAxD = MulRows(rAxD, iA), iBrBxD = MulRows(rBxD, iB);
    const float impulse = row->impulse;  // the fourth lanes of the Jacobians hold mass and impulse
    Store(row->rAxD, rAxD);
    Store(row->rBxD, rBxD);
    row->impulse = impulse;
    Store(row->iArAxD, iArAxD);
    Store(row->iBrBxD, iBrBxD);
    const float k = invSum + Dot(rAxD, iArAxD) + Dot(rBxD, iBrBxD);
    row->mass = k > 0.0f ? 1.0f / k : 0.0f;
}
/// The same four wide; a point that does not exist (valid 0) gets mass 0, which makes its rows do nothing.
inline void MakeRow(const Vec4x3& rA, const Vec4x3& rB, const Vec4x3& d, Float4 invSum, const Vec4x3 (&iA)[3],
                    const Vec4x3 (&iB)[3], Mask4 valid, WideRow* row) {
    row->rAxD = Cross(rA, d);
    row->rBxD = Cross(rB, d);
    row->iArAxD = Mul(row->rAxD, iA);
    row->iBrBxD = Mul(row->rBxD, iB);
    const Float4 k = invSum + Dot(row->rAxD, row->iArAxD) + Dot(row->rBxD, row->iBrBxD);
    const Float4 zero = Wide(0.0f);
    row->mass = Select(valid & (k > zero), Wide(1.0f) / k, zero);
}

/// The off-diagonal entry of a contact's inverse mass matrix in its tangent plane, t1 . K t2 = (rA x t1) . IA^-1
/// (rA x t2) + (rB x t1) . IB^-1 (rB x t2) (t1 . t2 = 0: no linear part), 1/kg: with the rows' own 1 / mass, the
/// inverse mass along any direction of the plane (SolveFriction).
inline float TangentCoupling(const Row& r1, const Row& r2) {
    return Dot(Load(r1.rAxD), Load(r2.iArAxD)) + Dot(Load(r1.rBxD), Load(r2.iBrBxD));
}
inline Float4 TangentCoupling(const WideRow& r1, const WideRow& r2) {
    return Dot(r1.rAxD, r2.iArAxD) + Dot(r1.rBxD, r2.iBrBxD);
}

/// The factor that brings a friction impulse of squared length sq back onto the cone of radius limit: 1 inside it.
inline float ConeScale(float sq, float limit) {
    if (!(sq > limit * limit)) return 1.0f;
    return limit > 0.0f ? limit / std::sqrt(sq) : 0.0f;
}
inline Float4 ConeScale(Float4 sq, Float4 limit) {
    const Float4 zero = Wide(0.0f);
    return Select(sq > limit * limit, Select(limit > zero, limit / Sqrt(sq), zero), Wide(1.0f));
}

// ---- The equations of one contact point, for either lane type ----
// B: the velocities (PairVelocities, WideVelocities); R: float or Float4; D: a direction (V4, Vec4x3); P: a point
// (Contact, WidePoint: rows normal, tangent1, tangent2, and current, relativeVelocity, maxNormalImpulse, support).

/// A row's angular part of impulse j (ApplyRow without the linear part).
inline void ApplyTurn(PairVelocities& x, const Row& row, float j) {
    x.wA = x.wA - Load(row.iArAxD) * Splat(j);
    x.wB = x.wB + Load(row.iBrBxD) * Splat(j);
}
inline void ApplyTurn(WideVelocities& x, const WideRow& row, Float4 j) {
    x.wA = Sub(x.wA, Scale(row.iArAxD, j));
    x.wB = Add(x.wB, Scale(row.iBrBxD, j));
}
/// The linear part of a pair's impulse jn n + j1 t1 + j2 t2 (its points' impulses summed per direction): to B, minus
/// to A.
inline void ApplyPush(PairVelocities& x, float invA, float invB, V4 n, V4 t1, V4 t2, float jn, float j1, float j2) {
    const V4 p = n * Splat(jn) + t1 * Splat(j1) + t2 * Splat(j2);
    x.vA = x.vA - p * Splat(invA);
    x.vB = x.vB + p * Splat(invB);
}
inline void ApplyPush(WideVelocities& x, Float4 invA, Float4 invB, const Vec4x3& n, const Vec4x3& t1, const Vec4x3& t2,
                      Float4 jn, Float4 j1, Float4 j2) {
    const Vec4x3 p = Add(Add(Scale(n, jn), Scale(t1, j1)), Scale(t2, j2));
    x.vA = Sub(x.vA, Scale(p, invA));
    x.vB = Add(x.vB, Scale(p, invB));
}

/// Warm start: the kept impulses of a pair's `count` points applied again. The points share the pair's directions,
/// so the linear part is applied once, from the impulses summed per direction; the angular part point by point.
template <class B, class R, class D, class P>
inline void WarmStartPoints(B& x, R invA, R invB, const D& n, const D& t1, const D& t2, const P* points,
                            std::size_t count) {
    R jn = Fill<R>(0.0f), j1 = Fill<R>(0.0f), j2 = Fill<R>(0.0f);
    for (std::size_t k = 0; k < count; ++k) {
        const P& c = points[k];
        ApplyTurn(x, c.normal, c.normal.impulse);
        ApplyTurn(x, c.tangent1, c.tangent1.impulse);
        ApplyTurn(x, c.tangent2, c.tangent2.impulse);
        jn = jn + c.normal.impulse;
        j1 = j1 + c.tangent1.impulse;
        j2 = j2 + c.tangent2.impulse;
    }
    ApplyPush(x, invA, invB, n, t1, t2, jn, j1, j2);
}

/// Friction (relax pass only): the TOTAL stays inside the Coulomb cone mu jn (book §15, Coulomb clamp), jn from the
/// last pass without bias (P::support; docs/soft-solver.md, "Convergence of the contact solvers"). A sticking contact
/// is two rows, t1 and t2, each with its own effective mass. A sliding one (the two rows would leave the cone) is one
/// row along its slip, so its impulse opposes the slip: the two rows' masses differ wherever the contact is off the
/// body's axes, and their clamped sum pushed a box sliding at a yaw sideways (3.3 cm off the Coulomb stop at every
/// step; ContactSolver.ABoxSlidingAtAYawStopsWhereCoulombSays). The accumulated solver does the same.
template <class B, class R, class D, class P>
inline void SolveFriction(B& x, R invA, R invB, const D& t1, const D& t2, R friction, P& c) {
    const R limit = friction * c.support;
    R speed1, speed2;
    RowSpeeds(x, t1, c.tangent1, t2, c.tangent2, &speed1, &speed2);
    R j1 = c.tangent1.impulse - c.tangent1.mass * speed1;
    R j2 = c.tangent2.impulse - c.tangent2.mass * speed2;
    const auto outside = j1 * j1 + j2 * j2 > limit * limit;
    if (Any(outside)) {
        // Sliding (outside the cone and slipping): effective mass along the slip u = t1 s1 + t2 s2, |u|^2 / (u . K u),
        // K the contact's inverse mass matrix in the tangent plane (1 / mass on its diagonal, P::coupling off it).
        const R zero = Fill<R>(0.0f);
        const R slipSq = speed1 * speed1 + speed2 * speed2;
        const auto slides = And(outside, slipSq > zero);
        const R k = speed1 * speed1 / c.tangent1.mass + speed2 * speed2 / c.tangent2.mass +
                    Fill<R>(2.0f) * speed1 * speed2 * c.coupling;
        const R mass = Select(k > zero, slipSq / k, zero);
        j1 = Select(slides, c.tangent1.impulse - mass * speed1, j1);
        j2 = Select(slides, c.tangent2.impulse - mass * speed2, j2);
        // Then scaled back onto the cone (a scale of 1 leaves the lanes inside it unchanged, bit for bit).
        const R scale = ConeScale(j1 * j1 + j2 * j2, limit);
        j1 = j1 * scale;
        j2 = j2 * scale;
    }
    const R d1 = j1 - c.tangent1.impulse, d2 = j2 - c.tangent2.impulse;
    c.tangent1.impulse = j1;
    c.tangent2.impulse = j2;
    ApplyRow(x, invA, invB, t1, c.tangent1, d1);
    ApplyRow(x, invA, invB, t2, c.tangent2, d2);
}

/// What a pass asks of the normal rows: 1 / h, the slop (m) and the fastest push-out as a negative speed (m/s).
template <class R>
struct PassLanes {
    R invH, slop, pushout;
};

/// The normal row. Speculative (separation s > 0): may close the gap this substep, no more (rigid, bias s / h).
/// Penetrating, biased pass: the soft push-out (S: biasRate, massScale, impulseScale; Softness or a batch's lanes).
/// Relax pass: rigid, no bias. The TOTAL impulse stays >= 0 (contacts push). Written as selects, not branches:
/// whether a contact is speculative is hard to predict.
template <class B, class R, class D, class S, class P>
inline void SolveNormal(B& x, R invA, R invB, const D& n, const S& soft, const PassLanes<R>& pass, bool useBias, P& c) {
    const R zero = Fill<R>(0.0f), one = Fill<R>(1.0f);
    const R s = c.current;
    const auto speculative = s > zero;
    R bias = zero, massScale = one, impulseScale = zero;
    if (useBias) {
        bias = Max(soft.biasRate * Min(s + pass.slop, zero), pass.pushout);
        massScale = soft.massScale;
        impulseScale = soft.impulseScale;
    }
    bias = Select(speculative, s * pass.invH, bias);
    massScale = Select(speculative, one, massScale);
    impulseScale = Select(speculative, zero, impulseScale);
    const R vn = RowSpeed(x, n, c.normal);
    // Restitution works from the fastest closing speed met before solving (the impact substep), not from the
    // step's start, which misses up to g dt of the fall.
    if (useBias) c.relativeVelocity = Min(c.relativeVelocity, vn);
    const R J = c.normal.impulse;
    const R jn = Max(J - c.normal.mass * massScale * (vn + bias) - impulseScale * J, zero);
    c.normal.impulse = jn;
    c.maxNormalImpulse = Max(c.maxNormalImpulse, jn);
    if (!useBias) c.support = jn;
    ApplyRow(x, invA, invB, n, c.normal, jn - J);
}

/// Restitution after the substeps: the normal speed -e times the closing speed met before solving.
template <class B, class R, class D, class P>
inline void SolveRestitution(B& x, R invA, R invB, const D& n, R restitution, P& c) {
    const R vn = RowSpeed(x, n, c.normal);
    const R J = c.normal.impulse;
    const R jn = Max(J - c.normal.mass * (vn + restitution * c.relativeVelocity), Fill<R>(0.0f));
    c.normal.impulse = jn;
    c.maxNormalImpulse = Max(c.maxNormalImpulse, jn);
    ApplyRow(x, invA, invB, n, c.normal, jn - J);
}

}  // namespace softkernel
