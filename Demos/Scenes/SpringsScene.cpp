#include "Demos/Scenes/SpringsScene.h"

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

int SpringsScene::Advance(float elapsed) {
    return stepping.Advance(elapsed, params.dt, monitor, [this] { Step(); });
}

void SpringsScene::Build() {
    stepping.Clear();
    system = std::make_unique<PhysicsSystem>();
    system->integrator = params.integrator;
    system->AddConstraint(Ground());

    // docs/book-reference.md §2.6: p0 at (0,6,0) with mass 50, p1 at (2,6,0) with mass 1; bounce/friction stay default.
    particles.assign(2, Particle());
    particles[0].SetPosition(vec3(0.0f, 6.0f, 0.0f));
    particles[0].SetMass(kHeavyMass);
    particles[1].SetPosition(vec3(2.0f, 6.0f, 0.0f));
    particles[1].SetMass(kLightMass);
    for (Particle& particle : particles) system->AddRigidbody(&particle);

    Spring spring(FromBookSpringConstant(params.k), FromBookSpringConstant(params.b), params.restLength);
    spring.SetParticles(&particles[0], &particles[1]);
    system->AddSpring(spring);
    monitor.Start(*system);
}

bool SpringsScene::Step() {
    system->Update(params.dt);
    ClampAboveFloor(&particles, kFloorY);
    return monitor.Check(*system);
}

void SpringsScene::AddParameters(ParameterSet* set) {
    auto reset = [this] { Reset(); };
    set->AddFloat("k", &params.k, -5.0f, 0.0f, "book spring k (negative attracts); applied on reset", reset);
    set->AddFloat("b", &params.b, 0.0f, 1.0f, "book spring damping; applied on reset", reset);
    set->AddFloat("l", &params.restLength, 0.0f, 5.0f, "spring rest length in m; applied on reset", reset);
    set->AddAction("reset", reset, "rebuild the scene with the panel values");
    stepping.AddParameters(set, &params.dt, reset);
}
