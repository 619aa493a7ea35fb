#pragma once
// The reference problems of psb-sweep (bench/sweep, docs/sweep.md) as scene files (scenes/reference/*.json), each
// with its error measured from a FileScene run's trajectory in the problem's own unit, and the conversion of a
// budget in that unit into an auto budget (docs/model-choice-validation.md).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "Demos/Scenes/FileScene.h"
#include "Physics/ModelChoice/ModelChoice.h"

namespace modelchoice {

/// Where one physics step lies in simulated time: the step runs from Before() to After(); the step count restarts
/// when the step size changes (an auto switch), so times of a fixed-step run are start + i dt exactly as the sweep's.
struct StepTime {
    double start = 0.0;   ///< s: simulated time at which the current step size began
    long long index = 0;  ///< steps of this size run before this one
    double dt = 0.0;      ///< s
    double Before() const { return start + double(index) * dt; }
    double After() const { return start + double(index + 1) * dt; }
    /// s: the time a fraction `f` (0..1) through this step.
    double At(double f) const { return start + (double(index) + f) * dt; }
};

/// Measures one problem's error on a FileScene run: Start before the first step, AfterStep after each, Error at the
/// end. The reference and the error are the sweep's (bench/sweep/Problems*.cpp), computed from the scene's state.
class ErrorObserver {
public:
    virtual ~ErrorObserver() = default;
    virtual void Start(const FileScene& scene) = 0;
    virtual void AfterStep(const FileScene& scene, const StepTime& step) = 0;
    /// The problem's error at simulated time `end` (s), or inf when the run left the problem's bounds.
    virtual double Error(const FileScene& scene, double end) = 0;
};

/// One reference problem of the validation.
struct ReferenceProblem {
    std::string name;          ///< the scene file's stem: scenes/reference/<name>.json
    std::string sweepProblem;  ///< psb-sweep's problem name
    std::string sweepParam;    ///< its param as docs/sweep/results.csv writes it ("-" when none)
    std::string errorUnit;     ///< the problem's error, as psb-sweep --list says
    BudgetQuantity quantity = BudgetQuantity::Position;  ///< the auto budget a budget in errorUnit becomes
    double scale = 1.0;      ///< auto bound = scale * budget (quantity's unit per errorUnit), unless `bound` is set
    std::string conversion;  ///< why that scale, one line for docs/model-choice-validation.md
    bool fast = false;       ///< in the small grid of the CTest
    std::function<std::unique_ptr<ErrorObserver>()> observer;
    /// s the equivalence check runs (0: the scene's duration). The bounces: the sweep's 15 s cap, so a model whose
    /// fifth apex comes after the scene's end is measured as the sweep measures it.
    double checkSeconds = 0.0;
    /// The auto bound for a budget in errorUnit, where the conversion is not a constant factor (the pendulums).
    std::function<double(double)> bound = nullptr;
    /// The auto bound for `budget` (in errorUnit).
    double AutoBound(double budget) const { return bound ? bound(budget) : scale * budget; }
};

/// Every problem, in the sweep's order.
const std::vector<ReferenceProblem>& ReferenceProblems();
/// The problem named `name`, or nullptr.
const ReferenceProblem* FindReferenceProblem(const std::string& name);

}  // namespace modelchoice
