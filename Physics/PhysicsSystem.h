#pragma once
// The world: bodies, constraints (immovable OBBs), springs, cloths; one fixed step at a time
// (docs/book-reference.md §3.4).
//
// Model only what the scene requires: bodies are sorted by kind when added, and each stage of Update runs
// only over the kinds present. A particle-only scene does no pair tests, impulses or spring work; a scene
// without springs or cloth pays nothing for them. Nothing is allocated per step in steady state.
//
// Stages live in the file of the chapter that introduced them:
//   PhysicsSystemParticles.cpp (ch14)  particle forces, integration, constraint solving
//   PhysicsSystemVolumes.cpp   (ch15)  broadphase + manifolds, impulses, volume integration, projection; the
//                                      soft step's pair search (SoftSolver.h does the rest)
//   PhysicsSystemSprings.cpp   (ch16)  spring and cloth forces, distance joints

#include <cstddef>
#include <string>
#include <vector>

#include "Physics/Broadphase.h"
#include "Physics/ContactSolver.h"
#include "Physics/Geometry/Geometry3D.h"
#include "Physics/Integrator.h"
#include "Physics/Islands.h"
#include "Physics/Rigidbody.h"
#include "Physics/SoftSolver.h"
#include "Physics/WorldSettings.h"

class Particle;
struct ParticleConstraint;
class RigidbodyVolume;
class Spring;
class Cloth;
class DistanceJoint;

/// A colliding pair found this step, with its manifold (normal from a to b).
struct CollisionPair {
    RigidbodyVolume* a = nullptr;
    RigidbodyVolume* b = nullptr;
    int indexA = -1, indexB = -1;  ///< positions of a and b in PhysicsSystem::Volumes() (indexA < indexB)
    CollisionManifold manifold;
};

class PhysicsSystem {
public:
    /// Engine settings (units and the book's defaults in WorldSettings.h); read by every stage of each step.
    WorldSettings settings;
    bool DebugRender = false;         ///< read by the drawing layer only
    bool RenderRandomColors = false;  ///< read by the drawing layer only

    PhysicsSystem();
    ~PhysicsSystem();
    PhysicsSystem(const PhysicsSystem&) = delete;
    PhysicsSystem& operator=(const PhysicsSystem&) = delete;

    /// Advances the world by one fixed step of dt seconds: builds the step's StepContext and hands it to every
    /// stage. dt <= 0 or non-finite does nothing.
    void Update(float deltaTime);

    /// Adds a body by pointer (not owned). Particles, volumes (sphere/box), distance joints and other
    /// Rigidbody subclasses are kept in separate lists so each stage touches only its own kind.
    /// Returns false and skips the body (LastError() names the bad value) for a null pointer, a volume that fails
    /// ValidateVolume (zero, negative or non-finite size or mass, non-finite state), or a particle with a
    /// non-finite position or velocity or a negative or non-finite mass. The book returns void; callers that ignore
    /// the result still compile.
    bool AddRigidbody(Rigidbody* body);
    void AddCloth(Cloth* cloth);
    /// Stores a copy, as the book does.
    void AddSpring(const Spring& spring);
    void AddConstraint(const OBB& constraint);
    void ClearRigidbodys();
    void ClearConstraints();
    void ClearSprings();
    void ClearCloths();

    // Read access for drawing, tests and benchmarks.
    const std::vector<Rigidbody*>& Bodies() const { return bodies; }  ///< insertion order
    const std::vector<Particle*>& Particles() const { return particles; }
    const std::vector<RigidbodyVolume*>& Volumes() const { return volumes; }
    const std::vector<DistanceJoint*>& Joints() const { return joints; }
    const std::vector<OBB>& Constraints() const { return constraints; }
    const std::vector<Spring>& Springs() const { return springs; }
    const std::vector<Cloth*>& Cloths() const { return cloths; }
    /// Colliding pairs found at the start of the last step (debug drawing of manifolds), [0, CollisionCount()).
    /// Every solver fills them. ContactSolver::Soft: the soft step's pairs with a touching point (separation
    /// <= 0; speculative points are left out), the points where the step found them, the pair's normal, and the
    /// deepest of those points' penetrations as depth; built from the solver's own contacts on the first call
    /// after a step (the step itself pays nothing; FillSoftCollisions).
    const std::vector<CollisionPair>& Collisions() const {
        if (softCollisionsPending) FillSoftCollisions();
        return results;
    }
    std::size_t CollisionCount() const {
        if (softCollisionsPending) FillSoftCollisions();
        return resultCount;
    }
    /// The Accumulated solver's kept contacts and impulses (empty while settings.contactSolver is Book).
    const AccumulatedContactSolver& AccumulatedSolver() const { return accumulatedSolver; }
    /// Islands and sleep of the volumes (settings.sleep; untouched while it is off).
    const Islands& SleepIslands() const { return islands; }
    /// The Soft solver's contacts and impulses of the last step (empty unless settings.contactSolver is Soft).
    const SoftContactSolver& SoftSolver() const { return softSolver; }
    /// Number of Update calls that advanced the world.
    long long StepCount() const { return stepCount; }
    /// Volume substeps the last Update took (1 unless it had to subdivide; see WorldSettings::maxVolumeSubsteps).
    int LastVolumeSubsteps() const { return lastVolumeSubsteps; }
    /// The last refusal (AddRigidbody) or warning (a step that needed more than maxVolumeSubsteps substeps),
    /// naming the bad value; empty if none since construction or ClearError().
    const std::string& LastError() const { return lastError; }
    void ClearError() { lastError.clear(); }
    /// Why the world stopped, naming the limit: a pair search found more than settings.maxPairs candidate volume
    /// pairs (WorldSettings.h). Empty while it runs; once set, Update does nothing (the world stays as it was).
    const std::string& StopReason() const { return stopReason; }

private:
    // ---- ch14: PhysicsSystemParticles.cpp
    /// Integrates every particle (free and cloth) with settings.integrator over ctx.dt; multi-stage integrators
    /// re-evaluate AccumulateParticleForces at their intermediate states.
    void IntegrateParticles(const StepContext& ctx);
    /// Gravity on every particle, then spring forces (AccumulateSpringForces).
    void AccumulateParticleForces();
    /// Free particles, then joints, then cloth particles against the constraints (book order).
    void SolveParticleConstraints();

    // ---- ch15: PhysicsSystemVolumes.cpp (each runs once per volume substep of ctx.h seconds). `sleep` is null
    // with settings.sleep off; otherwise sleeping volumes are not moved and only pairs with an active body are tested.
    /// Pair search over volumes only; fills results[0..resultCount). With sleep, a contact between an active and a
    /// sleeping body wakes the sleeping island and the search runs again.
    void FindCollisions(const StepContext& ctx, Islands* sleep);
    /// One pair search: every pair that can interact and, when `active` is given (one byte per volume), has an active
    /// body; fills results[0..resultCount) in increasing (indexA, indexB) order. Over settings.maxPairs: no
    /// results, and stopReason set.
    void FindPairs(const StepContext& ctx, const unsigned char* active);
    /// Sets stopReason for a search that passed settings.maxPairs.
    void StopAtPairLimit();
    /// Gravity on every volume, turned into this substep's velocity change before the impulses (ch15 note N1).
    void ApplyVolumeForces(const StepContext& ctx, const Islands* sleep);
    void ApplyImpulses(const StepContext& ctx);
    void IntegrateVolumes(const StepContext& ctx, const Islands* sleep);
    void ApplyLinearProjection(const StepContext& ctx);
    /// Number of equal volume substeps for a step of dt (1..settings.maxVolumeSubsteps); records a warning when
    /// clamped.
    int VolumeSubsteps(float dt);
    /// ContactSolver::Soft: the whole volume step (pair search with AABBs grown by the speculative margin, then
    /// SoftContactSolver::Step in settings.soft.substeps substeps). Fills ctx's substep fields.
    void StepSoftVolumes(StepContext& ctx);
    /// Writes the soft step's touching contacts into results[0..resultCount) (Collisions()); const because the
    /// readers are: it only turns the solver's kept contacts into the book's form.
    void FillSoftCollisions() const;

    // ---- ch16: PhysicsSystemSprings.cpp
    /// Adds the force of every spring (system and cloth) to its particles' `forces`.
    void AccumulateSpringForces();
    void SolveJoints();

    /// Rebuilds allParticles after bodies or cloths change.
    void RebuildParticleList();

    std::vector<Rigidbody*> bodies;  // every body, insertion order
    std::vector<Particle*> particles;
    std::vector<RigidbodyVolume*> volumes;
    std::vector<DistanceJoint*> joints;
    std::vector<Rigidbody*> others;  // any other Rigidbody subclass: generic virtual calls
    std::vector<Cloth*> cloths;
    std::vector<OBB> constraints;
    std::vector<Spring> springs;
    std::vector<Particle*> allParticles;                  // free particles then every cloth's particles
    std::vector<IntegratorScratch> integratorScratch;     // ch14: one per allParticles entry, grown only
    std::vector<ParticleConstraint> preparedConstraints;  // ch14: constraints with AABBs, rebuilt per step

    // Capacity reused; only [0, resultCount) is valid. Mutable: after a soft step Collisions() fills them.
    mutable std::vector<CollisionPair> results;
    mutable std::size_t resultCount = 0;
    mutable bool softCollisionsPending = false;       // the last step was a soft one and results are not yet filled
    Broadphase broadphase;                            // used only from settings.broadphaseMinVolumes volumes up
    std::vector<std::pair<int, int>> candidatePairs;  // broadphase output, capacity reused
    struct GrownBounds {
        vec3 min, max;
    };
    std::vector<GrownBounds> smallWorldBounds;  // soft step below broadphaseMinVolumes: grown boxes, capacity reused
    long long stepCount = 0;
    AccumulatedContactSolver accumulatedSolver;  // ch15: arbiter state of ContactSolver::Accumulated
    Islands islands;                             // settings.sleep: islands, sleep times, sleeping bodies
    SoftContactSolver softSolver;                // ch15: contacts and body state of ContactSolver::Soft
    long long volumeSubstepSerial = 0;           // volume substeps so far (one per Update without volumes): StepContext
    int lastVolumeSubsteps = 1;
    std::string lastError;
    std::string stopReason;
};
