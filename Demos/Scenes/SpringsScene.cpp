#include "SpringsScene.h"

SpringsScene::SpringsScene(const SpringsParams& p) { Reset(p); }

OBB SpringsScene::Ground() { return OBB(vec3(0.0f, 0.0f, 0.0f), vec3(10.0f, 0.15f, 10.0f)); }

void SpringsScene::Reset(const SpringsParams& p) {
    params = p;
    system = std::make_unique<PhysicsSystem>();
    system->integrator = params.integrator;
    system->AddConstraint(Ground());

    // Book.md 2.6: p0 at (0,6,0) with mass 50, p1 at (2,6,0) with mass 1; bounce/friction stay default.
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
    for (Particle& particle : particles) {
        const vec3 pos = particle.GetPosition();
        if (pos.y < kFloorY) particle.SetPosition(vec3(pos.x, kFloorY, pos.z));
    }
    return monitor.Check(*system);
}
