// ContactSolver::Book and ContactSolver::Accumulated (ImpulseSolvers.h): the book's substep loop and its two impulse
// stages.
#include "Physics/ImpulseSolvers.h"

#include "Physics/RigidbodyVolume.h"
#include "Physics/VolumeStages.h"
#include "Physics/WorldSettings.h"

void SubstepImpulseSolver::StepVolumes(VolumeStages& stages, StepContext& ctx) {
    // Volumes step in n equal substeps when one step would carry a volume through another (VolumeSubsteps);
    // n = 1 is the book's single step, with dt passed through unchanged.
    const int n = stages.VolumeSubsteps(ctx);
    ctx.substepCount = n;
    ctx.h = n == 1 ? ctx.dt : ctx.dt / static_cast<float>(n);
    ctx.invH = 1.0f / ctx.h;
    stages.lastVolumeSubsteps = n;
    // Islands and sleep (Islands.h): null while settings.sleep is off, and then nothing below changes.
    Islands* sleep = stages.islands.BeginStep(stages.volumes, ctx.settings.sleep) ? &stages.islands : nullptr;
    for (int s = 0; s < n; ++s) {
        ctx.substep = s;
        ctx.substepSerial = stages.substepSerial;
        stages.FindCollisions(ctx, sleep);
        if (!stages.stopReason.empty()) return;  // over settings.maxPairs: the world stays as it is
        stages.ApplyVolumeForces(ctx, sleep);
        if (stages.resultCount > 0) SolveImpulses(stages, ctx);
        stages.IntegrateVolumes(ctx, sleep);
        if (ctx.settings.linearProjection && stages.resultCount > 0) stages.ApplyLinearProjection(ctx);
        ++stages.substepSerial;
    }
    if (sleep != nullptr)
        stages.islands.Update(stages.volumes, stages.results.data(), stages.resultCount, ctx.dt, ctx.settings.sleep);
}

void BookImpulseSolver::SolveImpulses(VolumeStages& stages, const StepContext& ctx) {
    for (int k = 0; k < ctx.settings.solverIterations; ++k) {
        for (std::size_t i = 0; i < stages.resultCount; ++i) {
            const CollisionPair& pair = stages.results[i];
            const int contacts = static_cast<int>(pair.manifold.contacts.size());
            for (int c = 0; c < contacts; ++c) ApplyImpulse(*pair.a, *pair.b, pair.manifold, c);
        }
    }
}

void AccumulatedImpulseSolver::SolveImpulses(VolumeStages& stages, const StepContext& ctx) {
    // Results are in increasing (indexA, indexB) order, which the arbiter's lookup relies on. Impulses carry over
    // between consecutive substeps (ctx.substepSerial).
    solver.Solve(stages.volumes, stages.results.data(), stages.resultCount, ctx);
}
