#include "Demos/Scenes/Ch15Scene.h"

#include <cmath>

#include "Demos/Scenes/ContactSolverParameters.h"

Ch15Scene::Ch15Scene(const Ch15Params& p) : params(p) { Reset(); }

void Ch15Scene::Reset() {
    system = std::make_unique<PhysicsSystem>();
    bodies.assign(3, RigidbodyVolume(RigidbodyType::Box));

    // docs/book-reference.md §2.5: cor 0.5 and friction 0.6 are the defaults; all three are synced at reset.
    RigidbodyVolume& tilted = bodies[0];
    tilted.position = vec3(0.5f, 6.0f, 0.0f);
    tilted.SetEulerOrientation(vec3(0.0f, 0.0f, 0.4f));  // radians: roll ~22.92 degrees
    tilted.mass = 1.0f;

    RigidbodyVolume& heavy = bodies[1];
    heavy.position = vec3(0.0f, 1.0f, 0.0f);
    heavy.mass = 5.0f;

    // (0,-0.5,0)*(1,0.5,1) and (50,1,50)*0.25 as in the book: top face at y = 0.
    RigidbodyVolume& ground = bodies[2];
    ground.position = vec3(0.0f, -0.25f, 0.0f);
    ground.box.size = vec3(12.5f, 0.25f, 12.5f);
    ground.mass = 0.0f;

    for (RigidbodyVolume& body : bodies) {
        body.SynchCollisionVolumes();
        system->AddRigidbody(&body);
    }
    system->RenderRandomColors = true;
    ApplySettings();
}

void Ch15Scene::ApplySettings() {
    system->settings.projectionFraction = params.projectionFraction;
    system->settings.penetrationSlop = params.penetrationSlop;
    system->settings.solverIterations = params.iterations;
    system->settings.linearProjection = params.linearProjection;
    system->DebugRender = params.debugRender;
    params.contact.ApplyTo(&system->settings);
}

bool Ch15Scene::Step(float dt) {
    if (!(dt > 0.0f) || !std::isfinite(dt)) return false;
    system->Update(dt);
    return system->StopReason().empty();
}

void Ch15Scene::AddParameters(ParameterSet* set) {
    // The panel (docs/book-reference.md §2.5): three 55 px sliders on one line, then Reset and two checkboxes. Each
    // edit (panel or --set) goes into the world at once, as the book's sliders write its PhysicsSystem's fields;
    // params keeps them for the fresh world a Reset builds.
    using Widget = ParameterSet::Widget;
    auto apply = [this] { ApplySettings(); };
    set->AddFloat("projection-fraction", &params.projectionFraction, 0.2f, 0.8f,
                  "LinearProjectionPercent: fraction of the penetration beyond the slop removed per step", apply)
        .Alias("projection")
        .OnPanel(Widget::Slider("Porjection").Width(55.0f).AppliesAtOnce());
    set->AddFloat("slop", &params.penetrationSlop, 0.01f, 0.1f, "PenetrationSlack: penetration left uncorrected (m)",
                  apply)
        .OnPanel(Widget::Slider("Slop").Width(55.0f).SameLine().AppliesAtOnce());
    set->AddInt("iterations", &params.iterations, 1, 20, "ImpulseIteration: passes over every contact per step", apply)
        .OnPanel(Widget::Slider("Iteration").Width(55.0f).SameLine().AppliesAtOnce());
    set->AddAction(
           "reset", [this] { Reset(); }, "rebuild the scene")
        .OnPanel(Widget::Button("Reset"));
    set->AddBool("debug", &params.debugRender, "DebugRender: box edges and collision manifolds", apply)
        .OnPanel(Widget::Checkbox("Debug Render").SameLine().AppliesAtOnce());
    set->AddBool("linear-projection", &params.linearProjection, "DoLinearProjection: positional correction", apply)
        .OnPanel(Widget::Checkbox("Linear Projection").SameLine().AppliesAtOnce());
    AddContactSolverParameters(set, &params.contact,
                               "contact solver: the book's per-contact impulses, accumulated impulses (stacks stand) "
                               "or the soft step",
                               apply);
}
