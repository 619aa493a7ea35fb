#include "Demos/Scenes/MomentumScene.h"

#include <cmath>

#include "Demos/Scenes/ContactSolverParameters.h"

MomentumScene::MomentumScene(const MomentumParams& p) : params(p) { Reset(); }

void MomentumScene::Reset() {
    system = std::make_unique<PhysicsSystem>();
    system->RenderRandomColors = true;
    system->settings.solverIterations = 20;
    bodies.assign(kSpheres + 1, RigidbodyVolume(RigidbodyType::Sphere));

    // docs/book-reference.md §2.4: x = i * 2.00002 for i = 0..3 and 4 * 3.00003 for the last; y = 1.16 puts the bottoms
    // 0.01 above the ground top (0.15).
    for (int i = 0; i < kSpheres; ++i) {
        RigidbodyVolume& s = bodies[i];
        const float spacing = (1.0f + 0.00001f) * (i < kSpheres - 1 ? 2.0f : 3.0f);
        s.position = vec3(static_cast<float>(i) * spacing, 1.16f, 0.0f);
        s.velocityRetention = params.velocityRetention;
        if (!params.gravity) s.gravity = vec3();
    }
    RigidbodyVolume& last = bodies[kSpheres - 1];
    // The book normalises the direction towards x = 0 along the row: (-20, 0, 0).
    last.AddVelocityChange(Normalized(vec3(-last.position.x, 0.0f, 0.0f)) * kLaunchSpeed);

    RigidbodyVolume& ground = bodies[kSpheres];
    ground.type = RigidbodyType::Box;
    ground.box.size = vec3(15.0f, 0.15f, 15.0f);
    ground.mass = 0.0f;

    for (RigidbodyVolume& body : bodies) {
        body.SynchCollisionVolumes();  // erratum 5.2-28: the book leaves the volumes at the origin until drawn
        system->AddRigidbody(&body);
    }
    ApplySolverSettings();
}

void MomentumScene::ApplySolverSettings() { params.contact.ApplyTo(&system->settings); }

bool MomentumScene::Step(float dt) {
    if (!(dt > 0.0f) || !std::isfinite(dt)) return false;
    system->Update(dt);
    return system->StopReason().empty();
}

void MomentumScene::AddParameters(ParameterSet* set) {
    set->AddAction(
           "reset", [this] { Reset(); }, "rebuild the scene")
        .OnPanel(ParameterSet::Widget::Button("Reset"));
    AddContactSolverParameters(set, &params.contact,
                               "contact solver: the book's per-contact impulses, accumulated impulses or the soft step",
                               [this] { ApplySolverSettings(); });
}

vec3 MomentumScene::TotalMomentum() const {
    vec3 p;
    for (const RigidbodyVolume& body : bodies) p += body.velocity * body.mass;
    return p;
}
