#pragma once
// `model: auto` for any host with a parameter table and a world (docs/model-choice.md): the demos and scene files.
// The candidates are what the host's `--set` keys can change (integrator, dt, iterations, solver, soft-substeps)
// and what its world holds; probes are copies of the world as it is (ProbesOf: Physics/WorldCopy.h), so the
// estimate runs on the scene itself; the chosen model is applied through the same keys a user would set. GL-free.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "Demos/Scenes/ModelRequest.h"
#include "Demos/Scenes/Parameters.h"
#include "Physics/ModelChoice/ModelChoice.h"

class PhysicsSystem;

/// The auto model of one run: choice at the start, the live watch during it, and the reports.
class AutoModel {
public:
    /// The candidate space of a host: the keys `params` has (and their ranges) and what `world` holds. hostStep
    /// (s) is the step the host runs when it has no `dt` key or its dt is 0.
    static CandidateSpace SpaceOf(const ParameterSet& params, const PhysicsSystem& world, double hostStep);
    /// The `--set` assignments that put `model` into effect on a host with these parameters (only keys it has).
    static std::vector<std::pair<std::string, std::string>> Assignments(const ParameterSet& params,
                                                                        const ModelCandidate& model);

    /// Estimates the candidates on `world` and, when one meets the budget, applies the cheapest through `params`.
    /// False when the budget is invalid or no candidate meets it: *error then says so with the best estimate.
    /// `tuning` is the estimator's settings (its runSeconds is replaced by `runSeconds`).
    bool Choose(ParameterSet* params, const PhysicsSystem& world, double hostStep, double runSeconds,
                const AutoModelRequest& request, std::string* error, const ChoiceSettings& tuning = {});
    /// After each frame: the live watch (time = simulated s since the start); a switch is applied through `params`
    /// and logged (Log()).
    void AfterFrame(ParameterSet* params, const PhysicsSystem& world, double time);

    bool Active() const { return active; }
    /// The budget asked for (its bound is `error-budget`, in the quantity's unit).
    const AutoModelRequest& Request() const { return request; }
    const ModelChoiceResult& Choice() const { return choice; }
    const ModelCandidate& Current() const;
    /// The running estimate at the end of the run (budget unit); the calibration's until the first check.
    double RunningEstimate() const;
    /// For the host's exit code ("ran, but missed its budget"): true when the live watch found the running estimate
    /// over the budget and could not refine the model (ModelWatch::Missed); *estimate is the running estimate (budget
    /// unit) and *time the simulated time (s) of the check that found it. False without auto, after a choice
    /// measured over the whole run (nothing is watched), or when the latest check was within the budget.
    bool MissedBudget(double* estimate, double* time) const;
    /// s of CPU spent calibrating and watching (the overhead of auto).
    double OverheadCpuSeconds() const;
    /// Every candidate with its estimated error and cost, the chosen one marked (for --explain-model).
    std::string Explain() const;
    /// One line for the run's summary and the panel: the model, its estimate against the budget, its cost and the
    /// calibration's overhead.
    std::string Summary() const;
    /// The panel's rows: Summary without measured times, so rendered frames repeat exactly: the cost as predicted
    /// work per simulated second, the overhead as the probes' work over the run's.
    std::string PanelText() const;
    /// The switches made during the run, one line each ("t = 2.40 s: ... ").
    const std::vector<std::string>& Log() const { return log; }

private:
    bool active = false;
    AutoModelRequest request;
    CandidateSpace space;
    ChoiceSettings settings;
    ModelChoiceResult choice;
    std::unique_ptr<ModelWatch> watch;
    double hostStep = 0.03;
    std::vector<std::string> log;
};
