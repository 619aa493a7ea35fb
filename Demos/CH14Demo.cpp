#include "Demos/CH14Demo.h"

#include <cstdio>
#include <string>
#include <vector>

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/ParameterPanel.h"

namespace {
const vec3 kLight{0.0f, 1.0f, 0.0f};  // CH14's Render: straight down
constexpr std::size_t kDeltaHistory = 120;
}  // namespace

CH14Demo::CH14Demo() {
    UseBookCamera(9.0f);
    // The panel (docs/book-reference.md §2.1): the delta row, "Particle count" with a 100 px slider, Reset,
    // Show Help; then the model's --set keys.
    params.AddPanelText([this] {
        float average = 0.0f;
        for (float d : deltas) average += d;
        if (!deltas.empty()) average /= static_cast<float>(deltas.size());
        char row[64];
        std::snprintf(row, sizeof row, "Simulation delta: %.3f ms/frame", static_cast<double>(average));
        return std::string(row);
    });
    scene.AddParameters(&params);
    AddShowHelpButton();
    AddAutoModelKeys();
}

void CH14Demo::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    scene.Reset();
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
