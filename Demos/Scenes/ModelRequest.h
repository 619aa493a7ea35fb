#pragma once
// What a run asks of its model (docs/model-choice.md): plain data, read from the `--set` keys `model`,
// `error-budget` and `budget` (AddAutoModelParameters, Demos/Scenes/AutoModel.h) or from a scene file's "model"
// and "budget" (Demos/Scenes/SceneFile.h). The scene format holds one of these and nothing of the estimator.

struct ErrorBudget;  // Physics/ModelChoice/ModelChoice.h
class ParameterSet;  // Demos/Scenes/Parameters.h

/// The request: fixed (the scene's own settings) or auto with an error budget.
struct AutoModelRequest {
    /// The bound's range, the same for `--set error-budget=` and a scene file's "budget"."bound".
    static constexpr float kMinBound = 1e-9f, kMaxBound = 1e6f;
    int model = 0;        ///< 0 "fixed" (the scene's own settings, as before), 1 "auto"
    float bound = 0.01f;  ///< the error budget's bound, in the quantity's unit (`--set error-budget=`)
    int quantity = 0;     ///< BudgetQuantity as int: 0 position (m), 1 energy (relative), 2 constraint (m)
    bool Auto() const { return model == 1; }
    /// The budget as the estimator takes it (defined with the estimator's host, Demos/Scenes/AutoModel.cpp).
    ErrorBudget Budget() const;
};

/// Registers `model` (fixed|auto), `error-budget` (> 0; `tolerance` is its deprecated spelling) and `budget`
/// (position|energy|constraint) on *set; no widgets.
void AddAutoModelParameters(ParameterSet* set, AutoModelRequest* request);
