#include "Demos/CH16Demo.h"

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/SoftDemoPanel.h"

CH16Demo::CH16Demo() {
    UseBookCamera(9.0f);
    scene.AddParameters(&params);
    AddAutoModelKeys();
}

void CH16Demo::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    scene.Reset();
    reported = false;
}

void CH16Demo::InitializeDrawing() { InitializeBookView(); }

void CH16Demo::Update(float dt) {
    DemoBase::Update(dt);
    scene.Step(dt);
    ReportOnce(scene.Monitor(), "ch16", &reported);
}

void CH16Demo::Render() {
    DemoBase::Render();
    SetLightDirection(kSoftDemoLight);
    SetLightColors(BookColors::kConstraintAmbient, BookColors::kConstraintDiffuse);
    for (int i = 0; i < 4; ++i) ::Render(Ch16Scene::PostVisual(i));
    SetLightColors(BookColors::kGroundAmbient, BookColors::kGroundDiffuse);
    ::Render(Ch16Scene::Ground());
    // The book's DebugRender cannot be toggled (erratum 5.2-25): always the red one-sided triangles.
    if (scene.Monitor().Stable()) ::Render(scene.GetCloth(), scene.System().DebugRender);
}

void CH16Demo::ImGUI() {
    const Ch16Params& p = scene.Params();
    DrawSoftDemoPanel("Chapter 16 Demo", params, p.integrator, p.dt, scene.Monitor(), AutoModelRowHeight());
    DemoBase::ImGUI();
}

void CH16Demo::CollectState(std::vector<BodyState>* out) const {
    const std::vector<Particle>& verts = scene.GetCloth().verts;
    for (std::size_t i = 0; i < verts.size(); ++i)
        out->push_back({static_cast<int>(i), "cloth-particle", verts[i].GetPosition(), verts[i].GetVelocity()});
}
