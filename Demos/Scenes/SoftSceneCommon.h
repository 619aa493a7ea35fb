#pragma once
// Pieces shared by the chapter 16 scenes (springs, ch16, joints): the integrator and step-size parameters
// and a fixed-step accumulator that runs the scene's own dt inside the host's fixed updates.

#include <functional>
#include <string>
#include <vector>

#include "Demos/Scenes/Parameters.h"
#include "Physics/Integrator.h"
#include "Physics/Particle.h"
#include "Physics/StabilityMonitor.h"

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

/// The step plumbing every chapter 16 scene keeps: the "integrator" choice behind its panel and the
/// accumulator that runs its dt inside host time. The scene owns its params; this holds the rest.
class SoftSceneStepping {
public:
    /// Points the "integrator" choice at `integrator` (Reset(params)).
    void Select(Integrator integrator) { integratorIndex = IntegratorIndex(integrator); }
    /// The integrator the "integrator" choice names (Reset() from the panel values).
    Integrator Chosen() const { return IntegratorAt(integratorIndex); }
    /// Drops the host time carried over from before a rebuild.
    void Clear() { accumulator.Clear(); }
    /// AddStepParameters bound to this choice and to *dt.
    void AddParameters(ParameterSet* set, float* dt, const std::function<void()>& onChange) {
        AddStepParameters(set, &integratorIndex, dt, onChange);
    }
    /// Calls step() for each step of dt due after `elapsed` host seconds, stopping once monitor reports
    /// unstable. Returns the number of steps run.
    template <typename StepFn>
    int Advance(float elapsed, float dt, const StabilityMonitor& monitor, StepFn step) {
        const int due = accumulator.Advance(elapsed, dt);
        int run = 0;
        while (run < due && monitor.Stable()) {
            step();
            ++run;
        }
        return run;
    }

private:
    int integratorIndex = 0;
    StepAccumulator accumulator;
};

/// Raises every particle below floorY to it (the book's Update clamp y >= -5 in springs and joints).
void ClampAboveFloor(std::vector<Particle>* particles, float floorY);
