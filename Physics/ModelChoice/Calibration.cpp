// One span of probes (docs/model-choice.md, "What is estimated"): the candidate, its refinement and, over a whole
// run or for the convergence check, the refinement's refinement, run side by side from one state.
#include <cfloat>
#include <cmath>
#include <memory>

#include "Physics/ModelChoice/Internals.h"
#include "Physics/PhysicsSystem.h"

namespace model_choice {
double ProcessCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Formal order of accuracy of a candidate on a space: contact (volumes or particles bouncing off constraints) is
/// non-smooth, and the book joint's projection after the integrator's step is a first-order splitting, so first order;
/// otherwise (tension joints included) the integrator's.
int OrderOf(const ModelCandidate& c, const CandidateSpace& space) {
    if (space.hasVolumes || space.hasContacts || space.hasJoints) return 1;
    if (space.hasTensionJoints && c.integrator == Integrator::PositionVerlet) return 1;
    switch (c.integrator) {
        case Integrator::ExplicitEuler:
        case Integrator::SemiImplicitEuler:
            return 1;
        case Integrator::VelocityVerlet:
        case Integrator::PositionVerlet:
            return 2;
        case Integrator::RK4:
            return 4;
    }
    return 1;
}

/// Richardson factor: with the refinement's error 2^-p of the candidate's, the candidate's error is the
/// difference times 1 / (1 - 2^-p).
double RichardsonFactor(int order) { return 1.0 / (1.0 - std::pow(0.5, order)); }

/// The budget's quantity between a candidate's probe and its refinement's (or of the candidate alone, for
/// constraint error, which is observed, not estimated).
struct QuantityProbe {
    BudgetQuantity quantity;
    double energyScale = 1.0;  // J: |E0| of the span's start (floored)
    std::vector<double> a, b;
    // The difference at the end of a warm-up, taken off every later one (Rebase).
    bool based = false;
    std::vector<double> baseDelta;
    double baseEnergy = 0.0;

    double Measure(const ModelProbe& coarse, const ModelProbe* fine) {
        switch (quantity) {
            case BudgetQuantity::Position: {
                WorldPositions(coarse.World(), &a);
                WorldPositions(fine->World(), &b);
                double worst = 0.0;
                const std::size_t n = std::min(a.size(), b.size());
                for (std::size_t i = 0; i + 2 < n; i += 3) {
                    double d[3];
                    for (int c = 0; c < 3; ++c) d[c] = a[i + c] - b[i + c] - (based ? baseDelta[i + c] : 0.0);
                    worst = std::max(worst, std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
                }
                return worst;
            }
            case BudgetQuantity::Energy:
                return std::fabs(WorldEnergy(coarse.World()) - WorldEnergy(fine->World()) - baseEnergy) / energyScale;
            case BudgetQuantity::Constraint:
                return WorldConstraintError(coarse.World());
        }
        return kInf;
    }

    /// Takes the current difference as the zero of later ones.
    void Rebase(const ModelProbe& coarse, const ModelProbe* fine) {
        if (quantity == BudgetQuantity::Position) {
            WorldPositions(coarse.World(), &a);
            WorldPositions(fine->World(), &b);
            baseDelta.assign(std::min(a.size(), b.size()), 0.0);
            for (std::size_t i = 0; i < baseDelta.size(); ++i) baseDelta[i] = a[i] - b[i];
        } else if (quantity == BudgetQuantity::Energy) {
            baseEnergy = WorldEnergy(coarse.World()) - WorldEnergy(fine->World());
        }
        based = true;
    }
};

/// The level at which a difference is rounding (float states): relative for energy, scaled by the largest
/// coordinate (at least 1 m) for positions and joints. Each step rounds a position to its float, by up to half a
/// unit in its last place; a step that adds the same small travel each time rounds the same way each time, so over
/// `steps` steps the rounding can add up to steps / 2 such units (a projectile at 30 m over 10^5 steps: 0.2 m).
double ConvergenceNoise(BudgetQuantity quantity, const std::vector<double>& positions, double steps) {
    double scale = 1.0;
    if (quantity != BudgetQuantity::Energy) {
        for (double x : positions) scale = std::max(scale, std::fabs(x));
    }
    return (32.0 + 0.5 * std::max(steps, 0.0)) * FLT_EPSILON * scale;
}

/// Steps a candidate's positions are advanced by per simulated second: the soft solver on volumes moves them once
/// per substep.
bool Unrefined(const CandidateSpace& space, long long candidateUpdates, long long refinedUpdates) {
    return space.hasVolumes && candidateUpdates > 0 && 2 * refinedUpdates < 3 * candidateUpdates;
}

double UpdatesPerSecond(const ModelCandidate& c, const CandidateSpace& space) {
    const bool substeps = space.hasVolumes && c.solver == ContactSolver::Soft;
    return (substeps ? static_cast<double>(c.softSubsteps) : 1.0) / c.step;
}

bool JudgedAtEnd(const SpanOptions& o, const ErrorBudget& budget, const CandidateSpace& space) {
    return o.wholeRun && budget.quantity != BudgetQuantity::Constraint &&
           !(budget.quantity == BudgetQuantity::Position && space.impactsTimedInStep);
}

/// The refinement a span uses: Refine, or half the step (`byStep`: the convergence check along the step).
ModelCandidate RefineFor(const ModelCandidate& c, const CandidateSpace& space, bool byStep) {
    if (!byStep) return Refine(c, space);
    ModelCandidate r = c;
    r.step = c.step * 0.5;
    return r;
}

/// One span: the candidate and (unless the quantity is observed directly) its refinement run from the same
/// state for `span` seconds, sampled at up to 256 whole-step times (an oscillation must not hide between
/// samples). `warmSteps` steps of the candidate first run unmeasured, and the difference at their end is taken off
/// the later ones: probes built from a mid-run state of a world with volumes lack its contact history (no warm
/// start), so they first settle.
/// Over the whole run (`wholeRun`) a third probe at a quarter of the step runs beside them. An energy or position
/// budget is then the difference at the end, where the budget bounds it and where a user reads the run's last row,
/// not the largest over the run: two runs whose impacts fall a step apart differ by a whole bounce mid-run, which
/// says nothing about where either ends. One difference at one time can be small by chance (an impact falling at
/// the same place within both steps), so the finer pair's difference at the end, times 2^p (what it predicts for the
/// coarser pair when the error has order p), is taken when it is larger, and the convergence check (CheckOrder)
/// compares the two pairs.
/// A span with `missBound` > 0 stops at the first sample whose difference, with the Richardson factor, already
/// exceeds it: the span's contribution can only be larger (its growth is at least 0), so the candidate misses,
/// and what is left of the span would only say by how much. Its result is then that lower bound (`missedAt`).
/// RunSpan's state: the candidate, its refinement and, for a whole run or SpanOptions::third, the refinement's own
/// refinement, run side by side from one state, and the differences they made so far.
class SpanRun {
public:
    SpanRun(const ProbeFactory& factory, const ModelCandidate& c, const CandidateSpace& sp, const ErrorBudget& b,
            double span, const SpanOptions& options)
        : candidate(c), space(sp), budget(b), o(options) {
        start = ProcessCpuSeconds();
        if (o.clock) o.clock->StartPiece();
        coarse = factory();
        coarse->Apply(candidate);
        observed = budget.quantity == BudgetQuantity::Constraint;
        refined = RefineFor(candidate, space, o.byStep);
        refinedTwice = RefineFor(refined, space, o.byStep);
        if (!observed) {
            fine = factory();
            fine->Apply(refined);
        }
        third = (o.wholeRun || o.third) && !observed;
        // A whole run is judged where the budget bounds it, at the end (energy and position; constraint error is
        // observed). Not a position budget whose impacts are timed inside their step (impactsTimedInStep): there
        // two runs' impacts fall at nearly the same time, so the largest difference over the run is a measure as
        // for a smooth motion, and the end alone is not one, where coarse probes whose bounces died down early all
        // rest on the surface together while the answer still bounces.
        atEnd = JudgedAtEnd(o, budget, space);
        if (third) {
            finest = factory();
            finest->Apply(refinedTwice);
        }
        q = QuantityProbe{budget.quantity, 1.0, {}, {}, false, {}, 0.0};
        if (budget.quantity == BudgetQuantity::Energy) {
            q.energyScale = std::max(std::fabs(WorldEnergy(coarse->World())), 1e-12);
        }
        q2 = q;  // the refinement against the third probe
        warm = observed ? 0 : o.warmSteps;
        measured = std::max(2LL, std::llround(span / candidate.step));
        samples = static_cast<int>(std::min<long long>(256, measured));
    }

    /// Runs the warm-up and the measured part (up to a miss, the CPU limit or a blow-up) and says what it found.
    SpanResult Run() {
        Measure();
        Account();
        if (!ok) return r;
        return Conclude();
    }

private:
    bool Advance(double t) {
        if (!coarse->AdvanceTo(t)) {
            r.stable = false;
            return false;
        }
        if ((!observed && !fine->AdvanceTo(t)) || (finest && !finest->AdvanceTo(t))) {
            r.observed = kInf;  // the refinement blew up but the candidate did not: no estimate can be trusted
            return false;
        }
        return true;
    }

    void Measure() {
        if (warm > 0) {
            ok = Advance(candidate.step * static_cast<double>(warm));
            if (ok) q.Rebase(*coarse, fine.get());
        }
        reached = warm;
        own = PredictedWork(candidate, space);
        perSecond =
            own + (observed ? 0.0 : PredictedWork(refined, space)) + (third ? PredictedWork(refinedTwice, space) : 0.0);
        factor = observed ? 1.0 : RichardsonFactor(OrderOf(candidate, space));
        for (int s = 1; ok && s <= samples; ++s) {
            reached = warm + (measured * s) / samples;
            ok = Advance(candidate.step * static_cast<double>(reached));
            if (!ok) break;
            const double d = q.Measure(*coarse, fine.get());
            if (!std::isfinite(d)) {
                r.stable = false;
                ok = false;
                break;
            }
            full = std::max(full, d);
            last = d;
            if (third && !atEnd) finer = std::max(finer, q2.Measure(*fine, finest.get()));
            if (2 * s <= samples) half = full;
            if (o.missBound > 0.0 && !atEnd && s < samples && factor * full > o.missBound) {
                r.missedAt = candidate.step * static_cast<double>(reached - warm);
                break;
            }
            if (o.clock && s < samples &&
                o.clock->Poll(start, candidate.step * static_cast<double>(reached) * perSecond)) {
                r.stopped = true;
                break;
            }
        }
    }

    /// The span's cost: CPU, simulated time, share, work, and the rounding level of its finest probe.
    void Account() {
        r.probeCpuSeconds = ProcessCpuSeconds() - start;
        r.simulated = candidate.step * static_cast<double>(reached);
        r.share = static_cast<double>(reached) / static_cast<double>(warm + measured);
        r.work = r.simulated * perSecond;
        // The candidate's part of the span's CPU, by predicted work: the thread's CPU clock is a system call (about
        // 0.25 us), and reading it around every sample's advance was half a microsecond problem's calibration (the
        // projectile's: 69 us with it, 36 us without).
        r.cpuSeconds = r.probeCpuSeconds * own / perSecond;
        if (o.clock) o.clock->Add(r.probeCpuSeconds, r.work);
        // The finest probe that ran sets the rounding level: it made the most steps.
        const ModelCandidate& finestRun = third ? refinedTwice : refined;
        r.noise =
            ConvergenceNoise(budget.quantity, q.b, observed ? 0.0 : r.simulated * UpdatesPerSecond(finestRun, space));
    }

    SpanResult Conclude() {
        const double length = candidate.step * static_cast<double>(measured);
        r.observed = full;
        r.length = length;
        r.factor = factor;
        if (!observed && Unrefined(space, coarse->VolumeUpdates(), fine->VolumeUpdates())) {
            r.noEstimate = kUnrefined;
            r.observed = kInf;
            return r;
        }
        if (r.missedAt >= 0.0 || r.stopped) {
            r.growth = 0.0;  // a lower bound: the difference so far, nothing extrapolated
            return r;
        }
        // Growth in time, fitted from the measured part's halves, 0 (bounded: a symplectic integrator's energy
        // error, a stack that settled) to 1 (a drift: a phase error, a velocity bias). Nothing is extrapolated
        // faster than linearly: an instability starting is left to the live checks.
        double growth = 1.0;
        if (full > 0.0 && half > 0.0) growth = std::clamp(std::log2(full / half), 0.0, 1.0);
        if (o.fixedGrowth >= 0.0) growth = o.fixedGrowth;
        r.growth = growth;
        if (third) ConcludeThird();
        return r;
    }

    /// With a third probe: the finer pair's difference, times 2^p, where it says more than the candidate's own.
    void ConcludeThird() {
        if (atEnd) finer = q2.Measure(*fine, finest.get());
        if (!std::isfinite(finer)) {
            r.observed = kInf;  // as a refinement that blew up: the candidate itself ran
            return;
        }
        const double predicted = std::pow(2.0, OrderOf(candidate, space)) * finer;
        const double pair = atEnd ? last : full;
        r.pair = pair;
        r.finer = finer;
        r.observed = pair;
        // At the end: the larger. Over a span: the finer pair only when it differs more (the error is not
        // shrinking). A finer pair within rounding says nothing about the candidate's truncation error: its
        // difference is the finer probes' rounding (they make the most steps), not a prediction.
        if (finer > r.noise && ((atEnd && predicted > pair) || (!atEnd && finer > full))) {
            r.observed = predicted;
            r.pairObserved = pair;
        }
        r.growth = 0.0;  // nothing is extrapolated: the span is the run
    }

    const ModelCandidate& candidate;
    const CandidateSpace& space;
    const ErrorBudget& budget;
    const SpanOptions& o;
    SpanResult r;
    bool observed = false, third = false, atEnd = false, ok = true;
    ModelCandidate refined, refinedTwice;
    std::unique_ptr<ModelProbe> coarse, fine, finest;
    QuantityProbe q, q2;
    long long warm = 0, measured = 0, reached = 0;
    int samples = 0;
    double start = 0.0, own = 0.0, perSecond = 0.0, factor = 1.0;
    double half = 0.0, full = 0.0;  // running maximum at the measured part's middle and end
    double finer = 0.0;             // the third probe's: the largest over the run of the finer pair's difference
    double last = 0.0;              // the difference at the end
};

SpanResult RunSpan(const ProbeFactory& factory, const ModelCandidate& candidate, const CandidateSpace& space,
                   const ErrorBudget& budget, double span, const SpanOptions& o) {
    // Shared whole runs keep each run's state at its ends only: for a span judged at its end.
    if (JudgedAtEnd(o, budget, space) && o.clock && o.clock->SharesWholeRuns()) {
        return RunWholeShared(factory, candidate, space, budget, span, o);
    }
    return SpanRun(factory, candidate, space, budget, span, o).Run();
}

double SpanFor(const ChoiceSettings& s) {
    return std::min(s.runSeconds, std::clamp(s.spanFraction * s.runSeconds, s.minSpan, s.maxSpan));
}

/// Candidates of the same family (integrator and solver) that differ only in step and passes.
bool SameFamily(const ModelCandidate& a, const ModelCandidate& b) {
    return a.integrator == b.integrator && a.solver == b.solver;
}

int Passes(const ModelCandidate& c) { return c.solver == ContactSolver::Soft ? c.softSubsteps : c.iterations; }

}  // namespace model_choice
