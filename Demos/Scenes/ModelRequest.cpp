#include "Demos/Scenes/ModelRequest.h"

#include <algorithm>

#include "Demos/Scenes/Parameters.h"
#include "Physics/ModelChoice/ModelChoice.h"

ErrorBudget AutoModelRequest::Budget() const {
    ErrorBudget b;
    b.quantity = static_cast<BudgetQuantity>(std::clamp(quantity, 0, 2));
    b.bound = bound;
    return b;
}

void AddAutoModelParameters(ParameterSet* set, AutoModelRequest* request) {
    set->AddChoice("model", &request->model, {"fixed", "auto"},
                   "fixed: the scene's own settings; auto: the cheapest model whose estimated error meets the "
                   "budget (docs/model-choice.md)");
    set->AddFloat("error-budget", &request->bound, AutoModelRequest::kMinBound, AutoModelRequest::kMaxBound,
                  "auto model: the error budget's bound, in the budget quantity's unit (m or relative)")
        .DeprecatedAlias("tolerance");
    set->AddChoice("budget", &request->quantity, {"position", "energy", "constraint"},
                   "auto model: what the budget bounds: position error of any body at the end (m), relative "
                   "energy drift, or joint constraint error (m)");
}
