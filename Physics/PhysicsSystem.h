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
//   PhysicsSystemVolumes.cpp   (ch15)  broadphase + manifolds, impulses, volume integration, projection
//   PhysicsSystemSoft.cpp      (ch16)  spring and cloth forces, distance joints

#include <cstddef>
#include <string>
#include <vector>

#include "Physics/Broadphase.h"
#include "Physics/ContactSolver.h"
#include "Physics/Geometry/Geometry3D.h"
#include "Physics/Integrator.h"
#include "Physics/Rigidbody.h"

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
    // The book's public parameters, with its defaults.
    float LinearProjectionPercent = 0.45f;  ///< 0.2-0.8: smaller jitters less and sinks more
    float PenetrationSlack = 0.01f;         ///< 0.01-0.1: penetration left uncorrected
    int ImpulseIteration = 5;               ///< passes over every contact per step
    bool DoLinearProjection = true;
    bool DebugRender = false;         ///< read by the drawing layer only
    bool RenderRandomColors = false;  ///< read by the drawing layer only
    /// How particles (free, cloth and jointed) are integrated. The book ships semi-implicit Euler.
    Integrator integrator = Integrator::SemiImplicitEuler;
    /// Volume pairs are found by sweep-and-prune (Broadphase.h) from this many volumes up; all pairs below.
    std::size_t BroadphaseMinVolumes = 32;
    /// How contact impulses are solved (ContactSolver.h). Book (default) is the book's per-contact solver;
    /// Accumulated keeps contacts across steps and lets stacks stand (docs/ch15.md).
    ContactSolver contactSolver = ContactSolver::Book;
    /// Settings of the Accumulated solver (iterations and slop are ImpulseIteration and PenetrationSlack).
    AccumulatedSolverSettings accumulated;
    /// Volumes have no continuous collision, so a step in which a dynamic volume would travel (|v| dt + |g| dt^2 / 2)
    /// more than SubstepTravelFraction * (its smallest half extent + the smallest in the world) is split into n
    /// equal volume substeps, n <= MaxVolumeSubsteps (beyond, clamped with a LastError() warning; docs/ch15.md,
    /// "Extremes"). 1 turns it off. At the book's 0.03 s and its demos' speeds n is 1.
    int MaxVolumeSubsteps = 64;
    float SubstepTravelFraction = 0.75f;

    PhysicsSystem();
    ~PhysicsSystem();
    PhysicsSystem(const PhysicsSystem&) = delete;
    PhysicsSystem& operator=(const PhysicsSystem&) = delete;

    /// Advances the world by dt seconds (one fixed step). dt <= 0 or non-finite does nothing.
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
    /// Colliding pairs found at the start of the last step (debug drawing of manifolds).
    const std::vector<CollisionPair>& Collisions() const { return results; }
    std::size_t CollisionCount() const { return resultCount; }
    /// The Accumulated solver's kept contacts and impulses (empty while contactSolver is Book).
    const AccumulatedContactSolver& AccumulatedSolver() const { return accumulatedSolver; }
    /// Number of Update calls that advanced the world.
    long long StepCount() const { return stepCount; }
    /// Volume substeps the last Update took (1 unless it had to subdivide; see MaxVolumeSubsteps).
    int LastVolumeSubsteps() const { return lastVolumeSubsteps; }
    /// The last refusal (AddRigidbody) or warning (a step that needed more than MaxVolumeSubsteps substeps),
    /// naming the bad value; empty if none since construction or ClearError().
    const std::string& LastError() const { return lastError; }
    void ClearError() { lastError.clear(); }

private:
    // ---- ch14: PhysicsSystemParticles.cpp
    /// Integrates every particle (free and cloth) with `integrator`; multi-stage integrators re-evaluate
    /// AccumulateParticleForces at their intermediate states.
    void IntegrateParticles(float dt);
    /// Gravity on every particle, then spring forces (AccumulateSpringForces).
    void AccumulateParticleForces();
    /// Free particles, then joints, then cloth particles against the constraints (book order).
    void SolveParticleConstraints();

    // ---- ch15: PhysicsSystemVolumes.cpp
    void FindCollisions();  ///< pair search over volumes only; fills results[0..resultCount)
    /// Gravity on every volume, turned into this step's velocity change before the impulses (ch15 note N1).
    void ApplyVolumeForces(float dt);
    void ApplyImpulses();
    void IntegrateVolumes(float dt);
    void ApplyLinearProjection();
    /// Number of equal volume substeps for a step of dt (1..MaxVolumeSubsteps); records a warning when clamped.
    int VolumeSubsteps(float dt);

    // ---- ch16: PhysicsSystemSoft.cpp
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

    std::vector<CollisionPair> results;  // capacity reused; only [0, resultCount) is valid
    std::size_t resultCount = 0;
    Broadphase broadphase;                            // used only from BroadphaseMinVolumes volumes up
    std::vector<std::pair<int, int>> candidatePairs;  // broadphase output, capacity reused
    long long stepCount = 0;
    AccumulatedContactSolver accumulatedSolver;  // ch15: arbiter state of ContactSolver::Accumulated
    float volumeStepDt = 0.0f;                   // this step's dt, kept by ApplyVolumeForces for the solver
    long long volumeSubstepCount = 0;  // one per volume substep (one per Update without volumes): solver carry-over
    int lastVolumeSubsteps = 1;
    std::string lastError;
};
