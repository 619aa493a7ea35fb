#include "Demos/JointDemo.h"

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/SoftDemoPanel.h"

JointDemo::JointDemo() : scene(JointParams(), &rng) {
    UseBookCamera(9.0f);
    scene.AddParameters(&params);
    AddShowHelpButton();
    AddAutoModelKeys();
}

void JointDemo::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    // The scene was built in the constructor with the book's first spawn; rebuilding here would draw the
    // next random numbers, so only a later Initialize rebuilds.
    if (initialized) scene.Reset();
    initialized = true;
    reported = false;
}

void JointDemo::InitializeDrawing() { InitializeBookView(); }

void JointDemo::Update(float dt) {
    DemoBase::Update(dt);
    scene.Step(dt);
    ReportOnce(scene.Monitor(), "joints", &reported);
}

void JointDemo::Render() {
    DemoBase::Render();
    SetLightDirection(kSoftDemoLight);
    RenderSystemOrConstraints(scene.System(), scene.Monitor());
}

void JointDemo::ImGUI() {
    const JointParams& p = scene.Params();
    DrawSoftDemoPanel("Joint Demo", params, p.integrator, p.dt, scene.Monitor(), AutoModelRowHeight());
    DemoBase::ImGUI();
}

void JointDemo::CollectState(std::vector<BodyState>* out) const {
    const std::vector<Particle>& particles = scene.Particles();
    for (std::size_t i = 0; i < particles.size(); ++i)
        out->push_back({static_cast<int>(i), "particle", particles[i].GetPosition(), particles[i].GetVelocity()});
}
