#pragma once
// Chapter 16 (docs/book-reference.md §2.7): a 15 x 15 cloth dropped onto four posts. The scene (Ch16Scene) is GL-free
// and shared with the tests and bench/cloth_bench.cpp.

#include "Demos/DemoBase.h"
#include "Demos/Scenes/Ch16Scene.h"

class CH16Demo : public DemoBase {
public:
    /// Registers the scene's table: count, distance, k, spring-damping, reset, integrator, dt (--set resets).
    CH16Demo();
    /// Book camera preset (CH14's), scene rebuilt from the current values.
    void Initialize(int width, int height) override;
    /// Lighting on, light (0.5, 1, -1.5, 0) until the first Render.
    void InitializeDrawing() override;
    /// Origin, light (0, 1, 0, 0), the four posts drawn thin (half-size 0.1, 0.5, 0.1) in green although they
    /// collide at 0.3, the ground in blue, the cloth as red one-sided triangles (docs/book-reference.md §2.7).
    void Render() override;
    /// Camera, then one physics step of dt seconds (the host runs whole steps of PhysicsStep()); stops and
    /// prints the report once the stability monitor fails.
    void Update(float dt) override;
    /// The scene's dt (s): the host runs whole physics steps of it.
    float PhysicsStep() const override { return scene.Params().dt; }
    /// "Chapter 16 Demo" panel (DrawSoftDemoPanel) from the table: Count, Distance, Spring k (width 50), Reset.
    void ImGUI() override;
    /// One "cloth-particle" row per cloth particle, index z*N + x.
    void CollectState(std::vector<BodyState>* out) const override;
    /// The stability monitor's report once it has failed.
    bool Unstable(std::string* report) const override {
        if (scene.Monitor().Stable()) return false;
        *report = scene.Monitor().Report().message;
        return true;
    }

    const Ch16Scene& Scene() const { return scene; }

    const PhysicsSystem* World() const override { return &scene.System(); }

private:
    Ch16Scene scene;
    bool reported = false;
};
