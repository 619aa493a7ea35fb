#include "Demos/Scenes/LinearImpulseScene.h"

#include <cmath>

#include "Demos/Scenes/ContactSolverParameters.h"

LinearImpulseScene::LinearImpulseScene(const LinearImpulseParams& p) : params(p) { Reset(); }

void LinearImpulseScene::Reset() {
    system = std::make_unique<PhysicsSystem>();
    system->RenderRandomColors = true;
    pendingSteps = 0;
    const RigidbodyType kind = params.spheres ? RigidbodyType::Sphere : RigidbodyType::Box;
    bodies.assign(3, RigidbodyVolume(kind));

    // docs/book-reference.md §2.3: defaults everywhere (mass 1, radius 1, half-size 1). AddVelocityChange (the book's
    // AddLinearImpulse) adds to velocity.
    if (!params.drop) {
        bodies[0].position = vec3(-10.0f, 1.5f, -5.0f);
        bodies[1].position = vec3(5.0f, 1.5f, 2.5f);
        bodies[0].AddVelocityChange(vec3(15.0f, 5.0f, 7.5f));
        bodies[1].AddVelocityChange(vec3(-15.0f, 5.0f, -7.5f));
    } else {
        bodies[0].position = vec3(0.0f, 1.2f, 0.0f);
        bodies[1].position = vec3(0.0f, 4.0f, 0.0f);
    }
    RigidbodyVolume& ground = bodies[2];
    ground.type = RigidbodyType::Box;
    ground.box.size = vec3(10.0f, 0.15f, 10.0f);
    ground.mass = 0.0f;

    for (RigidbodyVolume& body : bodies) {
        body.SynchCollisionVolumes();  // erratum 5.2-28: the book leaves the volumes at the origin until drawn
        system->AddRigidbody(&body);
    }
    ApplySolverSettings();
}

void LinearImpulseScene::ApplySolverSettings() { params.contact.ApplyTo(&system->settings); }

void LinearImpulseScene::RequestSteps() { pendingSteps = params.frames; }

bool LinearImpulseScene::Step(float dt) {
    if (!(dt > 0.0f) || !std::isfinite(dt)) return false;
    if (!params.pause) {
        system->Update(dt);
    } else if (pendingSteps > 0) {
        --pendingSteps;
        system->Update(dt);
    }
    return system->StopReason().empty();
}

void LinearImpulseScene::AddParameters(ParameterSet* set) {
    // The panel: Step, Frames (100 px), Reset, Pause; then Spheres and Drop, which reset at once.
    using Widget = ParameterSet::Widget;
    set->AddAction(
           "step", [this] { RequestSteps(); }, "queue `frames` single steps (used while paused)")
        .OnPanel(Widget::Button("Step"));
    set->AddInt("frames", &params.frames, 1, 1000, "steps per press of Step")
        .OnPanel(Widget::InputInt("Frames").Width(100.0f).SameLine());
    set->AddAction(
           "reset", [this] { Reset(); }, "rebuild the scene")
        .OnPanel(Widget::Button("Reset").SameLine());
    set->AddBool("pause", &params.pause, "pause the simulation (the book starts paused)")
        .OnPanel(Widget::Checkbox("Pause").SameLine());
    set->AddBool("spheres", &params.spheres, "spheres instead of boxes (resets)", [this] { Reset(); })
        .OnPanel(Widget::Checkbox("Spheres").AppliesAtOnce());
    set->AddBool("drop", &params.drop, "drop the bodies onto each other instead of throwing them (resets)",
                 [this] { Reset(); })
        .OnPanel(Widget::Checkbox("Drop").SameLine().AppliesAtOnce());
    AddContactSolverParameters(set, &params.contact,
                               "contact solver: the book's per-contact impulses, accumulated impulses or the soft step",
                               [this] { ApplySolverSettings(); });
}
