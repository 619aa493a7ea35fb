#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "Physics/ModelChoice/Internals.h"
#include "Physics/ModelChoice/ModelChoice.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"

using namespace model_choice;  // NOLINT: this file's own internals (Physics/ModelChoice/Internals.h)

namespace {

/// A span, from `factory`'s state at `start` s: the calibration's at the start, or the watch's around an event.
struct PlannedSpan {
    enum class Kind { Start, Event };
    Kind kind = Kind::Start;
    ProbeFactory factory;
    double start = 0.0;
    double rest = 0.0;  ///< s of the run that follows the span's start
    int warmSteps = 0;
};

/// The run's impacts, from the pilot's irregularity per interval (`jump`: the largest change of a point's
/// acceleration times the step in each): intervals ten times more irregular than the median interval (free flight
/// between bounces: rounding). A run whose every interval is alike (a smooth spring) has none.
int Impacts(std::vector<double> jump) {
    if (jump.empty()) return 0;
    const std::vector<double> all = jump;
    std::nth_element(jump.begin(), jump.begin() + static_cast<std::ptrdiff_t>(jump.size() / 2), jump.end());
    const double median = jump[jump.size() / 2];
    int count = 0;
    for (double j : all) count += j > 10.0 * median && j > 1e-6 ? 1 : 0;
    return count;
}

/// Still flying near the pilot's end: its fastest point over the last interval (`speed`, m/s: not at the end alone,
/// where a bounce can be at its apex) is faster than a hop of the contact offset's height under the strongest
/// gravity; slower, a particle rests at the contact's resting height, the model's own (RaiseToImpactTiming).
bool Flying(const PhysicsSystem& world, double speed, const CandidateSpace& space) {
    double g = 0.0;
    for (const Particle* p : world.Particles()) g = std::max(g, static_cast<double>(Magnitude(p->GetGravity())));
    return speed > std::sqrt(2.0 * g * space.contactOffset);
}

/// What the pilot run saw of its particles' impacts (RaiseToImpactTiming).
struct PilotImpacts {
    double speed = 0.0;         ///< m/s: the impacts' count times the fastest point's speed at the pilot's end
    bool flying = false;        ///< an impact seen and a particle still flying over the pilot's last interval
    double offsetEnergy = 0.0;  ///< an impact seen: OffsetEnergyShare, else 0
};

/// The potential energy of every particle raised by the contact offset, over the world's energy (the energy
/// budget's scale, as the calibration's QuantityProbe takes it): what a particle that hit a constraint and flies or
/// rests CandidateSpace::contactOffset off the surface is off the rigid answer's energy, whatever the step.
double OffsetEnergyShare(const PhysicsSystem& world, const CandidateSpace& space) {
    double raised = 0.0;
    for (const Particle* p : world.Particles())
        raised += static_cast<double>(p->GetMass()) * Magnitude(p->GetGravity()) * space.contactOffset;
    return raised / std::max(std::fabs(WorldEnergy(world)), 1e-12);
}

/// `plan` with a span over the first contact of a world of several volumes that starts in free flight, if any
/// (FindContactOnset).
std::vector<PlannedSpan> WithOnsetSpan(std::vector<PlannedSpan> plan, const ProbeFactory& factory,
                                       const CandidateSpace& space, const ChoiceSettings& settings, double span,
                                       ModelChoiceResult* result, ChoiceClock* clock) {
    const ContactOnset o = FindContactOnset(factory, space, settings, span, result, clock);
    if (o.start > 0.0) plan.push_back({PlannedSpan::Kind::Event, o.from, o.start, settings.runSeconds - o.start, 0});
    return plan;
}

/// The calibration's spans: one at the start and, for a world without volumes, up to settings.eventSpans around
/// events the start span cannot see (a bounce, a cloth reaching an obstacle), from snapshots of a pilot run of the
/// scene's own model over the whole run. Particles restart exactly from a snapshot; volumes would lose their contact
/// history (and the scene's own model may let a stack fall), so their events are left to the live watch, except a
/// world of several volumes that starts in free flight: its first contact gets a span from a snapshot taken before
/// anything touched (FindContactOnset), which has no contact history to lose. Each
/// step's irregularity is the largest change of any point's acceleration times the step (m/s: what an impulse does,
/// and what gravity or a smooth spring hardly does); the run is cut into intervals of half a span, and an interval
/// ten times more irregular than any the start span covers gets a span from the snapshot of the interval before.
std::vector<PlannedSpan> PlanSpans(const ProbeFactory& factory, const CandidateSpace& space,
                                   const ChoiceSettings& settings, double span, ModelChoiceResult* result,
                                   ChoiceClock* clock, PilotImpacts* impacted) {
    using Kind = PlannedSpan::Kind;
    const double T = settings.runSeconds;
    std::vector<PlannedSpan> plan{{Kind::Start, factory, 0.0, T, 0}};
    const double interval = span / 2.0;
    const int intervals = static_cast<int>(std::ceil(T / interval - 1e-9));
    if (settings.eventSpans <= 0 || intervals < 4) return plan;
    if (space.hasVolumes) return WithOnsetSpan(std::move(plan), factory, space, settings, span, result, clock);
    const double start = ProcessCpuSeconds();
    clock->StartPiece();
    clock->Candidate(0.0, "the pilot run of the scene's own model");
    std::unique_ptr<ModelProbe> pilot = factory();
    pilot->Apply(space.base);
    const double offsetEnergy = OffsetEnergyShare(pilot->World(), space);
    const double h = space.base.step;
    std::vector<ProbeFactory> snapshots{factory};  // at k * interval
    std::vector<double> jump(static_cast<std::size_t>(intervals), 0.0);
    std::vector<double> x0, x1, x2, a1;  // positions two steps back, one back, now; the last acceleration
    long long n = 0;
    bool haveA = false;
    double late = 0.0;  // m/s: the fastest point over the pilot's last interval
    // The pilot covers at most 50 spans (all of a run up to 10 s at the 0.2 s floor; the first 100 s of a long one).
    const double pilotEnd = std::min(T, 50.0 * span);
    while ((n + 1) * h <= pilotEnd * (1.0 + 1e-12)) {
        if (!pilot->AdvanceTo((n + 1) * h)) break;  // the scene's own model blew up: plan from what came before
        ++n;
        // Past the choice's CPU limit: plan from what came before (the choice then stops; ChooseModel).
        if (clock->Poll(start, PredictedWork(space.base, space) * static_cast<double>(n) * h)) break;
        const double t = n * h;
        x0.swap(x1);
        x1.swap(x2);
        WorldPositions(pilot->World(), &x2);
        if (t > pilotEnd - interval) late = std::max(late, FastestPoint(x2, x1, h));
        const std::size_t k = static_cast<std::size_t>(std::min(intervals - 1, static_cast<int>(t / interval)));
        if (n >= 3 && x0.size() == x2.size()) {
            double worst = 0.0;
            if (a1.size() != x2.size()) a1.assign(x2.size(), 0.0);
            for (std::size_t i = 0; i < x2.size(); ++i) {
                const double a = (x2[i] - 2.0 * x1[i] + x0[i]) / (h * h);
                if (haveA) worst = std::max(worst, std::fabs(a - a1[i]) * h);
                a1[i] = a;
            }
            haveA = true;
            jump[k] = std::max(jump[k], worst);
        }
        if (t >= static_cast<double>(snapshots.size()) * interval - 1e-9 &&
            static_cast<int>(snapshots.size()) < intervals) {
            snapshots.push_back(pilot->Snapshot());
        }
    }
    const int impacts = Impacts(jump);
    impacted->speed = static_cast<double>(impacts) * FastestPoint(x2, x1, h);  // the fastest point at the pilot's end
    impacted->flying = impacts > 0 && Flying(pilot->World(), late, space);
    impacted->offsetEnergy = impacts > 0 ? offsetEnergy : 0.0;
    const double seen = std::max(jump[0], jump[1]);  // what the start span covers
    std::vector<int> picked;
    for (int e = 0; e < settings.eventSpans; ++e) {
        int best = -1;
        for (int k = 2; k < intervals; ++k) {
            bool near = false;  // picked spans cover two intervals each, never twice
            for (int p : picked) near = near || std::abs(p - k) < 2;
            if (near || k - 1 >= static_cast<int>(snapshots.size())) continue;
            if (jump[k] > 10.0 * seen && jump[k] > 1e-6 && (best < 0 || jump[k] > jump[best])) best = k;
        }
        if (best < 0) break;
        picked.push_back(best);
    }
    std::sort(picked.begin(), picked.end());
    for (int k : picked) {
        const double begin = (k - 1) * interval;
        plan.push_back({Kind::Event, snapshots[static_cast<std::size_t>(k - 1)], begin, T - begin, 0});
        result->eventTimes.push_back(begin);
    }
    AccountPilot(ProcessCpuSeconds() - start, PredictedWork(space.base, space) * static_cast<double>(n) * h, result,
                 clock);
    return plan;
}

/// What one span adds to a candidate's estimate: its difference extrapolated over the run after its start with
/// its fitted growth (a bounce at another time leaves a drift behind, growth near 1; a transient that settled, near
/// 0). Constraint error is observed, not extrapolated.
double Contribution(const PlannedSpan& p, const SpanResult& w, const ErrorBudget& budget) {
    if (budget.quantity == BudgetQuantity::Constraint) return w.observed;
    return w.factor * w.observed * std::pow(std::max(p.rest / w.length, 1.0), w.growth);
}

/// The convergence check (ChoiceSettings::orderBand): a candidate's error must shrink with its step at the order
/// p its estimate assumes, so its difference from its refinement (`pair`) must be about 2^p times its refinement's
/// from its own (`finer`), at least 2^(p - band). A finer pair within rounding (`noise`, which grows with the steps its
/// finest probe made) passes, marked withinRounding (RaiseToFamilyFloor then holds it to its family). A candidate that
/// fails is marked unreliable with the figures in its note, and is never chosen: its estimate assumed an order its
/// error does not have.
void CheckOrder(double pair, double finer, double noise, const CandidateSpace& space, const ChoiceSettings& settings,
                const char* over, CandidateEstimate* e) {
    e->pairDifference = pair;
    e->finerDifference = finer;
    const int p = OrderOf(e->model, space);
    const double least = std::pow(2.0, p - settings.orderBand);
    if (std::isfinite(pair) && std::isfinite(finer) && pair >= least * finer) return;
    if (std::isfinite(pair) && std::isfinite(finer) && finer <= noise) {
        e->withinRounding = true;
        return;
    }
    e->unreliable = true;
    char text[320];
    std::snprintf(text, sizeof text,
                  "unreliable: its error does not shrink at order %d (%s: it differs from its refinement by %.3g, "
                  "the refinement from its own by %.3g: ratio %.3g, order %d needs at least %.3g)",
                  p, over, pair, finer, finer > 0.0 ? pair / finer : kInf, p, least);
    e->note = text;
}

/// Whether a candidate is estimated over the whole run: a cheap world without volumes, or with one (no stack to
/// topple: a whole run is a measurement, not a chaotic divergence), whose candidate, refinement and third probe
/// (a quarter of the step) fit the choice's whole-run work.
bool WholeRunFits(const ModelCandidate& model, const ModelCandidate& fine, bool refined, const CandidateSpace& space,
                  const ChoiceSettings& settings) {
    if ((space.hasVolumes && space.volumeCount > 1.0) || !(settings.wholeRunWork > 0.0)) return false;
    const double probes = PredictedWork(model, space) +
                          (refined ? PredictedWork(fine, space) + PredictedWork(Refine(fine, space), space) : 0.0);
    return settings.runSeconds * probes <= settings.wholeRunWork;
}

/// A whole-run estimate's note (raised by the third probe or not) and its order check on the start span's pair.
void FinishWholeRun(const SpanResult& first, double raisedFrom, const CandidateSpace& space,
                    const ChoiceSettings& settings, CandidateEstimate* e) {
    if (e->stoppedAtLimit) return;  // the note says so
    if (e->stable && std::isfinite(e->estimate) && raisedFrom < 0.0) {
        e->note = "measured over the whole run";
    } else if (e->stable && std::isfinite(e->estimate)) {
        char text[128];
        std::snprintf(text, sizeof text,
                      "measured over the whole run; raised from %.3g by the finer pair (a quarter step)", raisedFrom);
        e->note = text;
    }
    if (e->stable && !e->partial && std::isfinite(e->estimate) && first.pair >= 0.0) {
        const bool alongSubsteps = Refine(e->model, space).step == e->model.step;
        CheckOrder(first.pair, first.finer, first.noise, space, settings,
                   alongSubsteps ? "over the whole run, doubling its substeps" : "over the whole run", e);
    }
}

/// A candidate's estimate: the sum of its spans' contributions (constraint error: the largest). Stops as soon as
/// it misses `bound` (the rest can only add), marking the estimate partial (a lower bound).
void Evaluate(const std::vector<PlannedSpan>& plan, double span, const CandidateSpace& space, const ErrorBudget& budget,
              const ChoiceSettings& settings, double bound, CandidateEstimate* e, double* cpuSeconds, double* work,
              ChoiceClock* clock) {
    e->estimate = 0.0;
    e->share = 0.0;
    e->segments.clear();
    double cpu = 0.0, simulated = 0.0;
    // Over the whole run (WholeRunFits): the candidate, its refinement and a third probe at a quarter of the step
    // run the whole run from the start, and the largest difference sampled over it, with the Richardson factor, is the
    // estimate (constraint error: the largest seen on the candidate alone). Not the position difference at the end:
    // there a bounce that died down leaves both at rest on the ground, and a spring is back near a turning point.
    // Energy is bounded at the end and is measured there. The third probe checks either (RunSpan). The start span then
    // spans the whole run: its contribution is its difference, nothing extrapolated.
    const bool refined = budget.quantity != BudgetQuantity::Constraint;
    const ModelCandidate fine = Refine(e->model, space);
    e->wholeRun = WholeRunFits(e->model, fine, refined, space, settings);
    double raisedFrom = -1.0;  // the pair's own estimate, when the third probe raised it
    SpanResult first;          // the start span (the whole run's convergence figures)
    const std::vector<PlannedSpan> whole{plan[0]};
    const std::vector<PlannedSpan>& spans = e->wholeRun ? whole : plan;
    const double length = e->wholeRun ? settings.runSeconds : span;
    for (std::size_t k = 0; k < spans.size(); ++k) {
        // A span stops as soon as its own difference misses (RunSpan); a whole run does not, as its estimate
        // is what a finer rung of its family is floored by (RaiseToFamilyFloor), and a lower bound is not.
        SpanOptions o;
        o.warmSteps = spans[k].warmSteps;
        o.wholeRun = e->wholeRun;
        o.missBound = e->wholeRun || !settings.stopSpansAtMiss ? -1.0 : bound;
        o.clock = clock;
        const SpanResult w = RunSpan(spans[k].factory, e->model, space, budget, length, o);
        *cpuSeconds += w.probeCpuSeconds;
        *work += w.work;
        e->share += w.share / static_cast<double>(spans.size());
        cpu += w.cpuSeconds;
        simulated += w.simulated;
        if (k == 0) first = w;
        if (w.stopped) {
            e->partial = true;
            e->stoppedAtLimit = true;
            e->estimate += w.factor * w.observed;
            e->note = "stopped at the choice's CPU limit";
            break;
        }
        if (!w.stable || !std::isfinite(w.observed)) {
            e->stable = w.stable;
            e->estimate = kInf;
            e->note = w.stable ? w.noEstimate : "unstable in the calibration";
            break;
        }
        if (k == 0) e->growth = w.growth;
        if (w.pairObserved >= 0.0) raisedFrom = w.factor * w.pairObserved;
        const double c = Contribution(spans[k], w, budget);
        e->segments.push_back(c);
        e->estimate = budget.quantity == BudgetQuantity::Constraint ? std::max(e->estimate, c) : e->estimate + c;
        // Missed already, within this span or after it: the rest can only add (a lower bound).
        if (w.missedAt >= 0.0 || (e->estimate > bound && k + 1 < spans.size())) {
            e->partial = true;
            char text[96];
            if (w.missedAt >= 0.0) {
                std::snprintf(text, sizeof text, "missed %.3g s into span %zu of %zu", w.missedAt, k + 1, spans.size());
            } else {
                std::snprintf(text, sizeof text, "missed after %zu of %zu spans", k + 1, spans.size());
            }
            e->note = text;
            break;
        }
    }
    if (e->wholeRun) FinishWholeRun(first, raisedFrom, space, settings, e);
    e->cpuPerSimSecond = simulated > 0.0 ? cpu / simulated : 0.0;
}

/// The convergence checks of a candidate that meets the budget (CheckOrder). Estimated on spans: its start span
/// again with the refinement's refinement beside the pair (seven of its spans; event spans are not repeated).
/// Measured over the whole run, the pair was checked there (Evaluate). Where the refinement is not half the step (the
/// soft solver on a world of volumes doubles its substeps), the error must also shrink with the step itself: the
/// candidate, half its step and a quarter, same substeps, over the same span. A check cut short by the choice's CPU
/// limit leaves the candidate unchecked, so it is not chosen.
void VerifyOrder(const PlannedSpan& start, double span, const CandidateSpace& space, const ErrorBudget& budget,
                 const ChoiceSettings& settings, CandidateEstimate* e, double* cpuSeconds, double* work,
                 ChoiceClock* clock) {
    if (budget.quantity == BudgetQuantity::Constraint) return;
    const bool alongSubsteps = Refine(e->model, space).step == e->model.step;
    for (int pass = 0; pass < 2 && !e->unreliable; ++pass) {
        const bool byStep = pass == 1;
        if ((pass == 0 && e->wholeRun) || (byStep && !alongSubsteps)) continue;
        SpanOptions o;
        o.warmSteps = start.warmSteps;
        o.wholeRun = e->wholeRun;
        o.third = true;
        o.clock = clock;
        o.byStep = byStep;
        const SpanResult w =
            RunSpan(start.factory, e->model, space, budget, e->wholeRun ? settings.runSeconds : span, o);
        *cpuSeconds += w.probeCpuSeconds;
        *work += w.work;
        if (w.stopped) {
            e->partial = true;
            e->stoppedAtLimit = true;
            e->note = "its convergence check stopped at the choice's CPU limit";
            return;
        }
        const bool ok = w.stable && std::isfinite(w.observed) && w.pair >= 0.0;
        const char* over =
            byStep ? (e->wholeRun ? "over the whole run, halving its step" : "over the start span, halving its step")
                   : (alongSubsteps ? "over the start span, doubling its substeps" : "over the start span");
        const double before = e->estimate;
        CheckOrder(ok ? w.pair : kInf, ok ? w.finer : kInf, w.noise, space, settings, over, e);
        // Along the step, the pair's difference is the step's part of the error, which doubling the substeps did
        // not see: the estimate is at least that part with its Richardson factor (over a span, extrapolated as
        // the start span was).
        const double stepPart =
            e->wholeRun ? w.factor * w.pair : w.factor * w.pair * std::pow(std::max(start.rest / span, 1.0), e->growth);
        if (byStep && !e->unreliable && stepPart > before) {
            char text[200];
            std::snprintf(text, sizeof text, "raised from %.3g: half its step differs by %.3g (%s)", before, w.pair,
                          e->wholeRun ? "over the whole run" : "over the start span");
            e->estimate = stepPart;
            e->note = text;
        }
    }
}

/// A span estimate can miss what a whole run sees (a period error that grows past the span, an impact a
/// cloth's spans fall short of), and a whole run whose finer pair is within rounding (withinRounding) showed no
/// order at all. When coarser steps of the candidate's family, with the same passes, were measured
/// over the whole run, the candidate's error is taken to be at least what the nearest of them predicts. The order
/// of that prediction is the one the family showed between its two nearest such rungs, kept between 1 and the
/// formal order (a joint's projection makes RK4 first order; one rung alone, or errors that did not shrink, give
/// 1): an error shrinks no faster than that as the step does. The note says when the floor raised the estimate.
void RaiseToFamilyFloor(const std::vector<CandidateEstimate>& candidates, const std::vector<std::size_t>& order,
                        std::size_t k, const CandidateSpace& space, CandidateEstimate* e) {
    if ((e->wholeRun && !e->withinRounding) || !e->stable || !std::isfinite(e->estimate)) return;
    const FamilyPrediction f = FamilyFloor(candidates, order, k, space, e);
    const double floor = f.floor;
    if (floor <= e->estimate) return;
    char text[192];
    std::snprintf(text, sizeof text,
                  "raised from %.3g: its family's dt %g s, measured over the whole run, predicts %.3g (order %.2g)",
                  e->estimate, f.step, floor, f.order);
    e->estimate = floor;
    e->note = text;
}

/// An energy budget on a world whose particles hit a constraint: in flight or at rest a hit particle is the contact
/// offset higher than the rigid answer's, so its energy is off by m g offset whatever the step (an energy the step
/// doubling cannot see, as the offset's position above). The estimate is at least that share of the world's energy.
void RaiseToOffsetEnergy(double offsetEnergy, CandidateEstimate* e) {
    if (!(offsetEnergy > e->estimate)) return;
    char text[160];
    std::snprintf(text, sizeof text,
                  "raised from %.3g: a particle that hit a constraint is %.3g of the world's energy off, its contact "
                  "offset's",
                  e->estimate, offsetEnergy);
    e->estimate = offsetEnergy;
    if (!e->unreliable) e->note = text;
}

/// A particle's impact falls somewhere inside a step, and the motion after it is shifted in time by up to a step,
/// by an amount that jumps with the impact's phase in the step, so step doubling can see two probes agree by
/// chance. A shift of the motion by dt moves the state at the end by its speed there times dt (nothing, once the
/// particles came to rest): the estimate is taken to be at least half of that bound per impact (the typical phase;
/// the safety factor covers the rest), `impactSpeed` being the impacts' count times the fastest point's speed at
/// the pilot's end. Position budgets on worlds whose particles hit constraints only.
/// A particle that hits a constraint is also stopped on a surface CandidateSpace::contactOffset out from the box's
/// (docs/ch14.md, "Contact that converges"): after an impact it flies from there, off the rigid answer's flight by
/// about that offset whatever the step. Step doubling cannot see a bias every candidate shares, so when the pilot saw
/// an impact and the particle still flying at its end (`flying`) the estimate is at least the offset. A particle
/// resting on the surface rests at the contact's resting height, the model's own (as the book's), not counted.
void RaiseToImpactTiming(const PilotImpacts& impacted, const CandidateSpace& space, const ErrorBudget& budget,
                         CandidateEstimate* e) {
    if (!space.hasContacts || !e->stable) return;
    if (budget.quantity == BudgetQuantity::Energy) {
        RaiseToOffsetEnergy(impacted.offsetEnergy, e);
        return;
    }
    if (budget.quantity != BudgetQuantity::Position) return;
    const double impactSpeed = impacted.speed;
    const double timing = space.impactsTimedInStep ? 0.0 : 0.5 * impactSpeed * e->model.step;
    const double offset = impacted.flying ? space.contactOffset : 0.0;
    const double floor = std::max(timing, offset);
    if (!(floor > e->estimate)) return;
    char text[192];
    if (offset >= timing) {
        std::snprintf(text, sizeof text,
                      "raised from %.3g: a particle that hit a constraint flies and rests %.3g m off its surface",
                      e->estimate, offset);
    } else {
        std::snprintf(
            text, sizeof text,
            "raised from %.3g: impacts times the speed at the end, %.3g m/s, each timed to within its step, allow %.3g",
            e->estimate, impactSpeed, floor);
    }
    e->estimate = floor;
    if (!e->unreliable) e->note = text;
}

/// The candidate a refusal names: the smallest complete and reliable estimate; one that is a lower bound (a span
/// stopped at a miss or at the CPU limit) or unreliable only while there is none.
void KeepBest(ModelChoiceResult* result, int index) {
    const CandidateEstimate& e = result->candidates[static_cast<std::size_t>(index)];
    if (!e.stable || !std::isfinite(e.estimate)) return;
    auto rank = [](const CandidateEstimate& c) { return c.partial || c.unreliable ? 1 : 0; };
    const CandidateEstimate* b =
        result->best >= 0 ? &result->candidates[static_cast<std::size_t>(result->best)] : nullptr;
    if (!b || rank(e) < rank(*b) || (rank(e) == rank(*b) && e.estimate < b->estimate)) result->best = index;
}

/// Every candidate of `space` in result->candidates (model and predicted work), and their indices cheapest first.
std::vector<std::size_t> CostOrder(const CandidateSpace& space, ModelChoiceResult* out) {
    ModelChoiceResult& result = *out;
    const std::vector<ModelCandidate> all = EnumerateCandidates(space);
    result.candidates.resize(all.size());
    std::vector<std::size_t> order(all.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        result.candidates[i].model = all[i];
        result.candidates[i].predictedWork = PredictedWork(all[i], space);
        order[i] = i;
    }
    // Cheapest first (by the deterministic work model, so the choice never depends on timing noise).
    // Ties keep enumeration order (the index breaks them; std::sort, as libstdc++'s stable_sort buffer trips ASan's
    // alloc-dealloc check).
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const double wa = result.candidates[a].predictedWork, wb = result.candidates[b].predictedWork;
        return wa < wb || (wa == wb && a < b);
    });
    return order;
}

/// Why candidate order[k], `e`, need not be run given the candidates before it (empty: it must be).
std::string WhySkip(const ModelChoiceResult& result, const std::vector<std::size_t>& order, std::size_t k,
                    const CandidateEstimate& e, const CandidateSpace& space, double bound) {
    // Skip what an evaluated candidate of the same family already rules out: one that is no finer in step
    // and no richer in passes than a candidate that missed the budget (or blew up) misses it too; and a finer
    // step is predicted, by the candidate's order, from the nearest coarser step of the family with the same
    // passes that was estimated, when that is the next rung (coarser steps are often outside the asymptotic
    // range, where an error does not shrink with the step as its order says).
    std::string why;
    const CandidateEstimate* nearest = nullptr;
    for (std::size_t j = 0; j < k && why.empty(); ++j) {
        const CandidateEstimate& f = result.candidates[order[j]];
        if (!f.evaluated || f.meets || !SameFamily(f.model, e.model)) continue;
        if (e.model.step >= f.model.step && Passes(e.model) <= Passes(f.model)) {
            why = "not run: a finer model of its family missed the budget";
        } else if (Passes(e.model) == Passes(f.model) && f.stable && std::isfinite(f.estimate) &&
                   f.model.step > e.model.step && (!nearest || f.model.step < nearest->model.step)) {
            nearest = &f;
        } else if (e.model.step == f.model.step && Passes(e.model) > Passes(f.model) && f.stable && !f.partial &&
                   f.estimate < 64.0 * bound) {
            // Near the budget, more passes at this step stopped helping (doubling them or more took off less
            // than a fifth: the step's own error dominates): a
            // richer candidate at the same step is not run. Far from it, a solve that has not converged at all
            // says nothing about how the next passes will do.
            for (std::size_t i = 0; i < j && why.empty(); ++i) {
                const CandidateEstimate& g = result.candidates[order[i]];
                if (g.evaluated && !g.meets && g.stable && !g.partial && SameFamily(g.model, f.model) &&
                    g.model.step == f.model.step && Passes(g.model) < Passes(f.model) &&
                    f.estimate > 0.8 * g.estimate) {
                    why = "not run: more passes stopped helping its family at this step";
                }
            }
        }
    }
    if (why.empty() && nearest) why = PredictedMiss(result, order, k, *nearest, e, space, bound);
    return why;
}

/// The margin's fallback, when no candidate met the budget over the safety factor: of the candidates whose estimate
/// is within the budget itself, the one of the smallest estimate, provided the estimate is complete and the error was
/// seen to shrink at the candidate's order by a finer pair above rounding (CheckOrder, over the whole run or its start
/// span; VerifyOrder runs it here for a span estimate that has not had it, within the CPU limit). The safety factor is
/// for an estimate whose order is assumed; this one's order was observed. Constraint budgets, observed rather than
/// estimated, have no such check and no fallback. Returns the index, or -1.
int MarginFallback(const PlannedSpan& start, double span, const std::vector<std::size_t>& order,
                   const CandidateSpace& space, const ErrorBudget& budget, const ChoiceSettings& settings,
                   ModelChoiceResult* result, ChoiceClock* clock) {
    if (budget.quantity == BudgetQuantity::Constraint) return -1;
    int pick = -1;
    for (std::size_t i = 0; i < order.size(); ++i) {
        CandidateEstimate& e = result->candidates[order[i]];
        // Its coarser whole-run rungs must agree: an end-of-run difference can be small by chance (a pendulum's
        // phase error crossing zero near the end), which the rungs' order-1 prediction would not be.
        auto trusted = [&] {
            return e.evaluated && e.stable && !e.partial && !e.unreliable && !e.withinRounding &&
                   e.finerDifference >= 0.0 && e.estimate <= budget.bound &&
                   FamilyFloor(result->candidates, order, i, space, &e).floor <= budget.bound;
        };
        if (e.finerDifference < 0.0 && e.evaluated && e.stable && !e.partial && !e.unreliable &&
            e.estimate <= budget.bound && !clock->Over()) {
            const double before = result->calibrationWork;
            VerifyOrder(start, span, space, budget, settings, &e, &result->calibrationCpuSeconds,
                        &result->calibrationWork, clock);
            result->checkWork += result->calibrationWork - before;
            result->unreliableCount += e.unreliable ? 1 : 0;
        }
        if (!trusted()) continue;
        if (pick < 0 || e.estimate < result->candidates[static_cast<std::size_t>(pick)].estimate) {
            pick = static_cast<int>(order[i]);
        }
    }
    if (pick >= 0) {
        CandidateEstimate& e = result->candidates[static_cast<std::size_t>(pick)];
        char text[200];
        std::snprintf(text, sizeof text,
                      "within the budget, not its margin; chosen as no candidate met the margin and its error was seen "
                      "to shrink at its order (%.3g, then %.3g at half the step)",
                      e.pairDifference, e.finerDifference);
        e.note = text;
    }
    return pick;
}

}  // namespace

ModelChoiceResult ChooseModel(const ProbeFactory& factory, const CandidateSpace& space, const ErrorBudget& budget,
                              const ChoiceSettings& settings) {
    ModelChoiceResult result;
    const std::vector<std::size_t> order = CostOrder(space, &result);
    const double span = SpanFor(settings);
    result.spanSeconds = span;
    const double bound = budget.bound / settings.safety;
    ChoiceClock clock(settings);
    PilotImpacts impacted;
    const std::vector<PlannedSpan> plan = PlanSpans(factory, space, settings, span, &result, &clock, &impacted);
    for (std::size_t k = 0; k < order.size(); ++k) {
        CandidateEstimate& e = result.candidates[order[k]];
        if (result.chosen >= 0) {
            e.note = "not run: costs more than the chosen model";
            continue;
        }
        if (result.stoppedAtLimit || clock.Over()) {
            result.stoppedAtLimit = true;
            e.note = "not run: the choice's CPU limit was reached";
            continue;
        }
        const std::string why = WhySkip(result, order, k, e, space, bound);
        if (!why.empty()) {
            e.note = why;
            continue;
        }
        if (result.evaluatedShare >= settings.maxEvaluations) {
            e.note = "not run: evaluation limit reached";
            continue;
        }
        ++result.evaluatedCount;
        e.evaluated = true;
        clock.Candidate(e.predictedWork * settings.runSeconds, e.model.Describe(space.hasParticles, space.hasVolumes));
        Evaluate(plan, span, space, budget, settings, bound, &e, &result.calibrationCpuSeconds, &result.calibrationWork,
                 &clock);
        result.evaluatedShare += e.share;
        RaiseToFamilyFloor(result.candidates, order, k, space, &e);
        RaiseToImpactTiming(impacted, space, budget, &e);
        if (e.stable && !e.partial && !e.unreliable && e.estimate <= bound) {
            const double before = result.calibrationWork;
            VerifyOrder(plan[0], span, space, budget, settings, &e, &result.calibrationCpuSeconds,
                        &result.calibrationWork, &clock);
            result.checkWork += result.calibrationWork - before;
        }
        result.unreliableCount += e.unreliable ? 1 : 0;
        result.stoppedAtLimit = result.stoppedAtLimit || e.stoppedAtLimit;
        e.meets = e.stable && !e.partial && !e.unreliable && e.estimate <= bound;
        if (e.meets) result.chosen = static_cast<int>(order[k]);
        KeepBest(&result, static_cast<int>(order[k]));
    }
    if (result.chosen < 0 && settings.marginFallback) {
        result.chosen = MarginFallback(plan[0], span, order, space, budget, settings, &result, &clock);
        result.withinMarginOnly = result.chosen >= 0;
    }
    result.feasible = result.chosen >= 0;
    result.cpuLimit = clock.Limit(0.0, 0.0);
    return result;
}
