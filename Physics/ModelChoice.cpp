#include "Physics/ModelChoice.h"

#include <time.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
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

/// The choice's CPU limit and its progress lines (ChoiceSettings::cpuLimit, runShare, progress). Windows report
/// what they cost when they end (Add, from the clock reads they make anyway); inside a window the clock is read only
/// once enough predicted work has passed since the last read (about a millisecond), so a microsecond problem reads
/// no clock more than before.
class ChoiceClock {
public:
    explicit ChoiceClock(const ChoiceSettings& s) : settings(s), lastLine(Wall()) {}
    /// The candidate about to be estimated: its own run's predicted work (the limit grows to a share of its run)
    /// and what a progress line says.
    void Candidate(double runWork, std::string what) {
        candidateRunWork = runWork;
        doing = std::move(what);
    }
    /// A finished piece of the choice (a window, the pilot): its CPU and predicted work.
    void Add(double cpuSeconds, double workUnits) {
        spent += cpuSeconds;
        work += workUnits;
        Report(0.0);
    }
    /// Inside a piece that started at thread CPU `pieceStart` and has done `pieceWork` so far: true once the limit
    /// is spent (the piece then stops).
    bool Poll(double pieceStart, double pieceWork) {
        if (pieceWork < polledWork + kPollWork) return false;
        polledWork = pieceWork;
        const double now = ThreadCpuSeconds() - pieceStart;
        Report(now);
        return spent + now >= Limit(now, pieceWork);
    }
    /// Between pieces.
    bool Over() const { return spent >= Limit(0.0, 0.0); }
    /// s of CPU: the limit with what has been measured so far (work's CPU rate times the candidate's run).
    double Limit(double extraCpu, double extraWork) const {
        const double rate = work + extraWork > 0.0 ? (spent + extraCpu) / (work + extraWork) : 0.0;
        return std::max(settings.cpuLimit, settings.runShare * rate * candidateRunWork);
    }
    double Spent() const { return spent; }
    void StartPiece() { polledWork = 0.0; }

private:
    static constexpr double kPollWork = 4e4;  // PredictedWork units, about a millisecond of CPU
    static double Wall() {
        return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    }
    void Report(double extraCpu) {
        if (!settings.progress) return;
        const double now = Wall();
        if (now < lastLine + settings.progressEvery) return;
        lastLine = now;
        char text[320];
        std::snprintf(text, sizeof text, "choosing a model: %.2f s CPU of a %.2f s limit; estimating %s",
                      spent + extraCpu, Limit(extraCpu, 0.0), doing.c_str());
        settings.progress(text);
    }
    const ChoiceSettings& settings;
    double spent = 0.0, work = 0.0, polledWork = 0.0, candidateRunWork = 0.0;
    double lastLine = 0.0;
    std::string doing;
};

/// One window: the candidate and (unless the quantity is observed directly) its refinement run from the same
/// state for `window` seconds, sampled at up to 256 whole-step times (an oscillation must not hide between
/// samples). `warmSteps` steps of the candidate first run unmeasured, and the difference at their end is taken off
/// the later ones: probes built from a mid-run state of a world with volumes lack its contact history (no warm
/// start), so they first settle.
/// Over the whole run (`wholeRun`) a third probe at a quarter of the step runs beside them. An energy budget is then
/// the difference at the end, where the budget bounds it, not the largest over the run: two runs that dissipate at
/// an impact a step apart differ by the impact's whole loss between the two times, which says nothing about the
/// energy either keeps. One difference at one time can be small by chance (an impact falling at the same place
/// within both steps), so the finer pair's difference at the end, times 2^p (what it predicts for the coarser pair
/// when the error has order p), is taken when it is larger. A position budget keeps the largest difference over
/// the run; there the finer pair's largest is taken, times 2^p, only when it exceeds the pair's: the error has
/// stopped shrinking with the step (a period error saturated at coarse steps). Where it is smaller the pair's
/// stands, as a finer pair at float rounding (RK4 at fine steps) times 2^p would overstate it.
struct WindowResult {
    bool stable = true;
    double observed = 0.0;         // the largest sampled difference (or observed value) over the measured part
    double length = 0.0;           // s: the measured part
    double factor = 1.0;           // the Richardson factor
    double growth = 1.0;           // the exponent used
    double cpuSeconds = 0.0;       // candidate's probe only: the window's CPU apportioned by predicted work
    double probeCpuSeconds = 0.0;  // every probe of the window, built and run
    double simulated = 0.0;        // s the candidate's probe ran
    double work = 0.0;             // PredictedWork units both probes did (a deterministic measure of their cost)
    double pairObserved = -1.0;    // a whole run raised by its third probe: what the pair alone observed, else < 0
    double missedAt = -1.0;        // s into the measured part where it already missed `missBound`, else < 0
    double share = 1.0;            // the part of the window that ran (1 unless it stopped early)
    // The convergence check over a whole run: the pair's difference (the largest, or at the end for energy), the
    // finer pair's on the same terms, and the rounding level below which neither says anything.
    double pair = -1.0, finer = -1.0, noise = 0.0;
    bool stopped = false;  // cut short by the choice's CPU limit
};

/// The level at which a difference is rounding (float states): relative for energy, scaled by the largest
/// coordinate (at least 1 m) for positions and joints.
double ConvergenceNoise(BudgetQuantity quantity, const std::vector<double>& positions) {
    double scale = 1.0;
    if (quantity != BudgetQuantity::Energy) {
        for (double x : positions) scale = std::max(scale, std::fabs(x));
    }
    return 32.0 * FLT_EPSILON * scale;
}

/// A window with `missBound` > 0 stops at the first sample whose difference, with the Richardson factor, already
/// exceeds it: the window's contribution can only be larger (its growth is at least 0), so the candidate misses,
/// and what is left of the window would only say by how much. Its result is then that lower bound (`missedAt`).
struct WindowOptions {
    int warmSteps = 0;
    double fixedGrowth = -1.0;  // >= 0: the growth exponent used instead of the window's own
    bool wholeRun = false;      // the window is the whole run (a third probe runs, energy is taken at the end)
    double missBound = -1.0;
    ChoiceClock* clock = nullptr;  // the choice's CPU limit (nullptr: none, as for the watch's checks)
    bool third = false;            // a third probe, at the refinement's refinement, also on a window
    bool byStep = false;           // refine by halving the step even where Refine doubles soft substeps
};

/// The refinement a window uses: Refine, or half the step (`byStep`: the convergence check along the step).
ModelCandidate RefineFor(const ModelCandidate& c, const CandidateSpace& space, bool byStep) {
    if (!byStep) return Refine(c, space);
    ModelCandidate r = c;
    r.step = c.step * 0.5;
    return r;
}

WindowResult RunWindow(const ProbeFactory& factory, const ModelCandidate& candidate, const CandidateSpace& space,
                       const ErrorBudget& budget, double window, const WindowOptions& o) {
    const int warmSteps = o.warmSteps;
    const double fixedGrowth = o.fixedGrowth, missBound = o.missBound;
    const bool wholeRun = o.wholeRun;
    ChoiceClock* clock = o.clock;
    WindowResult r;
    const double start = ThreadCpuSeconds();
    if (clock) clock->StartPiece();
    std::unique_ptr<ModelProbe> coarse = factory();
    coarse->Apply(candidate);
    std::unique_ptr<ModelProbe> fine, finest;
    const bool observed = budget.quantity == BudgetQuantity::Constraint;
    const ModelCandidate refined = RefineFor(candidate, space, o.byStep);
    const ModelCandidate refinedTwice = RefineFor(refined, space, o.byStep);
    if (!observed) {
        fine = factory();
        fine->Apply(refined);
    }
    const bool third = (wholeRun || o.third) && !observed;
    const bool atEnd = wholeRun && budget.quantity == BudgetQuantity::Energy;
    if (third) {
        finest = factory();
        finest->Apply(refinedTwice);
    }
    QuantityProbe q{budget.quantity, 1.0, {}, {}, false, {}, 0.0};
    if (budget.quantity == BudgetQuantity::Energy) {
        q.energyScale = std::max(std::fabs(WorldEnergy(coarse->World())), 1e-12);
    }
    QuantityProbe q2 = q;  // the refinement against the third probe
    const long long warm = observed ? 0 : warmSteps;
    const long long measured = std::max(2LL, std::llround(window / candidate.step));
    const int samples = static_cast<int>(std::min<long long>(256, measured));
    double half = 0.0, full = 0.0;  // running maximum at the measured part's middle and end
    double finer = 0.0;             // the third probe's: the largest over the run of the finer pair's difference
    double last = 0.0;              // the difference at the end
    bool ok = true;
    auto advance = [&](double t) {
        if (!coarse->AdvanceTo(t)) {
            r.stable = false;
            return false;
        }
        if ((!observed && !fine->AdvanceTo(t)) || (finest && !finest->AdvanceTo(t))) {
            r.observed = kInf;  // the refinement blew up but the candidate did not: no estimate can be trusted
            return false;
        }
        return true;
    };
    if (warm > 0) {
        ok = advance(candidate.step * static_cast<double>(warm));
        if (ok) q.Rebase(*coarse, fine.get());
    }
    long long reached = warm;  // steps of the candidate run, the warm-up included
    const double own = PredictedWork(candidate, space);
    const double perSecond =
        own + (observed ? 0.0 : PredictedWork(refined, space)) + (third ? PredictedWork(refinedTwice, space) : 0.0);
    const double factor = observed ? 1.0 : RichardsonFactor(OrderOf(candidate, space));
    for (int s = 1; ok && s <= samples; ++s) {
        reached = warm + (measured * s) / samples;
        ok = advance(candidate.step * static_cast<double>(reached));
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
        if (missBound > 0.0 && !atEnd && s < samples && factor * full > missBound) {
            r.missedAt = candidate.step * static_cast<double>(reached - warm);
            break;
        }
        if (clock && s < samples && clock->Poll(start, candidate.step * static_cast<double>(reached) * perSecond)) {
            r.stopped = true;
            break;
        }
    }
    r.probeCpuSeconds = ThreadCpuSeconds() - start;
    r.simulated = candidate.step * static_cast<double>(reached);
    r.share = static_cast<double>(reached) / static_cast<double>(warm + measured);
    r.work = r.simulated * perSecond;
    // The candidate's part of the window's CPU, by predicted work: the thread's CPU clock is a system call (about
    // 0.25 us), and reading it around every sample's advance was half a microsecond problem's calibration (the
    // projectile's: 69 us with it, 36 us without).
    r.cpuSeconds = r.probeCpuSeconds * own / perSecond;
    if (clock) clock->Add(r.probeCpuSeconds, r.work);
    r.noise = ConvergenceNoise(budget.quantity, q.b);
    if (!ok) return r;
    const double length = candidate.step * static_cast<double>(measured);
    if (r.missedAt >= 0.0 || r.stopped) {
        // A lower bound: the difference so far, nothing extrapolated.
        r.observed = full;
        r.length = length;
        r.factor = factor;
        r.growth = 0.0;
        return r;
    }
    // Growth in time, fitted from the measured part's halves, 0 (bounded: a symplectic integrator's energy error, a
    // stack that settled) to 1 (a drift: a phase error, a velocity bias). Nothing is extrapolated faster than
    // linearly: an instability starting is left to the live checks.
    double growth = 1.0;
    if (full > 0.0 && half > 0.0) growth = std::clamp(std::log2(full / half), 0.0, 1.0);
    if (fixedGrowth >= 0.0) growth = fixedGrowth;
    r.growth = growth;
    r.observed = full;
    r.length = length;
    r.factor = factor;
    if (third) {
        if (atEnd) finer = std::fabs(WorldEnergy(fine->World()) - WorldEnergy(finest->World())) / q.energyScale;
        if (!std::isfinite(finer)) {
            r.observed = kInf;  // as a refinement that blew up: the candidate itself ran
            return r;
        }
        const double predicted = std::pow(2.0, OrderOf(candidate, space)) * finer;
        const double pair = atEnd ? last : full;
        r.pair = pair;
        r.finer = finer;
        r.observed = pair;
        // Energy: the larger. Position: the finer pair only when it differs more (the error is not shrinking).
        if ((atEnd && predicted > pair) || (!atEnd && finer > full)) {
            r.observed = predicted;
            r.pairObserved = pair;
        }
        r.growth = 0.0;  // nothing is extrapolated: the window is the run
    }
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

namespace {

/// A window, from `factory`'s state at `start` s: the calibration's at the start, or the watch's around an event.
struct PlannedWindow {
    enum class Kind { Start, Event };
    Kind kind = Kind::Start;
    ProbeFactory factory;
    double start = 0.0;
    double span = 0.0;  ///< s of the run that follows the window's start
    int warmSteps = 0;
};

/// The calibration's windows: one at the start and, for a world without volumes, up to settings.eventWindows around
/// events the start window cannot see (a bounce, a cloth reaching an obstacle), from snapshots of a pilot run of the
/// scene's own model over the whole run. Particles restart exactly from a snapshot; volumes would lose their contact
/// history (and the scene's own model may let a stack fall), so their events are left to the live watch. Each
/// step's irregularity is the largest change of any point's acceleration times the step (m/s: what an impulse does,
/// and what gravity or a smooth spring hardly does); the run is cut into intervals of half a window, and an interval
/// ten times more irregular than any the start window covers gets a window from the snapshot of the interval before.
std::vector<PlannedWindow> PlanWindows(const ProbeFactory& factory, const CandidateSpace& space,
                                       const ChoiceSettings& settings, double window, ModelChoiceResult* result,
                                       ChoiceClock* clock) {
    using Kind = PlannedWindow::Kind;
    const double T = settings.runSeconds;
    std::vector<PlannedWindow> plan{{Kind::Start, factory, 0.0, T, 0}};
    const double interval = window / 2.0;
    const int intervals = static_cast<int>(std::ceil(T / interval - 1e-9));
    if (settings.eventWindows <= 0 || space.hasVolumes || intervals < 4) return plan;
    const double start = ThreadCpuSeconds();
    clock->StartPiece();
    clock->Candidate(0.0, "the pilot run of the scene's own model");
    std::unique_ptr<ModelProbe> pilot = factory();
    pilot->Apply(space.base);
    const double h = space.base.step;
    std::vector<ProbeFactory> snapshots{factory};  // at k * interval
    std::vector<double> jump(static_cast<std::size_t>(intervals), 0.0);
    std::vector<double> x0, x1, x2, a1;  // positions two steps back, one back, now; the last acceleration
    long long n = 0;
    bool haveA = false;
    // The pilot covers at most 50 windows (all of a run up to 10 s at the 0.2 s floor; the first 100 s of a long one).
    const double pilotEnd = std::min(T, 50.0 * window);
    while ((n + 1) * h <= pilotEnd * (1.0 + 1e-12)) {
        if (!pilot->AdvanceTo((n + 1) * h)) break;  // the scene's own model blew up: plan from what came before
        ++n;
        // Past the choice's CPU limit: plan from what came before (the choice then stops; ChooseModel).
        if (clock->Poll(start, PredictedWork(space.base, space) * static_cast<double>(n) * h)) break;
        const double t = n * h;
        x0.swap(x1);
        x1.swap(x2);
        WorldPositions(pilot->World(), &x2);
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
    const double seen = std::max(jump[0], jump[1]);  // what the start window covers
    std::vector<int> picked;
    for (int e = 0; e < settings.eventWindows; ++e) {
        int best = -1;
        for (int k = 2; k < intervals; ++k) {
            bool near = false;  // picked windows cover two intervals each, never twice
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
    result->pilotCpuSeconds = ThreadCpuSeconds() - start;
    result->calibrationWork += PredictedWork(space.base, space) * static_cast<double>(n) * h;
    result->calibrationCpuSeconds += result->pilotCpuSeconds;
    clock->Add(result->pilotCpuSeconds, PredictedWork(space.base, space) * static_cast<double>(n) * h);
    return plan;
}

/// What one window adds to a candidate's estimate: its difference extrapolated over the run after its start with
/// its fitted growth (a bounce at another time leaves a drift behind, growth near 1; a transient that settled, near
/// 0). Constraint error is observed, not extrapolated.
double Contribution(const PlannedWindow& p, const WindowResult& w, const ErrorBudget& budget) {
    if (budget.quantity == BudgetQuantity::Constraint) return w.observed;
    return w.factor * w.observed * std::pow(std::max(p.span / w.length, 1.0), w.growth);
}

/// The convergence check (ChoiceSettings::orderBand): a candidate's error must shrink with its step at the order
/// p its estimate assumes, so its difference from its refinement (`pair`) must be about 2^p times its refinement's
/// from its own (`finer`), at least 2^(p - band). A finer pair within rounding (`noise`) has converged and passes. A
/// candidate that fails is marked unreliable with the figures in its note, and is never chosen: its estimate
/// assumed an order its error does not have.
void CheckOrder(double pair, double finer, double noise, const CandidateSpace& space, const ChoiceSettings& settings,
                const char* over, CandidateEstimate* e) {
    e->pairDifference = pair;
    e->finerDifference = finer;
    const int p = OrderOf(e->model, space);
    const double least = std::pow(2.0, p - settings.orderBand);
    if (std::isfinite(pair) && std::isfinite(finer) && (finer <= noise || pair >= least * finer)) return;
    e->unreliable = true;
    char text[320];
    std::snprintf(text, sizeof text,
                  "unreliable: its error does not shrink at order %d (%s: it differs from its refinement by %.3g, "
                  "the refinement from its own by %.3g: ratio %.3g, order %d needs at least %.3g)",
                  p, over, pair, finer, finer > 0.0 ? pair / finer : kInf, p, least);
    e->note = text;
}

/// A candidate's estimate: the sum of its windows' contributions (constraint error: the largest). Stops as soon as
/// it misses `bound` (the rest can only add), marking the estimate partial (a lower bound).
void Evaluate(const std::vector<PlannedWindow>& plan, double window, const CandidateSpace& space,
              const ErrorBudget& budget, const ChoiceSettings& settings, double bound, CandidateEstimate* e,
              double* cpuSeconds, double* work, ChoiceClock* clock) {
    e->estimate = 0.0;
    e->share = 0.0;
    e->segments.clear();
    double cpu = 0.0, simulated = 0.0;
    // A cheap world without volumes, or with one (no stack to topple: a whole run is a measurement, not a chaotic
    // divergence): the candidate, its refinement and a third probe at a quarter of the step run the whole run from
    // the start, and the largest difference sampled over it, with the Richardson factor, is the estimate
    // (constraint error: the largest seen on the candidate alone). Not the position difference at the end: there a
    // bounce that died down leaves both at rest on the ground, and a spring is back near a turning point. Energy
    // is bounded at the end and is measured there. The third probe checks either (RunWindow).
    // The start window then spans the whole run: its contribution is its difference, nothing extrapolated.
    const bool refined = budget.quantity != BudgetQuantity::Constraint;
    const ModelCandidate fine = Refine(e->model, space);
    e->wholeRun = (!space.hasVolumes || space.volumeCount <= 1.0) && settings.wholeRunWork > 0.0 &&
                  settings.runSeconds *
                          (PredictedWork(e->model, space) +
                           (refined ? PredictedWork(fine, space) + PredictedWork(Refine(fine, space), space) : 0.0)) <=
                      settings.wholeRunWork;
    double raisedFrom = -1.0;  // the pair's own estimate, when the third probe raised it
    WindowResult first;        // the start window (the whole run's convergence figures)
    const std::vector<PlannedWindow> whole{plan[0]};
    const std::vector<PlannedWindow>& windows = e->wholeRun ? whole : plan;
    const double length = e->wholeRun ? settings.runSeconds : window;
    for (std::size_t k = 0; k < windows.size(); ++k) {
        // A window stops as soon as its own difference misses (RunWindow); a whole run does not, as its estimate
        // is what a finer rung of its family is floored by (RaiseToFamilyFloor), and a lower bound is not.
        WindowOptions o;
        o.warmSteps = windows[k].warmSteps;
        o.wholeRun = e->wholeRun;
        o.missBound = e->wholeRun || !settings.stopWindowsAtMiss ? -1.0 : bound;
        o.clock = clock;
        const WindowResult w = RunWindow(windows[k].factory, e->model, space, budget, length, o);
        *cpuSeconds += w.probeCpuSeconds;
        *work += w.work;
        e->share += w.share / static_cast<double>(windows.size());
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
            e->note = w.stable ? "its refinement blew up in the calibration" : "unstable in the calibration";
            break;
        }
        if (k == 0) e->growth = w.growth;
        if (w.pairObserved >= 0.0) raisedFrom = w.factor * w.pairObserved;
        const double c = Contribution(windows[k], w, budget);
        e->segments.push_back(c);
        e->estimate = budget.quantity == BudgetQuantity::Constraint ? std::max(e->estimate, c) : e->estimate + c;
        // Missed already, within this window or after it: the rest can only add (a lower bound).
        if (w.missedAt >= 0.0 || (e->estimate > bound && k + 1 < windows.size())) {
            e->partial = true;
            char text[96];
            if (w.missedAt >= 0.0) {
                std::snprintf(text, sizeof text, "missed %.3g s into window %zu of %zu", w.missedAt, k + 1,
                              windows.size());
            } else {
                std::snprintf(text, sizeof text, "missed after %zu of %zu windows", k + 1, windows.size());
            }
            e->note = text;
            break;
        }
    }
    if (e->stoppedAtLimit) {
        // the note says so
    } else if (e->wholeRun && e->stable && std::isfinite(e->estimate) && raisedFrom < 0.0) {
        e->note = "measured over the whole run";
    } else if (e->wholeRun && e->stable && std::isfinite(e->estimate)) {
        char text[128];
        std::snprintf(text, sizeof text,
                      "measured over the whole run; raised from %.3g by the finer pair (a quarter step)", raisedFrom);
        e->note = text;
    }
    if (e->wholeRun && e->stable && !e->partial && std::isfinite(e->estimate) && first.pair >= 0.0) {
        const bool alongSubsteps = Refine(e->model, space).step == e->model.step;
        CheckOrder(first.pair, first.finer, first.noise, space, settings,
                   alongSubsteps ? "over the whole run, doubling its substeps" : "over the whole run", e);
    }
    e->cpuPerSimSecond = simulated > 0.0 ? cpu / simulated : 0.0;
}

/// The convergence checks of a candidate that meets the budget (CheckOrder). Estimated on windows: its start window
/// again with the refinement's refinement beside the pair (seven of its windows; event windows are not repeated).
/// Measured over the whole run, the pair was checked there (Evaluate). Where the refinement is not half the step (the
/// soft solver on a world of volumes doubles its substeps), the error must also shrink with the step itself: the
/// candidate, half its step and a quarter, same substeps, over the same span. A check cut short by the choice's CPU
/// limit leaves the candidate unchecked, so it is not chosen.
void VerifyOrder(const PlannedWindow& start, double window, const CandidateSpace& space, const ErrorBudget& budget,
                 const ChoiceSettings& settings, CandidateEstimate* e, double* cpuSeconds, double* work,
                 ChoiceClock* clock) {
    if (budget.quantity == BudgetQuantity::Constraint) return;
    const bool alongSubsteps = Refine(e->model, space).step == e->model.step;
    for (int pass = 0; pass < 2 && !e->unreliable; ++pass) {
        const bool byStep = pass == 1;
        if ((pass == 0 && e->wholeRun) || (byStep && !alongSubsteps)) continue;
        WindowOptions o;
        o.warmSteps = start.warmSteps;
        o.wholeRun = e->wholeRun;
        o.third = true;
        o.clock = clock;
        o.byStep = byStep;
        const WindowResult w =
            RunWindow(start.factory, e->model, space, budget, e->wholeRun ? settings.runSeconds : window, o);
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
            byStep ? (e->wholeRun ? "over the whole run, halving its step" : "over the start window, halving its step")
                   : (alongSubsteps ? "over the start window, doubling its substeps" : "over the start window");
        const double before = e->estimate;
        CheckOrder(ok ? w.pair : kInf, ok ? w.finer : kInf, w.noise, space, settings, over, e);
        // Along the step, the pair's difference is the step's part of the error, which doubling the substeps did
        // not see: the estimate is at least that part with its Richardson factor (over a window, extrapolated as
        // the start window was).
        const double stepPart = e->wholeRun
                                    ? w.factor * w.pair
                                    : w.factor * w.pair * std::pow(std::max(start.span / window, 1.0), e->growth);
        if (byStep && !e->unreliable && stepPart > before) {
            char text[200];
            std::snprintf(text, sizeof text, "raised from %.3g: half its step differs by %.3g (%s)", before, w.pair,
                          e->wholeRun ? "over the whole run" : "over the start window");
            e->estimate = stepPart;
            e->note = text;
        }
    }
}

/// A window estimate can miss what a whole run sees (a period error that grows past the window, an impact a
/// cloth's windows fall short of). When coarser steps of the candidate's family, with the same passes, were measured
/// over the whole run, the candidate's error is taken to be at least what the nearest of them predicts. The order
/// of that prediction is the one the family showed between its two nearest such rungs, kept between 1 and the
/// formal order (a joint's projection makes RK4 first order; one rung alone, or errors that did not shrink, give
/// 1): an error shrinks no faster than that as the step does. The note says when the floor raised the estimate.
void RaiseToFamilyFloor(const std::vector<CandidateEstimate>& candidates, const std::vector<std::size_t>& order,
                        std::size_t k, const CandidateSpace& space, CandidateEstimate* e) {
    if (e->wholeRun || !e->stable || !std::isfinite(e->estimate)) return;
    const CandidateEstimate* nearest = nullptr;  // the finest whole-run rung coarser than e
    const CandidateEstimate* next = nullptr;     // the one after it
    for (std::size_t j = 0; j < k; ++j) {
        const CandidateEstimate& f = candidates[order[j]];
        if (!f.evaluated || !f.wholeRun || !f.stable || f.partial || !std::isfinite(f.estimate) ||
            !SameFamily(f.model, e->model) || Passes(f.model) != Passes(e->model) || f.model.step <= e->model.step) {
            continue;
        }
        if (!nearest || f.model.step < nearest->model.step) {
            next = nearest;
            nearest = &f;
        } else if (!next || f.model.step < next->model.step) {
            next = &f;
        }
    }
    if (!nearest) return;
    double p = 1.0;
    if (next && nearest->estimate > 0.0 && next->estimate > nearest->estimate) {
        p = std::log(next->estimate / nearest->estimate) / std::log(next->model.step / nearest->model.step);
    }
    p = std::clamp(p, 1.0, static_cast<double>(OrderOf(e->model, space)));
    const double floor = nearest->estimate * std::pow(e->model.step / nearest->model.step, p);
    if (floor <= e->estimate) return;
    char text[192];
    std::snprintf(text, sizeof text,
                  "raised from %.3g: its family's dt %g s, measured over the whole run, predicts %.3g (order %.2g)",
                  e->estimate, nearest->model.step, floor, p);
    e->estimate = floor;
    e->note = text;
}

/// The candidate a refusal names: the smallest complete and reliable estimate; one that is a lower bound (a window
/// stopped at a miss or at the CPU limit) or unreliable only while there is none.
void KeepBest(ModelChoiceResult* result, int index) {
    const CandidateEstimate& e = result->candidates[static_cast<std::size_t>(index)];
    if (!e.stable || !std::isfinite(e.estimate)) return;
    auto rank = [](const CandidateEstimate& c) { return c.partial || c.unreliable ? 1 : 0; };
    const CandidateEstimate* b =
        result->best >= 0 ? &result->candidates[static_cast<std::size_t>(result->best)] : nullptr;
    if (!b || rank(e) < rank(*b) || (rank(e) == rank(*b) && e.estimate < b->estimate)) result->best = index;
}

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
    // Ties keep enumeration order (the index breaks them; std::sort, as libstdc++'s stable_sort buffer trips ASan's
    // alloc-dealloc check).
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const double wa = result.candidates[a].predictedWork, wb = result.candidates[b].predictedWork;
        return wa < wb || (wa == wb && a < b);
    });
    const double window = WindowFor(settings);
    result.windowSeconds = window;
    const double bound = budget.bound / settings.safety;
    ChoiceClock clock(settings);
    const std::vector<PlannedWindow> plan = PlanWindows(factory, space, settings, window, &result, &clock);
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
        if (result.evaluatedShare >= settings.maxEvaluations) {
            e.note = "not run: evaluation limit reached";
            continue;
        }
        ++result.evaluatedCount;
        e.evaluated = true;
        clock.Candidate(e.predictedWork * settings.runSeconds, e.model.Describe(space.hasParticles, space.hasVolumes));
        Evaluate(plan, window, space, budget, settings, bound, &e, &result.calibrationCpuSeconds,
                 &result.calibrationWork, &clock);
        result.evaluatedShare += e.share;
        RaiseToFamilyFloor(result.candidates, order, k, space, &e);
        if (e.stable && !e.partial && !e.unreliable && e.estimate <= bound) {
            const double before = result.calibrationWork;
            VerifyOrder(plan[0], window, space, budget, settings, &e, &result.calibrationCpuSeconds,
                        &result.calibrationWork, &clock);
            result.checkWork += result.calibrationWork - before;
        }
        result.unreliableCount += e.unreliable ? 1 : 0;
        result.stoppedAtLimit = result.stoppedAtLimit || e.stoppedAtLimit;
        e.meets = e.stable && !e.partial && !e.unreliable && e.estimate <= bound;
        if (e.meets) result.chosen = static_cast<int>(order[k]);
        KeepBest(&result, static_cast<int>(order[k]));
    }
    result.feasible = result.chosen >= 0;
    result.cpuLimit = clock.Limit(0.0, 0.0);
    return result;
}

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

double ModelWatch::CheckWindow() const { return settings.checkWindowFraction * WindowFor(settings); }

bool ModelWatch::WantsSnapshot(double time) const {
    return !wholeRun && settings.maxEventChecks > 0 && time >= snapshotTime + 0.5 * CheckWindow() - 1e-9 &&
           time < settings.runSeconds - 1e-9;
}

void ModelWatch::TakeSnapshot(double time, ProbeFactory factory) {
    // The one before the newest is kept too: an event is checked from a snapshot at least half a window before it.
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
    if (time <= WindowFor(settings) + 1e-9) {
        baseline = std::max(baseline, jump);  // what the calibration window saw
    } else if (jump > 30.0 * baseline && jump > 1e-6 && eventChecks < settings.maxEventChecks && !eventPending) {
        eventPending = true;
        eventTime = time;
    }
}

bool ModelWatch::Check(double time, const ProbeFactory& factory, std::string* log) {
    if (!Due(time)) return false;
    const double T = settings.runSeconds;
    const bool event = eventPending && snapshot;
    // An event is checked from the snapshot taken at least half a window before it, over the rest of the run; a
    // periodic check from the world as it is, for the time since the last check.
    const ProbeFactory& from = event && previousSnapshot && snapshotTime > eventTime - 0.5 * CheckWindow()
                                   ? previousSnapshot
                                   : (event ? snapshot : factory);
    const double from_time = event ? (&from == &previousSnapshot ? previousSnapshotTime : snapshotTime) : time;
    // At least four steps measured, so the window's growth is fitted from more than two samples.
    const double window = std::min(T - from_time, std::max(CheckWindow(), 4.0 * current.step));
    if (event) {
        eventPending = false;
        ++eventChecks;
    } else {
        lastCheck = time;
    }
    if (!(window > 0.0)) return false;
    // Probes from a live world with volumes lack its contact history (no warm start): they settle first, unmeasured.
    const int warm = space.hasVolumes ? std::max(3, static_cast<int>(window / 3.0 / current.step)) : 0;
    WindowOptions o;
    o.warmSteps = warm;
    o.fixedGrowth = budget.quantity == BudgetQuantity::Position ? -1.0 : growth;
    const WindowResult w = RunWindow(from, current, space, budget, window, o);
    cpuSeconds += w.probeCpuSeconds;
    work += w.work;
    ++checks;
    const bool ok = w.stable && std::isfinite(w.observed);
    double latest = 0.0;  // what this window adds (position) or its whole-run estimate (energy, constraint)
    if (budget.quantity == BudgetQuantity::Position) {
        // A periodic window's rate stands for the time since the last check; an event's difference grows over the
        // rest of the run; the calibration's estimate, scaled for refinements since, stands for the rest.
        const double span = event ? T - from_time : time - lastCounted;
        if (!event) lastCounted = time;
        // Extrapolated with the window's own growth (a settled stack's jitter does not add up).
        latest = ok ? w.factor * w.observed * std::pow(std::max(span / w.length, 1.0), w.growth) : kInf;
        measured += latest;
        running = measured + predicted * scale * (T - time) / T;
    } else {
        // Energy and constraint: the window's regime taken as the whole run's (with the calibration's growth), for
        // the current model's share of the run, plus what earlier models left.
        const double estimate = ok ? (budget.quantity == BudgetQuantity::Constraint
                                          ? w.observed
                                          : w.factor * w.observed * std::pow(std::max(T / w.length, 1.0), growth))
                                   : kInf;
        lastEstimate = std::max(event ? lastEstimate : 0.0, estimate);
        latest = estimate;
        running = carried + lastEstimate * (T - modelStart) / T;
    }
    // The model was chosen with the safety factor's margin; it is changed only when the estimate says the budget
    // itself will be missed (a margin, so a model chosen near the edge does not flip on window-to-window noise).
    if (running <= budget.bound) {
        missed = false;
        return false;
    }
    // Unless the model is refined below, the run misses its budget as things stand (Missed).
    if (!missed) missedAt = time;
    missed = true;
    // What earlier windows measured (or earlier models left) is made. While it is under three times the budget,
    // refining still keeps the end near it; beyond, no finer model can: say so once and stop refining (it would
    // only cost).
    const double made = budget.quantity == BudgetQuantity::Position ? measured : carried;
    // A window that itself misses the budget (or blew up) is refined whatever was lost: the model is making large
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
        return false;
    }
    // A finer model changes only the current model's part of the estimate: what its latest window adds and the
    // rest of the run it stands for. When that is less than what earlier windows and models left (which no
    // refinement undoes), a refinement would take off less than half of the estimate (a quarter at first order) at
    // twice the cost: the model stays, unless its window itself misses the budget.
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
        return false;
    }
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
                  w.length, from_time, w.observed, current.Describe(space.hasParticles, space.hasVolumes).c_str(),
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
