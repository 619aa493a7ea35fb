#pragma once
// Joint Demo (docs/book-reference.md §2.8): CH14's particles in pairs held apart by distance joints. The scene
// (JointScene) is GL-free and shared with the tests.

#include "Demos/DemoBase.h"
#include "Demos/Scenes/JointScene.h"
#include "Math/Random.h"

class JointDemo : public DemoBase {
public:
    /// Registers count, reset, integrator and dt (--set resets the scene).
    JointDemo();
    /// Book camera preset (CH14's), lighting on, scene rebuilt from the current values.
    void Initialize(int width, int height) override;
    /// Origin, light (0, 1, 0, 0), the physics system: red particles, blue ground, green boards, joint lines.
    void Render() override;
    /// Camera, then the scene's steps due after dt with the y >= -5 clamp; stops and reports on a blow-up.
    void Update(float dt) override;
    /// "Joint Demo" panel at (400,10), size (370,75): particle count slider, Reset, Show Help.
    void ImGUI() override;
    /// One "particle" row per particle, in spawn order.
    void CollectState(std::vector<BodyState>* out) const override;

    const JointScene& Scene() const { return scene; }

private:
    MsvcRand rng;  // the book's rand(): seed 1, never reseeded, so each Reset spawns elsewhere
    JointScene scene;
    bool reported = false;
    bool initialized = false;
};
