// ContactSolver::Soft by constraint-graph colour (docs/ch15.md, "Graph colouring"): every pair takes the first of
// kColours colours that neither of its moving bodies has yet, so the pairs of one colour share no moving body and
// four of them can be solved at once, one per lane, with the same equations as SolvePair. Static and sleeping
// bodies have no colour (nothing is written to them), so every pair on the ground can share one. Pairs that find
// no colour, and a colour's last pair when it would be alone in its batch, are solved one by one after the batches.
// Colours, batches and lanes are filled in pair order, so the solve order is a fixed function of the pairs
// (deterministic).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>

#include "Physics/SoftSolver.h"

namespace {

using Float4 = SoftContactSolver::Float4;
using Vec4x3 = SoftContactSolver::Vec4x3;
using WideRow = SoftContactSolver::WideRow;
using WideBatch = SoftContactSolver::WideBatch;

inline Float4 Splat(float v) { return Float4{v, v, v, v}; }
/// std::max and std::min lane by lane ((a < b) ? b : a and (b < a) ? b : a).
inline Float4 Max(Float4 a, Float4 b) { return a < b ? b : a; }
inline Float4 Min(Float4 a, Float4 b) { return b < a ? b : a; }
using Mask4 = decltype(Float4{} < Float4{});
inline Float4 Select(Mask4 mask, Float4 a, Float4 b) { return mask ? a : b; }

inline Vec4x3 Sub(const Vec4x3& l, const Vec4x3& r) { return {l.x - r.x, l.y - r.y, l.z - r.z}; }
inline Vec4x3 Add(const Vec4x3& l, const Vec4x3& r) { return {l.x + r.x, l.y + r.y, l.z + r.z}; }
inline Vec4x3 Scale(const Vec4x3& v, Float4 s) { return {v.x * s, v.y * s, v.z * s}; }
/// Dot(l, r) lane by lane, in Dot's order (x, then y, then z).
inline Float4 Dot(const Vec4x3& l, const Vec4x3& r) { return l.x * r.x + l.y * r.y + l.z * r.z; }

/// Cross(l, r) lane by lane, in Cross's order.
inline Vec4x3 Cross(const Vec4x3& l, const Vec4x3& r) {
    return {l.y * r.z - l.z * r.y, l.z * r.x - l.x * r.z, l.x * r.y - l.y * r.x};
}

/// Velocities of the lanes' bodies.
struct WideBodies {
    Vec4x3 vA, wA, vB, wB;
};

/// RowSpeed, four wide: Dot(vB - vA, d) + Dot(wB, rB x d) - Dot(wA, rA x d).
inline Float4 RowSpeed(const WideBodies& s, const Vec4x3& d, const WideRow& row) {
    return Dot(Sub(s.vB, s.vA), d) + Dot(s.wB, row.rBxD) - Dot(s.wA, row.rAxD);
}

/// ApplyRow, four wide: j along d to B, -j to A.
inline void ApplyRow(WideBodies& s, Float4 invA, Float4 invB, const Vec4x3& d, const WideRow& row, Float4 j) {
    s.vA = Sub(s.vA, Scale(d, invA * j));
    s.vB = Add(s.vB, Scale(d, invB * j));
    s.wA = Sub(s.wA, Scale(row.iArAxD, j));
    s.wB = Add(s.wB, Scale(row.iBrBxD, j));
}

inline void SetLane(Vec4x3* v, int lane, const vec3& value) {
    v->x[lane] = value.x;
    v->y[lane] = value.y;
    v->z[lane] = value.z;
}
inline vec3 Lane(const Vec4x3& v, int lane) { return vec3(v.x[lane], v.y[lane], v.z[lane]); }

/// v M four wide (row-vector convention, as SoftSolver.cpp's Mul), M given by its rows m[0..2].
inline Vec4x3 Mul(const Vec4x3& v, const Vec4x3 (&m)[3]) {
    return {v.x * m[0].x + v.y * m[1].x + v.z * m[2].x, v.x * m[0].y + v.y * m[1].y + v.z * m[2].y,
            v.x * m[0].z + v.y * m[1].z + v.z * m[2].z};
}

static_assert(sizeof(vec3) == 12 && offsetof(SoftContactSolver::BodyState, v) == 0 &&
                  offsetof(SoftContactSolver::BodyState, w) == 16 && offsetof(SoftContactSolver::BodyState, dp) == 32,
              "BodyState's v, w and dp must each fill 16 bytes with their padding (Load4, Scatter)");

/// A vec3 with its padding float (16 bytes, 16-aligned in BodyState) as one Float4.
inline Float4 Load4(const vec3& v) {
    Float4 r;
    std::memcpy(&r, &v.x, sizeof(r));
    return r;
}

/// Four rows (x, y, z, pad) of lanes 0..3 turned into the lanes' x, y and z (a 4x4 transpose: data moves only).
inline Vec4x3 Transpose(Float4 r0, Float4 r1, Float4 r2, Float4 r3) {
    const Float4 xy01 = __builtin_shufflevector(r0, r1, 0, 4, 1, 5);  // x0 x1 y0 y1
    const Float4 xy23 = __builtin_shufflevector(r2, r3, 0, 4, 1, 5);
    const Float4 zp01 = __builtin_shufflevector(r0, r1, 2, 6, 3, 7);  // z0 z1 p0 p1
    const Float4 zp23 = __builtin_shufflevector(r2, r3, 2, 6, 3, 7);
    return {__builtin_shufflevector(xy01, xy23, 0, 1, 4, 5), __builtin_shufflevector(xy01, xy23, 2, 3, 6, 7),
            __builtin_shufflevector(zp01, zp23, 0, 1, 4, 5)};
}

/// The inverse: lane l's (x, y, z, 0) as row l.
inline void Untranspose(const Vec4x3& v, Float4 (&row)[4]) {
    const Float4 zero = {0.0f, 0.0f, 0.0f, 0.0f};
    const Float4 xy01 = __builtin_shufflevector(v.x, v.y, 0, 4, 1, 5);  // x0 y0 x1 y1
    const Float4 xy23 = __builtin_shufflevector(v.x, v.y, 2, 6, 3, 7);
    const Float4 z01 = __builtin_shufflevector(v.z, zero, 0, 4, 1, 5);  // z0 0 z1 0
    const Float4 z23 = __builtin_shufflevector(v.z, zero, 2, 6, 3, 7);
    row[0] = __builtin_shufflevector(xy01, z01, 0, 1, 4, 5);
    row[1] = __builtin_shufflevector(xy01, z01, 2, 3, 6, 7);
    row[2] = __builtin_shufflevector(xy23, z23, 0, 1, 4, 5);
    row[3] = __builtin_shufflevector(xy23, z23, 2, 3, 6, 7);
}

/// The lanes' body velocities (zero for an empty lane).
WideBodies Gather(const std::vector<SoftContactSolver::BodyState>& state, const WideBatch& batch) {
    const Float4 zero = {0.0f, 0.0f, 0.0f, 0.0f};
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
void Scatter(std::vector<SoftContactSolver::BodyState>& state, const WideBatch& batch, const WideBodies& s) {
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

/// SoftSolver.cpp's MakeRow four wide: Jacobians along d, their images under the inverse inertias and the
/// effective mass; a point that does not exist (valid 0) gets mass 0, which makes its rows do nothing.
void MakeRow(const Vec4x3& rA, const Vec4x3& rB, const Vec4x3& d, Float4 invSum, const Vec4x3 (&iA)[3],
             const Vec4x3 (&iB)[3], Mask4 valid, WideRow* row) {
    row->rAxD = Cross(rA, d);
    row->rBxD = Cross(rB, d);
    row->iArAxD = Mul(row->rAxD, iA);
    row->iBrBxD = Mul(row->rBxD, iB);
    const Float4 k = invSum + Dot(row->rAxD, row->iArAxD) + Dot(row->rBxD, row->iBrBxD);
    const Float4 zero = Splat(0.0f);
    row->mass = Select(valid & (k > zero), Splat(1.0f) / k, zero);
}

}  // namespace

void SoftContactSolver::BuildBlocks(bool colouring, const Softness& softness, const Softness& staticSoftness) {
    // Capacities are kept from step to step, so the steady state allocates nothing.
    const std::size_t n = state.size();
    blocks.clear();
    blockBodies.clear();
    batches.clear();
    overflow.clear();
    if (!colouring || pairs.size() < kBlockPairs) {
        // One block of every moving body: without colouring, every pair one by one in pair order; with fewer pairs
        // than a block holds (what the islands below would give: one block, bodies and pairs in order), the
        // batches and overflow of all of them. A small world pays for no islands.
        for (std::size_t i = 0; i < n; ++i)
            if (sim[i].dynamic) blockBodies.push_back(static_cast<int>(i));
        if (colouring) {
            blockPairList.resize(pairs.size());
            for (std::size_t i = 0; i < pairs.size(); ++i) blockPairList[i] = static_cast<int>(i);
            bodyColours.assign(n, 0u);
            BuildBatches(blockPairList, 0, pairs.size(), softness, staticSoftness);
        } else {
            for (std::size_t i = 0; i < pairs.size(); ++i) overflow.push_back(static_cast<int>(i));
        }
        blocks.push_back({0, blockBodies.size(), 0, batches.size(), 0, overflow.size()});
        return;
    }
    // Islands: union-find over the pairs of two moving bodies, the smaller root kept (a fixed function of the pairs).
    islandParent.resize(n);
    for (std::size_t i = 0; i < n; ++i) islandParent[i] = static_cast<int>(i);
    auto root = [this](int i) {
        while (islandParent[static_cast<std::size_t>(i)] != i) {
            int& parent = islandParent[static_cast<std::size_t>(i)];
            parent = islandParent[static_cast<std::size_t>(parent)];  // path halving
            i = parent;
        }
        return i;
    };
    for (const Pair& pair : pairs) {
        if (!sim[pair.a].dynamic || !sim[pair.b].dynamic) continue;
        const int ra = root(pair.a), rb = root(pair.b);
        if (ra != rb) islandParent[static_cast<std::size_t>(std::max(ra, rb))] = std::min(ra, rb);
    }
    auto moving = [this](const Pair& pair) { return sim[pair.a].dynamic ? pair.a : pair.b; };
    // Pairs per island, then islands into blocks in order of their first body, closed at kBlockPairs pairs.
    islandPairs.assign(n, 0);
    for (const Pair& pair : pairs) ++islandPairs[static_cast<std::size_t>(root(moving(pair)))];
    std::size_t blockCount = 0, open = 0;  // blocks closed; pairs in the open block
    bool openUsed = false;
    for (std::size_t i = 0; i < n; ++i) {
        if (!sim[i].dynamic) continue;
        const std::size_t r = static_cast<std::size_t>(root(static_cast<int>(i)));
        if (r != i) continue;  // the root is the island's first body: each island is met once, in order
        open += static_cast<std::size_t>(islandPairs[r]);
        islandPairs[r] = static_cast<int>(blockCount);  // read once: from here it holds the island's block
        openUsed = true;
        if (open >= kBlockPairs) {
            ++blockCount;
            open = 0;
            openUsed = false;
        }
    }
    if (openUsed) ++blockCount;
    auto blockOf = [&](int body) {
        return static_cast<std::size_t>(islandPairs[static_cast<std::size_t>(root(body))]);
    };
    // Bodies and pairs by block, each in its own order (counting sort).
    blockStart.assign(blockCount + 1, 0);
    for (std::size_t i = 0; i < n; ++i)
        if (sim[i].dynamic) ++blockStart[blockOf(static_cast<int>(i)) + 1];
    for (std::size_t b = 0; b < blockCount; ++b) blockStart[b + 1] += blockStart[b];
    blocks.resize(blockCount);
    for (std::size_t b = 0; b < blockCount; ++b) blocks[b].bodyBegin = blocks[b].bodyEnd = blockStart[b];
    blockBodies.resize(blockStart[blockCount]);
    for (std::size_t i = 0; i < n; ++i)
        if (sim[i].dynamic) blockBodies[blocks[blockOf(static_cast<int>(i))].bodyEnd++] = static_cast<int>(i);
    blockStart.assign(blockCount + 1, 0);
    for (const Pair& pair : pairs) ++blockStart[blockOf(moving(pair)) + 1];
    for (std::size_t b = 0; b < blockCount; ++b) blockStart[b + 1] += blockStart[b];
    blockPairList.resize(pairs.size());
    for (std::size_t i = 0; i < pairs.size(); ++i)
        blockPairList[blockStart[blockOf(moving(pairs[i]))]++] = static_cast<int>(i);
    // blockStart[b] is now where block b + 1's pairs start.
    bodyColours.assign(n, 0u);
    for (std::size_t b = 0; b < blockCount; ++b) {
        Block& block = blocks[b];
        block.batchBegin = batches.size();
        block.overflowBegin = overflow.size();
        BuildBatches(blockPairList, b == 0 ? 0 : blockStart[b - 1], blockStart[b], softness, staticSoftness);
        block.batchEnd = batches.size();
        block.overflowEnd = overflow.size();
    }
}

void SoftContactSolver::BuildBatches(const std::vector<int>& list, std::size_t begin, std::size_t end,
                                     const Softness& softness, const Softness& staticSoftness) {
    // Colour the pairs: the first colour free at both moving bodies.
    for (std::vector<int>& colour : colourPairs) colour.clear();
    for (std::size_t at = begin; at < end; ++at) {
        const std::size_t i = static_cast<std::size_t>(list[at]);
        const Pair& pair = pairs[i];
        const bool movesA = sim[pair.a].dynamic, movesB = sim[pair.b].dynamic;
        const std::uint32_t taken = (movesA ? bodyColours[pair.a] : 0u) | (movesB ? bodyColours[pair.b] : 0u);
        int colour = 0;
        while (colour < kColours && (taken >> colour & 1u) != 0u) ++colour;
        if (colour == kColours || (!movesA && !movesB)) {
            overflow.push_back(static_cast<int>(i));
            continue;
        }
        if (movesA) bodyColours[pair.a] |= 1u << colour;
        if (movesB) bodyColours[pair.b] |= 1u << colour;
        colourPairs[colour].push_back(static_cast<int>(i));
    }
    // Four pairs of a colour per batch; a lane without a pair keeps zeros (no bodies, zero masses: no effect).
    for (int colour = 0; colour < kColours; ++colour) {
        const std::vector<int>& list = colourPairs[colour];
        for (std::size_t first = 0; first < list.size(); first += 4) {
            // A batch of one pair would do four lanes' work for one: that pair is solved one by one, with the
            // overflow (a column of 10 cubes has two colours of five pairs: 18 % less time in the lab tool).
            if (list.size() - first == 1) {
                overflow.push_back(list[first]);
                continue;
            }
            batches.emplace_back();  // value-initialised: every lane and point zero
            WideBatch& batch = batches.back();
            batch.colour = colour;
            Vec4x3 IA[3] = {}, IB[3] = {};  // the lanes' world inverse inertias, by rows
            Mask4 valid[4] = {};            // point k of lane l exists
            for (int lane = 0; lane < 4; ++lane) {
                batch.pair[lane] = batch.a[lane] = batch.b[lane] = -1;
                if (first + static_cast<std::size_t>(lane) >= list.size()) continue;
                const int index = list[first + static_cast<std::size_t>(lane)];
                const Pair& pair = pairs[static_cast<std::size_t>(index)];
                batch.pair[lane] = index;
                batch.a[lane] = pair.a;
                batch.b[lane] = pair.b;
                if (sim[pair.a].dynamic) batch.movesA |= static_cast<std::uint8_t>(1u << lane);
                if (sim[pair.b].dynamic) batch.movesB |= static_cast<std::uint8_t>(1u << lane);
                SetLane(&batch.n, lane, pair.n);
                SetLane(&batch.t1, lane, pair.t1);
                SetLane(&batch.t2, lane, pair.t2);
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
                    SetLane(&p.rA, lane, c.rA);
                    SetLane(&p.rB, lane, c.rB);
                    p.normal.impulse[lane] = c.normal.impulse;  // the warm start Collide matched
                    p.support[lane] = c.support;
                    p.tangent1.impulse[lane] = c.tangent1.impulse;
                    p.tangent2.impulse[lane] = c.tangent2.impulse;
                    p.baseSeparation[lane] = c.separation;  // minus n . (rB - rA) below
                    valid[k][lane] = -1;
                }
                const auto& iA = sim[pair.a].invI;
                const auto& iB = sim[pair.b].invI;
                for (int r = 0; r < 3; ++r) {
                    SetLane(&IA[r], lane, vec3(iA[r][0], iA[r][1], iA[r][2]));
                    SetLane(&IB[r], lane, vec3(iB[r][0], iB[r][1], iB[r][2]));
                }
            }
            // PreparePair four wide: rows, base separation, normal speed before solving.
            const Float4 invSum = batch.invMassA + batch.invMassB;
            const WideBodies bodies = Gather(state, batch);
            for (int k = 0; k < batch.pointCount; ++k) {
                WidePoint& p = batch.points[k];
                MakeRow(p.rA, p.rB, batch.n, invSum, IA, IB, valid[k], &p.normal);
                MakeRow(p.rA, p.rB, batch.t1, invSum, IA, IB, valid[k], &p.tangent1);
                MakeRow(p.rA, p.rB, batch.t2, invSum, IA, IB, valid[k], &p.tangent2);
                p.baseSeparation = p.baseSeparation - Dot(Sub(p.rB, p.rA), batch.n);
                p.relativeVelocity = RowSpeed(bodies, batch.n, p.normal);
                p.maxNormalImpulse = Splat(0.0f);
            }
        }
    }
}

void SoftContactSolver::UpdateBatchSeparations(WideBatch& batch) const {
    // UpdatePairSeparations four wide: s = s_base + n . ((dpB - dpA) + rB dRB - rA dRA), rows of dR as vectors.
    // The lanes' dp and dR rows, each a padded 16-byte row of BodyState, transposed (an empty lane: zeros).
    const Float4 zero = Splat(0.0f);
    Float4 rows[2][4][4];  // [A, B][dp, dR row 0, 1, 2][lane]
    for (int lane = 0; lane < 4; ++lane) {
        if (batch.pair[lane] < 0) {
            for (auto& body : rows)
                for (auto& row : body) row[lane] = zero;
            continue;
        }
        const BodyState* bodies[2] = {&state[static_cast<std::size_t>(batch.a[lane])],
                                      &state[static_cast<std::size_t>(batch.b[lane])]};
        for (int i = 0; i < 2; ++i) {
            rows[i][0][lane] = Load4(bodies[i]->dp);
            for (int r = 0; r < 3; ++r) std::memcpy(&rows[i][r + 1][lane], bodies[i]->dR[r], sizeof(Float4));
        }
    }
    auto lanes = [&rows](int body, int row) {
        const Float4(&r)[4] = rows[body][row];
        return Transpose(r[0], r[1], r[2], r[3]);
    };
    const Vec4x3 RA[3] = {lanes(0, 1), lanes(0, 2), lanes(0, 3)};
    const Vec4x3 RB[3] = {lanes(1, 1), lanes(1, 2), lanes(1, 3)};
    const Vec4x3 dp = Sub(lanes(1, 0), lanes(0, 0));
    for (int k = 0; k < batch.pointCount; ++k) {
        WidePoint& p = batch.points[k];
        const Vec4x3 d = Sub(Add(dp, Mul(p.rB, RB)), Mul(p.rA, RA));
        p.current = Dot(d, batch.n) + p.baseSeparation;
    }
}

void SoftContactSolver::WideWarmStart(const Block& block) {
    for (std::size_t b = block.batchBegin; b < block.batchEnd; ++b) {
        const WideBatch& batch = batches[b];
        WideBodies s = Gather(state, batch);
        for (int k = 0; k < batch.pointCount; ++k) {
            const WidePoint& p = batch.points[k];
            ApplyRow(s, batch.invMassA, batch.invMassB, batch.n, p.normal, p.normal.impulse);
            ApplyRow(s, batch.invMassA, batch.invMassB, batch.t1, p.tangent1, p.tangent1.impulse);
            ApplyRow(s, batch.invMassA, batch.invMassB, batch.t2, p.tangent2, p.tangent2.impulse);
        }
        Scatter(state, batch, s);
    }
}

void SoftContactSolver::WideSolve(const Block& block, float invH, float maxPushout, float slop, bool useBias,
                                  bool updateSeparations) {
    const Float4 zero = Splat(0.0f), one = Splat(1.0f);
    const Float4 invH4 = Splat(invH), slop4 = Splat(slop), pushout = Splat(-maxPushout);
    for (std::size_t b = block.batchBegin; b < block.batchEnd; ++b) {
        WideBatch& batch = batches[b];
        if (updateSeparations) UpdateBatchSeparations(batch);
        WideBodies s = Gather(state, batch);
        if (!useBias) {
            // Friction in the relax pass only, and before the normal rows, as in SolvePair.
            for (int k = 0; k < batch.pointCount; ++k) {
                WidePoint& p = batch.points[k];
                const Float4 limit = batch.friction * p.support;
                Float4 j1 = p.tangent1.impulse - p.tangent1.mass * RowSpeed(s, batch.t1, p.tangent1);
                Float4 j2 = p.tangent2.impulse - p.tangent2.mass * RowSpeed(s, batch.t2, p.tangent2);
                const Float4 sq = j1 * j1 + j2 * j2;
                // Outside the cone: scaled back onto it (a scale of 1 leaves the others unchanged, bit for bit).
                Float4 scale = one;
                for (int lane = 0; lane < 4; ++lane)
                    if (sq[lane] > limit[lane] * limit[lane])
                        scale[lane] = limit[lane] > 0.0f ? limit[lane] / std::sqrt(sq[lane]) : 0.0f;
                j1 = j1 * scale;
                j2 = j2 * scale;
                const Float4 d1 = j1 - p.tangent1.impulse, d2 = j2 - p.tangent2.impulse;
                p.tangent1.impulse = j1;
                p.tangent2.impulse = j2;
                ApplyRow(s, batch.invMassA, batch.invMassB, batch.t1, p.tangent1, d1);
                ApplyRow(s, batch.invMassA, batch.invMassB, batch.t2, p.tangent2, d2);
            }
        }
        for (int k = 0; k < batch.pointCount; ++k) {
            WidePoint& p = batch.points[k];
            // SolvePair's normal row: speculative (s > 0) rigid with bias s/h; penetrating with the soft bias and
            // scales when biased; rigid without bias in the relax pass.
            const Float4 sep = p.current;
            const auto speculative = sep > zero;
            Float4 bias = zero, massScale = one, impulseScale = zero;
            if (useBias) {
                bias = Max(batch.biasRate * Min(sep + slop4, zero), pushout);
                massScale = batch.massScale;
                impulseScale = batch.impulseScale;
            }
            bias = Select(speculative, sep * invH4, bias);
            massScale = Select(speculative, one, massScale);
            impulseScale = Select(speculative, zero, impulseScale);
            const Float4 vn = RowSpeed(s, batch.n, p.normal);
            if (useBias) p.relativeVelocity = Min(p.relativeVelocity, vn);
            const Float4 J = p.normal.impulse;
            const Float4 jn = Max(J - p.normal.mass * massScale * (vn + bias) - impulseScale * J, zero);
            p.normal.impulse = jn;
            p.maxNormalImpulse = Max(p.maxNormalImpulse, jn);
            if (!useBias) p.support = jn;
            ApplyRow(s, batch.invMassA, batch.invMassB, batch.n, p.normal, jn - J);
        }
        Scatter(state, batch, s);
    }
}

void SoftContactSolver::StoreBatchImpulses() {
    for (const WideBatch& batch : batches) {
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
