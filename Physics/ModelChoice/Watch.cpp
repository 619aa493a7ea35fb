// The live watch (docs/model-choice.md, "During the run").
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "Physics/ModelChoice/Internals.h"
#include "Physics/ModelChoice/ModelChoice.h"

using namespace model_choice;  // NOLINT: the estimator's internals (Physics/ModelChoice/Internals.h)

ModelWatch::ModelWatch(const CandidateSpace& s, const ErrorBudget& b, const ChoiceSettings& c,
                       const CandidateEstimate& chosen)
    : space(s),
      budget(b),
      settings(c),
      current(chosen.model),
      running(chosen.estimate),
      predicted(chosen.estimate),
      growth(chosen.growth),
      wholeRun(chosen.wholeRun) {}

bool ModelWatch::Due(double time) const {
    if (wholeRun || time >= settings.runSeconds - 1e-9) return false;
    if (eventPending && snapshot) return true;
    const double every = settings.checkEvery > 0.0 ? settings.checkEvery : settings.runSeconds / 6.0;
    return every > 0.0 && time >= lastCheck + every - 1e-9;
}

double ModelWatch::CheckSpan() const { return settings.checkSpanFraction * SpanFor(settings); }

bool ModelWatch::WantsSnapshot(double time) const {
    return !wholeRun && settings.maxEventChecks > 0 && time >= snapshotTime + 0.5 * CheckSpan() - 1e-9 &&
           time < settings.runSeconds - 1e-9;
}

void ModelWatch::TakeSnapshot(double time, ProbeFactory factory) {
    // The one before the newest is kept too: an event is checked from a snapshot at least half a span before it.
    previousSnapshot = std::move(snapshot);
    previousSnapshotTime = snapshotTime;
    snapshot = std::move(factory);
    snapshotTime = time;
}

void ModelWatch::Observe(double time, const PhysicsSystem& world) {
    if (wholeRun) return;
    // Irregularity between frames: the largest change of any point's acceleration times the frame time (m/s; what
    // an impulse does, and what gravity or a smooth spring hardly does).
    const double dt = time - lastObserved;
    if (!(dt > 0.0) && observed > 0) return;  // no step since the last frame
    x0.swap(x1);
    x1.swap(x2);
    WorldPositions(world, &x2);
    // Frames of unequal length (a step that is not a whole number of frames) would read as irregular: the
    // acceleration estimate needs two equal intervals.
    const bool even = std::fabs(dt - lastInterval) <= 1e-6 * dt;
    lastInterval = dt;
    lastObserved = time;
    ++observed;
    if (observed < 3 || x0.size() != x2.size()) return;
    if (!even) {
        acceleration.clear();
        return;
    }
    double jump = 0.0;
    const bool haveAcceleration = acceleration.size() == x2.size();
    if (!haveAcceleration) acceleration.assign(x2.size(), 0.0);
    for (std::size_t i = 0; i < x2.size(); ++i) {
        const double a = (x2[i] - 2.0 * x1[i] + x0[i]) / (dt * dt);
        if (haveAcceleration) jump = std::max(jump, std::fabs(a - acceleration[i]) * dt);
        acceleration[i] = a;
    }
    if (!haveAcceleration) return;
    if (time <= SpanFor(settings) + 1e-9) {
        baseline = std::max(baseline, jump);  // what the calibration span saw
    } else if (jump > 30.0 * baseline && jump > 1e-6 && eventChecks < settings.maxEventChecks && !eventPending) {
        eventPending = true;
        eventTime = time;
    }
}

bool ModelWatch::Check(double time, const ProbeFactory& factory, std::string* log) {
    if (!Due(time)) return false;
    const bool event = eventPending && snapshot;
    double fromTime = time;
    SpanResult w;
    if (!RunCheckSpan(time, event, factory, &fromTime, &w)) return false;
    const double latest = Account(w, event, fromTime, time);
    // The model was chosen with the safety factor's margin; it is changed only when the estimate says the budget
    // itself will be missed (a margin, so a model chosen near the edge does not flip on span-to-span noise).
    if (running <= budget.bound) {
        missed = false;
        return false;
    }
    // Unless the model is refined below, the run misses its budget as things stand (Missed).
    if (!missed) missedAt = time;
    missed = true;
    if (KeepsModel(time, latest, log)) return false;
    return RefineModel(time, event, fromTime, w, log);
}

bool ModelWatch::RunCheckSpan(double time, bool event, const ProbeFactory& factory, double* fromTime, SpanResult* out) {
    const double T = settings.runSeconds;
    // An event is checked from the snapshot taken at least half a span before it, over the rest of the run; a
    // periodic check from the world as it is, for the time since the last check.
    const bool previous = event && previousSnapshot && snapshotTime > eventTime - 0.5 * CheckSpan();
    const ProbeFactory& from = previous ? previousSnapshot : (event ? snapshot : factory);
    *fromTime = event ? (previous ? previousSnapshotTime : snapshotTime) : time;
    // At least four steps measured, so the span's growth is fitted from more than two samples.
    const double span = std::min(T - *fromTime, std::max(CheckSpan(), 4.0 * current.step));
    if (event) {
        eventPending = false;
        ++eventChecks;
    } else {
        lastCheck = time;
    }
    if (!(span > 0.0)) return false;
    // Probes from a live world with volumes lack its contact history (no warm start): they settle first, unmeasured.
    const int warm = space.hasVolumes ? std::max(3, static_cast<int>(span / 3.0 / current.step)) : 0;
    SpanOptions o;
    o.warmSteps = warm;
    o.fixedGrowth = budget.quantity == BudgetQuantity::Position ? -1.0 : growth;
    *out = RunSpan(from, current, space, budget, span, o);
    cpuSeconds += out->probeCpuSeconds;
    work += out->work;
    ++checks;
    return true;
}

double ModelWatch::Account(const SpanResult& w, bool event, double fromTime, double time) {
    const double T = settings.runSeconds;
    const bool ok = w.stable && std::isfinite(w.observed);
    if (budget.quantity == BudgetQuantity::Position) {
        // A periodic span's rate stands for the time since the last check; an event's difference grows over the
        // rest of the run; the calibration's estimate, scaled for refinements since, stands for the rest.
        const double rest = event ? T - fromTime : time - lastCounted;
        if (!event) lastCounted = time;
        // Extrapolated with the span's own growth (a settled stack's jitter does not add up).
        const double latest = ok ? w.factor * w.observed * std::pow(std::max(rest / w.length, 1.0), w.growth) : kInf;
        measured += latest;
        running = measured + predicted * scale * (T - time) / T;
        return latest;
    }
    // Energy and constraint: the span's regime taken as the whole run's (with the calibration's growth), for the
    // current model's share of the run, plus what earlier models left.
    const double estimate = ok ? (budget.quantity == BudgetQuantity::Constraint
                                      ? w.observed
                                      : w.factor * w.observed * std::pow(std::max(T / w.length, 1.0), growth))
                               : kInf;
    lastEstimate = std::max(event ? lastEstimate : 0.0, estimate);
    running = carried + lastEstimate * (T - modelStart) / T;
    return estimate;
}

bool ModelWatch::KeepsModel(double time, double latest, std::string* log) {
    // What earlier spans measured (or earlier models left) is made. While it is under three times the budget,
    // refining still keeps the end near it; beyond, no finer model can: say so once and stop refining (it would
    // only cost).
    const double made = budget.quantity == BudgetQuantity::Position ? measured : carried;
    // A span that itself misses the budget (or blew up) is refined whatever was lost: the model is making large
    // errors now, the way to a blow-up.
    if (made > 3.0 * budget.bound && latest <= budget.bound) {
        if (!lostReported) {
            char text[256];
            std::snprintf(text, sizeof text,
                          "t = %.2f s: the %s error already made, %.3g, exceeds three times the budget %g: a finer "
                          "model cannot undo it, so %s stays (the run misses its budget)",
                          time, ToString(budget.quantity), made, budget.bound,
                          current.Describe(space.hasParticles, space.hasVolumes).c_str());
            *log = text;
            lostReported = true;
        }
        return true;
    }
    // A finer model changes only the current model's part of the estimate: what its latest span adds and the
    // rest of the run it stands for. When that is less than what earlier spans and models left (which no
    // refinement undoes), a refinement would take off less than half of the estimate (a quarter at first order) at
    // twice the cost: the model stays, unless its span itself misses the budget.
    const double currentPart =
        budget.quantity == BudgetQuantity::Position ? latest + (running - measured) : running - carried;
    const double earlier = running - currentPart;
    if (currentPart < earlier && latest <= budget.bound) {
        if (!keptReported) {
            char text[320];
            std::snprintf(text, sizeof text,
                          "t = %.2f s: estimated %s error at the end %.3g exceeds the budget %g, but %.3g of it was "
                          "made before this check and %s adds %.3g: a finer model would take off little, so it stays",
                          time, ToString(budget.quantity), running, budget.bound, earlier,
                          current.Describe(space.hasParticles, space.hasVolumes).c_str(), currentPart);
            *log = text;
            keptReported = true;
        }
        return true;
    }
    return false;
}

bool ModelWatch::RefineModel(double time, bool event, double fromTime, const SpanResult& w, std::string* log) {
    const double T = settings.runSeconds;
    // Refine within the family: the next smaller step the space allows, else more passes.
    ModelCandidate next = current;
    double smaller = 0.0;
    for (double st : space.steps) {
        if (st < current.step - 1e-12 && st > smaller) smaller = st;
    }
    const std::vector<int>& passList = current.solver == ContactSolver::Soft ? space.softSubsteps : space.iterations;
    int morePasses = 0;
    for (int p : passList) {
        if (p > Passes(current) && (morePasses == 0 || p < morePasses)) morePasses = p;
    }
    double ratio = 1.0;  // predicted error ratio of the refinement to the current model
    if (smaller > 0.0) {
        next.step = smaller;
        ratio = std::pow(smaller / current.step, OrderOf(current, space));
    } else if (space.hasVolumes && morePasses > 0) {
        (current.solver == ContactSolver::Soft ? next.softSubsteps : next.iterations) = morePasses;
        ratio = static_cast<double>(Passes(current)) / morePasses;
    } else {
        char text[256];
        std::snprintf(text, sizeof text,
                      "t = %.2f s: estimated %s error at the end %.3g exceeds the budget %g, and %s has no finer "
                      "setting on this host",
                      time, ToString(budget.quantity), running, budget.bound,
                      current.Describe(space.hasParticles, space.hasVolumes).c_str());
        *log = text;
        return false;
    }
    char text[400];
    std::snprintf(text, sizeof text,
                  "t = %.2f s: estimated %s error at the end %.3g exceeds the budget %g (%s %.3g s from t = %.2f s "
                  "differ by %.3g from the refinement): switching from %s to %s",
                  time, ToString(budget.quantity), running, budget.bound, event ? "an impact: the" : "the last",
                  w.length, fromTime, w.observed, current.Describe(space.hasParticles, space.hasVolumes).c_str(),
                  next.Describe(space.hasParticles, space.hasVolumes).c_str());
    *log = text;
    current = next;
    missed = false;
    ++switches;
    scale *= ratio;
    carried += lastEstimate * (time - modelStart) / T;
    modelStart = time;
    return true;
}
