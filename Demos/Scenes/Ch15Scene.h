#pragma once
// Chapter 15 (docs/book-reference.md §2.5): a tilted unit box (mass 1) falls onto a unit box (mass 5) resting on a
// static ground slab. GL-free; shared by CH15Demo, the tests and the benchmarks.

#include <memory>
#include <vector>

#include "Demos/Scenes/ContactSolverParameters.h"
#include "Demos/Scenes/Parameters.h"
#include "Demos/Scenes/Scene.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

/// The "Chapter 15 Demo" panel values (book defaults: 0.45 / 0.01 / 8, projection on, debug off). Ranges
/// and labels are in AddParameters, the one table.
struct Ch15Params {
    /// WorldSettings::projectionFraction: the fraction (not percent) of the penetration beyond the slop removed
    /// per step. The book's LinearProjectionPercent, panel "Porjection" [sic]; `--set projection-fraction`
    /// (alias projection).
    float projectionFraction = 0.45f;
    float penetrationSlop = 0.01f;  ///< WorldSettings::penetrationSlop, m (the book's PenetrationSlack, "Slop")
    int iterations = 8;             ///< WorldSettings::solverIterations (ImpulseIteration, "Iteration")
    bool linearProjection = true;   ///< positional correction on (DoLinearProjection, "Linear Projection")
    bool debugRender = false;       ///< draw box edges and manifolds (DebugRender, "Debug Render")
    /// Not book widgets: the contact solver, its soft settings and sleep (`--set solver=`, `soft-...`, `sleep=`).
    ContactSolverChoice contact;
};

class Ch15Scene final : public Scene {
public:
    explicit Ch15Scene(const Ch15Params& params = {});
    /// Rebuilds the three bodies (the book's ResetDemo), volumes synced; the panel values are kept.
    void Reset() override;
    /// One physics step of dt seconds (Scene::Step). The panel values are in the world already: every edit
    /// applies at once, as the book's sliders do.
    bool Step(float dt) override;
    /// Registers the panel's widgets in panel order (projection-fraction, slop, iterations, reset, debug,
    /// linear-projection), then the solver choice and the soft solver's keys (no widgets) on *set.
    void AddParameters(ParameterSet* set) override;
    /// 0: the host's step (`--dt`, `--set dt=`).
    float PhysicsStep() const override { return 0.0f; }

    Ch15Params& Params() { return params; }
    const Ch15Params& Params() const { return params; }
    PhysicsSystem& System() override { return *system; }
    const PhysicsSystem& System() const override { return *system; }
    /// [0] tilted box, [1] heavy box, [2] ground, in the order they were added.
    const std::vector<RigidbodyVolume>& Bodies() const { return bodies; }
    std::vector<RigidbodyVolume>& Bodies() { return bodies; }

private:
    void ApplySettings();

    Ch15Params params;
    std::unique_ptr<PhysicsSystem> system;
    std::vector<RigidbodyVolume> bodies;
};
