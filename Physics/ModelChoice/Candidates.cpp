// The budget and the candidates (docs/model-choice.md, "The budget" and "The candidates"); the quantities a budget
// bounds are Physics/ModelChoice/Measures.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "Physics/EnumIds.h"
#include "Physics/ModelChoice/ModelChoice.h"

namespace {

/// Contact passes per step of a candidate (the solver's work multiplier).
double PassWork(const ModelCandidate& c) {
    if (c.solver == ContactSolver::Soft) return 3.0 + 1.0 * c.softSubsteps;
    return 4.0 + c.iterations;
}

}  // namespace

namespace {
constexpr EnumId<BudgetQuantity> kQuantityIds[] = {{BudgetQuantity::Position, "position"},
                                                   {BudgetQuantity::Energy, "energy"},
                                                   {BudgetQuantity::Constraint, "constraint"}};
}  // namespace

const char* ToString(BudgetQuantity quantity) { return IdOf(kQuantityIds, quantity); }

bool ParseBudgetQuantity(const std::string& text, BudgetQuantity* out) { return ParseId(kQuantityIds, text, out); }

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
