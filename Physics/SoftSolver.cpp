// ContactSolver::Soft (SoftSolver.h): soft contact constraints solved in substeps with a relax pass; the design and
// the measured figures are in docs/soft-solver.md, "The soft-step solver".
#include "Physics/SoftSolver.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>

#include "Physics/Geometry/ContactManifold.h"
#include "Physics/JobPool.h"
#include "Physics/RigidbodyVolume.h"
#include "Physics/SoftContactKernel.h"
#include "Physics/WorldSettings.h"

using namespace softkernel;

namespace {

constexpr float kPi = 3.14159265358979f;
/// Bodies per job of the per-body loops: fixed, never derived from the thread count (docs/threads.md).
constexpr std::size_t kBodyChunk = 512;

/// Below this square of half a substep's turn (x = |w| h / 2 < 0.1 rad), SmallTurns replaces Integrate: Integrate
/// (Math/quaternion.h: q' = exp(w h / 2) q, normalised) for an isotropic body's small turn, with (h / 2) sin x / x
/// and cos x of the half angle from their Taylor series to x^6 and x^8 (the first terms left out are below 3e-15
/// at x = 0.1, far under float's rounding): the substep loop then pays no sin, cos or square root of the axis for
/// the small turns a substep makes (they were a tenth of a 100-box pile's step).
constexpr float kSmallHalfTurnSq = 0.01f;

/// A pair's velocities back to its moving bodies only. A static or sleeping body keeps its zero velocities (a pass
/// leaves them unchanged, bit for bit); not writing them lets blocks that share the ground run on different threads.
inline void StoreMovingVelocities(const PairVelocities& x, const SoftContactSolver::Pair& pair,
                                  const std::vector<unsigned char>& moving,
                                  std::vector<SoftContactSolver::BodyState>& state) {
    if (moving[static_cast<std::size_t>(pair.a)] != 0) {
        Store(state[static_cast<std::size_t>(pair.a)].v, x.vA);
        Store(state[static_cast<std::size_t>(pair.a)].w, x.wA);
    }
    if (moving[static_cast<std::size_t>(pair.b)] != 0) {
        Store(state[static_cast<std::size_t>(pair.b)].v, x.vB);
        Store(state[static_cast<std::size_t>(pair.b)].w, x.wB);
    }
}

/// RigidbodyVolume::InvTensor (R^T diag(1 / I) R, R = ToMat3(q), summed over R's rows k in order, each entry
/// (d_k a_i) a_j) as rows of four floats, a row at a time in four lanes: the same bits, without computing the body's
/// principal moments a second time (InvTensor was half of LoadBody's instructions, callgrind).
inline void WorldInverseInertia(const quat& q, const vec3& inertia, float (*out)[4]) {
    const mat3 R = ToMat3(q);
    float d[3];
    for (int i = 0; i < 3; ++i) d[i] = inertia[i] > 0.0f ? 1.0f / inertia[i] : 0.0f;
    V4 rows[3] = {Splat(0.0f), Splat(0.0f), Splat(0.0f)};
    for (int k = 0; k < 3; ++k) {
        const float* a = R[k];
        const V4 axis = Make(vec3(a[0], a[1], a[2]));
        for (int i = 0; i < 3; ++i) rows[i] = rows[i] + Splat(d[k] * a[i]) * axis;
    }
    for (int i = 0; i < 3; ++i) std::memcpy(out[i], &rows[i], sizeof(float) * 4);
}

/// |x| lane by lane (the sign bit cleared, as std::fabs).
inline simd4::Float4 Abs(simd4::Float4 x) {
    using Bits = decltype(simd4::Float4{} < simd4::Float4{});
    Bits b;
    std::memcpy(&b, &x, sizeof b);
    b &= Bits{0x7fffffff, 0x7fffffff, 0x7fffffff, 0x7fffffff};
    std::memcpy(&x, &b, sizeof x);
    return x;
}

/// A 4x4 transpose: out[c][r] = in[r][c] (data moves only).
inline void Transpose4(const simd4::Float4 (&in)[4], simd4::Float4 (&out)[4]) {
    const simd4::Float4 a = __builtin_shufflevector(in[0], in[1], 0, 4, 1, 5);  // 00 10 01 11
    const simd4::Float4 b = __builtin_shufflevector(in[2], in[3], 0, 4, 1, 5);  // 20 30 21 31
    const simd4::Float4 c = __builtin_shufflevector(in[0], in[1], 2, 6, 3, 7);  // 02 12 03 13
    const simd4::Float4 d = __builtin_shufflevector(in[2], in[3], 2, 6, 3, 7);  // 22 32 23 33
    out[0] = __builtin_shufflevector(a, b, 0, 1, 4, 5);
    out[1] = __builtin_shufflevector(a, b, 2, 3, 6, 7);
    out[2] = __builtin_shufflevector(c, d, 0, 1, 4, 5);
    out[3] = __builtin_shufflevector(c, d, 2, 3, 6, 7);
}

}  // namespace

Softness MakeSoftness(float hertz, float zeta, float h) {
    // Implicit spring-damper over one step (docs/soft-solver.md, "The soft-step solver"): omega = 2 pi f, a1 = 2 zeta +
    // h omega, a2 = h omega a1, a3 = 1 / (1 + a2); bias rate omega / a1, mass scale a2 a3, impulse scale a3.
    Softness s;
    if (!(hertz > 0.0f) || !(h > 0.0f)) return s;
    const float omega = 2.0f * kPi * hertz;
    const float a1 = 2.0f * zeta + h * omega;
    const float a2 = h * omega * a1;
    const float a3 = 1.0f / (1.0f + a2);
    s.biasRate = omega / a1;
    s.massScale = a2 * a3;
    s.impulseScale = a3;
    return s;
}

void SoftContactSolver::Clear() {
    pairs.clear();
    contacts.clear();
    previousPairs.clear();
    previousContacts.clear();
    kept.clear();
    previousKept.clear();
    warmStarted = 0;
    reusedManifolds = 0;
    inheritedNormal = 0.0f;
    lastStep = -2;
}

float SoftContactSolver::TotalNormalImpulse() const {
    float sum = 0.0f;
    for (const Contact& c : contacts) sum += c.normal.impulse;
    return sum;
}

float SoftContactSolver::DeepestPenetration() const {
    float deepest = 0.0f;
    for (const Contact& c : contacts) deepest = std::max(deepest, -c.separation);
    return deepest;
}

void SoftContactSolver::Step(const std::vector<RigidbodyVolume*>& volumes,
                             const std::vector<std::pair<int, int>>& candidates, const StepContext& ctx,
                             const unsigned char* active) {
    const SoftSolverSettings& soft = ctx.settings.soft;
    const bool carryOver = ctx.step == lastStep + 1;
    lastStep = ctx.step;

    averagePositions = ctx.settings.volumePositions == VolumePositions::Average;
    LoadBodies(volumes, ctx, active);
    Collide(volumes, candidates, ctx, carryOver);

    // Softness from the contact stiffness, capped at a quarter of the substep rate (a stiffer spring than the
    // substep can resolve would overshoot).
    const float hertz = std::min(soft.contactHertz, 0.25f * ctx.invH);
    const Softness softness = MakeSoftness(hertz, soft.contactDampingRatio, ctx.h);
    // A contact with a static body has only one body to move, so it is made twice as stiff.
    const Softness staticSoftness = MakeSoftness(2.0f * hertz, soft.contactDampingRatio, ctx.h);
    // With colouring the batches prepare their own rows, four wide; Prepare does the pairs solved one by one.
    graph.Build(ctx.settings.softGraphColouring, pairEnds, moving);
    BuildBatches(softness, staticSoftness, ctx.jobs);
    Prepare(volumes, ctx);
    BuildShock(ctx);
    // Every substep of a block before the next block: islands share no moving body, so this is the order of one
    // pass over all of them, with the block's rows still in cache (kBlockPairs). For the same reason the blocks are
    // the jobs of the step's threads: a block writes only its own bodies, contacts and batches (static and sleeping
    // bodies are read, never written), so any thread may run it and the bits stay those of one thread.
    const std::vector<Block>& blocks = graph.Blocks();
    OrderBlocks();
    auto solveBlock = [&](std::size_t job) {
        const std::size_t b = blockOrder[job];
        const Block& block = blocks[b];
        UpdateSeparations(block);
        // The warm start re-applies the impulses the contacts ended the last substep with. Rows are fixed for the
        // step and every pass applies only its change to a row's total, so after the first substep that is each
        // body's velocity change from the contacts over the last substep (BodyState::v0), re-applied per body
        // (IntegrateVelocities) rather than row by row: no pass over the contacts. Not in a block with shock points:
        // the shock pass moves velocities by impulses that are not the rows'.
        const bool shock = !shockBlockStart.empty() && shockBlockStart[b + 1] > shockBlockStart[b];
        for (int s = 0; s < ctx.substepCount; ++s) {
            const bool perBody = s > 0 && !shock;
            IntegrateVelocities(block, perBody);
            if (!perBody) WarmStart(block);
            for (int k = 0; k < soft.iterations; ++k)
                Solve(block, ctx.invH, softness, staticSoftness, soft.maxPushoutSpeed, soft.linearSlop, true);
            if (!shockPoints.empty())
                ShockPass(b, ctx.invH, staticSoftness.biasRate, soft.maxPushoutSpeed, soft.linearSlop, false);
            IntegratePositions(ctx, block);
            // The first relax pass brings each pair's separations up to date as it reaches the pair (the same
            // values UpdateSeparations gives: poses do not change during a pass); without one, UpdateSeparations
            // does.
            if (soft.relaxIterations == 0) UpdateSeparations(block);
            for (int k = 0; k < soft.relaxIterations; ++k)
                Solve(block, ctx.invH, softness, staticSoftness, soft.maxPushoutSpeed, soft.linearSlop, false, k == 0);
            // Again after the relax pass, without push-out: the velocities the next substep starts from.
            if (!shockPoints.empty()) ShockPass(b, ctx.invH, 0.0f, 0.0f, soft.linearSlop, true);
        }
        StoreBatchImpulses(block);  // the block's batches' impulses back to its contacts (none without colouring)
    };
    ForEachJob(ctx.jobs, blocks.size(), solveBlock);
    ApplyRestitution(soft.restitutionThreshold);
    StoreBodies(volumes, ctx.jobs);
}

void SoftContactSolver::OrderBlocks() {
    // Longest first, so the last jobs a thread claims are short ones and the threads end near each other (the
    // blocks are independent: the order they run in changes no bit). A block's size is its rows: four per batch,
    // one per pair solved alone; ties in block order, so the job order is a function of the graph alone.
    const std::vector<Block>& blocks = graph.Blocks();
    blockOrder.resize(blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b) blockOrder[b] = b;
    auto rows = [&](std::size_t b) {
        return 4 * (blocks[b].batchEnd - blocks[b].batchBegin) + (blocks[b].overflowEnd - blocks[b].overflowBegin);
    };
    std::sort(blockOrder.begin(), blockOrder.end(),
              [&](std::size_t x, std::size_t y) { return rows(x) != rows(y) ? rows(x) > rows(y) : x < y; });
}

void SoftContactSolver::LoadBodies(const std::vector<RigidbodyVolume*>& volumes, const StepContext& ctx,
                                   const unsigned char* active) {
    const std::size_t n = volumes.size();
    if (state.size() != n) {
        state.resize(n);
        sim.resize(n);
        moving.resize(n);
    }
    ForEachChunk(ctx.jobs, n, kBodyChunk, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) LoadBody(*volumes[i], ctx, active == nullptr || active[i] != 0, i);
    });
}

void SoftContactSolver::LoadBody(const RigidbodyVolume& body, const StepContext& ctx, bool awake, std::size_t i) {
    BodyState& st = state[i];
    BodySim& bs = sim[i];
    // A sleeping body (active[i] == 0) is held like a static one and StoreBodies leaves it untouched.
    bs.dynamic = body.HasVolume() && body.mass > 0.0f && awake;
    moving[i] = bs.dynamic ? 1 : 0;
    bs.p = body.position;
    bs.q = body.orientation;
    bs.q0 = body.orientation;
    st = BodyState();
    if (!bs.dynamic) {
        // Static bodies are immovable here: no velocity, never integrated.
        st.v = vec3();
        st.w = vec3();
        bs.invMass = 0.0f;
        for (auto& row : bs.invI)
            for (float& f : row) f = 0.0f;
        bs.gravityStep = vec3();
        bs.torqueStep = vec3();
        bs.retention = 1.0f;
        bs.epsilon = 0.0f;
        return;
    }
    st.v = body.velocity;
    st.w = body.angVel;
    bs.invMass = body.InvMass();
    bs.inertia = body.LocalInertia();
    WorldInverseInertia(body.orientation, bs.inertia, bs.invI);
    bs.isotropic = bs.inertia.x == bs.inertia.y && bs.inertia.y == bs.inertia.z;
    // The book's force model: forces = gravity * mass (ApplyForces), plus any torque the body carries.
    // Times h once here rather than every substep (the same products).
    bs.gravityStep = body.gravity * ctx.h;
    const vec3& t = body.torques;
    const float(*m)[4] = bs.invI;  // Mul(torques, InvTensor()), from the rows
    const vec3 angularAccel = {t.x * m[0][0] + t.y * m[1][0] + t.z * m[2][0],
                               t.x * m[0][1] + t.y * m[1][1] + t.z * m[2][1],
                               t.x * m[0][2] + t.y * m[1][2] + t.z * m[2][2]};
    bs.torqueStep = angularAccel * ctx.h;
    bs.retention = body.StepRetention(ctx.h);
    bs.epsilon = body.StepVelocityEpsilon(ctx.h);
}

void SoftContactSolver::Collide(const std::vector<RigidbodyVolume*>& volumes,
                                const std::vector<std::pair<int, int>>& candidates, const StepContext& ctx,
                                bool carryOver) {
    // This step's buffers become last step's; capacities are kept, so nothing is allocated once they have grown.
    // The buffers that were last step's are overwritten slot by slot below (each chunk clears its own slots), not
    // cleared here: clearing them all on one thread was a sixth of the narrow phase.
    pairs.swap(previousPairs);
    contacts.swap(previousContacts);
    kept.swap(previousKept);
    if (!carryOver) {
        previousPairs.clear();
        previousContacts.clear();
        previousKept.clear();
    }
    // In chunks of candidates on the step's threads (SoftSolverCollide.cpp): every candidate's manifold into its own
    // slot, counting each chunk's pairs and points; then each chunk's pairs and contacts at the place the counts
    // give, so they are in candidate order, as one loop over the candidates makes them.
    const std::size_t chunks = ChunkCount(candidates.size(), kCandidateChunk);
    manifolds.resize(candidates.size());
    kept.resize(candidates.size());
    chunkCounts.assign(chunks, ChunkCounts());
    ForEachJob(ctx.jobs, chunks, [&](std::size_t c) { FindManifolds(volumes, candidates, ctx, c); });
    std::size_t pairCount = 0, contactCount = 0;
    for (ChunkCounts& counts : chunkCounts) {
        counts.firstPair = pairCount;
        counts.firstContact = contactCount;
        pairCount += counts.pairs;
        contactCount += counts.contacts;
    }
    pairs.resize(pairCount);
    pairEnds.resize(pairCount);
    contacts.resize(contactCount);
    ForEachJob(ctx.jobs, chunks, [&](std::size_t c) { MakePairs(volumes, candidates, ctx, c); });
    // The warm start's totals, summed in contact order (an unmatched contact adds its zero impulse: no change).
    warmStarted = 0;
    reusedManifolds = 0;
    inheritedNormal = 0.0f;
    for (const ChunkCounts& counts : chunkCounts) {
        warmStarted += counts.matched;
        reusedManifolds += counts.reused;
    }
    for (const Contact& c : contacts) inheritedNormal += c.normal.impulse;
}

void SoftContactSolver::Prepare(const std::vector<RigidbodyVolume*>& /*volumes*/, const StepContext& /*ctx*/) {
    for (const int i : graph.Overflow()) PreparePair(pairs[static_cast<std::size_t>(i)]);
}

void SoftContactSolver::PreparePair(const Pair& pair) {
    const BodySim& A = sim[pair.a];
    const BodySim& B = sim[pair.b];
    const PairVelocities x = LoadVelocities(state[pair.a], state[pair.b]);
    const V4 n = Load(pair.n), t1 = Load(pair.t1), t2 = Load(pair.t2);
    const float invSum = A.invMass + B.invMass;
    for (std::size_t k = pair.first; k < pair.first + pair.count; ++k) {
        Contact& c = contacts[k];
        const V4 rA = Make(c.rA), rB = Make(c.rB);
        MakeRow(rA, rB, n, invSum, A.invI, B.invI, &c.normal);
        MakeRow(rA, rB, t1, invSum, A.invI, B.invI, &c.tangent1);
        MakeRow(rA, rB, t2, invSum, A.invI, B.invI, &c.tangent2);
        c.coupling = TangentCoupling(c.tangent1, c.tangent2);
        // The separation is tracked through the step from the bodies' motion (Solve), not re-collided.
        c.baseSeparation = c.separation - Dot(c.rB - c.rA, pair.n);
        c.relativeVelocity = RowSpeed(x, n, c.normal);
        c.maxNormalImpulse = 0.0f;
    }
}

static_assert(offsetof(SoftContactSolver::BodySim, gravityStep) % 16 == 0 &&
                  offsetof(SoftContactSolver::BodySim, torqueStep) % 16 == 0,
              "BodySim's gravityStep and torqueStep each fill 16 bytes with their padding (Load4)");

void SoftContactSolver::IntegrateVelocities(const Block& block, bool warm) {
    using simd4::Float4;
    const Float4 zero = simd4::Wide(0.0f);
    auto store = [](vec3& to, Float4 v) { std::memcpy(&to.x, &v, sizeof v); };
    for (std::size_t k = block.bodyBegin; k < block.bodyEnd; ++k) {
        const std::size_t i = static_cast<std::size_t>(graph.BlockBodies()[k]);
        BodySim& bs = sim[i];
        BodyState& st = state[i];
        if (averagePositions) bs.vStart = st.v;  // before forces and contacts (IntegratePositions)
        // Semi-implicit Euler, then the body's velocity retention and threshold per substep (RigidbodyVolume), a
        // lane per component (the vec3 operations' bits; the padding lanes stay 0).
        const Float4 retention = simd4::Wide(bs.retention);
        Float4 v = (simd4::Load4(st.v) + simd4::Load4(bs.gravityStep)) * retention;
        Float4 w = (simd4::Load4(st.w) + simd4::Load4(bs.torqueStep)) * retention;
        if (bs.epsilon > 0.0f) {
            const Float4 epsilon = simd4::Wide(bs.epsilon);
            v = Select(Abs(v) < epsilon, zero, v);
            w = Select(Abs(w) < epsilon, zero, w);
        }
        // The warm start: what the contacts gave the body over the last substep (the velocities it ended with minus
        // those it started from after this step), on top of the new ones.
        const Float4 dv = warm ? simd4::Load4(st.v) - simd4::Load4(st.v0) : zero;
        const Float4 dw = warm ? simd4::Load4(st.w) - simd4::Load4(st.w0) : zero;
        store(st.v0, v);
        store(st.w0, w);
        store(st.v, warm ? v + dv : v);
        store(st.w, warm ? w + dw : w);
    }
}

void SoftContactSolver::IntegratePositions(const StepContext& ctx, const Block& block) {
    const float h = ctx.h;
    int turns[4];  // bodies waiting for SmallTurns, which does four at once
    int waiting = 0;
    for (std::size_t k = block.bodyBegin; k < block.bodyEnd; ++k) {
        const int index = graph.BlockBodies()[k];
        const std::size_t i = static_cast<std::size_t>(index);
        BodySim& bs = sim[i];
        BodyState& st = state[i];
        // VolumePositions::Average: the substep's mean velocity, exact for constant acceleration.
        // A substep whose velocity changes by more than twice g h (an impact) moves by v h (SmoothVolumeStep).
        const bool smooth = averagePositions && SmoothVolumeStep(bs.vStart, st.v, bs.gravityStep);
        const vec3 move = smooth ? (bs.vStart + st.v) * (0.5f * h) : st.v * h;
        st.dp += move;
        bs.p += move;
        // Orientation advanced by the world angular velocity (exponential map, normalised), keeping the world
        // angular momentum of a body whose principal moments differ (AdvanceRotation: between contacts a box turns
        // as a free body does, not at a constant w); the rotation since the step began moves the fixed anchors
        // (Solve). Each body's turn depends on its own state only, so the order bodies are turned in changes no bit.
        const float w2 = MagnitudeSq(st.w);
        if (!(w2 > 0.0f)) continue;
        const float x2 = 0.25f * h * h * w2;  // the square of half the substep's turn, rad^2
        if (bs.isotropic && x2 < kSmallHalfTurnSq) {
            turns[waiting++] = index;
            if (waiting == 4) {
                SmallTurns(turns, waiting, h);
                waiting = 0;
            }
            continue;
        }
        const vec3 before = st.w;
        bs.q = AdvanceRotation(bs.q, &st.w, bs.inertia, h);
        st.w0 = st.w0 + (st.w - before);  // a free body's change of w is no contact's (IntegrateVelocities' warm start)
        const mat3 dR = ToMat3(bs.q * Conjugate(bs.q0));
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) st.dR[r][c] = dR[r][c];
    }
    if (waiting > 0) SmallTurns(turns, waiting, h);
}

void SoftContactSolver::SmallTurns(const int* bodies, int count, float h) {
    // SmallTurn, Normalized and ToMat3(q q0*) of up to four bodies, one per lane; each lane does the scalar
    // functions' operations in their order (Math/Simd4.h), so the bits are theirs. An empty lane turns nothing.
    using simd4::Float4;
    // The lanes' w, q and q0 as rows of four floats, transposed (data moves only).
    const Float4 none = {0.0f, 0.0f, 0.0f, 0.0f}, identity = {0.0f, 0.0f, 0.0f, 1.0f};
    Float4 W[4], Q[4], Q0[4];
    for (int l = 0; l < 4; ++l) {
        if (l >= count) {
            W[l] = none;
            Q[l] = Q0[l] = identity;
            continue;
        }
        const std::size_t i = static_cast<std::size_t>(bodies[l]);
        W[l] = simd4::Load4(state[i].w);
        std::memcpy(&Q[l], &sim[i].q.x, sizeof(Float4));
        std::memcpy(&Q0[l], &sim[i].q0.x, sizeof(Float4));
    }
    const simd4::Vec4x3 w3 = simd4::Transpose(W[0], W[1], W[2], W[3]);
    Float4 q4[4], o4[4];
    Transpose4(Q, q4);
    Transpose4(Q0, o4);
    const Float4 wx = w3.x, wy = w3.y, wz = w3.z, qx = q4[0], qy = q4[1], qz = q4[2], qw = q4[3];
    const Float4 ox = -o4[0], oy = -o4[1], oz = -o4[2], ow = o4[3];  // q0*
    const Float4 x2 = 0.25f * h * h * (wx * wx + wy * wy + wz * wz);
    const Float4 k = 0.5f * h * (1.0f - x2 / 6.0f * (1.0f - x2 / 20.0f * (1.0f - x2 / 42.0f)));
    const Float4 c = 1.0f - x2 / 2.0f * (1.0f - x2 / 12.0f * (1.0f - x2 / 30.0f * (1.0f - x2 / 56.0f)));
    const Float4 ax = wx * k, ay = wy * k, az = wz * k;  // the turn quat(ax, ay, az, c), then times q
    Float4 rx = c * qx + ax * qw + ay * qz - az * qy, ry = c * qy - ax * qz + ay * qw + az * qx;
    Float4 rz = c * qz + ax * qy - ay * qx + az * qw, rw = c * qw - ax * qx - ay * qy - az * qz;
    const Float4 len = simd4::Sqrt(rx * rx + ry * ry + rz * rz + rw * rw), inv = 1.0f / len;
    rx = rx * inv, ry = ry * inv, rz = rz * inv, rw = rw * inv;
    const Float4 dx = rw * ox + rx * ow + ry * oz - rz * oy, dy = rw * oy - rx * oz + ry * ow + rz * ox;
    const Float4 dz = rw * oz + rx * oy - ry * ox + rz * ow, dw = rw * ow - rx * ox - ry * oy - rz * oz;
    const Float4 xx = dx * dx, yy = dy * dy, zz = dz * dz, xy = dx * dy, xz = dx * dz, yz = dy * dz;
    const Float4 wxd = dw * dx, wyd = dw * dy, wzd = dw * dz;
    const Float4 zero = {0.0f, 0.0f, 0.0f, 0.0f};
    const Float4 rq[4] = {rx, ry, rz, rw};  // q, then dR by rows (each row's padding float stays 0)
    const Float4 rows[3][4] = {{1.0f - 2.0f * (yy + zz), 2.0f * (xy + wzd), 2.0f * (xz - wyd), zero},
                               {2.0f * (xy - wzd), 1.0f - 2.0f * (xx + zz), 2.0f * (yz + wxd), zero},
                               {2.0f * (xz + wyd), 2.0f * (yz - wxd), 1.0f - 2.0f * (xx + yy), zero}};
    Float4 q[4], dR[3][4];
    Transpose4(rq, q);
    for (int r = 0; r < 3; ++r) Transpose4(rows[r], dR[r]);
    for (int l = 0; l < count; ++l) {
        const std::size_t i = static_cast<std::size_t>(bodies[l]);
        BodyState& st = state[i];
        if (!(len[l] > 0.0f) || !std::isfinite(len[l])) {  // Normalized's identity; ToMat3 of q0* then
            sim[i].q = quat();
            const mat3 m = ToMat3(sim[i].q * Conjugate(sim[i].q0));
            for (int r = 0; r < 3; ++r)
                for (int col = 0; col < 3; ++col) st.dR[r][col] = m[r][col];
            continue;
        }
        std::memcpy(&sim[i].q.x, &q[l], sizeof(Float4));
        for (int r = 0; r < 3; ++r) std::memcpy(st.dR[r], &dR[r][l], sizeof(Float4));
    }
}

void SoftContactSolver::UpdateSeparations(const Block& block) {
    for (std::size_t k = block.batchBegin; k < block.batchEnd; ++k) UpdateBatchSeparations(batches[k]);
    for (std::size_t k = block.overflowBegin; k < block.overflowEnd; ++k)
        UpdatePairSeparations(pairs[static_cast<std::size_t>(graph.Overflow()[k])]);
}

void SoftContactSolver::UpdatePairSeparations(const Pair& pair) {
    const BodyState& A = state[pair.a];
    const BodyState& B = state[pair.b];
    const V4 dp = Load(B.dp) - Load(A.dp);
    const V4 n = Load(pair.n);
    const V4 a0 = Load(A.dR[0]), a1 = Load(A.dR[1]), a2 = Load(A.dR[2]);
    const V4 b0 = Load(B.dR[0]), b1 = Load(B.dR[1]), b2 = Load(B.dR[2]);
    for (std::size_t k = pair.first; k < pair.first + pair.count; ++k) {
        Contact& c = contacts[k];
        // The base separation plus the motion of both anchors since the step began: dp + rB dR_B - rA dR_A.
        const V4 rBdR = Splat(c.rB.x) * b0 + Splat(c.rB.y) * b1 + Splat(c.rB.z) * b2;
        const V4 rAdR = Splat(c.rA.x) * a0 + Splat(c.rA.y) * a1 + Splat(c.rA.z) * a2;
        c.current = Dot(dp + rBdR - rAdR, n) + c.baseSeparation;
    }
}

void SoftContactSolver::WarmStart(const Block& block) {
    WideWarmStart(block);
    for (std::size_t k = block.overflowBegin; k < block.overflowEnd; ++k)
        WarmStartPair(pairs[static_cast<std::size_t>(graph.Overflow()[k])]);
}

void SoftContactSolver::WarmStartPair(const Pair& pair) {
    // The pair's two bodies are worked on in locals (no other pair touches them meanwhile).
    BodyState& A = state[pair.a];
    BodyState& B = state[pair.b];
    PairVelocities x = LoadVelocities(A, B);
    const float invA = sim[pair.a].invMass, invB = sim[pair.b].invMass;
    const V4 n = Load(pair.n), t1 = Load(pair.t1), t2 = Load(pair.t2);
    WarmStartPoints(x, invA, invB, n, t1, t2, &contacts[pair.first], pair.count);
    StoreMovingVelocities(x, pair, moving, state);
}

void SoftContactSolver::Solve(const Block& block, float invH, const Softness& dynamicSoftness,
                              const Softness& staticSoftness, float maxPushout, float slop, bool useBias,
                              bool updateSeparations) {
    WideSolve(block, invH, maxPushout, slop, useBias, updateSeparations);
    for (std::size_t k = block.overflowBegin; k < block.overflowEnd; ++k) {
        const Pair& pair = pairs[static_cast<std::size_t>(graph.Overflow()[k])];
        if (updateSeparations) UpdatePairSeparations(pair);
        SolvePair(pair, pair.touchesStatic ? staticSoftness : dynamicSoftness, invH, maxPushout, slop, useBias);
    }
}

void SoftContactSolver::SolvePair(const Pair& pair, const Softness& softness, float invH, float maxPushout, float slop,
                                  bool useBias) {
    BodyState& A = state[pair.a];
    BodyState& B = state[pair.b];
    PairVelocities x = LoadVelocities(A, B);
    const float invA = sim[pair.a].invMass, invB = sim[pair.b].invMass;
    const V4 n = Load(pair.n), t1 = Load(pair.t1), t2 = Load(pair.t2);
    // Friction only in the relax pass, as Box2D's soft step does since 2026: the biased pass's friction was undone
    // by the relax pass's anyway, at a third of the solve's rows (docs/soft-solver.md, "The soft-step solver"). It
    // comes before the normal rows, so the pass ends on non-penetration: friction's lever arms change the corners'
    // normal speeds, and solved last it left a cube landing flat at 5 m/s rising at 0.14 m/s (at 6 substeps; 0.008 m/s
    // this way round: SoftSolver.SpeculativeContactStopsFastBodyWithoutPopping).
    // The two passes as two loops, each with its bias flag a constant: the kernel's tests of it fold away.
    const PassLanes<float> pass = {invH, slop, -maxPushout};
    const std::size_t end = pair.first + pair.count;
    if (useBias) {
        for (std::size_t k = pair.first; k < end; ++k) SolveNormal(x, invA, invB, n, softness, pass, true, contacts[k]);
    } else {
        for (std::size_t k = pair.first; k < end; ++k) SolveFriction(x, invA, invB, t1, t2, pair.friction, contacts[k]);
        for (std::size_t k = pair.first; k < end; ++k)
            SolveNormal(x, invA, invB, n, softness, pass, false, contacts[k]);
    }
    StoreMovingVelocities(x, pair, moving, state);
}

void SoftContactSolver::ApplyRestitution(float threshold) {
    for (const Pair& pair : pairs) {
        if (pair.restitution == 0.0f) continue;
        BodyState& A = state[pair.a];
        BodyState& B = state[pair.b];
        PairVelocities x = LoadVelocities(A, B);
        const float invA = sim[pair.a].invMass, invB = sim[pair.b].invMass;
        const V4 n = Load(pair.n);
        // Several passes, not one: a face's corners are solved one after another, and one pass leaves the
        // spin the first corner's impulse gave (a cube dropped flat from 2 m with e = 0.5 left spinning at
        // 1.0 rad/s after one pass, 0.07 after two, 3e-4 after four: SoftSolver.FlatBounceDoesNotSpin).
        for (int pass = 0; pass < kRestitutionPasses; ++pass) {
            for (std::size_t k = pair.first; k < pair.first + pair.count; ++k) {
                Contact& c = contacts[k];
                // Only a real impact (closing faster than the threshold before solving) that the solver pushed on.
                if (c.relativeVelocity > -threshold || c.maxNormalImpulse == 0.0f) continue;
                SolveRestitution(x, invA, invB, n, pair.restitution, c);
            }
        }
        StoreVelocities(x, A, B);
    }
}

void SoftContactSolver::StoreBodies(const std::vector<RigidbodyVolume*>& volumes, JobPool* jobs) {
    ForEachChunk(jobs, volumes.size(), kBodyChunk, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const BodySim& bs = sim[i];
            if (!bs.dynamic) continue;
            RigidbodyVolume& body = *volumes[i];
            body.velocity = state[i].v;
            body.angVel = state[i].w;
            body.position = bs.p;
            body.orientation = bs.q;
            body.SynchCollisionVolumes();
        }
    });
}
