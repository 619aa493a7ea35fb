#include "Demos/CH15Demo.h"

#include <glad/gl.h>

#include <string>

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/ParameterPanel.h"
#include "Demos/Scenes/ContactSolverParameters.h"

CH15Demo::CH15Demo() {
    UseBookCamera(12.0f);
    scene.AddParameters(&params);
    // Not a book row: the panel shows a non-book contact solver in effect.
    params.AddPanelText(
        [this] { return ContactSolverRow(scene.System().settings.contactSolver, scene.Params().contact.soft); });
    AddAutoModelKeys();
}

void CH15Demo::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    scene.Reset();
}

void CH15Demo::InitializeDrawing() {
    glPointSize(5.0f);
    EnableBookLighting();
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
    // The book's panel is 75 high; a non-book contact solver adds its row.
    const bool bookSolver = scene.System().settings.contactSolver == ContactSolver::Book;
    DrawPanel("Chapter 15 Demo", BookPanel::kHeight + (bookSolver ? 0.0f : BookPanel::kSolverRowHeight));
    DemoBase::ImGUI();
}

void CH15Demo::CollectState(std::vector<BodyState>* out) const {
    const std::vector<RigidbodyVolume>& bodies = scene.Bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i)
        out->push_back({static_cast<int>(i), "box", bodies[i].position, bodies[i].velocity});
}
