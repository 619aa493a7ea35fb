#pragma once
// Joint Demo (docs/book-reference.md §2.8): CH14's particles in pairs held apart by distance joints. The scene
// (JointScene) is GL-free and shared with the tests.

#include "Demos/DemoBase.h"
#include "Demos/Scenes/JointScene.h"
#include "Math/Random.h"

class JointDemo : public DemoBase {
public:
    /// Registers the scene's table (particles, reset, integrator, dt; --set resets) and Show Help.
    JointDemo();
    /// Book camera preset (CH14's), scene rebuilt from the current values.
    void Initialize(int width, int height) override;
    /// Lighting on, light (0.5, 1, -1.5, 0) until the first Render.
    void InitializeDrawing() override;
    /// Origin, light (0, 1, 0, 0), the physics system: red particles, blue ground, green boards, joint lines.
    void Render() override;
    /// Camera, then one physics step of dt seconds (the host runs whole steps of PhysicsStep()); stops and
    /// prints the report once the stability monitor fails.
    void Update(float dt) override;
    /// The scene's dt (s): the host runs whole physics steps of it.
    float PhysicsStep() const override { return scene.Params().dt; }
    /// "Joint Demo" panel (DrawSoftDemoPanel) from the table: particle count slider, Reset, Show Help.
    void ImGUI() override;
    /// One "particle" row per particle, in spawn order.
    void CollectState(std::vector<BodyState>* out) const override;
    /// The stability monitor's report once it has failed.
    bool Unstable(std::string* report) const override {
        if (scene.Monitor().Stable()) return false;
        *report = scene.Monitor().Report().message;
        return true;
    }

    const JointScene& Scene() const { return scene; }

    const PhysicsSystem* World() const override { return &scene.System(); }

private:
    MsvcRand rng;  // the book's rand(): seed 1, never reseeded, so each Reset spawns elsewhere
    JointScene scene;
    bool reported = false;
    bool initialized = false;
};
