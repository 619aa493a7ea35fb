#pragma once
// Simple Springs (docs/book-reference.md §2.6): a 50 kg and a 1 kg particle joined by one spring fall onto the ground.
// The scene (SpringsScene) is GL-free and shared with the tests.

#include "Demos/DemoBase.h"
#include "Demos/Scenes/SpringsScene.h"

class SimpleSprings : public DemoBase {
public:
    /// Registers k, b, l, reset, integrator and dt (--set resets the scene; the sliders wait for Reset).
    SimpleSprings();
    /// Book camera preset (CH14's), lighting on, scene rebuilt from the current values.
    void Initialize(int width, int height) override;
    /// Origin, light (0, 1, 0, 0), the physics system: red particles, blue ground, the spring line.
    void Render() override;
    /// Camera, then the scene's steps due after dt (one 0.03 s step per 0.03 s by default) with the y >= -5
    /// clamp; stops and prints the report to stderr once the stability monitor fails.
    void Update(float dt) override;
    /// "Simple Springs Demo" panel at (400,10), size (370,75): k, b, l sliders, Reset, Show Help.
    void ImGUI() override;
    /// One "particle" row per particle: 0 heavy, 1 light.
    void CollectState(std::vector<BodyState>* out) const override;

    const SpringsScene& Scene() const { return scene; }

private:
    SpringsScene scene;
    bool reported = false;
};
