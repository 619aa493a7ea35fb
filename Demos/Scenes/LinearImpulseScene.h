#pragma once
// Linear Impulse (docs/book-reference.md §2.3): two spheres or two boxes thrown at each other (or dropped onto each
// other) above a static ground slab, with the demo's pause / single-step controls. GL-free; shared by LinearImpulse,
// the tests and the benchmarks.

#include <memory>
#include <vector>

#include "Demos/Scenes/ContactSolverParameters.h"
#include "Demos/Scenes/Parameters.h"
#include "Demos/Scenes/Scene.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

/// The "Linear Impulse Demo" panel values. The book starts paused; headless runs start unpaused (pause=1
/// restores the book's start).
struct LinearImpulseParams {
    bool spheres = false;  ///< "Spheres": spheres instead of boxes
    bool drop = false;     ///< "Drop": stacked at rest instead of thrown
    bool pause = false;    ///< "Pause"
    int frames = 1;        ///< "Frames": steps taken by one press of "Step"
    /// Not book widgets: the contact solver, its soft settings and sleep (`--set solver=`, `soft-...`, `sleep=`).
    ContactSolverChoice contact;
};

class LinearImpulseScene final : public Scene {
public:
    explicit LinearImpulseScene(const LinearImpulseParams& params = {});
    /// Rebuilds the bodies from spheres/drop (the book's ResetDemo), volumes synced (erratum 5.2-28).
    void Reset() override;
    /// The "Step" button: queue `frames` single steps to run while paused.
    void RequestSteps();
    /// The book's Update: one physics step of dt seconds unless paused; while paused, one queued step if any.
    bool Step(float dt) override;
    /// Registers the panel's widgets (docs/book-reference.md §2.3) on *set: step, frames, reset, pause, spheres, drop;
    /// then the solver choice and the soft solver's keys (no widgets), which apply to the running world at once.
    void AddParameters(ParameterSet* set) override;
    /// 0: the host's step (`--dt`, `--set dt=`).
    float PhysicsStep() const override { return 0.0f; }

    LinearImpulseParams& Params() { return params; }
    int PendingSteps() const { return pendingSteps; }
    PhysicsSystem& System() override { return *system; }
    const PhysicsSystem& System() const override { return *system; }
    /// [0] first body (red), [1] second body (blue), [2] ground.
    const std::vector<RigidbodyVolume>& Bodies() const { return bodies; }

private:
    void ApplySolverSettings();

    LinearImpulseParams params;
    int pendingSteps = 0;
    std::unique_ptr<PhysicsSystem> system;
    std::vector<RigidbodyVolume> bodies;
};
