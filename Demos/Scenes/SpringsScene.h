#pragma once
// Simple Springs (docs/book-reference.md §2.6): a heavy particle (50 kg) and a light one (1 kg) joined by one spring,
// falling onto the ground. GL-free; shared by the SimpleSprings demo, the tests and the benchmarks.

#include <memory>
#include <vector>

#include "Demos/Scenes/Parameters.h"
#include "Demos/Scenes/SoftSceneCommon.h"
#include "Physics/Integrator.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/Spring.h"
#include "Physics/StabilityMonitor.h"

/// The demo's panel values. k and b are the BOOK's numbers (velocity change per 0.03 s step); the scene
/// converts them with FromBookSpringConstant so the motion matches the book at any dt (docs/ERRATA.md, Chapter 16).
struct SpringsParams {
    float k = -2.0f;          ///< book k, -5..0 (negative attracts)
    float b = 0.5f;           ///< book damping, 0..1
    float restLength = 1.0f;  ///< m, 0..5
    Integrator integrator = Integrator::SemiImplicitEuler;
    float dt = 0.03f;  ///< fixed step (book: 0.03 s, erratum 5.2-16)
};

class SpringsScene {
public:
    static constexpr float kHeavyMass = 50.0f;
    static constexpr float kLightMass = 1.0f;
    static constexpr float kFloorY = -5.0f;  ///< the book's Update clamps y >= -5

    explicit SpringsScene(const SpringsParams& params = {});
    /// Rebuilds the world from params (the book's ResetDemo); the step count restarts at 0.
    void Reset(const SpringsParams& params);
    /// Rebuilds from the current (panel) values, the integrator taken from the "integrator" choice.
    void Reset();
    /// One fixed step of params.dt, the y >= -5 clamp, then the stability check. False once unstable.
    bool Step();

    /// Runs the steps of params.dt due after `elapsed` host seconds (StepAccumulator); stops once unstable.
    /// Returns the number of steps run.
    int Advance(float elapsed);
    /// Registers the panel values and the "reset" action on *set; --set resets the scene.
    void AddParameters(ParameterSet* set);

    SpringsParams& Params() { return params; }
    const SpringsParams& Params() const { return params; }
    PhysicsSystem& System() { return *system; }
    const PhysicsSystem& System() const { return *system; }
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
