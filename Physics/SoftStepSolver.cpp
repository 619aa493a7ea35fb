// ContactSolver::Soft's step of the volumes (SoftStepSolver.h; docs/soft-solver.md, "The soft-step solver").
#include "Physics/SoftStepSolver.h"

#include <algorithm>

#include "Physics/RigidbodyVolume.h"
#include "Physics/VolumeStages.h"
#include "Physics/WorldSettings.h"

void SoftStepSolver::StepVolumes(VolumeStages& stages, StepContext& ctx) {
    // Pairs are found once per step, with every AABB grown by the speculative margin and the body's travel over the
    // step, so that contacts about to touch are solved before they do.
    const WorldSettings& settings = ctx.settings;
    const int n = std::max(settings.soft.substeps, 1);
    ctx.substepCount = n;
    ctx.h = ctx.dt / static_cast<float>(n);
    ctx.invH = 1.0f / ctx.h;
    ctx.substep = 0;
    ctx.substepSerial = stages.substepSerial;
    stages.lastVolumeSubsteps = n;
    stages.resultCount = 0;  // Collisions() turns the soft step's contacts into the book's form when asked

    // Islands and sleep (Islands.h): null while settings.sleep is off. Sleeping bodies are held like static ones;
    // a pair is searched only when one body is active, and a sleeping island whose grown AABB meets an active
    // body's is woken before the solve (then the search runs again for its own pairs).
    Islands* sleep = stages.islands.BeginStep(stages.volumes, settings.sleep) ? &stages.islands : nullptr;
    const unsigned char* active = sleep != nullptr ? sleep->ActiveMask() : nullptr;
    const float margin = std::max(settings.soft.speculativeMargin, 0.0f);
    const std::size_t count = stages.volumes.size();
    std::vector<std::pair<int, int>>& candidates = stages.candidatePairs;
    // With every body asleep (or static) no pair can have an active body and nothing moves: the search and the
    // solver's pass over every body are skipped, and the solver only forgets its (already empty) contacts, which
    // is what its Step would leave. A settled world then costs the wake checks and the island update.
    if (sleep != nullptr && std::find(active, active + count, 1) == active + count) {
        candidates.clear();
        solver.Clear();
    } else {
        stages.FindGrownPairs(ctx, active, margin);
        if (sleep != nullptr)
            while (stages.stopReason.empty() && sleep->WakeTouched(candidates.data(), candidates.size()) > 0)
                stages.FindGrownPairs(ctx, active, margin);
        if (!stages.stopReason.empty()) return;
        solver.Step(stages.volumes, candidates, ctx, active);
    }
    if (sleep != nullptr) UpdateIslands(stages, ctx);
    stages.substepSerial += n;
    stages.collisionsPending = true;
}

void SoftStepSolver::UpdateIslands(VolumeStages& stages, const StepContext& ctx) const {
    // Islands are linked over the same candidate pairs that wake them (grown boxes that meet), not only over pairs
    // with contact points: two islands near enough to wake each other are one island, so they fall asleep together
    // instead of waking each other in turn.
    stages.islands.BeginUpdate(stages.volumes, ctx.dt, ctx.settings.sleep);
    for (const std::pair<int, int>& p : stages.candidatePairs) stages.islands.LinkPair(p.first, p.second);
    stages.islands.EndUpdate(stages.volumes, ctx.settings.sleep);
}

void SoftStepSolver::FillCollisions(const VolumeStages& stages) const {
    stages.collisionsPending = false;
    stages.resultCount = 0;
    const std::vector<RigidbodyVolume*>& volumes = stages.volumes;
    const std::vector<SoftContactSolver::Contact>& contacts = solver.Contacts();
    for (const SoftContactSolver::Pair& pair : solver.Pairs()) {
        const std::size_t a = static_cast<std::size_t>(pair.a), b = static_cast<std::size_t>(pair.b);
        if (b >= volumes.size() || volumes[a] != pair.bodyA || volumes[b] != pair.bodyB) continue;
        if (stages.resultCount == stages.results.size()) stages.results.emplace_back();
        CollisionPair& slot = stages.results[stages.resultCount];
        CollisionManifold& m = slot.manifold;
        ResetCollisionManifold(&m);
        m.normal = pair.n;
        m.depth = 0.0f;
        // The anchors are from body a's centre at the start of the step, as the manifold found them.
        const vec3 start = solver.StartPosition(pair.a);
        for (std::size_t k = pair.first; k < pair.first + pair.count; ++k) {
            const SoftContactSolver::Contact& c = contacts[k];
            if (c.separation > 0.0f) continue;
            m.contacts.push_back(start + c.rA);
            m.depth = std::max(m.depth, -c.separation);
        }
        if (m.contacts.empty()) continue;
        m.colliding = true;
        slot.a = volumes[a];
        slot.b = volumes[b];
        slot.indexA = pair.a;
        slot.indexB = pair.b;
        ++stages.resultCount;
    }
}
