#include "Demos/ConservationOfMomentum.h"

#include <glad/gl.h>

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/ParameterPanel.h"
#include "Demos/Scenes/ContactSolverParameters.h"

ConservationOfMomentum::ConservationOfMomentum() {
    // docs/book-reference.md §2.4 gives only the zoom; target and rotation are the CH14 preset the other ch15 demos
    // use.
    UseBookCamera(12.0f);
    scene.AddParameters(&params);
    // Not a book row: the panel shows a non-book contact solver in effect (--set solver=).
    params.AddPanelText(
        [this] { return ContactSolverRow(scene.System().settings.contactSolver, scene.Params().contact.soft); });
    AddAutoModelKeys();
}

void ConservationOfMomentum::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    scene.Reset();
}

void ConservationOfMomentum::InitializeDrawing() {
    glPointSize(5.0f);
    EnableBookLighting();
}

void ConservationOfMomentum::Render() {
    DemoBase::Render();
    SetLightDirection(vec3(0.0f, 1.0f, 0.0f));
    ::Render(scene.System());
}

void ConservationOfMomentum::Update(float dt) {
    DemoBase::Update(dt);
    scene.Step(dt);
}

void ConservationOfMomentum::ImGUI() {
    // The book's 100 px panel has room below its widgets for the row naming a non-book contact solver.
    DrawPanel("Conservation Demo", BookPanel::kTallHeight);
    DemoBase::ImGUI();
}

void ConservationOfMomentum::CollectState(std::vector<BodyState>* out) const {
    const std::vector<RigidbodyVolume>& bodies = scene.Bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const char* kind = bodies[i].type == RigidbodyType::Sphere ? "sphere" : "box";
        out->push_back({static_cast<int>(i), kind, bodies[i].position, bodies[i].velocity});
    }
}
