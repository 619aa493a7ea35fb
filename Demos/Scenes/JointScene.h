#pragma once
// Joint Demo (docs/book-reference.md §2.8): CH14's particles and ramps, with particle i and i + n/2 held apart by a
// distance joint. GL-free; shared by JointDemo, the tests and the benchmarks.

#include <memory>
#include <vector>

#include "Demos/Scenes/BookConstants.h"
#include "Demos/Scenes/Parameters.h"
#include "Demos/Scenes/Scene.h"
#include "Demos/Scenes/SoftSceneCommon.h"
#include "Math/Random.h"
#include "Physics/DistanceJoint.h"
#include "Physics/Integrator.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/StabilityMonitor.h"

/// The demo's panel values; ranges and labels are in AddParameters, the one table.
struct JointParams {
    int particleCount = 50;  ///< particles (the book's numParticles, an odd count rounds up); applied on Reset
    Integrator integrator = Integrator::SemiImplicitEuler;
    float dt = kBookStep;  ///< s: the physics step the demo asks its host for (book: 0.03, erratum 5.2-16)
};

class JointScene final : public Scene {
public:
    /// rng is the demo's generator; it is NOT reseeded by Reset, as the book's rand() is never reseeded.
    explicit JointScene(const JointParams& params = {}, MsvcRand* rng = nullptr);
    JointScene(const JointScene&) = delete;
    JointScene& operator=(const JointScene&) = delete;
    /// Rebuilds the world (the book's ResetDemo). An odd count is rounded UP to even for the particles that
    /// are created (erratum 5.2-23), so every particle has a joint; params.particleCount is left as given.
    void Reset(const JointParams& params);
    /// Rebuilds from the current (panel) values, the integrator taken from the "integrator" choice.
    void Reset() override;
    /// One physics step of dt seconds, the y >= -5 clamp, then the stability check. False once unstable.
    /// Nothing once unstable, or for dt <= 0 or non-finite.
    bool Step(float dt) override;
    /// Registers the panel values and the "reset" action on *set; --set resets the scene.
    void AddParameters(ParameterSet* set) override;
    /// The `dt` parameter (s): the step the scene asks its host for.
    float PhysicsStep() const override { return params.dt; }

    JointParams& Params() { return params; }
    const JointParams& Params() const { return params; }
    PhysicsSystem& System() override { return *system; }
    const PhysicsSystem& System() const override { return *system; }
    const std::vector<Particle>& Particles() const { return particles; }
    const std::vector<DistanceJoint>& Joints() const { return joints; }
    const StabilityMonitor& Monitor() const { return monitor; }

    /// The four CH14 constraints in order (ground, obb1, obb2, obb3), docs/book-reference.md §2.1.
    static std::vector<OBB> Constraints();
    /// CH14's spawn box: centre (-0.5, 6.5, -1.01), half-size (3.8505, 2, 4.034834).
    static vec3 SpawnCenter() { return vec3(-0.5f, 6.5f, -1.01f); }
    static vec3 SpawnHalfSize() { return vec3(3.8505f, 2.0f, 4.034834f); }

private:
    void Build();

    JointParams params;
    SoftSceneStepping stepping;
    MsvcRand ownRng;
    MsvcRand* rng;
    std::unique_ptr<PhysicsSystem> system;
    std::vector<Particle> particles;
    std::vector<DistanceJoint> joints;
    StabilityMonitor monitor;
};
