// ContactSolver::Soft, the four-wide path (docs/soft-solver.md, "Graph colouring"): the pairs of one batch (one colour
// of the contact graph, SoftSolverGraph.h: no moving body twice) are solved together, one per lane, with the equations
// of SoftContactKernel.h, the same the scalar path uses, so a lane gives the scalar path's bits.
#include <algorithm>
#include <cstddef>
#include <cstring>

#include "Physics/JobPool.h"
#include "Physics/SoftContactKernel.h"
#include "Physics/SoftSolver.h"

using namespace softkernel;

namespace {

/// Batches per job of BuildBatches: fixed, never derived from the thread count (docs/threads.md).
constexpr std::size_t kBatchChunk = 64;

using WideBatch = SoftContactSolver::WideBatch;
using WidePoint = SoftContactSolver::WidePoint;

static_assert(sizeof(vec3) == 12 && offsetof(SoftContactSolver::BodyState, v) == 0 &&
                  offsetof(SoftContactSolver::BodyState, w) == 16 && offsetof(SoftContactSolver::BodyState, dp) == 32,
              "BodyState's v, w and dp must each fill 16 bytes with their padding (Load4, Scatter)");

/// The lanes' body velocities (zero for an empty lane). Gather and Scatter are inlined into every pass: called, they
/// handed the twelve lane vectors over through memory (1.6 % of tower 10's step, callgrind).
__attribute__((always_inline)) inline WideVelocities Gather(const std::vector<SoftContactSolver::BodyState>& state,
                                                            const WideBatch& batch) {
    const Float4 zero = Wide(0.0f);
    Float4 vA[4], wA[4], vB[4], wB[4];
    for (int lane = 0; lane < 4; ++lane) {
        if (batch.pair[lane] < 0) {
            vA[lane] = wA[lane] = vB[lane] = wB[lane] = zero;
            continue;
        }
        const SoftContactSolver::BodyState& A = state[static_cast<std::size_t>(batch.a[lane])];
        const SoftContactSolver::BodyState& B = state[static_cast<std::size_t>(batch.b[lane])];
        vA[lane] = Load4(A.v);
        wA[lane] = Load4(A.w);
        vB[lane] = Load4(B.v);
        wB[lane] = Load4(B.w);
    }
    return {Transpose(vA[0], vA[1], vA[2], vA[3]), Transpose(wA[0], wA[1], wA[2], wA[3]),
            Transpose(vB[0], vB[1], vB[2], vB[3]), Transpose(wB[0], wB[1], wB[2], wB[3])};
}

/// Writes the lanes' velocities back to their moving bodies (static and sleeping ones are never written).
__attribute__((always_inline)) inline void Scatter(std::vector<SoftContactSolver::BodyState>& state,
                                                   const WideBatch& batch, const WideVelocities& s) {
    Float4 vA[4], wA[4], vB[4], wB[4];
    Untranspose(s.vA, vA);
    Untranspose(s.wA, wA);
    Untranspose(s.vB, vB);
    Untranspose(s.wB, wB);
    for (int lane = 0; lane < 4; ++lane) {
        if ((batch.movesA >> lane & 1u) != 0u) {
            SoftContactSolver::BodyState& A = state[static_cast<std::size_t>(batch.a[lane])];
            std::memcpy(&A.v.x, &vA[lane], sizeof(Float4));
            std::memcpy(&A.w.x, &wA[lane], sizeof(Float4));
        }
        if ((batch.movesB >> lane & 1u) != 0u) {
            SoftContactSolver::BodyState& B = state[static_cast<std::size_t>(batch.b[lane])];
            std::memcpy(&B.v.x, &vB[lane], sizeof(Float4));
            std::memcpy(&B.w.x, &wB[lane], sizeof(Float4));
        }
    }
}

/// Zeroes what FillBatch reads before writing it or writes in some lanes only: the counts and move bits, the
/// per-lane constants, and each point's impulses, support and separation (an empty lane or a missing point keeps
/// zero there). FillBatch writes the rest whole for the points the batch has (and no pass reads the others), so a
/// slot kept from the last step is not zeroed all over (that was 1 % of a 10-box tower's step, callgrind).
void ClearBatch(WideBatch& batch) {
    const Float4 zero = Wide(0.0f);
    batch.pointCount = 0;
    batch.movesA = batch.movesB = 0;
    batch.invMassA = batch.invMassB = batch.friction = zero;
    batch.biasRate = batch.massScale = batch.impulseScale = zero;
    for (WidePoint& p : batch.points) {
        p.normal.impulse = p.tangent1.impulse = p.tangent2.impulse = zero;
        p.support = p.baseSeparation = zero;
    }
}

}  // namespace

void SoftContactSolver::BuildBatches(const Softness& softness, const Softness& staticSoftness, JobPool* jobs) {
    const std::vector<SoftContactGraph::Batch>& lanes = graph.Batches();
    // Each batch is filled from its own lanes only, so chunks of batches run on the step's threads; a slot kept from
    // the last step is cleared by its own job (ClearBatch).
    batches.resize(lanes.size());
    ForEachChunk(jobs, lanes.size(), kBatchChunk, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) {
            ClearBatch(batches[k]);
            FillBatch(lanes[k], softness, staticSoftness, &batches[k]);
        }
    });
}

void SoftContactSolver::FillBatch(const SoftContactGraph::Batch& lanes, const Softness& softness,
                                  const Softness& staticSoftness, WideBatch* out) {
    WideBatch& batch = *out;
    batch.colour = lanes.colour;
    // The lanes' vectors as padded 16-byte rows (an empty lane or a missing point: zeros), transposed once below
    // rather than written lane by lane into the batch and read back at once.
    const Float4 zero = Wide(0.0f);
    Float4 n[4], t1[4], t2[4], iA[3][4], iB[3][4], rA[4][4], rB[4][4];  // [lane]; [row or point][lane]
    Mask4 valid[4] = {};                                                // point k of lane l exists
    for (int lane = 0; lane < 4; ++lane) {
        n[lane] = t1[lane] = t2[lane] = zero;
        for (int r = 0; r < 3; ++r) iA[r][lane] = iB[r][lane] = zero;
        for (int k = 0; k < 4; ++k) rA[k][lane] = rB[k][lane] = zero;
        batch.pair[lane] = batch.a[lane] = batch.b[lane] = -1;
        const int index = lanes.pair[lane];
        if (index < 0) continue;
        const Pair& pair = pairs[static_cast<std::size_t>(index)];
        batch.pair[lane] = index;
        batch.a[lane] = pair.a;
        batch.b[lane] = pair.b;
        if (sim[pair.a].dynamic) batch.movesA |= static_cast<std::uint8_t>(1u << lane);
        if (sim[pair.b].dynamic) batch.movesB |= static_cast<std::uint8_t>(1u << lane);
        n[lane] = Load4(pair.n);
        t1[lane] = Load4(pair.t1);
        t2[lane] = Load4(pair.t2);
        batch.invMassA[lane] = sim[pair.a].invMass;
        batch.invMassB[lane] = sim[pair.b].invMass;
        batch.friction[lane] = pair.friction;
        const Softness& soft = pair.touchesStatic ? staticSoftness : softness;
        batch.biasRate[lane] = soft.biasRate;
        batch.massScale[lane] = soft.massScale;
        batch.impulseScale[lane] = soft.impulseScale;
        batch.pointCount = std::max(batch.pointCount, static_cast<int>(pair.count));
        for (std::size_t k = 0; k < pair.count; ++k) {
            const Contact& c = contacts[pair.first + k];
            WidePoint& p = batch.points[k];
            rA[k][lane] = Load4(c.rA);  // the fourth lane (separation, id) is dropped by the transpose
            rB[k][lane] = Load4(c.rB);
            p.normal.impulse[lane] = c.normal.impulse;  // the warm start Collide matched
            p.support[lane] = c.support;
            p.tangent1.impulse[lane] = c.tangent1.impulse;
            p.tangent2.impulse[lane] = c.tangent2.impulse;
            p.baseSeparation[lane] = c.separation;  // minus n . (rB - rA) below
            valid[k][lane] = -1;
        }
        for (int r = 0; r < 3; ++r) {
            std::memcpy(&iA[r][lane], sim[pair.a].invI[r], sizeof(Float4));
            std::memcpy(&iB[r][lane], sim[pair.b].invI[r], sizeof(Float4));
        }
    }
    auto lanes4 = [](const Float4(&l)[4]) { return Transpose(l[0], l[1], l[2], l[3]); };
    batch.n = lanes4(n);
    batch.t1 = lanes4(t1);
    batch.t2 = lanes4(t2);
    const Vec4x3 IA[3] = {lanes4(iA[0]), lanes4(iA[1]), lanes4(iA[2])};  // world inverse inertias, by rows
    const Vec4x3 IB[3] = {lanes4(iB[0]), lanes4(iB[1]), lanes4(iB[2])};
    for (int k = 0; k < batch.pointCount; ++k) {
        batch.points[k].rA = lanes4(rA[k]);
        batch.points[k].rB = lanes4(rB[k]);
    }
    // PreparePair four wide: rows, base separation, normal speed before solving.
    const Float4 invSum = batch.invMassA + batch.invMassB;
    const WideVelocities bodies = Gather(state, batch);
    for (int k = 0; k < batch.pointCount; ++k) {
        WidePoint& p = batch.points[k];
        MakeRow(p.rA, p.rB, batch.n, invSum, IA, IB, valid[k], &p.normal);
        MakeRow(p.rA, p.rB, batch.t1, invSum, IA, IB, valid[k], &p.tangent1);
        MakeRow(p.rA, p.rB, batch.t2, invSum, IA, IB, valid[k], &p.tangent2);
        p.coupling = TangentCoupling(p.tangent1, p.tangent2);
        p.baseSeparation = p.baseSeparation - Dot(Sub(p.rB, p.rA), batch.n);
        p.relativeVelocity = RowSpeed(bodies, batch.n, p.normal);
        p.maxNormalImpulse = Wide(0.0f);
    }
}

void SoftContactSolver::UpdateBatchSeparations(WideBatch& batch) const {
    // UpdatePairSeparations four wide: s = s_base + n . ((dpB - dpA) + rB dRB - rA dRA), rows of dR as vectors.
    // The lanes' dp and dR rows, each a padded 16-byte row of BodyState, transposed straight from the bodies. An empty
    // lane reads a body at rest (zero dp, identity dR): its anchors are zero, so its separation stays 0 as with zero
    // rows, and no pass reads it.
    static const BodyState kRest;
    const BodyState* A[4];
    const BodyState* B[4];
    for (int lane = 0; lane < 4; ++lane) {
        const bool empty = batch.pair[lane] < 0;
        A[lane] = empty ? &kRest : &state[static_cast<std::size_t>(batch.a[lane])];
        B[lane] = empty ? &kRest : &state[static_cast<std::size_t>(batch.b[lane])];
    }
    auto dp = [](const BodyState* const(&s)[4]) {
        return Transpose(Load4(s[0]->dp), Load4(s[1]->dp), Load4(s[2]->dp), Load4(s[3]->dp));
    };
    auto row = [](const BodyState* const(&s)[4], int r) {
        Float4 l[4];
        for (int lane = 0; lane < 4; ++lane) std::memcpy(&l[lane], s[lane]->dR[r], sizeof(Float4));
        return Transpose(l[0], l[1], l[2], l[3]);
    };
    const Vec4x3 RA[3] = {row(A, 0), row(A, 1), row(A, 2)};
    const Vec4x3 RB[3] = {row(B, 0), row(B, 1), row(B, 2)};
    const Vec4x3 d0 = Sub(dp(B), dp(A));
    for (int k = 0; k < batch.pointCount; ++k) {
        WidePoint& p = batch.points[k];
        const Vec4x3 d = Sub(Add(d0, Mul(p.rB, RB)), Mul(p.rA, RA));
        p.current = Dot(d, batch.n) + p.baseSeparation;
    }
}

void SoftContactSolver::WideWarmStart(const Block& block) {
    for (std::size_t b = block.batchBegin; b < block.batchEnd; ++b) {
        const WideBatch& batch = batches[b];
        WideVelocities s = Gather(state, batch);
        WarmStartPoints(s, batch.invMassA, batch.invMassB, batch.n, batch.t1, batch.t2, batch.points,
                        static_cast<std::size_t>(batch.pointCount));
        Scatter(state, batch, s);
    }
}

void SoftContactSolver::WideSolve(const Block& block, float invH, float maxPushout, float slop, bool useBias,
                                  bool updateSeparations) {
    const PassLanes<Float4> pass = {Wide(invH), Wide(slop), Wide(-maxPushout)};
    for (std::size_t b = block.batchBegin; b < block.batchEnd; ++b) {
        WideBatch& batch = batches[b];
        if (updateSeparations) UpdateBatchSeparations(batch);
        WideVelocities s = Gather(state, batch);
        // Friction in the relax pass only, and before the normal rows, as in SolvePair (with the bias flag a
        // constant in each branch, as there).
        if (useBias) {
            for (int k = 0; k < batch.pointCount; ++k)
                SolveNormal(s, batch.invMassA, batch.invMassB, batch.n, batch, pass, true, batch.points[k]);
        } else {
            for (int k = 0; k < batch.pointCount; ++k)
                SolveFriction(s, batch.invMassA, batch.invMassB, batch.t1, batch.t2, batch.friction, batch.points[k]);
            for (int k = 0; k < batch.pointCount; ++k)
                SolveNormal(s, batch.invMassA, batch.invMassB, batch.n, batch, pass, false, batch.points[k]);
        }
        Scatter(state, batch, s);
    }
}

void SoftContactSolver::StoreBatchImpulses(const Block& block) {
    for (std::size_t b = block.batchBegin; b < block.batchEnd; ++b) {
        const WideBatch& batch = batches[b];
        for (int lane = 0; lane < 4; ++lane) {
            if (batch.pair[lane] < 0) continue;
            const Pair& pair = pairs[static_cast<std::size_t>(batch.pair[lane])];
            for (std::size_t k = 0; k < pair.count; ++k) {
                const WidePoint& p = batch.points[k];
                Contact& c = contacts[pair.first + k];
                c.normal.impulse = p.normal.impulse[lane];
                c.tangent1.impulse = p.tangent1.impulse[lane];
                c.tangent2.impulse = p.tangent2.impulse[lane];
                c.current = p.current[lane];
                c.relativeVelocity = p.relativeVelocity[lane];
                c.maxNormalImpulse = p.maxNormalImpulse[lane];
                if (pair.restitution != 0.0f) {  // ApplyRestitution solves the normal row once more
                    c.normal.rAxD = Lane(p.normal.rAxD, lane);
                    c.normal.rBxD = Lane(p.normal.rBxD, lane);
                    c.normal.iArAxD = Lane(p.normal.iArAxD, lane);
                    c.normal.iBrBxD = Lane(p.normal.iBrBxD, lane);
                    c.normal.mass = p.normal.mass[lane];
                }
            }
        }
    }
}
