#include "Demos/SimpleSprings.h"

#include <imgui.h>

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/SoftDemoPanel.h"

SimpleSprings::SimpleSprings() { scene.AddParameters(&params); }

void SimpleSprings::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    InitializeBookView();
    scene.Reset();
    reported = false;
}

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
    SpringsParams& p = scene.Params();
    BeginSoftPanel("Simple Springs Demo", scene.Params().integrator, p.dt, scene.Monitor());
    ImGui::PushItemWidth(100.0f);
    ImGui::SliderFloat("k", &p.k, -5.0f, 0.0f);
    ImGui::SameLine();
    ImGui::SliderFloat("b", &p.b, 0.0f, 1.0f);
    ImGui::SameLine();
    ImGui::SliderFloat("l", &p.restLength, 0.0f, 5.0f);
    ImGui::PopItemWidth();  // erratum 5.2-26: the book never pops it
    if (ImGui::Button("Reset")) {
        scene.Reset();
        reported = false;
    }
    ImGui::SameLine();
    if (ImGui::Button("Show Help")) show_help = true;
    EndSoftPanel(params, scene.Monitor());
    DemoBase::ImGUI();
}

void SimpleSprings::CollectState(std::vector<BodyState>* out) const {
    const std::vector<Particle>& particles = scene.Particles();
    for (std::size_t i = 0; i < particles.size(); ++i)
        out->push_back({static_cast<int>(i), "particle", particles[i].GetPosition(), particles[i].GetVelocity()});
}
