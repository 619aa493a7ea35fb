#pragma once
// Conservation Of Momentum (docs/book-reference.md §2.4): four unit spheres in a row on the ground and a fifth sent at
// them at 20 m/s. GL-free; shared by ConservationOfMomentum, the tests and the benchmarks.

#include <memory>
#include <vector>

#include "Demos/Scenes/Parameters.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

/// The demo has only a Reset button. velocityRetention and gravity are not panel values: tests use them to isolate
/// the impulses from the book's per-step damping (0.98) and from ground contact.
struct MomentumParams {
    /// Velocity kept per 0.03 s by every sphere (RigidbodyVolume::velocityRetention; the book's damping 0.98).
    float velocityRetention = 0.98f;
    bool gravity = true;  ///< false: no gravity, so the spheres never touch the ground (0.01 m gap)
    /// Not a book widget: the contact solver, an index of ContactSolverChoices() (0 the book's; `--set solver=`).
    int solver = 0;
    /// WorldSettings::soft, used when solver is soft (`--set soft-substeps=...`, ContactSolverParameters.h).
    SoftSolverSettings soft;
    /// Islands and sleep (WorldSettings::sleep.enabled, `--set sleep=1`); off, as in the book.
    bool sleep = false;
};

class MomentumScene {
public:
    static constexpr int kSpheres = 5;
    static constexpr float kLaunchSpeed = 20.0f;  ///< m/s, sphere 4 towards x = 0

    explicit MomentumScene(const MomentumParams& params = {});
    /// Rebuilds the spheres and ground (the book's ResetDemo), volumes synced (erratum 5.2-28).
    void Reset();
    /// One physics step of dt seconds.
    void Step(float dt);
    /// Registers the reset action, the panel's only widget (docs/book-reference.md §2.4), on *set; then the solver
    /// choice and the soft solver's keys (no widgets), which apply to the running world at once.
    void AddParameters(ParameterSet* set);
    /// Sum of m v over the spheres (kg m/s).
    vec3 TotalMomentum() const;

    MomentumParams& Params() { return params; }
    PhysicsSystem& System() { return *system; }
    const PhysicsSystem& System() const { return *system; }
    /// Spheres 0..4 then the ground (index 5).
    const std::vector<RigidbodyVolume>& Bodies() const { return bodies; }

private:
    void ApplySolverSettings();

    MomentumParams params;
    std::unique_ptr<PhysicsSystem> system;
    std::vector<RigidbodyVolume> bodies;
};
