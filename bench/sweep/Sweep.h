#pragma once
// psb-sweep: reference problems with exact (or converged) answers, each run over the settings that matter to
// it, one CSV row per run. A problem builds its world directly on the Physics API, steps it, and
// reports one error number, whether the state stayed finite and bounded, and the CPU time of the stepping
// alone (setup, references and error evaluation are not timed).

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "Physics/ContactSolver.h"
#include "Physics/Integrator.h"

namespace sweep {

/// One point of a problem's grid. Fields a problem does not use keep their "n/a" values and print as "-".
struct Settings {
    bool hasIntegrator = false;  ///< particle problems: PhysicsSystem::integrator; volumes always use their own
    Integrator integrator = Integrator::SemiImplicitEuler;
    double dt = 0.01;     ///< s per frame
    int substeps = 1;     ///< PhysicsSystem::Update calls of dt / substeps per frame
    int iterations = -1;  ///< PhysicsSystem::ImpulseIteration; -1 = not used
    int projection = -1;  ///< PhysicsSystem::DoLinearProjection as 0/1; -1 = not used
    int solver = -1;      ///< PhysicsSystem::contactSolver as int(ContactSolver); -1 = not used
    /// WorldSettings::soft of the run (the soft solver's own substeps and passes); written to the CSV, and used,
    /// only when solver is ContactSolver::Soft.
    SoftSolverSettings soft;
    double param = 0.0;  ///< the problem's swept physical parameter (stiffness, mass ratio, e); 0 = none
};

/// What one run measured.
struct Outcome {
    double error = 0.0;       ///< the problem's error number (units in Problem::errorUnit); inf if unmeasurable
    bool stable = true;       ///< every sampled state finite and inside the problem's bounds
    double simSeconds = 0.0;  ///< simulated time actually run (shorter when stopped as unstable)
    double cpuSeconds = 0.0;  ///< thread CPU time of the stepping loop only
    long long steps = 0;      ///< PhysicsSystem::Update calls
    std::string note;         ///< e.g. the StabilityMonitor report; no commas
};

struct Problem {
    std::string name;
    std::string description;  ///< one line for --list
    std::string errorUnit;    ///< what `error` is, for --list and the docs
    std::string paramName;    ///< what Settings::param is ("" when unused)
    /// The settings to run: the full grid, or a few points for CI (--quick).
    std::function<std::vector<Settings>(bool quick)> grid;
    std::function<Outcome(const Settings&)> run;
    /// False: run only when named with --problem (the physics it needs does not give a meaningful answer yet).
    bool inDefault = true;
};

/// Every problem in a fixed order (the sweep and its shards rely on it).
const std::vector<Problem>& AllProblems();

// Registration, one function per source file.
void AddParticleProblems(std::vector<Problem>* out);
void AddRigidProblems(std::vector<Problem>* out);
void AddClothProblems(std::vector<Problem>* out);

/// The default step sizes, 1e-4 .. 0.1 s; every value divides 1 s and 2 s into whole steps.
const std::vector<double>& StepSizes();
/// A few of them for --quick.
const std::vector<double>& QuickStepSizes();
/// --dt: use these step sizes instead (e.g. a demo's 0.03 s); a step that does not divide a problem's
/// duration runs round(T / dt) steps and is compared with the reference at that time.
void OverrideStepSizes(const std::vector<double>& dts);

/// The bounce problems' error: the first five apex heights of a body dropped from h0 (m) with restitution e,
/// against h_n = e^(2n) h0 + c (1 - e^(2n)) / (1 - e^2) (c, m: a contact offset the engine adds at each bounce; 0 =
/// the textbook e^(2n) h0). Sample after every step; shared by psb-sweep and psb-model-choice-bench.
struct ApexTracker {
    ApexTracker(double restitution, double dropHeight, double offset) : e(restitution), h0(dropHeight), c(offset) {}
    double e = 0.0, h0 = 0.0, c = 0.0;
    double worst = 0.0;  ///< largest relative apex error so far
    int apexes = 0;
    /// y (m) and the vertical velocity (m/s) after a step: an apex is the highest point before vy turns to <= 0.
    void Sample(double y, double vy);
    bool Done() const { return apexes >= 5; }
    /// The largest relative error of the five; a missing apex counts as 100 %.
    double Error() const;

private:
    double peak = -std::numeric_limits<double>::infinity();
    bool rising = false;
};

/// Thread CPU time in seconds (CLOCK_THREAD_CPUTIME_ID).
double CpuNow();

/// Complete elliptic integral of the first kind K(k) = pi / (2 AGM(1, sqrt(1 - k^2))), for 0 <= k < 1.
double EllipticK(double k);
/// Period of a simple pendulum of length L (m) released from rest at theta0 (rad) under gravity g (m/s^2):
/// 4 sqrt(L/g) K(sin(theta0/2)). Exact, any amplitude below pi.
double PendulumPeriod(double length, double g, double theta0);

}  // namespace sweep
