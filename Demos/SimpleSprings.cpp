#include "Demos/SimpleSprings.h"

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/SoftDemoPanel.h"

SimpleSprings::SimpleSprings() {
    UseBookCamera(9.0f);
    scene.AddParameters(&params);
    AddShowHelpButton();
    AddAutoModelKeys();
}

void SimpleSprings::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    scene.Reset();
    reported = false;
}

void SimpleSprings::InitializeDrawing() { InitializeBookView(); }

void SimpleSprings::Update(float dt) {
    DemoBase::Update(dt);
    scene.Step(dt);
    ReportOnce(scene.Monitor(), "springs", &reported);
}

void SimpleSprings::Render() {
    DemoBase::Render();
    SetLightDirection(kSoftDemoLight);
    RenderSystemOrConstraints(scene.System(), scene.Monitor());
}

void SimpleSprings::ImGUI() {
    const SpringsParams& p = scene.Params();
    DrawSoftDemoPanel("Simple Springs Demo", params, p.integrator, p.dt, scene.Monitor(), AutoModelRowHeight());
    DemoBase::ImGUI();
}

void SimpleSprings::CollectState(std::vector<BodyState>* out) const {
    const std::vector<Particle>& particles = scene.Particles();
    for (std::size_t i = 0; i < particles.size(); ++i)
        out->push_back({static_cast<int>(i), "particle", particles[i].GetPosition(), particles[i].GetVelocity()});
}
