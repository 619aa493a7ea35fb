#pragma once
// ContactSolver::Book and ContactSolver::Accumulated behind IContactSolver. Both step the volumes the book's way, in
// VolumeStages::VolumeSubsteps equal substeps, each: pair search with manifolds, forces, impulses, integration,
// linear projection (docs/book-reference.md §3.4); they differ only in the impulses (SolveImpulses).

#include "Physics/ContactSolver.h"
#include "Physics/IContactSolver.h"

/// The book's substep loop; a subclass supplies the impulse stage.
class SubstepImpulseSolver : public IContactSolver {
public:
    void StepVolumes(VolumeStages& stages, StepContext& ctx) override;
    /// The manifolds are found while stepping: nothing is left to fill.
    void FillCollisions(const VolumeStages& /*stages*/) const override {}

protected:
    /// Changes the velocities of stages.results[0..resultCount) (resultCount > 0) over one substep of ctx.h.
    virtual void SolveImpulses(VolumeStages& stages, const StepContext& ctx) = 0;
};

/// ContactSolver::Book: settings.solverIterations passes of ApplyImpulse (RigidbodyVolume.h) over every contact,
/// nothing kept between steps.
class BookImpulseSolver final : public SubstepImpulseSolver {
public:
    ContactSolver Kind() const override { return ContactSolver::Book; }
    void Clear() override {}

protected:
    void SolveImpulses(VolumeStages& stages, const StepContext& ctx) override;
};

/// ContactSolver::Accumulated: sequential impulses with an arbiter (ContactSolver.h), warm-started from the contacts
/// of the substep just before.
class AccumulatedImpulseSolver final : public SubstepImpulseSolver {
public:
    ContactSolver Kind() const override { return ContactSolver::Accumulated; }
    void Clear() override { solver.Clear(); }
    /// The kept contacts and impulses.
    const AccumulatedContactSolver& State() const { return solver; }

protected:
    void SolveImpulses(VolumeStages& stages, const StepContext& ctx) override;

private:
    AccumulatedContactSolver solver;
};
