// The rungs of a candidate's family (docs/model-choice.md, "Cheapest"): what its coarser steps, already estimated,
// predict for it. Physics/ModelChoice/Choose.cpp uses them to skip candidates predicted to miss, to hold an estimate
// that showed no order to its family's, and to check the margin's fallback.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "Physics/ModelChoice/Internals.h"

namespace model_choice {

FamilyPrediction FamilyFloor(const std::vector<CandidateEstimate>& candidates, const std::vector<std::size_t>& order,
                             std::size_t k, const CandidateSpace& space, const CandidateEstimate* e) {
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
    if (!nearest) return {};
    double p = 1.0;
    if (next && nearest->estimate > 0.0 && next->estimate > nearest->estimate) {
        p = std::log(next->estimate / nearest->estimate) / std::log(next->model.step / nearest->model.step);
    }
    p = std::clamp(p, 1.0, static_cast<double>(OrderOf(e->model, space)));
    return {nearest->estimate * std::pow(e->model.step / nearest->model.step, p), nearest->model.step, p};
}

/// An estimate whose error was seen to shrink at its order (CheckOrder ran, above rounding, and passed).
bool CheckedRung(const CandidateEstimate& f) {
    return f.evaluated && f.stable && !f.partial && !f.unreliable && !f.withinRounding && f.finerDifference > 0.0 &&
           f.pairDifference > 0.0 && std::isfinite(f.estimate);
}

/// WhySkip's prediction of a finer step from `nearest`, the nearest coarser rung of e's family with the same passes
/// that was estimated: its estimate times the step ratio to the power of the candidate's order, or of the order the
/// family's two nearest such rungs showed (complete estimates) where that is faster. At the formal order alone the
/// rung may be at most 2.5 steps coarser (coarser steps are often outside the asymptotic range, where an error does
/// not shrink with the step as its order says); with two rungs that showed their order, up to 5 (an order of 2 where
/// 1 is assumed stays within the factor 8 of the rule); from a rung whose own error was seen to shrink at its order
/// (CheckedRung), up to 10, at the faster of that order and the one its pairs showed. Predicted above 8 times the
/// bound: not run.
std::string PredictedMiss(const ModelChoiceResult& result, const std::vector<std::size_t>& order, std::size_t k,
                          const CandidateEstimate& nearest, const CandidateEstimate& e, const CandidateSpace& space,
                          double bound) {
    const CandidateEstimate* next = nullptr;  // the nearest complete rung coarser than `nearest`
    for (std::size_t j = 0; j < k; ++j) {
        const CandidateEstimate& f = result.candidates[order[j]];
        if (f.evaluated && f.stable && !f.partial && std::isfinite(f.estimate) && SameFamily(f.model, e.model) &&
            Passes(f.model) == Passes(e.model) && f.model.step > nearest.model.step &&
            (!next || f.model.step < next->model.step)) {
            next = &f;
        }
    }
    double p = OrderOf(e.model, space);
    const bool observed = next && !nearest.partial && nearest.estimate > 0.0;
    if (observed && next->estimate > nearest.estimate) {
        p = std::max(p, std::log(next->estimate / nearest.estimate) / std::log(next->model.step / nearest.model.step));
    } else if (observed) {
        p = kInf;  // the error did not shrink between the rungs: no order to predict with
    }
    double reach = observed ? 5.0 : 2.5;
    // A rung whose own error was seen to shrink at its order (CheckOrder: its pair and its finer pair, above
    // rounding) is in the range where the order holds: it predicts up to 10 steps finer, at the faster of the formal
    // order and the one its two pairs showed.
    if (CheckedRung(nearest)) {
        reach = 10.0;
        p = std::max(p, std::log2(nearest.pairDifference / nearest.finerDifference));
    }
    if (!std::isfinite(p) || nearest.model.step > reach * (1.0 + 1e-9) * e.model.step) return "";
    const double predicted = nearest.estimate * std::pow(e.model.step / nearest.model.step, p);
    if (!(predicted > 8.0 * bound)) return "";
    char text[120];
    std::snprintf(text, sizeof text, "not run: predicted %.3g from its family's dt %g s", predicted,
                  nearest.model.step);
    return text;
}

}  // namespace model_choice
