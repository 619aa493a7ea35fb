#pragma once
// The estimator's internals shared by Physics/ModelChoice/Choose.cpp (the choice), Physics/ModelChoice/Watch.cpp (the
// live watch) and Physics/ModelChoice/Calibration.cpp (one span of probes): docs/model-choice.md. Not for use outside
// those files.

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "Physics/ModelChoice/ModelChoice.h"

namespace model_choice {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// s of CPU of the whole process: a probe on a world with threads (WorldSettings::threads) spends some on the job
/// pool's workers, which the choice's CPU limit counts too.
double ProcessCpuSeconds();
/// Formal order of accuracy of a candidate on a space: contact (volumes or particles bouncing off constraints) and
/// joints' projections make it first order; otherwise the integrator's.
int OrderOf(const ModelCandidate& c, const CandidateSpace& space);
/// Richardson factor: with the refinement's error 2^-p of the candidate's, the candidate's error is the
/// difference times 1 / (1 - 2^-p).
double RichardsonFactor(int order);
/// Contact passes of a candidate: soft substeps or solver iterations.
int Passes(const ModelCandidate& c);
/// Candidates of the same family (integrator and solver) that differ only in step and passes.
bool SameFamily(const ModelCandidate& a, const ModelCandidate& b);
/// s: the calibration span of a run.
double SpanFor(const ChoiceSettings& s);
/// The level at which a difference is rounding (float states) after `steps` steps: relative for energy, scaled by
/// the largest coordinate (at least 1 m) for positions and joints.
double ConvergenceNoise(BudgetQuantity quantity, const std::vector<double>& positions, double steps);
/// A refinement that did not refine: on a world of volumes, the finer probe made fewer than 1.5 times the
/// candidate's volume (sub)steps over the same time (a halved step whose substeps are bound by travel takes the
/// same substeps: the two runs are the same run, and their difference, 0, estimates nothing).
bool Unrefined(const CandidateSpace& space, long long candidateUpdates, long long refinedUpdates);
constexpr const char* kUnrefined = "its refinement took no more volume substeps (bound by travel): no estimate";

/// A model's whole run from the start, kept for the candidates that share it (Physics/ModelChoice/WholeRuns.cpp):
/// its state at each end a candidate that runs it may measure at.
struct WholeRunRecord {
    struct AtEnd {
        double end = 0.0;  // s
        std::vector<double> positions;
        double energy = 0.0;          // J
        long long volumeUpdates = 0;  // ModelProbe::VolumeUpdates at this end
    };
    ModelCandidate model;
    long long failStep = -1;  // the step (1-based) at which it blew up or stopped, else < 0
    std::vector<AtEnd> ends;
    double cpuSeconds = 0.0;  // its own run's
    const AtEnd* At(double end) const {
        for (const AtEnd& a : ends) {
            if (a.end == end) return &a;
        }
        return nullptr;
    }
};
/// The whole runs of one choice, all from its start (the calibration's first span).
struct WholeRunCache {
    const WholeRunRecord* Find(const ModelCandidate& m) const;
    std::vector<WholeRunRecord> records;
};

/// The choice's CPU limit and its progress lines (ChoiceSettings::cpuLimit, runShare, progress). Spans report
/// what they cost when they end (Add, from the clock reads they make anyway); inside a span the clock is read only
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
    /// A finished piece of the choice (a span, the pilot): its CPU and predicted work.
    void Add(double cpuSeconds, double workUnits) {
        spent += cpuSeconds;
        work += workUnits;
        Report(0.0);
    }
    /// Inside a piece that started at process CPU `pieceStart` and has done `pieceWork` so far: true once the limit
    /// is spent (the piece then stops).
    bool Poll(double pieceStart, double pieceWork) {
        if (pieceWork < polledWork + kPollWork) return false;
        polledWork = pieceWork;
        const double now = ProcessCpuSeconds() - pieceStart;
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
    WholeRunCache runs;  ///< the choice's whole runs, shared between candidates (RunWholeShared)
    bool SharesWholeRuns() const { return settings.shareWholeRuns; }

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

/// What one span measured (RunSpan).
struct SpanResult {
    bool stable = true;
    double observed = 0.0;         // the largest sampled difference (or observed value) over the measured part
    double length = 0.0;           // s: the measured part
    double factor = 1.0;           // the Richardson factor
    double growth = 1.0;           // the exponent used
    double cpuSeconds = 0.0;       // candidate's probe only: the span's CPU apportioned by predicted work
    double probeCpuSeconds = 0.0;  // every probe of the span, built and run
    double simulated = 0.0;        // s the candidate's probe ran
    double work = 0.0;             // PredictedWork units both probes did (a deterministic measure of their cost)
    double pairObserved = -1.0;    // a whole run raised by its third probe: what the pair alone observed, else < 0
    double missedAt = -1.0;        // s into the measured part where it already missed `missBound`, else < 0
    double share = 1.0;            // the part of the span that ran (1 unless it stopped early)
    // The convergence check over a whole run: the pair's difference (the largest, or at the end for energy), the
    // finer pair's on the same terms, and the rounding level below which neither says anything.
    double pair = -1.0, finer = -1.0, noise = 0.0;
    bool stopped = false;  // cut short by the choice's CPU limit
    // Why a stable candidate has no estimate (observed infinite): its refinement blew up, or it integrated no finer,
    // making fewer than 1.5 times the candidate's volume (sub)steps (Unrefined, kUnrefined).
    const char* noEstimate = "its refinement blew up in the calibration";
};

/// How a span runs (RunSpan).
struct SpanOptions {
    int warmSteps = 0;
    double fixedGrowth = -1.0;  // >= 0: the growth exponent used instead of the span's own
    bool wholeRun = false;      // the span is the whole run (a third probe runs, energy is taken at the end)
    double missBound = -1.0;
    ChoiceClock* clock = nullptr;  // the choice's CPU limit (nullptr: none, as for the watch's checks)
    bool third = false;            // a third probe, at the refinement's refinement, also on a span
    bool byStep = false;           // refine by halving the step even where Refine doubles soft substeps
};

/// One span: the candidate and (unless the quantity is observed directly) its refinement run from the same state
/// for `span` seconds (Physics/ModelChoice/Calibration.cpp says how).
SpanResult RunSpan(const ProbeFactory& factory, const ModelCandidate& candidate, const CandidateSpace& space,
                   const ErrorBudget& budget, double span, const SpanOptions& o);

/// m/s: the fastest point between two sets of positions a step `h` apart (0 when they differ in size).
double FastestPoint(const std::vector<double>& now, const std::vector<double>& before, double h);

/// Adds a pilot run's CPU and work to the choice's calibration and its clock.
void AccountPilot(double cpuSeconds, double work, ModelChoiceResult* result, ChoiceClock* clock);

/// Where a world of volumes estimated on spans first makes contact, when it starts in free flight and the start span
/// ends before it (Physics/ModelChoice/Onset.cpp): a pilot run of the scene's own model up to its first colliding
/// pair, its snapshots taken while nothing touched (a probe from one lacks no contact history). `from` builds probes
/// from the snapshot a span covering the onset starts at, `start` s into the run (< 0: no such onset; a world of one
/// volume has none, being measured over the whole run), also added to result->eventTimes. The pilot's cost is added to
/// *result and the clock.
struct ContactOnset {
    ProbeFactory from;
    double start = -1.0;
};
ContactOnset FindContactOnset(const ProbeFactory& factory, const CandidateSpace& space, const ChoiceSettings& settings,
                              double span, ModelChoiceResult* result, ChoiceClock* clock);

/// RunSpan over the whole run from the choice's start (SpanOptions::wholeRun, a position or energy budget, with the
/// choice's clock): the same figures as the side-by-side span, each of the three probes' runs kept in the clock's
/// WholeRunCache and run once per choice (Physics/ModelChoice/WholeRuns.cpp).
SpanResult RunWholeShared(const ProbeFactory& factory, const ModelCandidate& candidate, const CandidateSpace& space,
                          const ErrorBudget& budget, double span, const SpanOptions& o);
/// A whole run judged at its end (SpanRun: energy and position budgets; not a position budget whose impacts are
/// timed inside their step, judged by the largest difference over the run; not constraint error, observed).
bool JudgedAtEnd(const SpanOptions& o, const ErrorBudget& budget, const CandidateSpace& space);
/// Steps a candidate's positions are advanced by per simulated second (soft substeps on volumes).
double UpdatesPerSecond(const ModelCandidate& c, const CandidateSpace& space);
/// The refinement a span uses: Refine, or half the step (`byStep`).
ModelCandidate RefineFor(const ModelCandidate& c, const CandidateSpace& space, bool byStep);

/// FamilyFloor: what the nearest coarser whole-run rung of e's family with the same passes predicts for e, at the
/// order its two nearest such rungs showed, kept between 1 and the formal order (floor 0: no such rung); that rung's
/// step and the order used. Rungs are the candidates before order[k] (Physics/ModelChoice/Rungs.cpp).
struct FamilyPrediction {
    double floor = 0.0, step = 0.0, order = 1.0;
};
FamilyPrediction FamilyFloor(const std::vector<CandidateEstimate>& candidates, const std::vector<std::size_t>& order,
                             std::size_t k, const CandidateSpace& space, const CandidateEstimate* e);
/// Why order[k], `e`, is predicted to miss `bound` by more than 8x from `nearest`, the nearest coarser rung of its
/// family with the same passes that was estimated (empty: it is not; Physics/ModelChoice/Rungs.cpp).
std::string PredictedMiss(const ModelChoiceResult& result, const std::vector<std::size_t>& order, std::size_t k,
                          const CandidateEstimate& nearest, const CandidateEstimate& e, const CandidateSpace& space,
                          double bound);

}  // namespace model_choice
