#pragma once
// Chapter 16 (docs/book-reference.md §2.7): an N x N cloth dropped from height 6 onto four posts over a ground box.
// GL-free; shared by CH16Demo, the tests and the cloth benchmark.

#include <array>
#include <memory>

#include "Demos/Scenes/BookConstants.h"
#include "Demos/Scenes/Parameters.h"
#include "Demos/Scenes/Scene.h"
#include "Demos/Scenes/SoftSceneCommon.h"
#include "Physics/Cloth.h"
#include "Physics/Integrator.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/StabilityMonitor.h"

/// The demo's panel values. springK and springDamping are the BOOK's numbers (velocity change per 0.03 s step);
/// the scene converts them with FromBookSpringConstant so the cloth looks as in the book (docs/ERRATA.md,
/// Chapter 16). Ranges and labels are in AddParameters, the one table.
struct Ch16Params {
    int particlesPerSide = 15;     ///< cloth particles per side (book num_part, "Count"; the cloth clamps to >= 3)
    float particleSpacing = 0.2f;  ///< m between neighbouring particles (book part_dist, "Distance")
    float springK = -3.0f;         ///< book k of every cloth spring: N/m x 0.03 s ("Spring k")
    float springDamping = 0.0f;    ///< book spring damping d: N s/m x 0.03 s (no widget in the book)
    Integrator integrator = Integrator::SemiImplicitEuler;
    float dt = kBookStep;  ///< s: the physics step the demo asks its host for (book: 0.03, erratum 5.2-16)
};

class Ch16Scene final : public Scene {
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
    void Reset() override;
    /// One physics step of dt seconds, then the stability check. False once unstable.
    /// Nothing once unstable, or for dt <= 0 or non-finite.
    bool Step(float dt) override;
    /// Registers the panel values and the "reset" action on *set; --set resets the scene.
    void AddParameters(ParameterSet* set) override;
    /// The `dt` parameter (s): the step the scene asks its host for.
    float PhysicsStep() const override { return params.dt; }

    Ch16Params& Params() { return params; }
    const Ch16Params& Params() const { return params; }
    PhysicsSystem& System() override { return *system; }
    const PhysicsSystem& System() const override { return *system; }
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
