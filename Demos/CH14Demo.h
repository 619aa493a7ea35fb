#pragma once
// Chapter 14 (docs/book-reference.md §2.1): 50 particles spawned with the book's random sequence bounce down four OBB
// constraints. The scene (Ch14Scene) is GL-free and shared with the tests and bench/particles_bench.cpp.

#include <deque>

#include "Demos/DemoBase.h"
#include "Demos/Scenes/Ch14Scene.h"

class CH14Demo : public DemoBase {
public:
    /// Registers the panel and model parameters: particles (1..300, on Reset as the book), reset, integrator,
    /// dt, seed. particles and seed set before the first step rebuild at once (so --set applies).
    CH14Demo();
    /// Book camera preset, lighting on, light (0.5, 1, -1.5, 0) until the first Render, scene built.
    void Initialize(int width, int height) override;
    /// Origin axes, light (0, 1, 0, 0), then the physics system (red particles, blue ground, green boards).
    void Render() override;
    /// Camera, then one physics step and the y < -5 clamp. The step is the `dt` parameter (s) if set, else
    /// the host's fixed delta (book: 0.03). The panel's "Simulation delta" averages these steps in ms
    /// (deterministic; the book measured wall-clock time between fixed updates).
    void Update(float dt) override;
    /// "Chapter 14 Demo" panel at (400,10), size (370,75): delta, particle count slider, Reset, Show Help.
    void ImGUI() override;
    /// One "particle" row per particle, in spawn order.
    void CollectState(std::vector<BodyState>* out) const override;

    const Ch14Scene& Scene() const { return scene; }
    /// Rebuilds the scene from the current parameter values (the book's ResetDemo).
    void ResetDemo();

private:
    Ch14Scene scene;
    int numParticles = 50;
    int integratorIndex = static_cast<int>(Integrator::SemiImplicitEuler);
    float stepDt = 0.0f;  // 0: the host's fixed step
    int seed = 1;
    std::deque<float> deltas;  // the last 120 fixed deltas (ms), as the book's deque
};
