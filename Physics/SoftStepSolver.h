#pragma once
// ContactSolver::Soft behind IContactSolver: once per step, a search over boxes grown by the speculative margin and
// each body's travel (VolumeStages::FindGrownPairs), then the soft step (SoftSolver.h) in settings.soft.substeps
// substeps. No travel split and no linear projection: the substeps and the soft bias replace both.

#include "Physics/IContactSolver.h"
#include "Physics/SoftSolver.h"

class SoftStepSolver final : public IContactSolver {
public:
    ContactSolver Kind() const override { return ContactSolver::Soft; }
    void StepVolumes(VolumeStages& stages, StepContext& ctx) override;
    void Clear() override { solver.Clear(); }
    /// The soft step's pairs with a touching point (separation <= 0; speculative points are left out), the points
    /// where the step found them, the pair's normal, and the deepest of those points' penetrations as depth. Built
    /// from the solver's own contacts when first read after a step (the step itself pays nothing).
    void FillCollisions(const VolumeStages& stages) const override;
    /// The contacts, impulses and body state of the last step.
    const SoftContactSolver& State() const { return solver; }

private:
    /// Islands after the step, linked over the candidate pairs.
    void UpdateIslands(VolumeStages& stages, const StepContext& ctx) const;

    SoftContactSolver solver;
};
