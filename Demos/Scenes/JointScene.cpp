#include "Demos/Scenes/JointScene.h"

#include <cmath>

JointScene::JointScene(const JointParams& p, MsvcRand* r) : rng(r != nullptr ? r : &ownRng) { Reset(p); }

std::vector<OBB> JointScene::Constraints() {
    // docs/book-reference.md §2.1 (CH14), in order; constraint 0 is the ground.
    return {
        OBB(vec3(0.0f, 0.0f, 0.0f), vec3(10.0f, 0.15f, 10.0f)),
        OBB(vec3(0.0f, 1.86f, -1.92f), vec3(2.0f, 0.15f, 2.0f), Rotation3x3(30.716f, 0.0f, 0.0f)),
        OBB(vec3(-1.0f, 3.6f, 1.2f), vec3(2.0f, 0.15f, 2.0f), Rotation3x3(-33.964f, -24.233f, 9.128f)),
        OBB(vec3(0.0f, 3.93f, -2.27f), vec3(2.0f, 0.15f, 0.7817011f), Rotation3x3(24.702f, 0.0f, 0.0f)),
    };
}

void JointScene::Reset(const JointParams& p) {
    params = p;
    stepping.Select(params.integrator);
    Build();
}

void JointScene::Reset() {
    params.integrator = stepping.Chosen();
    Build();
}

void JointScene::Build() {
    system = std::make_unique<PhysicsSystem>();
    system->settings.integrator = params.integrator;
    for (const OBB& c : Constraints()) system->AddConstraint(c);

    // erratum 5.2-23: the book rounds the SLIDER value up when it is odd and creates the odd count, leaving
    // one particle without a joint; the count created is what must be even.
    int createCount = params.particleCount < 2 ? 2 : params.particleCount;
    if (createCount % 2 != 0) createCount += 1;
    const int numJoints = createCount / 2;

    // Random calls per particle, in order: x, y, z, bounce (docs/book-reference.md §2.1); joint lengths after all of
    // them.
    const vec3 lo = SpawnCenter() - SpawnHalfSize();
    const vec3 hi = SpawnCenter() + SpawnHalfSize();
    particles.assign(createCount, Particle());  // never resized again: joints and the system point in
    for (Particle& particle : particles) {
        const float x = rng->Range(lo.x, hi.x);
        const float y = rng->Range(lo.y, hi.y);
        const float z = rng->Range(lo.z, hi.z);
        particle.SetPosition(vec3(x, y, z));
        particle.SetBounce(rng->Range(0.0f, 1.0f));
        system->AddRigidbody(&particle);
    }
    joints.assign(numJoints, DistanceJoint());
    for (int i = 0; i < numJoints; ++i) {
        joints[i].Initialize(&particles[i], &particles[i + numJoints], rng->Range(0.5f, 1.0f));
        system->AddRigidbody(&joints[i]);
    }
    monitor.Start(*system);
}

bool JointScene::Step(float dt) {
    if (!monitor.Stable() || !(dt > 0.0f) || !std::isfinite(dt)) return false;
    system->Update(dt);
    ClampAboveFloor(&particles, kBookFloorY);
    return monitor.Check(*system);
}

void JointScene::AddParameters(ParameterSet* set) {
    // The panel (docs/book-reference.md §2.8): "Particle count", a 100 px slider with the book's empty label,
    // Reset (Show Help is the demo's).
    using Widget = ParameterSet::Widget;
    auto reset = [this] { Reset(); };
    set->AddInt("particles", &params.particleCount, 2, 100, "particle count (odd rounds up); applied on reset", reset)
        .Alias("count")
        .OnPanel(Widget::Slider("##count").Width(100.0f).Caption("Particle count"));  // erratum 5.2-26: "" clashes
    set->AddAction("reset", reset, "rebuild the scene with the panel values (new random spawn)")
        .OnPanel(Widget::Button("Reset").SameLine());
    stepping.AddParameters(set, &params.dt, reset);
}
