#pragma once
// Pieces shared by the chapter 16 scenes (springs, ch16, joints): the integrator and step-size parameters
// and a fixed-step accumulator that runs the scene's own dt inside the host's fixed updates.

#include <functional>
#include <string>
#include <vector>

#include "Integrator.h"
#include "Parameters.h"

/// Integrator ids in IntegratorIds() order ("explicit-euler", "euler", ...): the "integrator" choice list.
std::vector<std::string> IntegratorChoices();
/// Index of an integrator in IntegratorChoices(); 0 if absent.
int IntegratorIndex(Integrator integrator);
/// The integrator at an index of IntegratorChoices(); the book's semi-implicit Euler if out of range.
Integrator IntegratorAt(int index);

/// Step-size range offered on the panel and by --set dt=..., in seconds.
constexpr float kMinSceneDt = 0.0005f;
constexpr float kMaxSceneDt = 0.1f;

/// Registers "integrator" (choice bound to *integratorIndex) and "dt" (s, bound to *dt) on *set; onChange runs
/// after --set (the scenes reset, as the book's widgets take effect on Reset).
void AddStepParameters(ParameterSet* set, int* integratorIndex, float* dt, const std::function<void()>& onChange);

/// Runs whole scene steps of dt inside elapsed host time; the remainder carries over, so simulated time
/// follows host time for any dt (one step per call when both are the book's 0.03 s).
class StepAccumulator {
public:
    /// Adds elapsed seconds; returns how many steps of dt are due now.
    int Advance(double elapsed, double dt);
    void Clear() { accumulated = 0.0; }

private:
    double accumulated = 0.0;
};
