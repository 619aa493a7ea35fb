#pragma once
// The chapter 16 demos (docs/book-reference.md §2.6-2.8) as one class over their scene: Simple Springs (a 50 kg and a
// 1 kg particle on one spring), Chapter 16 (a 15 x 15 cloth dropped onto four posts) and Joint Demo (CH14's
// particles in pairs held apart by distance joints). The scenes (SpringsScene, Ch16Scene, JointScene) are GL-free
// and shared with the tests and benchmarks; the demos differ only in the scene and its ParticleSceneLook.

#include <string>
#include <vector>

#include "Demos/DemoBase.h"
#include "Demos/Scenes/Ch16Scene.h"
#include "Demos/Scenes/JointScene.h"
#include "Demos/Scenes/SpringsScene.h"

/// What a chapter 16 demo shows of its scene: the id its stability report names, the panel title, whether the
/// book gives it a Show Help button, and whether the first Initialize keeps the scene its constructor built
/// (joints: a rebuild would draw the next random spawns of a generator the book never reseeds).
struct ParticleSceneLook {
    const char* id;
    const char* title;
    bool showHelp;
    bool keepsFirstBuild;
};

template <class SceneT>
class ParticleSceneDemo final : public DemoBase {
public:
    /// The look of this scene's demo (defined for SpringsScene, Ch16Scene and JointScene).
    static const ParticleSceneLook kLook;

    /// Book camera preset (CH14's); the scene's table (k, damping, ... reset, integrator, dt: --set resets the
    /// scene, the sliders wait for Reset), Show Help where the book has it, then the auto model's keys.
    ParticleSceneDemo();
    /// The scene rebuilt from the current values (but see ParticleSceneLook::keepsFirstBuild).
    void Initialize(int width, int height) override;
    /// Lighting on, light (0.5, 1, -1.5, 0) until the first Render.
    void InitializeDrawing() override { InitializeBookView(); }
    /// Origin, light (0, 1, 0, 0), then the scene: springs and joints as the physics system (red particles, blue
    /// ground, green boards, spring and joint lines; only the constraints once unstable); ch16 as its posts, drawn
    /// thin (half-size 0.1, 0.5, 0.1) in green although they collide at 0.3, the blue ground and the cloth as red
    /// one-sided triangles.
    void Render() override;
    /// Camera, then one physics step of dt seconds (the host runs whole steps of PhysicsStep()); stops and prints
    /// the report once the stability monitor fails.
    void Update(float dt) override;
    /// The scene's dt (s): the host runs whole physics steps of it.
    float PhysicsStep() const override { return scene.PhysicsStep(); }
    /// The look's panel (DrawSoftDemoPanel) drawn from the table.
    void ImGUI() override;
    /// One row per particle: "particle" (springs: 0 heavy, 1 light; joints: spawn order) or "cloth-particle"
    /// (ch16: index z*N + x).
    void CollectState(std::vector<BodyState>* out) const override;
    /// The stability monitor's report once it has failed.
    bool Unstable(std::string* report) const override {
        if (scene.Monitor().Stable()) return false;
        *report = scene.Monitor().Report().message;
        return true;
    }

    const SceneT& Scene() const { return scene; }
    const PhysicsSystem* World() const override { return &scene.System(); }

private:
    SceneT scene;
    bool reported = false;
    bool initialized = false;
};

using SimpleSprings = ParticleSceneDemo<SpringsScene>;
using CH16Demo = ParticleSceneDemo<Ch16Scene>;
using JointDemo = ParticleSceneDemo<JointScene>;

extern template class ParticleSceneDemo<SpringsScene>;
extern template class ParticleSceneDemo<Ch16Scene>;
extern template class ParticleSceneDemo<JointScene>;
