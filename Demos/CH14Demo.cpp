#include "Demos/CH14Demo.h"

#include <imgui.h>

#include <string>
#include <vector>

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"

namespace {
const vec3 kLight{0.0f, 1.0f, 0.0f};  // CH14's Render: straight down
constexpr std::size_t kDeltaHistory = 120;
}  // namespace

CH14Demo::CH14Demo() {
    auto resetIfFresh = [this] {
        if (scene.System().StepCount() == 0) ResetDemo();
    };
    params.AddInt("particles", &numParticles, 1, 300, "particle count; takes effect on reset (book)", resetIfFresh);
    params.AddAction(
        "reset", [this] { ResetDemo(); }, "respawn the particles (the panel's Reset button)");
    std::vector<std::string> ids;
    for (Integrator i : kAllIntegrators) ids.push_back(ToString(i));
    params.AddChoice("integrator", &integratorIndex, ids, "particle integrator (book: euler)",
                     [this] { scene.SetIntegrator(kAllIntegrators[integratorIndex]); });
    params.AddFloat("dt", &stepDt, 0.0f, 0.1f, "physics step in s; 0 = the host's fixed step (book: 0.03)");
    params.AddInt("seed", &seed, 0, 2147483647, "MSVC rand() seed of the spawns (book: 1); on reset", resetIfFresh);
}

void CH14Demo::ResetDemo() {
    Ch14Params p;
    p.particles = numParticles;
    p.integrator = kAllIntegrators[integratorIndex];
    p.dt = stepDt > 0.0f ? stepDt : Ch14Params().dt;
    p.seed = static_cast<std::uint32_t>(seed);
    scene.Reset(p);
}

void CH14Demo::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    InitializeBookView();
    ResetDemo();
}

void CH14Demo::Update(float dt) {
    DemoBase::Update(dt);
    deltas.push_back(dt * 1000.0f);
    while (deltas.size() > kDeltaHistory) deltas.pop_front();
    scene.Step(dt);
}

void CH14Demo::Render() {
    DemoBase::Render();
    SetLightDirection(kLight);
    ::Render(scene.System());
}

void CH14Demo::ImGUI() {
    float average = 0.0f;
    for (float d : deltas) average += d;
    if (!deltas.empty()) average /= static_cast<float>(deltas.size());

    ImGui::SetNextWindowPos(ImVec2(400.0f, 10.0f), ImGuiCond_Once);
    ImGui::SetNextWindowSize(ImVec2(370.0f, 75.0f), ImGuiCond_Always);
    ImGui::Begin("Chapter 14 Demo", nullptr, ImGuiWindowFlags_NoResize);
    ImGui::Text("Simulation delta: %.3f ms/frame", average);
    ImGui::Text("Particle count");
    ImGui::SameLine();
    ImGui::PushItemWidth(100.0f);
    ImGui::SliderInt("##particles", &numParticles, 1, 300);  // book label "" (erratum 5.2-26: ID clash)
    ImGui::PopItemWidth();                                   // erratum 5.2-26: the book never pops it
    ImGui::SameLine();
    if (ImGui::Button("Reset")) ResetDemo();
    ImGui::SameLine();
    if (ImGui::Button("Show Help")) show_help = true;
    ImGui::End();
    DemoBase::ImGUI();
}

void CH14Demo::CollectState(std::vector<BodyState>* out) const {
    const std::vector<Particle>& particles = scene.Particles();
    for (std::size_t i = 0; i < particles.size(); ++i) {
        BodyState row;
        row.body = static_cast<int>(i);
        row.kind = "particle";
        row.position = particles[i].GetPosition();
        row.velocity = particles[i].GetVelocity();
        out->push_back(row);
    }
}
