#include "Demos/CH14Demo.h"

#include <cstdio>
#include <string>
#include <vector>

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/ParameterPanel.h"
#include "Demos/Scenes/SoftSceneCommon.h"

namespace {
const vec3 kLight{0.0f, 1.0f, 0.0f};  // CH14's Render: straight down
constexpr std::size_t kDeltaHistory = 120;
}  // namespace

CH14Demo::CH14Demo() {
    UseBookCamera(9.0f);
    // The panel (docs/book-reference.md §2.1): the delta row, "Particle count" with a 100 px slider, Reset,
    // Show Help; then the model's --set keys.
    using Widget = ParameterSet::Widget;
    auto resetIfFresh = [this] {
        if (scene.System().StepCount() == 0) ResetDemo();
    };
    params.AddPanelText([this] {
        float average = 0.0f;
        for (float d : deltas) average += d;
        if (!deltas.empty()) average /= static_cast<float>(deltas.size());
        char row[64];
        std::snprintf(row, sizeof row, "Simulation delta: %.3f ms/frame", static_cast<double>(average));
        return std::string(row);
    });
    params.AddInt("particles", &particleCount, 1, 300, "particle count; takes effect on reset (book)", resetIfFresh)
        .OnPanel(Widget::Slider("##particles").Width(100.0f).Caption("Particle count"));  // erratum 5.2-26: "" clashes
    params
        .AddAction(
            "reset", [this] { ResetDemo(); }, "respawn the particles (the panel's Reset button)")
        .OnPanel(Widget::Button("Reset").SameLine());
    std::vector<std::string> ids;
    for (Integrator i : kAllIntegrators) ids.push_back(ToString(i));
    params.AddChoice("integrator", &integratorIndex, ids, "particle integrator (book: euler)",
                     [this] { scene.SetIntegrator(kAllIntegrators[integratorIndex]); });
    params.AddFloat("dt", &stepDt, 0.0f, kMaxSceneDt, "physics step in s; 0 = the host's fixed step (book: 0.03)")
        .Step();
    AddParticleContactParameter(&params, &contactIndex,
                                [this] { scene.SetParticleContact(ParticleContactAt(contactIndex)); });
    params.AddInt("seed", &seed, 0, 2147483647, "MSVC rand() seed of the spawns (book: 1); on reset", resetIfFresh);
    AddShowHelpButton();
    AddAutoModelKeys();
}

void CH14Demo::ResetDemo() {
    Ch14Params p;
    p.particleCount = particleCount;
    p.integrator = kAllIntegrators[integratorIndex];
    p.dt = stepDt > 0.0f ? stepDt : Ch14Params().dt;
    p.seed = static_cast<std::uint32_t>(seed);
    p.particleContact = ParticleContactAt(contactIndex);
    scene.Reset(p);
}

void CH14Demo::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    ResetDemo();
}

void CH14Demo::InitializeDrawing() { InitializeBookView(); }

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
    DrawPanel("Chapter 14 Demo", BookPanel::kHeight, PanelScrollbar::Auto);
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
