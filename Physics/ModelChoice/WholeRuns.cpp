// Whole runs shared between candidates (docs/model-choice.md, "Whole runs"): a candidate measured over the whole run
// runs itself, its refinement and the refinement's refinement from the start to the same end. The soft solver's
// refinement doubles its substeps at the same step, so the refinement of "4 substeps" is the candidate "8 substeps"
// and its third probe "16 substeps": each of those runs once per choice, kept here with its state at the end, and
// the figures are the same as when the three run side by side (each probe's steps do not depend on when it is read).
#include <algorithm>
#include <cmath>
#include <memory>

#include "Physics/ModelChoice/Internals.h"
#include "Physics/PhysicsSystem.h"

namespace model_choice {

namespace {

bool SameRun(const ModelCandidate& a, const ModelCandidate& b) {
    return a.integrator == b.integrator && a.solver == b.solver && a.iterations == b.iterations &&
           a.softSubsteps == b.softSubsteps && a.step == b.step;
}

/// The sample (1..samples) of a side-by-side run at which a probe that failed at its `failStep`-th step (1-based)
/// would have failed: the first whose time its AdvanceTo reaches that step at (samples + 1: never).
int FailSample(const WholeRunRecord& r, const ModelCandidate& m, double candidateStep, long long measured,
               int samples) {
    if (r.failStep < 0) return samples + 1;
    for (int s = 1; s <= samples; ++s) {
        const double t = candidateStep * static_cast<double>((measured * s) / samples);
        if (static_cast<double>(r.failStep) * m.step <= t * (1.0 + 1e-12) + 1e-12) return s;
    }
    return samples + 1;
}

/// The budget's quantity between two runs' states at one end: the largest distance of a body, or the energy's
/// difference over `energyScale`.
double Differ(const WholeRunRecord::AtEnd& a, const WholeRunRecord::AtEnd& b, BudgetQuantity quantity,
              double energyScale) {
    if (quantity == BudgetQuantity::Energy) return std::fabs(a.energy - b.energy) / energyScale;
    double worst = 0.0;
    const std::size_t n = std::min(a.positions.size(), b.positions.size());
    for (std::size_t i = 0; i + 2 < n; i += 3) {
        const double d[3] = {a.positions[i] - b.positions[i], a.positions[i + 1] - b.positions[i + 1],
                             a.positions[i + 2] - b.positions[i + 2]};
        worst = std::max(worst, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    }
    return worst;
}

/// s: where a whole run of a candidate of step `step` over `span` s ends (SpanRun's measured part: whole steps).
double WholeRunEnd(double step, double span) {
    return step * static_cast<double>(std::max(2LL, std::llround(span / step)));
}

/// Runs `m` from the start as a side-by-side span advances it (ModelProbe::AdvanceTo, whole steps), one step per call
/// so a failure's step is known, and keeps its state at every end a candidate running it may measure at: its own as a
/// candidate, and those of the candidates whose refinement or third probe it is (steps of 2 and 4 times its own, or
/// its own step where the refinement doubles the soft substeps). Reads the choice's clock after about a millisecond's
/// work; false when the clock stopped it (nothing kept).
bool RunOne(const ProbeFactory& factory, const ModelCandidate& m, const CandidateSpace& space, double span,
            ChoiceClock* clock, double pieceStart, double* work, WholeRunRecord* out) {
    std::vector<double> ends = {WholeRunEnd(m.step, span), WholeRunEnd(2.0 * m.step, span),
                                WholeRunEnd(4.0 * m.step, span)};
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    std::unique_ptr<ModelProbe> probe = factory();
    probe->Apply(m);
    const double started = ProcessCpuSeconds();
    const double perStep = PredictedWork(m, space) * m.step;
    const long long chunk = std::max(1LL, static_cast<long long>(4e4 / std::max(perStep, 1e-12)));
    auto within = [&](long long steps, double end) {
        return static_cast<double>(steps) * m.step <= end * (1.0 + 1e-12) + 1e-12;  // as AdvanceTo counts
    };
    long long k = 0;  // steps made
    for (double end : ends) {
        // Step by step up to the last step before `end`, then AdvanceTo(end) itself, as the span's last sample.
        while (out->failStep < 0 && within(k + 2, end)) {
            if (!probe->AdvanceTo(static_cast<double>(k + 1) * m.step)) {
                out->failStep = k + 1;
                break;
            }
            ++k;
            *work += perStep;
            if (k % chunk == 0 && clock->Poll(pieceStart, *work)) return false;
        }
        if (out->failStep >= 0) break;
        if (!probe->AdvanceTo(end)) {
            out->failStep = k + 1;
            break;
        }
        for (; within(k + 1, end); ++k) *work += perStep;
        WholeRunRecord::AtEnd at;
        at.end = end;
        WorldPositions(probe->World(), &at.positions);
        at.energy = WorldEnergy(probe->World());
        at.volumeUpdates = probe->VolumeUpdates();
        out->ends.push_back(std::move(at));
    }
    out->model = m;
    out->cpuSeconds = ProcessCpuSeconds() - started;
    return true;
}

/// Makes sure the cache holds `m`'s run with its state at `end` (or its failure); false when the clock stopped it.
bool Keep(const ProbeFactory& factory, const ModelCandidate& m, const CandidateSpace& space, double span, double end,
          ChoiceClock* clock, double pieceStart, double* work) {
    const WholeRunRecord* kept = clock->runs.Find(m);
    if (kept && (kept->failStep >= 0 || kept->At(end))) return true;
    WholeRunRecord made;
    if (!RunOne(factory, m, space, span, clock, pieceStart, work, &made)) return false;
    clock->runs.records.push_back(std::move(made));
    return true;
}

}  // namespace

const WholeRunRecord* WholeRunCache::Find(const ModelCandidate& m) const {
    for (auto r = records.rbegin(); r != records.rend(); ++r) {
        if (SameRun(r->model, m)) return &*r;  // the newest
    }
    return nullptr;
}

SpanResult RunWholeShared(const ProbeFactory& factory, const ModelCandidate& candidate, const CandidateSpace& space,
                          const ErrorBudget& budget, double span, const SpanOptions& o) {
    SpanResult r;
    ChoiceClock& clock = *o.clock;
    const ModelCandidate refined = RefineFor(candidate, space, o.byStep);
    const ModelCandidate models[3] = {candidate, refined, RefineFor(refined, space, o.byStep)};
    const long long measured = std::max(2LL, std::llround(span / candidate.step));
    const int samples = static_cast<int>(std::min<long long>(256, measured));
    const double end = WholeRunEnd(candidate.step, span);
    const double start = ProcessCpuSeconds();
    clock.StartPiece();
    double work = 0.0;
    for (int i = 0; i < 3 && !r.stopped; ++i)
        r.stopped = !Keep(factory, models[i], space, span, end, &clock, start, &work);
    r.probeCpuSeconds = ProcessCpuSeconds() - start;
    r.work = work;
    clock.Add(r.probeCpuSeconds, work);
    r.factor = RichardsonFactor(OrderOf(candidate, space));
    r.length = end;
    if (r.stopped) {
        r.growth = 0.0;
        r.share = 0.0;
        return r;
    }
    const WholeRunRecord* rec[3];
    for (int i = 0; i < 3; ++i) rec[i] = clock.runs.Find(models[i]);
    // The side-by-side run's outcome: the first sample any probe failed at, the candidate's failure first.
    int fail[3];
    for (int i = 0; i < 3; ++i) fail[i] = FailSample(*rec[i], models[i], candidate.step, measured, samples);
    const int first = std::min({fail[0], fail[1], fail[2]});
    const long long reached = first <= samples ? (measured * first) / samples : measured;
    r.simulated = candidate.step * static_cast<double>(reached);
    r.share = static_cast<double>(reached) / static_cast<double>(measured);
    r.cpuSeconds = rec[0]->cpuSeconds;
    const WholeRunRecord::AtEnd* at[3];
    for (int i = 0; i < 3; ++i) at[i] = rec[i]->At(end);
    if (first <= samples || !at[0] || !at[1] || !at[2]) {
        if (first <= samples ? fail[0] == first : !at[0]) {
            r.stable = false;
        } else {
            r.observed = kInf;
        }
        return r;
    }
    if (Unrefined(space, at[0]->volumeUpdates, at[1]->volumeUpdates)) {
        r.noEstimate = kUnrefined;
        r.observed = kInf;
        return r;
    }
    const double energyScale =
        budget.quantity == BudgetQuantity::Energy ? std::max(std::fabs(WorldEnergy(factory()->World())), 1e-12) : 1.0;
    const double pair = Differ(*at[0], *at[1], budget.quantity, energyScale);
    const double finer = Differ(*at[1], *at[2], budget.quantity, energyScale);
    if (!std::isfinite(pair)) {
        r.stable = false;
        return r;
    }
    r.noise = ConvergenceNoise(budget.quantity, at[1]->positions, r.simulated * UpdatesPerSecond(models[2], space));
    r.growth = 0.0;  // nothing is extrapolated: the span is the run
    r.pair = pair;
    r.finer = finer;
    r.observed = pair;
    if (!std::isfinite(finer)) {
        r.observed = kInf;
        return r;
    }
    // At the end, the larger of the pair's difference and the finer pair's times 2^p (SpanRun::ConcludeThird).
    const double predicted = std::pow(2.0, OrderOf(candidate, space)) * finer;
    if (finer > r.noise && predicted > pair) {
        r.observed = predicted;
        r.pairObserved = pair;
    }
    return r;
}

}  // namespace model_choice
