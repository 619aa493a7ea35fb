#pragma once
// What a world asks of its contact solver (docs/architecture.md, "One step"). PhysicsSystem makes one object for its
// settings.contactSolver when the setting is first read or changes (never per step) and each step calls it; nothing
// in the step asks which solver it has. The three implementations:
//   Book, Accumulated  ImpulseSolvers.h: the book's substep loop (search, forces, impulses, integrate, projection)
//                      with the book's per-contact impulses or the accumulated ones (ContactSolver.h)
//   Soft               SoftStepSolver.h: one grown-box search per step, then the soft step (SoftSolver.h)
// A solver steps the volumes with the stages they share (VolumeStages.h) and keeps its own contacts between steps.

#include "Physics/ContactSolverSettings.h"

class VolumeStages;
struct StepContext;

class IContactSolver {
public:
    virtual ~IContactSolver() = default;

    /// The setting this object implements.
    virtual ContactSolver Kind() const = 0;
    /// Advances every volume by one step of ctx.dt: sets ctx's substep fields and stages.lastVolumeSubsteps, finds
    /// the pairs, solves the contacts, moves the bodies and updates the islands. Returns early, the world unchanged
    /// from there on, when a pair search sets stages.stopReason (settings.maxPairs).
    virtual void StepVolumes(VolumeStages& stages, StepContext& ctx) = 0;
    /// Forgets every kept contact: the next step starts cold (the world's bodies were cleared).
    virtual void Clear() = 0;
    /// Writes the last step's touching pairs into stages.results when the step left them for later
    /// (stages.collisionsPending; a solver that fills them while stepping never sets it). Clears the flag.
    virtual void FillCollisions(const VolumeStages& stages) const = 0;
};
