#pragma once
// Conservation Of Momentum (docs/book-reference.md §2.4): four unit spheres in a row on the ground and a fifth sent at
// them at 20 m/s. GL-free; shared by ConservationOfMomentum, the tests and the benchmarks.

#include <memory>
#include <vector>

#include "Demos/Scenes/ContactSolverParameters.h"
#include "Demos/Scenes/Parameters.h"
#include "Demos/Scenes/Scene.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

/// The demo has only a Reset button. velocityRetention and gravity are not panel values: tests use them to isolate
/// the impulses from the book's per-step damping (0.98) and from ground contact.
struct MomentumParams {
    /// Velocity kept per 0.03 s by every sphere (RigidbodyVolume::velocityRetention; the book's damping 0.98).
    float velocityRetention = 0.98f;
    bool gravity = true;  ///< false: no gravity, so the spheres never touch the ground (0.01 m gap)
    /// Not book widgets: the contact solver, its soft settings and sleep (`--set solver=`, `soft-...`, `sleep=`).
    ContactSolverChoice contact;
};

class MomentumScene final : public Scene {
public:
    static constexpr int kSpheres = 5;
    static constexpr float kLaunchSpeed = 20.0f;  ///< m/s, sphere 4 towards x = 0

    explicit MomentumScene(const MomentumParams& params = {});
    /// Rebuilds the spheres and ground (the book's ResetDemo), volumes synced (erratum 5.2-28).
    void Reset() override;
    /// One physics step of dt seconds.
    bool Step(float dt) override;
    /// Registers the reset action, the panel's only widget (docs/book-reference.md §2.4), on *set; then the solver
    /// choice and the soft solver's keys (no widgets), which apply to the running world at once.
    void AddParameters(ParameterSet* set) override;
    /// 0: the host's step (`--dt`, `--set dt=`).
    float PhysicsStep() const override { return 0.0f; }
    /// Sum of m v over the spheres (kg m/s).
    vec3 TotalMomentum() const;

    MomentumParams& Params() { return params; }
    PhysicsSystem& System() override { return *system; }
    const PhysicsSystem& System() const override { return *system; }
    /// Spheres 0..4 then the ground (index 5).
    const std::vector<RigidbodyVolume>& Bodies() const { return bodies; }

private:
    void ApplySolverSettings();

    MomentumParams params;
    std::unique_ptr<PhysicsSystem> system;
    std::vector<RigidbodyVolume> bodies;
};
