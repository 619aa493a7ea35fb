#pragma once
// One world's engine settings and the context one step hands to each of its stages. Every field has its unit
// and the book's default; the book's own name, where ours differs, is given in the comment and listed in
// docs/STYLE.md, "Renames in the engine".

#include <cstddef>

#include "Physics/ContactSolverSettings.h"
#include "Physics/Integrator.h"
#include "Physics/JointModel.h"
#include "Physics/ParticleContact.h"
#include "Physics/SleepSettings.h"
#include "Physics/StepFactor.h"
#include "Physics/VolumePositions.h"

class JobPool;

/// Engine settings of one PhysicsSystem (its `settings`), read by every stage of every step.
struct WorldSettings {
    // ---- particles (ch14, ch16)
    /// How particles (free, cloth and jointed) are integrated. Book: semi-implicit Euler (EULER_INTEGRATION).
    Integrator integrator = Integrator::SemiImplicitEuler;
    /// s: the step at which Particle::velocityRetention is defined (book: 0.03, its fixed step). A step of dt
    /// retains velocityRetention^(dt / particleRetentionStep), the same fraction per second.
    float particleRetentionStep = kBookStep;
    /// How free and cloth particles meet OBB constraints (Particle.h). Book: ParticleContact::Book, whose resting
    /// particles hop by a step-independent amount; Skin converges as the step shrinks, Reflect (model=auto's) to the
    /// rigid answer at second order. Jointed particles keep the
    /// book's contact (DistanceJoint re-solves them against the raw boxes).
    ParticleContact particleContact = ParticleContact::Book;
    /// How distance joints hold their particles (JointModel.h). Book: JointModel::Book, a projection after an
    /// unconstrained step, first order whatever the integrator; Tension puts the joint's force into every force
    /// evaluation, so each integrator keeps its order (docs/ch16.md, "A joint that keeps the integrator's order").
    JointModel jointModel = JointModel::Book;

    // ---- rigid volumes (ch15)
    /// How contact impulses are solved (ContactSolverSettings.h; the world makes its IContactSolver from it). Book: its
    /// per-contact solver.
    ContactSolver contactSolver = ContactSolver::Book;
    /// Passes over every contact per (sub)step, count. Book: ImpulseIteration = 5.
    int solverIterations = 5;
    /// How volumes' positions follow their linear velocity in every contact solver (VolumePositions.h). Book:
    /// VolumePositions::Euler (x += v h); Average moves by the (sub)step's mean velocity, exact for constant
    /// acceleration (docs/ch15.md, "A position update exact for constant acceleration").
    VolumePositions volumePositions = VolumePositions::Euler;
    /// m: penetration left uncorrected by linear projection and the Baumgarte bias (0.01-0.1). Book:
    /// PenetrationSlack = 0.01.
    float penetrationSlop = 0.01f;
    /// Linear projection on or off after integration. Book: DoLinearProjection = true.
    bool linearProjection = true;
    /// Fraction (0..1, not a percent) of the penetration beyond the slop that linear projection removes per
    /// (sub)step; 0.2-0.8, smaller jitters less and sinks more. Book: LinearProjectionPercent = 0.45.
    float projectionFraction = 0.45f;
    /// Settings of ContactSolver::Accumulated (its iterations and slop are the two above).
    AccumulatedSolverSettings accumulated;
    /// Settings of ContactSolver::Soft (its own iterations, substeps and slop; the book's solverIterations,
    /// penetrationSlop and linear projection are not used by it).
    SoftSolverSettings soft;
    /// Islands and sleep (rigid volumes only).
    SleepSettings sleep;
    /// Volumes have no continuous collision, so a step in which a dynamic volume would travel
    /// (|v| dt + |g| dt^2 / 2) more than substepTravelFraction * (its smallest half extent + the smallest in the
    /// world) is split into n equal volume substeps, n <= maxVolumeSubsteps (count; beyond, clamped with a
    /// LastError() warning; docs/ch15.md, "Extremes"). 1 turns it off. Not in the book (n = 1 at its 0.03 s).
    int maxVolumeSubsteps = 64;
    /// Fraction (of the half-extent sum) one substep may travel. Not in the book.
    float substepTravelFraction = 0.75f;
    /// Volume count from which pairs are found by the grid broadphase (Broadphase.h); all pairs below. Not in the book.
    std::size_t broadphaseMinVolumes = 32;
    /// Most candidate volume pairs one pair search may find, count (about 150 bytes each with their manifolds).
    /// Beyond it the world stops (PhysicsSystem::StopReason names the limit) before anything per pair is
    /// allocated: 10,000 spheres at one point would need 50 million pairs and gigabytes. A pile of 10,000 boxes
    /// (the scene-file limit) has about 13 per body. Not in the book.
    std::size_t maxPairs = 250000;
    /// ContactSolver::Soft solves its pairs in batches of four by constraint-graph colour (pairs of one colour share
    /// no moving body; docs/soft-solver.md, "Graph colouring"); false solves them one by one in pair order. The same
    /// equations either way, in another order. Not in the book.
    bool softGraphColouring = true;
    /// Threads the volume step may use, count: 1 is the single-thread path, 0 the process default
    /// (DefaultThreadCount() in JobPool.h: physics-sandbox --threads, else the hardware's concurrency). The pair
    /// search, the manifolds and the soft solve's blocks are cut into chunks of fixed size and merged in a fixed
    /// order, so every count gives the same bits (docs/threads.md). Not in the book.
    int threads = 0;
};

/// What one PhysicsSystem::Update hands to each stage: the step's times and counters and the world's settings.
/// Built on the stack per step; no stage keeps it.
struct StepContext {
    const WorldSettings& settings;
    /// The step's threads (settings.threads resolved; JobPool::Shared). Null runs every stage on the calling thread.
    JobPool* jobs = nullptr;
    float dt = 0.0f;     ///< s, the whole step
    float invDt = 0.0f;  ///< 1/s
    /// s, one volume substep (dt / substepCount; dt itself when substepCount is 1, bit for bit).
    float h = 0.0f;
    float invH = 0.0f;     ///< 1/s
    int substepCount = 1;  ///< volume substeps of this step
    int substep = 0;       ///< index of the current volume substep, 0..substepCount-1
    long long step = 0;    ///< steps taken before this one (PhysicsSystem::StepCount())
    /// Volume substeps taken before the current one over the world's life (one per step without volumes): the
    /// Accumulated solver carries impulses over only from the substep just before.
    long long substepSerial = 0;
};
