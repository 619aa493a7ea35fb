#include "Demos/LinearImpulse.h"

#include <glad/gl.h>

#include "Application/Render/FixedFunctionPhysics.h"
#include "Application/Render/FixedFunctionPrimitives.h"
#include "Demos/ParameterPanel.h"
#include "Demos/Scenes/ContactSolverParameters.h"

LinearImpulse::LinearImpulse() {
    UseBookCamera(9.0f);
    scene.AddParameters(&params);
    // Not a book row: the panel shows a non-book contact solver in effect (--set solver=).
    params.AddPanelText(
        [this] { return ContactSolverRow(scene.System().settings.contactSolver, scene.Params().contact.soft); });
    AddAutoModelKeys();
}

void LinearImpulse::Initialize(int width, int height) {
    DemoBase::Initialize(width, height);
    scene.Reset();
}

void LinearImpulse::InitializeDrawing() {
    glPointSize(5.0f);
    EnableBookLighting();
}

void LinearImpulse::Render() {
    DemoBase::Render();
    SetLightDirection(vec3(0.0f, 1.0f, 0.0f));
    ::Render(scene.System());
}

void LinearImpulse::Update(float dt) {
    DemoBase::Update(dt);
    scene.Step(dt);
}

void LinearImpulse::ImGUI() {
    // The book's 100 px panel has room below its widgets for the row naming a non-book contact solver.
    DrawPanel("Linear Impulse Demo", BookPanel::kTallHeight);
    DemoBase::ImGUI();
}

void LinearImpulse::CollectState(std::vector<BodyState>* out) const {
    const std::vector<RigidbodyVolume>& bodies = scene.Bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const char* kind = bodies[i].type == RigidbodyType::Sphere ? "sphere" : "box";
        out->push_back({static_cast<int>(i), kind, bodies[i].position, bodies[i].velocity});
    }
}
