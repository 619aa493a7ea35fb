#pragma once
// The error budget (docs/model-choice.md): a scene states the accuracy it needs, and the cheapest model whose
// estimated error meets it is chosen from the scene itself, then kept under watch while the run goes on.
//
// A model is one candidate: integrator x step x contact-solver passes (iterations or soft substeps) x contact
// solver. Its error is estimated by step doubling on the actual scene: the candidate and its refinement (half the
// step, twice the passes) run side by side from the same state over a calibration span, and the difference, with
// a Richardson factor for the candidate's order and an extrapolation in time fitted from the two halves of the
// span, is the estimate at the end of the run. During the run the refinement runs again over short spans from
// the live state; when the projected end-of-run error leaves the budget, the model is refined and the switch logged.
//
// Nothing here knows a scene: a probe is a copy of the host's world made in the physics layer (ProbesOf,
// Physics/WorldCopy.h), or whatever ProbeFactory a caller hands in (the tests). GL-free.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "Physics/ContactSolver.h"
#include "Physics/Integrator.h"

class PhysicsSystem;

/// What an error budget bounds.
enum class BudgetQuantity {
    Position,    ///< m: the largest distance of any body (particle, volume, cloth particle) from where it should be
    Energy,      ///< relative: |E - E_reference| / |E0| of the world's mechanical energy at the end of the run
    Constraint,  ///< m: the largest violation of a distance joint or spring-free constraint seen during the run
};
/// "position", "energy", "constraint".
const char* ToString(BudgetQuantity quantity);
/// Parses an id from ToString; false (output untouched) for anything else.
bool ParseBudgetQuantity(const std::string& text, BudgetQuantity* out);

/// A scene's accuracy request.
struct ErrorBudget {
    BudgetQuantity quantity = BudgetQuantity::Position;
    double bound = 0.0;  ///< in the quantity's unit; finite and > 0
};
/// False, with *error naming the bad value, unless the bound is finite and positive.
bool ValidateBudget(const ErrorBudget& budget, std::string* error);

/// One model the sandbox could run a scene with.
struct ModelCandidate {
    Integrator integrator = Integrator::SemiImplicitEuler;  ///< particles, cloth and joints
    ContactSolver solver = ContactSolver::Book;             ///< rigid volumes
    double step = 0.03;                                     ///< s, one physics step
    int iterations = 5;                                     ///< book and accumulated solvers: passes per step
    int softSubsteps = 4;                                   ///< soft solver: substeps per step
    /// One line: "rk4, dt 0.02 s" / "soft solver 8 substeps, dt 0.03 s": the integrator when `particles`, the
    /// solver and its passes when `volumes`, and the step.
    std::string Describe(bool particles = true, bool volumes = true) const;
};

/// What the candidates may vary: each list holds the values the host can set and the scene needs (a world
/// without volumes varies no solver; a host without a step key keeps its one step). An empty list keeps `base`'s.
struct CandidateSpace {
    ModelCandidate base;
    std::vector<Integrator> integrators;
    std::vector<double> steps;  ///< s
    std::vector<ContactSolver> solvers;
    std::vector<int> iterations;    ///< book and accumulated solvers only
    std::vector<int> softSubsteps;  ///< soft solver only
    bool hasParticles = false;      ///< the world has particles (free, cloth or jointed): the integrator matters
    bool hasVolumes = false;        ///< the world has rigid volumes: the contact solver matters
    bool hasContacts = false;       ///< particles can hit constraints (non-smooth: first order at best)
    /// Particles on the book's distance joints (JointModel::Book): each step projects their positions back onto the
    /// joint and drops the velocity along it, a first-order splitting whatever the integrator (docs/model-choice.md,
    /// "The candidates"). False for JointModel::Tension, whose joints keep the integrator's order.
    bool hasJoints = false;
    /// Particles on tension joints (JointModel::Tension): the integrator's order. Tension pulls only under velocity
    /// Verlet and RK4 (TensionKeepsOrder); position Verlet, whose history the joint's projection restarts every step,
    /// stays first order (docs/ch16.md).
    bool hasTensionJoints = false;
    /// m: how far off a constraint's surface a particle that hits it is put (Particle::kContactOffset; 0: none). A
    /// bias against the rigid answer that no step removes: a position estimate is at least this once particles hit.
    double contactOffset = 0.0;
    /// The particle contact finds each impact's time inside its step (ParticleContact::Reflect): an impact's timing
    /// error is second order, not the up-to-a-step shift RaiseToImpactTiming allows for otherwise.
    bool impactsTimedInStep = false;
    // Counts for the work model (PredictedWork).
    double particleCount = 0.0;  ///< free and cloth particles
    double springCount = 0.0;    ///< springs, cloth springs included, and joints
    double volumeCount = 0.0;    ///< dynamic volumes
};
/// Every combination the space allows, in a fixed order (the estimator's order is by cost, not this).
std::vector<ModelCandidate> EnumerateCandidates(const CandidateSpace& space);
/// The candidate's refinement used to estimate its error: twice the substeps for the soft solver on a world of
/// volumes only, else half the step. Either costs twice the candidate.
ModelCandidate Refine(const ModelCandidate& candidate, const CandidateSpace& space);
/// Deterministic work per simulated second of a candidate on a space (force evaluations, integrations and contact
/// passes per step, over the step): the order in which candidates are tried, and "cheapest". Never timing, so the
/// same scene always gets the same model.
double PredictedWork(const ModelCandidate& candidate, const CandidateSpace& space);
/// "m" or "(relative)".
const char* BudgetUnit(BudgetQuantity quantity);

class ModelProbe;
/// Builds a probe, a fresh copy of the scene at the state of the moment the factory was made.
using ProbeFactory = std::function<std::unique_ptr<ModelProbe>()>;

/// A fresh copy of the scene that the estimator can run.
class ModelProbe {
public:
    virtual ~ModelProbe() = default;
    /// Sets the model (before the first Advance).
    virtual void Apply(const ModelCandidate& model) = 0;
    /// Runs whole steps of the model's step until `seconds` of simulated time have passed since the probe was
    /// made (never past it); false once the world blew up (the stability monitor) or a state is non-finite.
    virtual bool AdvanceTo(double seconds) = 0;
    /// The probe's world (for WorldPositions, WorldEnergy, WorldConstraintError).
    virtual const PhysicsSystem& World() const = 0;
    /// A factory of probes that start from this probe's world as it is now.
    virtual ProbeFactory Snapshot() const = 0;
    /// Volume (sub)steps made since Apply (PhysicsSystem::LastVolumeSubsteps summed; one per step without volumes):
    /// how finely the probe really integrated, which a halved step does not change where substeps are bound by travel.
    virtual long long VolumeUpdates() const { return 0; }
};
/// Probes over `world` as it is at the factory's first call: that state is copied once (WorldCopy) and each probe
/// runs its own copy of it. `world` must outlive the factory's first call.
ProbeFactory ProbesOf(const PhysicsSystem& world);
/// Probes over `world` as it is now (copied at once): a snapshot the watch keeps for later.
ProbeFactory ProbesNow(const PhysicsSystem& world);
/// Every body's position as x, y, z triples: particles and volumes in insertion order, then cloth particles.
void WorldPositions(const PhysicsSystem& world, std::vector<double>* out);
/// J: kinetic energy of particles (cloth included) and volumes (linear and angular), gravitational potential
/// energy (-m g . x), and spring energy (k (l - rest)^2 / 2 with the book's sign convention). Static bodies
/// (mass 0) count nothing.
double WorldEnergy(const PhysicsSystem& world);
/// m: the largest |length - rest length| of any distance joint; 0 without joints.
double WorldConstraintError(const PhysicsSystem& world);

/// How the estimator works; every number has its unit and the default is the documented one.
struct ChoiceSettings {
    double runSeconds = 10.0;  ///< s: the run's simulated length (the estimate is for its end)
    /// Fraction of the run used to calibrate, and its floor and ceiling (s); the span is whole steps of each
    /// candidate (at least two) and never longer than the run. Every candidate tried costs about three spans of
    /// its own run (itself and its refinement at half the step), so the span is short.
    double spanFraction = 0.05;
    double minSpan = 0.2;
    double maxSpan = 2.0;
    /// Worlds without volumes: at most this many more calibration spans, each from a snapshot of a pilot run of the
    /// scene's own model just before an event (a bounce, an impact) the start span cannot see; 0 = none.
    int eventSpans = 3;
    /// The live watch also looks for events (a frame whose irregularity is ten times what the calibration span
    /// saw: a bounce, an impact, a cloth reaching an obstacle; thirty times, the watch being on the host's frames) and
    /// checks the model over each, from a snapshot taken before it; at most this many event checks per run (0: none,
    /// and no snapshots are taken).
    int maxEventChecks = 6;
    /// A world without volumes or with one whose candidate, run beside its refinement and a third probe at a quarter
    /// of its step over the whole run, costs at most this many PredictedWork units is estimated over the whole run
    /// instead of spans: the difference at the run's end, measured rather than extrapolated (a bounce's or a
    /// period's error, which a span cannot see). About 0.13 s of CPU for a particle world; 0: never.
    double wholeRunWork = 5e6;
    /// Whole runs are shared between candidates: each model's run from the start is made once per choice and kept
    /// (the soft solver's refinement, twice the substeps, is the next candidate of its family). False runs each
    /// candidate's three probes side by side, for the same figures at a higher cost (a comparison).
    bool shareWholeRuns = true;
    /// A calibration span (not a whole run) stops at the first sample whose difference alone already misses the
    /// budget: the candidate misses, and the rest of the span would only say by how much. False runs every
    /// span to its end (the same choice at a higher cost, as a comparison).
    bool stopSpansAtMiss = true;
    /// A candidate meets the budget when safety * estimate <= bound.
    double safety = 2.0;
    /// When none meets it, the candidate of the smallest estimate within the bound itself runs, if its estimate is
    /// complete and its order was observed (a finer pair above rounding): ChooseModel's margin fallback
    /// (docs/model-choice.md, "The margin"). False refuses instead.
    bool marginFallback = true;
    /// Candidates estimated at most (the rest are reported as not run): a bound on the calibration of a budget
    /// nothing meets. A candidate whose span stopped early at a miss counts for the part of its spans that
    /// ran. The validation's cases need at most 66 (the incline at 1e-3, whose whole runs never stop early; the
    /// tower of 10 at 1e-3 estimates 122 candidates for 8.4 candidates' worth, a world of volumes having up to
    /// 180); 60 whole candidates refused the incline and the tower of 10 at 1e-3, which finer candidates meet.
    int maxEvaluations = 100;
    /// The live check: a span of this fraction of the calibration span, run every `checkEvery` seconds of
    /// simulated time (0 = a sixth of the run).
    double checkSpanFraction = 0.3;
    double checkEvery = 0.0;
    /// The convergence check: a candidate's difference from its refinement over the refinement's from its own
    /// refinement must be at least 2^(p - orderBand), p the order the candidate is estimated at (the error shrinks
    /// about as that order says). A candidate below is unreliable and never chosen. Differences both within
    /// rounding (ConvergenceNoise) are not compared.
    double orderBand = 0.5;
    /// s of CPU the choice may spend (calibration, convergence checks and a refusal): where `runShare` times the
    /// predicted CPU of the candidate being estimated is more, that instead (a choice costs at most half the run it
    /// chooses). Past it the choice stops, and refuses unless a candidate already met the budget. Tests set a tiny
    /// limit and a zero share to test the stop without depending on timing.
    double cpuLimit = 1.0;
    double runShare = 0.5;
    /// Called with a line of progress (what is being estimated, the CPU spent against the limit) at most once per
    /// `progressEvery` s of wall time while the choice runs; the first after that long. Empty: no progress.
    std::function<void(const std::string&)> progress;
    double progressEvery = 1.0;
};

/// One candidate as the estimator saw it.
struct CandidateEstimate {
    ModelCandidate model;
    double estimate = 0.0;         ///< the budget's quantity at the end of the run, estimated (inf: unstable)
    double predictedWork = 0.0;    ///< PredictedWork: what "cheapest" means
    double cpuPerSimSecond = 0.0;  ///< s CPU per simulated s: its spans' CPU x its share of their work (reported)
    double growth = 0.0;           ///< the error's fitted growth exponent in time
    bool evaluated = false;        ///< false: skipped (its predicted cost was above the chosen one's)
    bool stable = true;
    bool meets = false;     ///< safety * estimate <= bound
    bool partial = false;   ///< the estimate stopped at a span where it already missed (a lower bound)
    bool wholeRun = false;  ///< estimated over the whole run (ChoiceSettings::wholeRunWork), not spans
    double share = 0.0;     ///< the part of its spans that ran (below 1 when one stopped at a miss)
    /// The convergence check (ChoiceSettings::orderBand): the candidate's largest difference from its refinement
    /// and the refinement's from its own (over the whole run, or over the start span), when it was run (< 0: not).
    double pairDifference = -1.0;
    double finerDifference = -1.0;
    bool unreliable = false;  ///< its error did not shrink at its order: never chosen
    /// The check passed only because the finer pair's difference is within the rounding its many steps can make:
    /// it says nothing of the order, so the estimate is also held to what its family's coarser steps predict.
    bool withinRounding = false;
    bool stoppedAtLimit = false;   ///< its estimate was cut short by the choice's CPU limit
    std::vector<double> segments;  ///< each span's share of the estimate (start span first)
    std::string note;              ///< why skipped, or why the estimate is not trusted
};

/// What ChooseModel found.
struct ModelChoiceResult {
    bool feasible = false;  ///< a candidate meets the budget
    int chosen = -1;        ///< index into candidates of the cheapest that meets it (-1 when none)
    int best = -1;          ///< index of the candidate with the smallest estimate (for the refusal message)
    std::vector<CandidateEstimate> candidates;  ///< every candidate, in EnumerateCandidates order
    double calibrationCpuSeconds = 0.0;         ///< s of CPU spent on probes, the pilot included
    double pilotCpuSeconds = 0.0;               ///< s of CPU of the pilot run (worlds without volumes)
    /// PredictedWork units the probes and the pilot did: the calibration's cost, deterministic (CPU time is not).
    double calibrationWork = 0.0;
    std::vector<double> eventTimes;  ///< s: where the calibration's event spans start
    int evaluatedCount = 0;          ///< candidates estimated
    double evaluatedShare = 0.0;     ///< their spans that ran, in candidates (ChoiceSettings::maxEvaluations)
    double spanSeconds = 0.0;        ///< s of simulated time per calibration run
    /// The choice stopped at its CPU limit (ChoiceSettings::cpuLimit), which was `cpuLimit` s when it stopped.
    bool stoppedAtLimit = false;
    double cpuLimit = 0.0;
    int unreliableCount = 0;  ///< candidates whose error did not shrink at their order
    /// The chosen candidate met the budget but not its margin (ChoiceSettings::marginFallback).
    bool withinMarginOnly = false;
    double checkWork = 0.0;  ///< the part of calibrationWork spent on convergence checks (VerifyOrder)
};

/// Estimates every candidate on probes from `factory` (cheapest first, skipping those predicted to cost more
/// than the cheapest that already meets the budget) and picks the cheapest that meets it.
ModelChoiceResult ChooseModel(const ProbeFactory& factory, const CandidateSpace& space, const ErrorBudget& budget,
                              const ChoiceSettings& settings);

/// The live watch: after the choice, call Check at each frame with the simulated time since the start and a
/// factory that builds probes from the world as it is now. It runs the current model and its refinement over a
/// short span every settings.checkEvery seconds, keeps the running estimate (the error of earlier models for their
/// share of the run plus the current model's span extrapolated with the calibration's growth) and, when it
/// exceeds the budget itself, refines the model (the next smaller step, else more passes).
namespace model_choice {
struct SpanResult;  // Internals.h: one span's run
}  // namespace model_choice
class ModelWatch {
public:
    ModelWatch(const CandidateSpace& space, const ErrorBudget& budget, const ChoiceSettings& settings,
               const CandidateEstimate& chosen);
    /// True when the model changed at this call: then Current() is the new model and *log says when and why.
    /// *log is also set (and false returned) when the estimate left the budget but no finer model exists.
    bool Check(double time, const ProbeFactory& factory, std::string* log);
    /// True when Check at `time` would run a span (so a host builds its factory only then).
    bool Due(double time) const;
    /// After each frame, before Check: the host's world at `time` (s), for event detection.
    void Observe(double time, const PhysicsSystem& world);
    /// True when the host should hand in a snapshot of its world as it is now (TakeSnapshot), every half check
    /// span, so an event can be checked from before it.
    bool WantsSnapshot(double time) const;
    void TakeSnapshot(double time, ProbeFactory snapshot);
    const ModelCandidate& Current() const { return current; }
    /// The running estimate of the error at the end of the run, in the budget's unit.
    double RunningEstimate() const { return running; }
    /// s of CPU spent on the watch's probes so far.
    double CpuSeconds() const { return cpuSeconds; }
    /// Checks run so far.
    int Checks() const { return checks; }
    /// PredictedWork units the watch's probes did so far (deterministic).
    double Work() const { return work; }
    /// The current model's predicted work per simulated second.
    double CurrentWork() const { return PredictedWork(current, space); }
    /// Model changes so far.
    int Switches() const { return switches; }
    /// True when the latest check found the running estimate over the budget and did not refine the model (no
    /// finer setting, the error already made, or a finer model would take off little): as things stand the run
    /// misses its budget. MissedAt is the time (s) of the first such check in a row; the estimate is
    /// RunningEstimate(). A later check under the budget, or a refinement, clears it.
    bool Missed() const { return missed; }
    double MissedAt() const { return missedAt; }

private:
    CandidateSpace space;
    ErrorBudget budget;
    ChoiceSettings settings;
    ModelCandidate current;
    double CheckSpan() const;
    // Check's parts: run the span (false: none left to run), fold it into the running estimate (returns what the
    // span adds, or its whole-run estimate), keep the model though the estimate is over (true, *log set once), or
    // refine it (true when it changed).
    bool RunCheckSpan(double time, bool event, const ProbeFactory& factory, double* fromTime,
                      model_choice::SpanResult* out);
    double Account(const model_choice::SpanResult& w, bool event, double fromTime, double time);
    bool KeepsModel(double time, double latest, std::string* log);
    bool RefineModel(double time, bool event, double fromTime, const model_choice::SpanResult& w, std::string* log);

    double running = 0.0;
    double predicted = 0.0;     // the calibration's estimate for the chosen model over the whole run
    double scale = 1.0;         // predicted error ratio of the current model to the chosen one
    double measured = 0.0;      // position: the checks' estimate for the time before the last one
    double lastCounted = 0.0;   // s: position: up to where periodic checks have counted
    double carried = 0.0;       // energy, constraint: what earlier models left, each for its share of the run
    double lastEstimate = 0.0;  // energy, constraint: the last check's whole-run estimate
    double modelStart = 0.0;    // s: when the current model took over
    double growth = 1.0;        // the calibration's fitted growth exponent, used for every check
    bool wholeRun = false;      // the choice was measured over the whole run: nothing is left to check
    double lastCheck = 0.0;     // s
    double cpuSeconds = 0.0;
    double work = 0.0;
    int switches = 0;
    bool lostReported = false;  // the error already made exceeds the budget (said once)
    bool keptReported = false;  // a check kept the model, as a finer one would change little (said once)
    bool missed = false;        // Missed
    double missedAt = 0.0;      // s
    // Events: the host's last three frames' positions and the last acceleration, the irregularity the calibration
    // span saw, the pending event, and the two newest snapshots.
    std::vector<double> x0, x1, x2, acceleration;
    double lastObserved = 0.0, lastInterval = 0.0;
    long long observed = 0;
    double baseline = 0.0;
    bool eventPending = false;
    double eventTime = 0.0;
    int eventChecks = 0;
    ProbeFactory snapshot, previousSnapshot;
    double snapshotTime = 0.0, previousSnapshotTime = 0.0;
    int checks = 0;
};
