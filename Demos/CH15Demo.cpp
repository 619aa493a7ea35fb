#include "Demos/CH15Demo.h"

#include <glad/gl.h>
#include <imgui.h>

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"

CH15Demo::CH15Demo() { scene.AddParameters(&params); }

void CH15Demo::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    UseBookCamera(12.0f);
    glPointSize(5.0f);
    EnableBookLighting();
    scene.Reset();
}

void CH15Demo::Render() {
    DemoBase::Render();
    SetLightDirection(vec3(0.0f, 1.0f, 0.0f));
    ::Render(scene.System());
}

void CH15Demo::Update(float dt) {
    DemoBase::Update(dt);
    scene.Step(dt);
}

void CH15Demo::ImGUI() {
    // docs/book-reference.md §2.5; the book's PushItemWidth calls are popped here (erratum 5.2-26).
    Ch15Params& p = scene.Params();
    // The book's panel is 75 high; a non-book contact solver adds a row so the panel shows the model in effect.
    const bool bookSolver = p.solver == 0;
    BeginPanel("Chapter 15 Demo", bookSolver ? 75.0f : 95.0f);
    ImGui::PushItemWidth(55.0f);
    ImGui::SliderFloat("Porjection", &p.projection, 0.2f, 0.8f);
    ImGui::PopItemWidth();
    ImGui::SameLine();
    ImGui::PushItemWidth(55.0f);
    ImGui::SliderFloat("Slop", &p.slop, 0.01f, 0.1f);
    ImGui::PopItemWidth();
    ImGui::SameLine();
    ImGui::PushItemWidth(55.0f);
    ImGui::SliderInt("Iteration", &p.iterations, 1, 20);
    ImGui::PopItemWidth();
    if (ImGui::Button("Reset")) scene.Reset();
    ImGui::SameLine();
    ImGui::Checkbox("Debug Render", &p.debug);
    ImGui::SameLine();
    ImGui::Checkbox("Linear Projection", &p.linearProjection);
    if (!bookSolver) ImGui::Text("Contact solver: %s", ToString(ContactSolver::Accumulated));
    ImGui::End();
    DemoBase::ImGUI();
}

void CH15Demo::CollectState(std::vector<BodyState>* out) const {
    const std::vector<RigidbodyVolume>& bodies = scene.Bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i)
        out->push_back({static_cast<int>(i), "box", bodies[i].position, bodies[i].velocity});
}
