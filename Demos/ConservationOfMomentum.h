#pragma once
// Conservation Of Momentum (docs/book-reference.md §2.4): a sphere sent into a row of four at 20 m/s.

#include "Demos/DemoBase.h"
#include "Demos/Scenes/MomentumScene.h"

class ConservationOfMomentum : public DemoBase {
public:
    /// Registers the reset action.
    ConservationOfMomentum();
    /// The CH14 camera preset with zoom 12; the scene (ImpulseIteration 20).
    void Initialize(int width, int height) override;
    /// Point size 5, lighting on.
    void InitializeDrawing() override;
    /// Origin, light (0, 1, 0, 0), then the physics system in random colours.
    void Render() override;
    /// Camera, then one physics step of dt.
    void Update(float dt) override;
    /// "Conservation Demo": Reset.
    void ImGUI() override;
    /// One "sphere" row per sphere and a "box" row for the ground.
    void CollectState(std::vector<BodyState>* out) const override;

    const MomentumScene& Scene() const { return scene; }

    const PhysicsSystem* World() const override { return &scene.System(); }

private:
    MomentumScene scene;
};
