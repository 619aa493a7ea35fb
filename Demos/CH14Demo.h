#pragma once
// Chapter 14 (docs/book-reference.md §2.1): 50 particles spawned with the book's random sequence bounce down four OBB
// constraints. The scene (Ch14Scene) is GL-free and shared with the tests and bench/particles_bench.cpp.

#include <deque>

#include "Demos/DemoBase.h"
#include "Demos/Scenes/Ch14Scene.h"

class CH14Demo : public DemoBase {
public:
    /// Registers the demo's table: the panel (delta row, particles applied on Reset as the book, Reset, Show
    /// Help), the model keys integrator, dt, seed and the error-budget keys (DemoBase::AddAutoModelKeys). particles and
    /// seed set before the first step rebuild at once (so --set applies).
    CH14Demo();
    /// Book camera preset, scene built.
    void Initialize(int width, int height) override;
    /// Lighting on, light (0.5, 1, -1.5, 0) until the first Render.
    void InitializeDrawing() override;
    /// Origin axes, light (0, 1, 0, 0), then the physics system (red particles, blue ground, green boards).
    void Render() override;
    /// Camera, then one physics step of dt seconds and the y < -5 clamp. The panel's "Simulation delta"
    /// averages these steps in ms (deterministic; the book measured wall-clock time between fixed updates).
    void Update(float dt) override;
    /// The `dt` parameter (s) if set, else 0: the host's own fixed step (book: 0.03).
    float PhysicsStep() const override { return scene.PhysicsStep(); }
    /// "Chapter 14 Demo" panel drawn from the table: delta, particle count slider, Reset, Show Help.
    void ImGUI() override;
    /// One "particle" row per particle, in spawn order.
    void CollectState(std::vector<BodyState>* out) const override;

    const Ch14Scene& Scene() const { return scene; }

    const PhysicsSystem* World() const override { return &scene.System(); }
    void ExportNotes(std::vector<std::string>* notes) const override {
        notes->push_back("the demo lifts particles below y = -5 back to it after each step (not in the format)");
    }

private:
    Ch14Scene scene;
    std::deque<float> deltas;  // the last 120 fixed deltas (ms), as the book's deque
};
