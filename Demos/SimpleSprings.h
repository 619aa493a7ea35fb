#pragma once
// Simple Springs (docs/book-reference.md §2.6): a 50 kg and a 1 kg particle joined by one spring fall onto the ground.
// The scene (SpringsScene) is GL-free and shared with the tests.

#include "Demos/DemoBase.h"
#include "Demos/Scenes/SpringsScene.h"

class SimpleSprings : public DemoBase {
public:
    /// Registers the scene's table (k, spring-damping, rest-length, reset, integrator, dt; --set resets the
    /// scene, the sliders wait for Reset) and the Show Help button.
    SimpleSprings();
    /// Book camera preset (CH14's), scene rebuilt from the current values.
    void Initialize(int width, int height) override;
    /// Lighting on, light (0.5, 1, -1.5, 0) until the first Render.
    void InitializeDrawing() override;
    /// Origin, light (0, 1, 0, 0), the physics system: red particles, blue ground, the spring line.
    void Render() override;
    /// Camera, then one physics step of dt seconds (the host runs whole steps of PhysicsStep()); stops and
    /// prints the report once the stability monitor fails.
    void Update(float dt) override;
    /// The scene's dt (s): the host runs whole physics steps of it.
    float PhysicsStep() const override { return scene.Params().dt; }
    /// "Simple Springs Demo" panel (DrawSoftDemoPanel) from the table: k, b, l sliders, Reset, Show Help.
    void ImGUI() override;
    /// One "particle" row per particle: 0 heavy, 1 light.
    void CollectState(std::vector<BodyState>* out) const override;
    /// The stability monitor's report once it has failed.
    bool Unstable(std::string* report) const override {
        if (scene.Monitor().Stable()) return false;
        *report = scene.Monitor().Report().message;
        return true;
    }

    const SpringsScene& Scene() const { return scene; }

    const PhysicsSystem* World() const override { return &scene.System(); }

private:
    SpringsScene scene;
    bool reported = false;
};
