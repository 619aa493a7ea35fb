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
//   settings.contactSolver     (ch15)  the volumes: the world's contact solver object (IContactSolver.h), made
//                                      when the setting changes, steps them with the shared VolumeStages.h
//   PhysicsSystemSprings.cpp   (ch16)  spring and cloth forces, distance joints

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "Physics/Broadphase.h"
#include "Physics/ContactSolver.h"
#include "Physics/DistanceJoint.h"
#include "Physics/Geometry/Geometry3D.h"
#include "Physics/IContactSolver.h"
#include "Physics/Integrator.h"
#include "Physics/Islands.h"
#include "Physics/Rigidbody.h"
#include "Physics/SoftSolver.h"
#include "Physics/VolumeStages.h"
#include "Physics/WorldSettings.h"

class Particle;
struct ParticleConstraint;
class RigidbodyVolume;
class Spring;
class Cloth;
class DistanceJoint;

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
    /// after a step (the step itself pays nothing; SoftStepSolver::FillCollisions).
    const std::vector<CollisionPair>& Collisions() const {
        if (stages.collisionsPending) solver->FillCollisions(stages);
        return stages.results;
    }
    std::size_t CollisionCount() const {
        if (stages.collisionsPending) solver->FillCollisions(stages);
        return stages.resultCount;
    }
    /// The contact solver object that steps the volumes: made for settings.contactSolver at construction and again
    /// at the start of the first Update after the setting changed (its kept contacts go with it); never null.
    const IContactSolver& Solver() const { return *solver; }
    /// The Accumulated solver's kept contacts and impulses (empty unless Solver() is the Accumulated one).
    const AccumulatedContactSolver& AccumulatedSolver() const;
    /// Islands and sleep of the volumes (settings.sleep; untouched while it is off).
    const Islands& SleepIslands() const { return stages.islands; }
    /// The Soft solver's contacts and impulses of the last step (empty unless Solver() is the Soft one).
    const SoftContactSolver& SoftSolver() const;
    /// Number of Update calls that advanced the world.
    long long StepCount() const { return stepCount; }
    /// Volume substeps the last Update took (1 unless it had to subdivide; see WorldSettings::maxVolumeSubsteps).
    int LastVolumeSubsteps() const { return stages.lastVolumeSubsteps; }
    /// The last refusal (AddRigidbody) or warning (a step that needed more than maxVolumeSubsteps substeps),
    /// naming the bad value; empty if none since construction or ClearError().
    const std::string& LastError() const { return lastError; }
    void ClearError() { lastError.clear(); }
    /// Why the world stopped, naming the limit: a pair search found more than settings.maxPairs candidate volume
    /// pairs (WorldSettings.h). Empty while it runs; once set, Update does nothing (the world stays as it was).
    const std::string& StopReason() const { return stages.stopReason; }

private:
    // ---- ch14: PhysicsSystemParticles.cpp
    /// Integrates every particle (free and cloth) with settings.integrator over ctx.dt; multi-stage integrators
    /// re-evaluate AccumulateParticleForces at their intermediate states.
    void IntegrateParticles(const StepContext& ctx);
    /// Gravity on every particle, then spring forces (AccumulateSpringForces).
    void AccumulateParticleForces();
    /// Free particles, then joints, then cloth particles against the constraints (book order).
    void SolveParticleConstraints(float dt);

    // ---- ch15: the contact solver (IContactSolver.h) with the shared stages (VolumeStages.h)
    /// Makes a new solver object when settings.contactSolver no longer matches the one the world has.
    void MatchSolverToSettings();

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
    TensionPlan tensionPlan;  // JointModel::Tension: the joints it pulls, grouped (PlanTensions)
    std::size_t tensionPlanFor = static_cast<std::size_t>(-1);  // joints.size() when tensionPlan was made
    std::vector<Rigidbody*> others;                             // any other Rigidbody subclass: generic virtual calls
    std::vector<Cloth*> cloths;
    std::vector<OBB> constraints;
    std::vector<Spring> springs;
    std::vector<Particle*> allParticles;                  // free particles then every cloth's particles
    std::vector<IntegratorScratch> integratorScratch;     // ch14: one per allParticles entry, grown only
    std::vector<ParticleConstraint> preparedConstraints;  // ch14: constraints with AABBs, rebuilt per step

    std::string lastError;
    VolumeStages stages{volumes, lastError};  // ch15: pairs, islands and the stages every contact solver uses
    std::unique_ptr<IContactSolver> solver;   // ch15: made for settings.contactSolver (MatchSolverToSettings)
    long long stepCount = 0;
};
