#include "Demos/JointDemo.h"

#include <imgui.h>

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/SoftDemoPanel.h"

JointDemo::JointDemo() : scene(JointParams(), &rng) { scene.AddParameters(&params); }

void JointDemo::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    InitializeBookView();
    // The scene was built in the constructor with the book's first spawn; rebuilding here would draw the
    // next random numbers, so only a later Initialize rebuilds.
    if (initialized) scene.Reset();
    initialized = true;
    reported = false;
}

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
    JointParams& p = scene.Params();
    BeginSoftPanel("Joint Demo", p.integrator, p.dt, scene.Monitor());
    ImGui::Text("Particle count");
    ImGui::SameLine();
    ImGui::PushItemWidth(100.0f);
    ImGui::SliderInt("##count", &p.numParticles, 2, 100);  // book label "" (erratum 5.2-26: ID clash)
    ImGui::PopItemWidth();                                 // erratum 5.2-26: the book never pops it
    ImGui::SameLine();
    if (ImGui::Button("Reset")) {
        scene.Reset();
        reported = false;
    }
    ImGui::SameLine();
    if (ImGui::Button("Show Help")) show_help = true;
    EndSoftPanel(params, scene.Monitor());
    DemoBase::ImGUI();
}

void JointDemo::CollectState(std::vector<BodyState>* out) const {
    const std::vector<Particle>& particles = scene.Particles();
    for (std::size_t i = 0; i < particles.size(); ++i)
        out->push_back({static_cast<int>(i), "particle", particles[i].GetPosition(), particles[i].GetVelocity()});
}
