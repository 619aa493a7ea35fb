#include "Physics/ModelChoice.h"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "Physics/Cloth.h"
#include "Physics/DistanceJoint.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"
#include "Physics/StabilityMonitor.h"

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double ThreadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// Formal order of accuracy of a candidate on a space: contact (volumes or particles bouncing off constraints) is
/// non-smooth, so first order; otherwise the integrator's.
int OrderOf(const ModelCandidate& c, const CandidateSpace& space) {
    if (space.hasVolumes || space.hasContacts) return 1;
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

/// Contact passes per step of a candidate (the solver's work multiplier).
double PassWork(const ModelCandidate& c) {
    if (c.solver == ContactSolver::Soft) return 3.0 + 1.0 * c.softSubsteps;
    return 4.0 + c.iterations;
}

}  // namespace

const char* ToString(BudgetQuantity quantity) {
    switch (quantity) {
        case BudgetQuantity::Position:
            return "position";
        case BudgetQuantity::Energy:
            return "energy";
        case BudgetQuantity::Constraint:
            return "constraint";
    }
    return "?";
}

bool ParseBudgetQuantity(const std::string& text, BudgetQuantity* out) {
    for (BudgetQuantity q : {BudgetQuantity::Position, BudgetQuantity::Energy, BudgetQuantity::Constraint}) {
        if (text == ToString(q)) {
            *out = q;
            return true;
        }
    }
    return false;
}

const char* BudgetUnit(BudgetQuantity quantity) { return quantity == BudgetQuantity::Energy ? "(relative)" : "m"; }

bool ValidateBudget(const ErrorBudget& budget, std::string* error) {
    if (std::isfinite(budget.bound) && budget.bound > 0.0) return true;
    char text[160];
    std::snprintf(text, sizeof text, "error budget %g %s (%s): must be finite and > 0", budget.bound,
                  BudgetUnit(budget.quantity), ToString(budget.quantity));
    *error = text;
    return false;
}

std::string ModelCandidate::Describe(bool particles, bool volumes) const {
    char text[160];
    std::string out;
    if (particles) out += ToString(integrator);
    if (volumes) {
        if (!out.empty()) out += ", ";
        if (solver == ContactSolver::Soft) {
            std::snprintf(text, sizeof text, "soft solver %d substeps", softSubsteps);
        } else {
            std::snprintf(text, sizeof text, "%s solver %d iterations", ToString(solver), iterations);
        }
        out += text;
    }
    std::snprintf(text, sizeof text, "%sdt %g s", out.empty() ? "" : ", ", step);
    return out + text;
}

std::vector<ModelCandidate> EnumerateCandidates(const CandidateSpace& space) {
    const ModelCandidate& base = space.base;
    std::vector<Integrator> integrators = space.integrators;
    if (!space.hasParticles || integrators.empty()) integrators = {base.integrator};
    std::vector<double> steps = space.steps;
    if (steps.empty()) steps = {base.step};
    std::vector<ContactSolver> solvers = space.solvers;
    if (!space.hasVolumes || solvers.empty()) solvers = {base.solver};

    std::vector<ModelCandidate> out;
    for (Integrator integrator : integrators) {
        for (ContactSolver solver : solvers) {
            std::vector<int> passes;
            const bool soft = solver == ContactSolver::Soft;
            if (space.hasVolumes) passes = soft ? space.softSubsteps : space.iterations;
            if (passes.empty()) passes = {soft ? base.softSubsteps : base.iterations};
            for (int p : passes) {
                for (double step : steps) {
                    ModelCandidate c = base;
                    c.integrator = integrator;
                    c.solver = solver;
                    c.step = step;
                    (soft ? c.softSubsteps : c.iterations) = p;
                    out.push_back(c);
                }
            }
        }
    }
    return out;
}

ModelCandidate Refine(const ModelCandidate& candidate, const CandidateSpace& space) {
    ModelCandidate r = candidate;
    // The soft step already splits each step into substeps: twice the substeps refines its time resolution at
    // twice the cost. Everything else (particles, the book and accumulated solvers): half the step.
    if (space.hasVolumes && !space.hasParticles && r.solver == ContactSolver::Soft) {
        r.softSubsteps *= 2;
    } else {
        r.step = candidate.step * 0.5;
    }
    return r;
}

double PredictedWork(const ModelCandidate& c, const CandidateSpace& space) {
    const double particleWork =
        (space.particleCount + space.springCount) * ForceEvaluations(c.integrator) + space.particleCount;
    const double volumeWork = space.volumeCount * PassWork(c);
    return (particleWork + volumeWork + 1.0) / c.step;
}

void WorldPositions(const PhysicsSystem& world, std::vector<double>* out) {
    out->clear();
    auto add = [out](const vec3& x) {
        out->push_back(x.x);
        out->push_back(x.y);
        out->push_back(x.z);
    };
    for (const Rigidbody* body : world.Bodies()) {
        if (body->type == RigidbodyType::Particle) {
            add(static_cast<const Particle*>(body)->GetPosition());
        } else if (body->type == RigidbodyType::Box || body->type == RigidbodyType::Sphere) {
            add(static_cast<const RigidbodyVolume*>(body)->position);
        }
    }
    for (const Cloth* cloth : world.Cloths()) {
        for (const Particle& p : cloth->verts) add(p.GetPosition());
    }
}

double WorldEnergy(const PhysicsSystem& world) {
    double energy = StabilityMonitor::MechanicalEnergy(world);
    for (const RigidbodyVolume* v : world.Volumes()) {
        if (!(v->mass > 0.0f)) continue;
        const double m = v->mass;
        const vec3& u = v->velocity;
        energy += 0.5 * m * (double(u.x) * u.x + double(u.y) * u.y + double(u.z) * u.z);
        const vec3 iw = MultiplyVector(v->angVel, v->InertiaTensor());
        energy += 0.5 * (double(iw.x) * v->angVel.x + double(iw.y) * v->angVel.y + double(iw.z) * v->angVel.z);
        const vec3& g = v->gravity;
        energy -= m * (double(g.x) * v->position.x + double(g.y) * v->position.y + double(g.z) * v->position.z);
    }
    return energy;
}

double WorldConstraintError(const PhysicsSystem& world) {
    double worst = 0.0;
    for (const DistanceJoint* j : world.Joints()) {
        if (!j->p1 || !j->p2) continue;
        const vec3 d = j->p2->GetPosition() - j->p1->GetPosition();
        const double length = std::sqrt(double(d.x) * d.x + double(d.y) * d.y + double(d.z) * d.z);
        worst = std::max(worst, std::fabs(length - j->length));
    }
    return worst;
}

namespace {

/// The budget's quantity between a candidate's probe and its refinement's (or of the candidate alone, for
/// constraint error, which is observed, not estimated).
struct QuantityProbe {
    BudgetQuantity quantity;
    double energyScale = 1.0;  // J: |E0| of the window's start (floored)
    std::vector<double> a, b;

    double Measure(const ModelProbe& coarse, const ModelProbe* fine) {
        switch (quantity) {
            case BudgetQuantity::Position: {
                WorldPositions(coarse.World(), &a);
                WorldPositions(fine->World(), &b);
                double worst = 0.0;
                for (std::size_t i = 0; i + 2 < a.size() && i + 2 < b.size(); i += 3) {
                    const double dx = a[i] - b[i], dy = a[i + 1] - b[i + 1], dz = a[i + 2] - b[i + 2];
                    worst = std::max(worst, std::sqrt(dx * dx + dy * dy + dz * dz));
                }
                return worst;
            }
            case BudgetQuantity::Energy:
                return std::fabs(WorldEnergy(coarse.World()) - WorldEnergy(fine->World())) / energyScale;
            case BudgetQuantity::Constraint:
                return WorldConstraintError(coarse.World());
        }
        return kInf;
    }
};

/// One window: the candidate and (unless the quantity is observed directly) its refinement run from the same
/// state to `window` seconds, sampled at up to 256 whole-step times (an oscillation must not hide between samples).
struct WindowResult {
    bool stable = true;
    double estimate = kInf;        // the quantity at the end of `horizon`, extrapolated
    double observed = 0.0;         // the largest sampled difference (or observed value)
    double growth = 1.0;           // the fitted exponent
    double cpuSeconds = 0.0;       // candidate's probe only
    double probeCpuSeconds = 0.0;  // both probes
};

WindowResult RunWindow(const ProbeFactory& factory, const ModelCandidate& candidate, const CandidateSpace& space,
                       const ErrorBudget& budget, double window, double horizon, double fixedGrowth = -1.0) {
    WindowResult r;
    const double start = ThreadCpuSeconds();
    std::unique_ptr<ModelProbe> coarse = factory();
    coarse->Apply(candidate);
    std::unique_ptr<ModelProbe> fine;
    const bool observed = budget.quantity == BudgetQuantity::Constraint;
    if (!observed) {
        fine = factory();
        fine->Apply(Refine(candidate, space));
    }
    QuantityProbe q{budget.quantity, 1.0, {}, {}};
    if (budget.quantity == BudgetQuantity::Energy) {
        q.energyScale = std::max(std::fabs(WorldEnergy(coarse->World())), 1e-12);
    }
    const long long steps = std::max(2LL, std::llround(window / candidate.step));
    const int samples = static_cast<int>(std::min<long long>(256, steps));
    double half = 0.0, full = 0.0;  // running maximum at the window's middle and end
    double cpu = 0.0;
    for (int s = 1; s <= samples; ++s) {
        const double t = candidate.step * static_cast<double>((steps * s) / samples);
        const double before = ThreadCpuSeconds();
        const bool coarseOk = coarse->AdvanceTo(t);
        cpu += ThreadCpuSeconds() - before;
        const bool fineOk = observed || fine->AdvanceTo(t);
        if (!coarseOk || !fineOk) {
            r.stable = coarseOk;
            if (!coarseOk) break;
            // The refinement blew up but the candidate did not: no estimate can be trusted.
            r.estimate = kInf;
            r.probeCpuSeconds = ThreadCpuSeconds() - start;
            r.cpuSeconds = cpu;
            return r;
        }
        const double d = q.Measure(*coarse, fine.get());
        if (!std::isfinite(d)) {
            r.stable = false;
            break;
        }
        full = std::max(full, d);
        if (2 * s <= samples) half = full;
    }
    r.cpuSeconds = cpu;
    r.probeCpuSeconds = ThreadCpuSeconds() - start;
    if (!r.stable) return r;
    const double length = candidate.step * static_cast<double>(steps);
    // Growth in time fitted from the window's halves, 0 (bounded, e.g. a symplectic integrator's energy error) to
    // 1 (a drift: a phase error, a velocity bias). Discretisation errors do not grow faster than linearly while
    // the run is stable; what does (an instability starting) is left to the live checks, not extrapolated from a
    // transient (a stack settling in its first steps would otherwise be extrapolated quadratically).
    double growth = 1.0;
    if (full > 0.0 && half > 0.0) growth = std::clamp(std::log2(full / half), 0.0, 1.0);
    if (observed) growth = std::min(growth, 1.0);
    if (fixedGrowth >= 0.0) growth = fixedGrowth;
    r.growth = growth;
    r.observed = full;
    const double factor = observed ? 1.0 : RichardsonFactor(OrderOf(candidate, space));
    r.estimate = factor * full * std::pow(std::max(horizon / length, 1.0), growth);
    return r;
}

double WindowFor(const ChoiceSettings& s) {
    return std::min(s.runSeconds, std::clamp(s.windowFraction * s.runSeconds, s.minWindow, s.maxWindow));
}

/// Candidates of the same family (integrator and solver) that differ only in step and passes.
bool SameFamily(const ModelCandidate& a, const ModelCandidate& b) {
    return a.integrator == b.integrator && a.solver == b.solver;
}

int Passes(const ModelCandidate& c) { return c.solver == ContactSolver::Soft ? c.softSubsteps : c.iterations; }

}  // namespace

ModelChoiceResult ChooseModel(const ProbeFactory& factory, const CandidateSpace& space, const ErrorBudget& budget,
                              const ChoiceSettings& settings) {
    ModelChoiceResult result;
    const std::vector<ModelCandidate> all = EnumerateCandidates(space);
    result.candidates.resize(all.size());
    std::vector<std::size_t> order(all.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        result.candidates[i].model = all[i];
        result.candidates[i].predictedWork = PredictedWork(all[i], space);
        order[i] = i;
    }
    // Cheapest first (by the deterministic work model, so the choice never depends on timing noise).
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return result.candidates[a].predictedWork < result.candidates[b].predictedWork;
    });
    const double window = WindowFor(settings);
    result.windowSeconds = window;
    const double bound = budget.bound / settings.safety;
    for (std::size_t k = 0; k < order.size(); ++k) {
        CandidateEstimate& e = result.candidates[order[k]];
        if (result.chosen >= 0) {
            e.note = "not run: costs more than the chosen model";
            continue;
        }
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
            } else if (e.model.step == f.model.step && Passes(e.model) > Passes(f.model) && f.stable &&
                       f.estimate < 64.0 * bound) {
                // Near the budget, more passes at this step stopped helping (the step's own error dominates): a
                // richer candidate at the same step is not run. Far from it, a solve that has not converged at all
                // says nothing about how the next passes will do.
                for (std::size_t i = 0; i < j && why.empty(); ++i) {
                    const CandidateEstimate& g = result.candidates[order[i]];
                    if (g.evaluated && !g.meets && g.stable && SameFamily(g.model, f.model) &&
                        g.model.step == f.model.step && Passes(g.model) < Passes(f.model) &&
                        f.estimate > 0.5 * g.estimate) {
                        why = "not run: more passes stopped helping its family at this step";
                    }
                }
            }
        }
        if (why.empty() && nearest && nearest->model.step <= 2.5 * e.model.step) {
            const double predicted =
                nearest->estimate * std::pow(e.model.step / nearest->model.step, OrderOf(e.model, space));
            if (predicted > 8.0 * bound) {
                char text[120];
                std::snprintf(text, sizeof text, "not run: predicted %.3g from its family's dt %g s", predicted,
                              nearest->model.step);
                why = text;
            }
        }
        if (!why.empty()) {
            e.note = why;
            continue;
        }
        if (result.evaluatedCount >= settings.maxEvaluations) {
            e.note = "not run: evaluation limit reached";
            continue;
        }
        ++result.evaluatedCount;
        e.evaluated = true;
        double used = window;
        WindowResult w;
        const double screen = std::max(settings.screenFraction * window, 2.0 * e.model.step);
        if (screen >= 2.0 * e.model.step && screen < 0.9 * window) {
            w = RunWindow(factory, e.model, space, budget, screen, settings.runSeconds);
            result.calibrationCpuSeconds += w.probeCpuSeconds;
            used = screen;
            if (w.stable && w.estimate <= settings.screenMargin * bound) {
                w = RunWindow(factory, e.model, space, budget, window, settings.runSeconds);
                result.calibrationCpuSeconds += w.probeCpuSeconds;
                used = window;
            } else if (w.stable) {
                e.note = "missed by far on the screening window";
            }
        } else {
            w = RunWindow(factory, e.model, space, budget, window, settings.runSeconds);
            result.calibrationCpuSeconds += w.probeCpuSeconds;
        }
        e.stable = w.stable;
        e.estimate = w.stable ? w.estimate : kInf;
        e.growth = w.growth;
        const double length = e.model.step * std::max(2.0, std::round(used / e.model.step));
        e.cpuPerSimSecond = w.cpuSeconds / length;
        e.meets = e.stable && e.estimate <= bound;
        if (!e.stable) e.note = "unstable in the calibration window";
        if (e.meets) result.chosen = static_cast<int>(order[k]);
        if (e.stable && std::isfinite(e.estimate) &&
            (result.best < 0 || e.estimate < result.candidates[result.best].estimate)) {
            result.best = static_cast<int>(order[k]);
        }
    }
    result.feasible = result.chosen >= 0;
    return result;
}

ModelWatch::ModelWatch(const CandidateSpace& s, const ErrorBudget& b, const ChoiceSettings& c,
                       const ModelCandidate& chosen, double calibrationEstimate, double calibrationGrowth)
    : space(s),
      budget(b),
      settings(c),
      current(chosen),
      running(calibrationEstimate),
      currentEstimate(calibrationEstimate),
      growth(calibrationGrowth) {}

bool ModelWatch::Due(double time) const {
    const double every = settings.checkEvery > 0.0 ? settings.checkEvery : settings.runSeconds / 6.0;
    return every > 0.0 && time >= lastCheck + every - 1e-9 && time < settings.runSeconds - 1e-9;
}

bool ModelWatch::Check(double time, const ProbeFactory& factory, std::string* log) {
    if (!Due(time)) return false;
    lastCheck = time;
    const double window = std::min(settings.runSeconds - time, settings.checkWindowFraction * WindowFor(settings));
    if (!(window > 0.0)) return false;
    // The current regime taken as the whole run's: the window's difference extrapolated over the full run length
    // with the calibration's growth (a short window's own fit follows the phase of an oscillation, not its trend).
    const WindowResult w = RunWindow(factory, current, space, budget, window, settings.runSeconds, growth);
    cpuSeconds += w.probeCpuSeconds;
    ++checks;
    const double estimate = w.stable ? w.estimate : kInf;
    currentEstimate = estimate;
    const double share = (settings.runSeconds - modelStart) / settings.runSeconds;
    running = carried + estimate * share;
    // The model was chosen with the safety factor's margin; it is changed only when the estimate says the budget
    // itself will be missed (a margin, so a model chosen near the edge does not flip on window-to-window noise).
    if (running <= budget.bound) return false;
    // Refine within the family: the next smaller step the space allows, else twice the passes.
    ModelCandidate next = current;
    double smaller = 0.0;
    for (double s : space.steps) {
        if (s < current.step - 1e-12 && s > smaller) smaller = s;
    }
    const std::vector<int>& passList = current.solver == ContactSolver::Soft ? space.softSubsteps : space.iterations;
    int morePasses = 0;
    for (int p : passList) {
        if (p > Passes(current) && (morePasses == 0 || p < morePasses)) morePasses = p;
    }
    if (smaller > 0.0) {
        next.step = smaller;
    } else if (space.hasVolumes && morePasses > 0) {
        (current.solver == ContactSolver::Soft ? next.softSubsteps : next.iterations) = morePasses;
    } else {
        char text[256];
        std::snprintf(text, sizeof text,
                      "t = %.2f s: estimated %s error at the end %.3g exceeds the budget %g, and %s "
                      "has no finer setting on this host",
                      time, ToString(budget.quantity), running, budget.bound,
                      current.Describe(space.hasParticles, space.hasVolumes).c_str());
        *log = text;
        return false;
    }
    // What the model made so far stays in the estimate, for its share of the run.
    carried += estimate * (time - modelStart) / settings.runSeconds;
    char text[320];
    std::snprintf(text, sizeof text,
                  "t = %.2f s: estimated %s error at the end %.3g exceeds the budget %g (the last %.3g s "
                  "differ by %.3g from the refinement): switching from %s to %s",
                  time, ToString(budget.quantity), running, budget.bound, window, w.observed,
                  current.Describe(space.hasParticles, space.hasVolumes).c_str(),
                  next.Describe(space.hasParticles, space.hasVolumes).c_str());
    *log = text;
    current = next;
    modelStart = time;
    return true;
}
