#pragma once
// Simple Springs (docs/book-reference.md §2.6): a heavy particle (50 kg) and a light one (1 kg) joined by one spring,
// falling onto the ground. GL-free; shared by the SimpleSprings demo, the tests and the benchmarks.

#include <memory>
#include <vector>

#include "Demos/Scenes/BookConstants.h"
#include "Demos/Scenes/Parameters.h"
#include "Demos/Scenes/Scene.h"
#include "Demos/Scenes/SoftSceneCommon.h"
#include "Physics/Integrator.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/Spring.h"
#include "Physics/StabilityMonitor.h"

/// The demo's panel values. springK and springDamping are the BOOK's numbers (velocity change per 0.03 s step);
/// the scene converts them with FromBookSpringConstant so the motion matches the book at any dt (docs/ERRATA.md,
/// Chapter 16). Ranges and labels are in AddParameters, the one table.
struct SpringsParams {
    float springK = -2.0f;       ///< book k: N/m x 0.03 s, negative attracts (panel "k")
    float springDamping = 0.5f;  ///< book damping b: N s/m x 0.03 s (panel "b")
    float restLength = 1.0f;     ///< m (panel "l")
    Integrator integrator = Integrator::SemiImplicitEuler;
    float dt = kBookStep;  ///< s: the physics step the demo asks its host for (book: 0.03, erratum 5.2-16)
};

class SpringsScene final : public Scene {
public:
    static constexpr float kHeavyMass = 50.0f;
    static constexpr float kLightMass = 1.0f;

    explicit SpringsScene(const SpringsParams& params = {});
    /// Rebuilds the world from params (the book's ResetDemo); the step count restarts at 0.
    void Reset(const SpringsParams& params);
    /// Rebuilds from the current (panel) values, the integrator taken from the "integrator" choice.
    void Reset() override;
    /// One physics step of dt seconds, the y >= -5 clamp, then the stability check. False once unstable.
    /// Nothing once unstable, or for dt <= 0 or non-finite.
    bool Step(float dt) override;
    /// Registers the panel values and the "reset" action on *set; --set resets the scene.
    void AddParameters(ParameterSet* set) override;
    /// The `dt` parameter (s): the step the scene asks its host for.
    float PhysicsStep() const override { return params.dt; }

    SpringsParams& Params() { return params; }
    const SpringsParams& Params() const { return params; }
    PhysicsSystem& System() override { return *system; }
    const PhysicsSystem& System() const override { return *system; }
    const StabilityMonitor& Monitor() const { return monitor; }
    /// p0 (heavy, index 0) and p1 (light, index 1).
    const std::vector<Particle>& Particles() const { return particles; }
    /// The OBB ground: half-size (10, 0.15, 10) at the origin.
    static OBB Ground();

private:
    void Build();

    SpringsParams params;
    SoftSceneStepping stepping;
    std::unique_ptr<PhysicsSystem> system;
    std::vector<Particle> particles;
    StabilityMonitor monitor;
};
