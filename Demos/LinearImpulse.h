#pragma once
// Linear Impulse (docs/book-reference.md §2.3): two spheres or boxes thrown at (or dropped onto) each other, with pause
// and single-step controls. Headless runs start unpaused (pause=1 gives the book's paused start).

#include "Demos/DemoBase.h"
#include "Demos/Scenes/LinearImpulseScene.h"

class LinearImpulse : public DemoBase {
public:
    /// Registers step, frames, reset, pause, spheres and drop.
    LinearImpulse();
    /// The CH14 camera preset with zoom 9; the scene.
    void Initialize(int width, int height) override;
    /// Point size 5, lighting on.
    void InitializeDrawing() override;
    /// Origin, light (0, 1, 0, 0), then the physics system in random colours.
    void Render() override;
    /// Camera, then a step unless paused (or one queued step while paused).
    void Update(float dt) override;
    /// "Linear Impulse Demo": Step, Frames, Reset, Pause; Spheres, Drop.
    void ImGUI() override;
    /// One "sphere" or "box" row per body (the ground is a box).
    void CollectState(std::vector<BodyState>* out) const override;

    const LinearImpulseScene& Scene() const { return scene; }

    const PhysicsSystem* World() const override { return &scene.System(); }

private:
    LinearImpulseScene scene;
};
