#pragma once
// Chapter 16 (docs/book-reference.md §2.7): an N x N cloth dropped from height 6 onto four posts over a ground box.
// GL-free; shared by CH16Demo, the tests and the cloth benchmark.

#include <array>
#include <memory>

#include "Demos/Scenes/Parameters.h"
#include "Demos/Scenes/SoftSceneCommon.h"
#include "Physics/Cloth.h"
#include "Physics/Integrator.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/StabilityMonitor.h"

/// The demo's panel values. k and damping are the BOOK's numbers (velocity change per 0.03 s step); the
/// scene converts them with FromBookSpringConstant so the cloth looks as in the book (docs/ERRATA.md, Chapter 16).
struct Ch16Params {
    int count = 15;         ///< particles per side, 5..30 on the panel (the cloth clamps to >= 3)
    float distance = 0.2f;  ///< m between neighbours, 0.1..1
    float k = -3.0f;        ///< book k for structural, shear and bend springs, -5..0
    float damping = 0.0f;   ///< book spring damping d (no widget in the book)
    Integrator integrator = Integrator::SemiImplicitEuler;
    float dt = 0.03f;  ///< fixed step (book: 0.03 s, erratum 5.2-16)
};

class Ch16Scene {
public:
    static constexpr float kClothHeight = 6.0f;
    /// Posts collide with this half-size (docs/book-reference.md §2.7) ...
    static constexpr float kPostCollisionHalf = 0.3f;
    /// ... but are drawn with this one, as the book does.
    static constexpr float kPostDrawHalf = 0.1f;
    static constexpr float kPostHalfHeight = 0.5f;

    explicit Ch16Scene(const Ch16Params& params = {});
    /// Rebuilds the world from params (the book's ResetDemo); the step count restarts at 0.
    void Reset(const Ch16Params& params);
    /// Rebuilds from the current (panel) values, the integrator taken from the "integrator" choice.
    void Reset();
    /// One fixed step of params.dt, then the stability check. False once unstable.
    bool Step();

    /// Runs the steps of params.dt due after `elapsed` host seconds (StepAccumulator); stops once unstable.
    /// Returns the number of steps run.
    int Advance(float elapsed);
    /// Registers the panel values and the "reset" action on *set; --set resets the scene.
    void AddParameters(ParameterSet* set);

    Ch16Params& Params() { return params; }
    const Ch16Params& Params() const { return params; }
    PhysicsSystem& System() { return *system; }
    const PhysicsSystem& System() const { return *system; }
    const Cloth& GetCloth() const { return *cloth; }
    const StabilityMonitor& Monitor() const { return monitor; }

    /// Ground: half-size (10, 0.1, 10) at the origin (constraint 0).
    static OBB Ground();
    /// Post centres in the book's order.
    static const std::array<vec3, 4>& PostPositions();
    /// Post i as collided with (half-size 0.3, 0.5, 0.3); constraints 1..4.
    static OBB PostCollider(int i);
    /// Post i as drawn (half-size 0.1, 0.5, 0.1).
    static OBB PostVisual(int i);

private:
    void Build();

    Ch16Params params;
    SoftSceneStepping stepping;
    std::unique_ptr<PhysicsSystem> system;
    std::unique_ptr<Cloth> cloth;
    StabilityMonitor monitor;
};
