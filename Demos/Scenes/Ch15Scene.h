#pragma once
// Chapter 15 (docs/book-reference.md §2.5): a tilted unit box (mass 1) falls onto a unit box (mass 5) resting on a
// static ground slab. GL-free; shared by CH15Demo, the tests and the benchmarks.

#include <memory>
#include <vector>

#include "Demos/Scenes/Parameters.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

/// The "Chapter 15 Demo" panel values (book defaults: 0.45 / 0.01 / 8, projection on, debug off).
struct Ch15Params {
    float projection = 0.45f;  ///< LinearProjectionPercent, 0.2..0.8 (the panel's "Porjection")
    float slop = 0.01f;        ///< PenetrationSlack, 0.01..0.1 m
    int iterations = 8;        ///< ImpulseIteration, 1..20
    bool linearProjection = true;
    bool debug = false;  ///< DebugRender: edges and manifolds
    /// Not a book widget: 0 = the book's per-contact solver, 1 = accumulated impulses (ContactSolver.h).
    int solver = 0;
};

class Ch15Scene {
public:
    explicit Ch15Scene(const Ch15Params& params = {});
    /// Rebuilds the three bodies (the book's ResetDemo), volumes synced; the panel values are kept.
    void Reset();
    /// Copies the panel values into the system, then one step of dt seconds.
    void Step(float dt);
    /// Registers projection, slop, iterations, linear-projection, debug and the reset action on *set.
    void AddParameters(ParameterSet* set);

    Ch15Params& Params() { return params; }
    const Ch15Params& Params() const { return params; }
    PhysicsSystem& System() { return *system; }
    const PhysicsSystem& System() const { return *system; }
    /// [0] tilted box, [1] heavy box, [2] ground, in the order they were added.
    const std::vector<RigidbodyVolume>& Bodies() const { return bodies; }
    std::vector<RigidbodyVolume>& Bodies() { return bodies; }

private:
    void ApplySettings();

    Ch15Params params;
    std::unique_ptr<PhysicsSystem> system;
    std::vector<RigidbodyVolume> bodies;
};
