#pragma once
// ContactSolver::Soft: a soft step for rigid volumes (docs/soft-solver.md, "The soft-step solver"). Once per step the
// candidate pairs are collided with a speculative margin (ContactManifold.h), each point is matched by feature id
// to last step's contact of the same pair (warm start), and every contact is prepared with anchors fixed for the
// step. Then per substep of h = dt / substeps: integrate velocities, warm start, biased soft solve, integrate
// positions, relax without bias; restitution once after the substeps; impulses kept for the next step.
//
// Data-oriented: the step works on contiguous arrays of per-body solver state and contact constraints, in fixed
// orders (deterministic); storage is reused from step to step, so the steady state allocates nothing.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "Math/Simd4.h"
#include "Math/matrices.h"
#include "Math/quaternion.h"
#include "Math/vectors.h"
#include "Physics/Geometry/ContactManifold.h"
#include "Physics/SoftSolverGraph.h"
#include "Physics/SoftSolverRows.h"

class JobPool;
class RigidbodyVolume;
struct StepContext;

/// Contact softness of one substep (a spring of `hertz` and damping ratio `zeta` over a step of h, implicit):
/// the bias rate (1/s) that turns a separation into a target speed, and the mass and impulse scales that blend
/// the rigid solve with the previous impulse. hertz 0 is rigid (bias 0, mass scale 1, impulse scale 0).
struct Softness {
    float biasRate = 0.0f;
    float massScale = 1.0f;
    float impulseScale = 0.0f;
};
/// Softness for a contact spring of `hertz` (Hz) and damping ratio `zeta` over a substep of h seconds.
Softness MakeSoftness(float hertz, float zeta, float h);

class SoftContactSolver {
public:
    /// Advances every volume by one step of ctx.dt in ctx.substepCount substeps of ctx.h (ctx.settings.soft).
    /// `candidates` are pairs (i, j), i < j, of indices into `volumes` in increasing order (broadphase output,
    /// AABBs grown by the speculative margin); pairs of two static bodies are skipped. Impulses are carried over
    /// only from the step just before (ctx.step one more than at the last Step). `active` (one byte per volume,
    /// Islands::ActiveMask) marks the bodies that move when sleep is on: the others are held like static ones and
    /// left untouched; nullptr moves every dynamic body.
    void Step(const std::vector<RigidbodyVolume*>& volumes, const std::vector<std::pair<int, int>>& candidates,
              const StepContext& ctx, const unsigned char* active = nullptr);
    /// Forgets every kept contact (the next Step starts cold).
    void Clear();

    /// Touching (or speculative) pairs and contact points of the last Step, and how many points inherited an
    /// impulse from a contact of the same pair with the same feature id.
    std::size_t PairCount() const { return pairs.size(); }
    std::size_t ContactCount() const { return contacts.size(); }
    std::size_t WarmStartedCount() const { return warmStarted; }
    /// Box-box manifolds of the last Step re-expressed from an earlier step's instead of collided anew
    /// (SoftSolverSettings::manifoldReuseDistance).
    std::size_t ManifoldReuseCount() const { return reusedManifolds; }
    /// Normal impulse inherited from last step's matched contacts (after warmStartFactor) summed over the last
    /// Step's contacts, N s: what the warm start applies before the first solve.
    float InheritedNormalImpulse() const { return inheritedNormal; }
    /// Normal impulse of the last substep summed over every contact of the last Step, N s.
    float TotalNormalImpulse() const;
    /// Deepest penetration (m, >= 0) over the contacts found at the start of the last Step.
    float DeepestPenetration() const;

    // The rows and the per-body velocity state (SoftSolverRows.h; 16-byte aligned, four lanes wide).
    using Row = SoftRow;
    using BodyState = SoftBodyState;
    using WideRow = SoftWideRow;
    struct Contact {
        Row normal, tangent1, tangent2;
        float current = 0.0f;           // separation at the bodies' present poses (UpdateSeparations), m
        float relativeVelocity = 0.0f;  // normal speed before solving, m/s (restitution)
        float maxNormalImpulse = 0.0f;  // largest total normal impulse of the step, N s
        float baseSeparation = 0.0f;    // separation - n . (rB - rA): the separation with the step's offsets removed
        float support = 0.0f;           // normal impulse of the last pass without bias (the friction cone's bound), N s
        float coupling = 0.0f;    // (rA x t1) . IA^-1 (rA x t2) + (rB x t1) . IB^-1 (rB x t2), 1/kg (SolveFriction)
        vec3 rA;                  // anchors from the body centres at the start of the step, world, m
        float separation = 0.0f;  // from the manifold, m (< 0 penetrating)
        vec3 rB;
        std::uint32_t id = 0;  // feature id (ContactManifold.h)
    };
    struct alignas(16) Pair {
        vec3 n;  // normal from a to b
        float padN = 0.0f;
        vec3 t1;  // tangent basis
        float padT1 = 0.0f;
        vec3 t2;
        float padT2 = 0.0f;
        int a = -1, b = -1;                      // indices into the volumes
        float friction = 0.0f;                   // sqrt(muA muB)
        float restitution = 0.0f;                // min(eA, eB)
        const RigidbodyVolume* bodyA = nullptr;  // identity check only (a changed body list inherits nothing)
        const RigidbodyVolume* bodyB = nullptr;
        std::size_t first = 0, count = 0;  // contacts[first, first + count)
        bool touchesStatic = false;        // one body is static: the stiffer static softness applies
    };
    /// Per-body constants of the step and its pose.
    struct alignas(16) BodySim {
        float invI[3][4];  // world inverse inertia at the start of the step (zero for static), rows padded to four
        // A substep's velocity changes from the forces, padded to 16 bytes (IntegrateVelocities loads them whole):
        vec3 gravityStep;  // g h, m/s (zero for static)
        float padG = 0.0f;
        vec3 torqueStep;  // I^-1 torque h, rad/s
        float padT = 0.0f;
        vec3 p;        // position, m
        vec3 vStart;   // linear velocity the substep began with, m/s (VolumePositions::Average only)
        quat q, q0;    // orientation now and at the start of the step
        vec3 inertia;  // principal moments, kg m^2 (body frame): torque-free rotation keeps L (AdvanceRotation)
        float invMass = 0.0f;
        float retention = 1.0f;  // velocity kept per substep (FactorOverStep of the body's retention)
        float epsilon = 0.0f;    // velocity components below this are zeroed per substep
        bool dynamic = false;
        bool isotropic = false;  // equal principal moments: a free turn keeps w (IntegratePositions' SmallTurn)
    };

    /// Four floats, one per lane of a wide batch, and a vector per lane (Math/Simd4.h).
    using Float4 = simd4::Float4;
    using Vec4x3 = simd4::Vec4x3;
    /// Point k of every lane's pair (a lane whose pair has fewer points holds zero masses there: no effect).
    struct WidePoint {
        Vec4x3 rA, rB;
        WideRow normal, tangent1, tangent2;
        Float4 baseSeparation, current, relativeVelocity, maxNormalImpulse, support, coupling;
    };
    /// Up to four pairs of one colour (no moving body twice), solved together: lane l is pairs[pair[l]], or
    /// empty (pair -1: no bodies, zero masses).
    struct WideBatch {
        int colour = 0;
        int pair[4];
        int a[4], b[4];
        int pointCount;               // most points of any lane
        std::uint8_t movesA, movesB;  // bit l: lane l's body a (b) moves, so the batch writes its velocities back
        Vec4x3 n, t1, t2;
        Float4 invMassA, invMassB, friction;
        Float4 biasRate, massScale, impulseScale;  // the lane's softness (static pairs: the stiffer one)
        WidePoint points[4];
    };

    /// The contact graph's colours and block size, and a block (SoftSolverGraph.h).
    static constexpr int kColours = SoftContactGraph::kColours;
    static constexpr std::size_t kBlockPairs = SoftContactGraph::kBlockPairs;
    using Block = SoftContactGraph::Block;
    /// Passes of the restitution solve over a pair's impact points (ApplyRestitution).
    static constexpr int kRestitutionPasses = 4;
    /// The last Step's pairs, its blocks, the moving bodies of each block, its batches, and the pairs solved one
    /// by one after a block's batches (a moving body already in every colour, or the one pair of a colour's last
    /// batch; without colouring, every pair, in one block).
    const std::vector<Pair>& Pairs() const { return pairs; }
    /// The last Step's contact points, pair by pair (Pair::first, Pair::count).
    const std::vector<Contact>& Contacts() const { return contacts; }
    /// Where body i (an index into the last Step's volumes) was at the start of the last Step, m: contact anchors
    /// (Contact::rA, rB) are from there.
    vec3 StartPosition(int i) const {
        const std::size_t k = static_cast<std::size_t>(i);
        return sim[k].p - state[k].dp;
    }
    const std::vector<Block>& Blocks() const { return graph.Blocks(); }
    const std::vector<int>& BlockBodies() const { return graph.BlockBodies(); }
    const std::vector<WideBatch>& Batches() const { return batches; }
    const std::vector<int>& OverflowPairs() const { return graph.Overflow(); }

    /// One contact point of the shock pass (SoftSolverShock.cpp): the pair's body nearer the static ones in the
    /// contact graph (`lower`, fewer pairs away) is held still and only `upper` is moved. n points from lower to
    /// upper; anchors from the bodies' centres at the start of the step.
    struct ShockPoint {
        vec3 n, rU, rL;
        vec3 rUxN, iUrUxN;      // rU x n and its image under upper's world inverse inertia
        vec3 rLxN;              // rL x n (lower's row)
        float mass = 0.0f;      // 1 / (upper's inverse mass + rUxN . iUrUxN), kg
        float base = 0.0f;      // separation at the step's start minus n . (rU - rL), m
        float friction = 0.0f;  // the pair's mu
        float load = 0.0f;      // normal impulse the shock passes gave at the point this substep, N s
        vec3 t1, t2;            // the pair's tangents, signed as the solve's tangent impulses push upper
        vec3 given;             // (a pair's first point) friction impulse the sweeps gave upper this substep, N s
        struct Slots {
            float* support = nullptr;   // the solve's normal impulse of its last pass without bias at the point
            float* tangent1 = nullptr;  // its tangent impulses this substep
            float* tangent2 = nullptr;
        } rows;
        bool rolls = false;        // a sphere in the pair: friction works at the points, turns included
        std::size_t sequence = 0;  // order of creation (pair order): the sort's last key
        int upper = -1, lower = -1;
        int layer = 0;  // lower's distance from a static body, in pairs
        std::size_t block = 0;
    };
    /// The last Step's shock points, by block, then by layer (bottom up), then in pair order.
    const std::vector<ShockPoint>& ShockPoints() const { return shockPoints; }

private:
    // The four-wide path (SoftSolverWide.cpp): the graph's batches (SoftSolverGraph.h) filled and prepared once per
    // step before Prepare; each pass over a block runs its batches colour by colour, then its overflow pairs one by
    // one (the scalar path); the impulses go back to the contacts before restitution.
    void BuildBatches(const Softness& softness, const Softness& staticSoftness, JobPool* jobs);
    void FillBatch(const SoftContactGraph::Batch& lanes, const Softness& softness, const Softness& staticSoftness,
                   WideBatch* out);
    void UpdateBatchSeparations(WideBatch& batch) const;
    void WideWarmStart(const Block& block);
    /// One pass over a block's batches; `updateSeparations`: each batch first brings its separations up to date
    /// (the first relax pass after IntegratePositions does UpdateSeparations' work on the batches it visits anyway).
    void WideSolve(const Block& block, float invH, float maxPushout, float slop, bool useBias, bool updateSeparations);
    void StoreBatchImpulses(const Block& block);
    /// blockOrder: the blocks, most rows first (the order the step's threads claim them in).
    void OrderBlocks();
    /// One pair of the scalar passes (the overflow, or every pair without colouring).
    void WarmStartPair(const Pair& pair);
    void SolvePair(const Pair& pair, const Softness& softness, float invH, float maxPushout, float slop, bool useBias);
    void UpdatePairSeparations(const Pair& pair);
    void PreparePair(const Pair& pair);

    /// Current separation of every contact from the bodies' motion since the step began. Poses change only in
    /// IntegratePositions, so separations are brought up to date once before the substeps (here) and once after
    /// each integration (by the first relax pass, pair by pair as it reaches them; here when there is no relax
    /// pass), and every solve pass in between reads them.
    void UpdateSeparations(const Block& block);
    /// Per body, in fixed chunks on ctx.jobs (LoadBody: body i's state and constants; `awake`: not held by sleep).
    void LoadBodies(const std::vector<RigidbodyVolume*>& volumes, const StepContext& ctx, const unsigned char* active);
    void LoadBody(const RigidbodyVolume& body, const StepContext& ctx, bool awake, std::size_t i);
    void Collide(const std::vector<RigidbodyVolume*>& volumes, const std::vector<std::pair<int, int>>& candidates,
                 const StepContext& ctx, bool carryOver);
    /// Warm start: contact c (its id set) takes the impulse of old's contact with the same feature id, if any
    /// (true then).
    inline bool Inherit(const Pair& old, const Pair& pair, float warmStartFactor, Contact* c) const;
    // Collide's two passes over chunk `chunk` of kCandidateChunk candidates (SoftSolverCollide.cpp): the manifolds,
    // counted in chunkCounts; then the chunk's pairs and contacts from its first slots on.
    void FindManifolds(const std::vector<RigidbodyVolume*>& volumes, const std::vector<std::pair<int, int>>& candidates,
                       const StepContext& ctx, std::size_t chunk);
    void MakePairs(const std::vector<RigidbodyVolume*>& volumes, const std::vector<std::pair<int, int>>& candidates,
                   const StepContext& ctx, std::size_t chunk);
    /// Candidates per job of Collide: fixed, never derived from the thread count (docs/threads.md).
    static constexpr std::size_t kCandidateChunk = 128;
    struct ChunkCounts {
        std::size_t pairs = 0, contacts = 0, matched = 0;  // touching pairs, their points, points warm started
        std::size_t reused = 0;                            // manifolds reused (ManifoldReuseCount)
        std::size_t firstPair = 0, firstContact = 0;       // where the chunk's pairs and contacts start
    };
    void Prepare(const std::vector<RigidbodyVolume*>& volumes, const StepContext& ctx);
    // The two per-body loops of a substep: each lives here only.
    /// Gravity, retention and threshold of one substep; `warm`: then the velocity change the block's contacts gave
    /// each body over the last substep, again (the warm start of every substep after the first; Step).
    void IntegrateVelocities(const Block& block, bool warm);
    void IntegratePositions(const StepContext& ctx, const Block& block);
    /// IntegratePositions' small turn of `count` (1..4) isotropic bodies at once, four wide (SoftSolver.cpp).
    void SmallTurns(const int* bodies, int count, float h);
    void WarmStart(const Block& block);
    void Solve(const Block& block, float invH, const Softness& softness, const Softness& staticSoftness,
               float maxPushout, float slop, bool useBias, bool updateSeparations = false);
    void ApplyRestitution(float threshold);
    // Shock propagation (SoftSolverShock.cpp): built once per step after BuildBlocks for the blocks whose mass
    // ratio reaches soft.shockMassRatio; run after each substep's biased passes.
    void BuildShock(const StepContext& ctx);
    void BuildShockLayers();
    void BuildShockPoints();
    /// Bottom up, each point's upper body is given the normal speed the biased pass asks of the contact against a
    /// lower body held still: approach no faster than the gap closes, push out of penetration at the static
    /// softness' bias rate. Then (`relax`: after the relax pass) the friction sweep.
    void ShockPass(std::size_t block, float invH, float biasRate, float maxPushout, float slop, bool relax);
    /// End of the points of the pair that starts at `first` (same upper and lower body).
    std::size_t ShockGroupEnd(std::size_t first, std::size_t end) const;
    void ShockNormals(std::size_t first, std::size_t last, float invH, float biasRate, float maxPushout, float slop,
                      bool relax);
    /// The normal impulse through a pair this substep, N s: its points' shock and solve impulses and the upper
    /// body's share of what leans on it.
    float PairLoad(std::size_t first, std::size_t last) const;
    /// The upper body given the lower one's sideways velocity, within the cone of the pair's load.
    void ShockFriction(std::size_t first, std::size_t last);
    /// The moving bodies' state back to the volumes, in fixed chunks on `jobs` (null: this thread).
    void StoreBodies(const std::vector<RigidbodyVolume*>& volumes, JobPool* jobs);

    std::vector<BodyState> state;
    std::vector<BodySim> sim;
    std::vector<Pair> pairs, previousPairs;
    std::vector<Contact> contacts, previousContacts;
    std::vector<ContactManifold> manifolds;  // Collide: one per candidate pair, capacity reused
    /// Per candidate: its bodies and its box-box manifold in their frames, for the next Step to reuse (ReuseLocal).
    struct KeptPair {
        int a = -1, b = -1;
        const RigidbodyVolume* bodyA = nullptr;  // identity check only, as Pair's
        const RigidbodyVolume* bodyB = nullptr;
        LocalManifold local;
    };
    std::vector<KeptPair> kept, previousKept;   // in candidate order, swapped every Step
    std::vector<ChunkCounts> chunkCounts;       // Collide: one per chunk of candidates
    std::vector<std::pair<int, int>> pairEnds;  // per pair: its bodies (a, b), the graph's input
    std::vector<unsigned char> moving;          // per body: it moves this step (BodySim::dynamic), the graph's input
    SoftContactGraph graph;                     // blocks, colours and batches of the pairs
    std::vector<WideBatch> batches;             // the graph's batches, filled
    std::vector<std::size_t> blockOrder;        // OrderBlocks: block indices, most rows first
    std::vector<ShockPoint> shockPoints;
    std::vector<std::size_t> shockBlockStart;  // per block: its first shock point (one more entry at the end)
    std::vector<int> bodyLayer, bodyBlock, layerQueue, adjacencyStart, adjacency;  // BuildShock's scratch
    std::vector<unsigned char> blockShocks;
    std::vector<ShockPoint::Slots> rowSlots;  // per contact: where the solve keeps its impulses (or batch lanes)
    std::vector<float> carried;               // per body: the load leaning on it this substep (ShockPass), N s
    std::vector<int> shockDown;               // per body: the shock pairs it rests on
    std::size_t warmStarted = 0;
    std::size_t reusedManifolds = 0;
    float inheritedNormal = 0.0f;
    long long lastStep = -2;
    bool averagePositions = false;  // settings.volumePositions == Average in the current step
};
