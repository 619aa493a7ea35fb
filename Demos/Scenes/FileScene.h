#pragma once
// A scene built from a scene file's SceneDescription (docs/scenes.md): the world holds only what the file names,
// so no stage runs for a kind of body or constraint the scene does not have. GL-free; shared by SceneFileDemo
// and the tests.

#include <memory>
#include <string>
#include <vector>

#include "Demos/Scenes/ContactSolverParameters.h"
#include "Demos/Scenes/Parameters.h"
#include "Demos/Scenes/Scene.h"
#include "Demos/Scenes/SceneFile.h"
#include "Physics/Cloth.h"
#include "Physics/DistanceJoint.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"
#include "Physics/StabilityMonitor.h"

/// Where one SceneDescription body lives in the built world.
struct FileSceneBody {
    SceneBodyKind kind = SceneBodyKind::Box;
    std::size_t index = 0;  ///< into FileScene::Particles() or FileScene::Volumes()
};

class FileScene final : public Scene {
public:
    explicit FileScene(const SceneDescription& description);
    /// Rebuilds the world from the description.
    void Reset() override;
    /// One physics step of dt seconds; false (and the world frozen) once the stability monitor reports a blow-up,
    /// once the world has stopped (PhysicsSystem::StopReason: too many overlapping pairs), or for dt <= 0 or
    /// non-finite.
    bool Step(float dt) override;
    /// Registers the model settings (integrator, solver and the soft solver's keys, iterations, slop, projection,
    /// dt) and reset on *set;
    /// a change applies to the running world at once (dt from the next host step).
    void AddParameters(ParameterSet* set) override;
    /// One line naming the model in effect: integrator, contact solver, iterations, step.
    std::string ModelSummary() const;
    /// The scene's physics step (s); 0 = the host's.
    float PhysicsStep() const override { return description.world.step; }

    const SceneDescription& Description() const { return description; }
    PhysicsSystem& System() override { return *system; }
    const PhysicsSystem& System() const override { return *system; }
    const std::vector<Particle>& Particles() const { return particles; }
    const std::vector<RigidbodyVolume>& Volumes() const { return volumes; }
    const std::vector<DistanceJoint>& Joints() const { return joints; }
    const std::vector<std::unique_ptr<Cloth>>& Cloths() const { return cloths; }
    /// One entry per description body, in file order.
    const std::vector<FileSceneBody>& BodyIndex() const { return bodyIndex; }
    const StabilityMonitor& Monitor() const { return monitor; }

private:
    void ApplyWorldSettings();

    SceneDescription description;
    int integratorChoice = 0;  // index into kAllIntegrators, mirrors description.world.integrator
    int contactChoice = 0;     // the "particle-contact" choice (ParticleContactIndex)
    int jointChoice = 0;       // the "joint-model" choice (0 book, 1 tension)
    int positionsChoice = 0;   // the "volume-positions" choice (0 euler, 1 average)
    // The "solver", soft-solver and "sleep" keys (the type every rigid-volume scene uses); each change is written
    // into description.world (contactSolver, soft, sleep.enabled) before the world's settings are applied.
    ContactSolverChoice contact;
    std::unique_ptr<PhysicsSystem> system;
    std::vector<Particle> particles;       // never resized after Reset: the system and springs point in
    std::vector<RigidbodyVolume> volumes;  // likewise
    std::vector<DistanceJoint> joints;     // likewise
    std::vector<std::unique_ptr<Cloth>> cloths;
    std::vector<FileSceneBody> bodyIndex;
    StabilityMonitor monitor;
};
