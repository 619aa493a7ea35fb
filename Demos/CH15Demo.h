#pragma once
// Chapter 15 (docs/book-reference.md §2.5): two boxes stacking on a ground slab, with the solver panel.

#include "Demos/DemoBase.h"
#include "Demos/Scenes/Ch15Scene.h"

class CH15Demo : public DemoBase {
public:
    /// Registers the scene's table and the contact-solver text row.
    CH15Demo();
    /// Camera target (3.75622, 2.98255, 0), zoom 12, rotation (-67.9312, 19.8); the scene.
    void Initialize(int width, int height) override;
    /// Point size 5, lighting on.
    void InitializeDrawing() override;
    /// Origin, light (0, 1, 0, 0), then the physics system (random colours; edges and manifolds if debug).
    void Render() override;
    /// Camera, then one physics step of dt.
    void Update(float dt) override;
    /// "Chapter 15 Demo" from the table: Porjection / Slop / Iteration sliders, Reset, Debug Render, Linear
    /// Projection; a non-book contact solver adds its row.
    void ImGUI() override;
    /// One "box" row per body.
    void CollectState(std::vector<BodyState>* out) const override;

    const Ch15Scene& Scene() const { return scene; }

    const PhysicsSystem* World() const override { return &scene.System(); }

private:
    Ch15Scene scene;
};
