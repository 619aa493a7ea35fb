#include "Demos/Scenes/SpringsScene.h"

#include <cmath>

SpringsScene::SpringsScene(const SpringsParams& p) { Reset(p); }

OBB SpringsScene::Ground() { return OBB(vec3(0.0f, 0.0f, 0.0f), vec3(10.0f, 0.15f, 10.0f)); }

void SpringsScene::Reset(const SpringsParams& p) {
    params = p;
    stepping.Select(params.integrator);
    Build();
}

void SpringsScene::Reset() {
    params.integrator = stepping.Chosen();
    Build();
}

void SpringsScene::Build() {
    system = std::make_unique<PhysicsSystem>();
    system->settings.integrator = params.integrator;
    system->settings.particleContact = stepping.Contact();
    system->AddConstraint(Ground());

    // docs/book-reference.md §2.6: p0 at (0,6,0) with mass 50, p1 at (2,6,0) with mass 1; bounce/friction stay default.
    particles.assign(2, Particle());
    particles[0].SetPosition(vec3(0.0f, 6.0f, 0.0f));
    particles[0].SetMass(kHeavyMass);
    particles[1].SetPosition(vec3(2.0f, 6.0f, 0.0f));
    particles[1].SetMass(kLightMass);
    for (Particle& particle : particles) system->AddRigidbody(&particle);

    Spring spring(FromBookSpringConstant(params.springK), FromBookSpringConstant(params.springDamping),
                  params.restLength);
    spring.SetParticles(&particles[0], &particles[1]);
    system->AddSpring(spring);
    monitor.Start(*system);
}

bool SpringsScene::Step(float dt) {
    if (!monitor.Stable() || !(dt > 0.0f) || !std::isfinite(dt)) return false;
    system->Update(dt);
    ClampAboveFloor(&particles, kBookFloorY);
    return monitor.Check(*system);
}

void SpringsScene::AddParameters(ParameterSet* set) {
    // The panel (docs/book-reference.md §2.6): three 100 px sliders on one line, then Reset (Show Help is
    // the demo's).
    using Widget = ParameterSet::Widget;
    auto reset = [this] { Reset(); };
    set->AddFloat("k", &params.springK, -5.0f, 0.0f, "book spring k (negative attracts); applied on reset", reset)
        .OnPanel(Widget::Slider("k").Width(100.0f));
    set->AddFloat("spring-damping", &params.springDamping, 0.0f, 1.0f, "book spring damping b; applied on reset", reset)
        .Alias("b")
        .OnPanel(Widget::Slider("b").Width(100.0f).SameLine());
    set->AddFloat("rest-length", &params.restLength, 0.0f, 5.0f, "spring rest length in m; applied on reset", reset)
        .Alias("l")
        .OnPanel(Widget::Slider("l").Width(100.0f).SameLine());
    set->AddAction("reset", reset, "rebuild the scene with the panel values").OnPanel(Widget::Button("Reset"));
    stepping.AddParameters(set, &params.dt, reset);
    stepping.AddContactParameter(set, [this] { system->settings.particleContact = stepping.Contact(); });
}
