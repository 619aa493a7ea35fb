#include "Demos/LinearImpulse.h"

#include <glad/gl.h>
#include <imgui.h>

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"

LinearImpulse::LinearImpulse() { scene.AddParameters(&params); }

void LinearImpulse::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    UseBookCamera(9.0f);
    glPointSize(5.0f);
    EnableBookLighting();
    scene.Reset();
}

void LinearImpulse::Render() {
    DemoBase::Render();
    SetLightDirection(vec3(0.0f, 1.0f, 0.0f));
    ::Render(scene.System());
}

void LinearImpulse::Update(float dt) {
    DemoBase::Update(dt);
    scene.Update(dt);
}

void LinearImpulse::ImGUI() {
    // docs/book-reference.md §2.3; the PushItemWidth is popped here (erratum 5.2-26).
    LinearImpulseParams& p = scene.Params();
    BeginPanel("Linear Impulse Demo", 100.0f);
    if (ImGui::Button("Step")) scene.RequestSteps();
    ImGui::SameLine();
    ImGui::PushItemWidth(100.0f);
    if (ImGui::InputInt("Frames", &p.frames) && p.frames < 1) p.frames = 1;
    ImGui::PopItemWidth();
    ImGui::SameLine();
    if (ImGui::Button("Reset")) scene.Reset();
    ImGui::SameLine();
    ImGui::Checkbox("Pause", &p.pause);
    if (ImGui::Checkbox("Spheres", &p.spheres)) scene.Reset();
    ImGui::SameLine();
    if (ImGui::Checkbox("Drop", &p.drop)) scene.Reset();
    ImGui::End();
    DemoBase::ImGUI();
}

void LinearImpulse::CollectState(std::vector<BodyState>* out) const {
    const std::vector<RigidbodyVolume>& bodies = scene.Bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const char* kind = bodies[i].type == RigidbodyType::Sphere ? "sphere" : "box";
        out->push_back({static_cast<int>(i), kind, bodies[i].position, bodies[i].velocity});
    }
}
