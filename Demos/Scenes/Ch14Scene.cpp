#include "Demos/Scenes/Ch14Scene.h"

#include <cmath>
#include <iterator>
#include <string>
#include <vector>

#include "Demos/Scenes/SoftSceneCommon.h"
#include "Math/Random.h"

Ch14Scene::Ch14Scene(const Ch14Params& p) { Reset(p); }

std::array<OBB, 4> Ch14Scene::Constraints() {
    // docs/book-reference.md §2.1: positions, Rotation3x3(pitch, yaw, roll) in degrees, half-sizes.
    OBB ground(vec3(0.0f, 0.0f, 0.0f), vec3(10.0f, 0.15f, 10.0f));
    OBB obb1(vec3(0.0f, 1.86f, -1.92f), vec3(2.0f, 0.15f, 2.0f), Rotation3x3(30.716f, 0.0f, 0.0f));
    OBB obb2(vec3(-1.0f, 3.6f, 1.2f), vec3(2.0f, 0.15f, 2.0f), Rotation3x3(-33.964f, -24.233f, 9.128f));
    OBB obb3(vec3(0.0f, 3.93f, -2.27f), vec3(2.0f, 0.15f, 0.7817011f), Rotation3x3(24.702f, 0.0f, 0.0f));
    return {ground, obb1, obb2, obb3};
}

void Ch14Scene::Reset(const Ch14Params& p) {
    params = p;
    panelParticles = p.particleCount;
    for (std::size_t i = 0; i < std::size(kAllIntegrators); ++i)
        if (kAllIntegrators[i] == p.integrator) integratorIndex = static_cast<int>(i);
    contactIndex = ParticleContactIndex(p.particleContact);
    panelSeed = static_cast<int>(p.seed);
    if (params.particleCount < 1) params.particleCount = 1;
    if (!(params.dt > 0.0f) || !std::isfinite(params.dt)) params.dt = Ch14Params().dt;
    system = std::make_unique<PhysicsSystem>();
    system->settings.integrator = params.integrator;
    system->settings.particleContact = params.particleContact;
    for (const OBB& box : Constraints()) system->AddConstraint(box);

    bodies.clear();
    bodies.reserve(static_cast<std::size_t>(params.particleCount));
    MsvcRand random(params.seed);
    const vec3 lo(kSpawnCenter.x - kSpawnHalfSize.x, kSpawnCenter.y - kSpawnHalfSize.y,
                  kSpawnCenter.z - kSpawnHalfSize.z);
    const vec3 hi(kSpawnCenter.x + kSpawnHalfSize.x, kSpawnCenter.y + kSpawnHalfSize.y,
                  kSpawnCenter.z + kSpawnHalfSize.z);
    for (int i = 0; i < params.particleCount; ++i) {
        // The book's call order per particle: x, y, z, then bounce (separate statements, so the order is fixed).
        const float x = random.Range(lo.x, hi.x);
        const float y = random.Range(lo.y, hi.y);
        const float z = random.Range(lo.z, hi.z);
        const float bounce = random.Range(0.0f, 1.0f);
        bodies.emplace_back();
        bodies.back().SetPosition(vec3(x, y, z));
        bodies.back().SetBounce(bounce);
    }
    for (Particle& particle : bodies) system->AddRigidbody(&particle);
}

void Ch14Scene::Reset() {
    Ch14Params p;
    p.particleCount = panelParticles;
    p.integrator = kAllIntegrators[integratorIndex];
    p.dt = stepDt > 0.0f ? stepDt : Ch14Params().dt;
    p.seed = static_cast<std::uint32_t>(panelSeed);
    p.particleContact = ParticleContactAt(contactIndex);
    Reset(p);
}

bool Ch14Scene::Step(float dt) {
    if (!(dt > 0.0f) || !std::isfinite(dt)) return false;
    system->Update(dt);
    ClampAboveFloor(&bodies, kBookFloorY);
    return system->StopReason().empty();
}

void Ch14Scene::AddParameters(ParameterSet* set) {
    // The panel (docs/book-reference.md §2.1) after the demo's delta row: "Particle count" with a 100 px slider,
    // Reset; then the model's keys.
    using Widget = ParameterSet::Widget;
    auto resetIfFresh = [this] {
        if (system->StepCount() == 0) Reset();
    };
    set->AddInt("particles", &panelParticles, 1, 300, "particle count; takes effect on reset (book)", resetIfFresh)
        .OnPanel(Widget::Slider("##particles").Width(100.0f).Caption("Particle count"));  // erratum 5.2-26: "" clashes
    set->AddAction(
           "reset", [this] { Reset(); }, "respawn the particles (the panel's Reset button)")
        .OnPanel(Widget::Button("Reset").SameLine());
    std::vector<std::string> ids;
    for (Integrator i : kAllIntegrators) ids.push_back(ToString(i));
    set->AddChoice("integrator", &integratorIndex, ids, "particle integrator (book: euler)",
                   [this] { SetIntegrator(kAllIntegrators[integratorIndex]); });
    // Up to 1 s, --dt's range: here --dt and --set dt= are one setting (docs/app.md, "Steps").
    set->AddFloat("dt", &stepDt, 0.0f, 1.0f, "physics step in s; 0 = the host's fixed step (book: 0.03)").Step();
    AddParticleContactParameter(set, &contactIndex, [this] { SetParticleContact(ParticleContactAt(contactIndex)); });
    set->AddInt("seed", &panelSeed, 0, 2147483647, "MSVC rand() seed of the spawns (book: 1); on reset", resetIfFresh);
}

void Ch14Scene::SetIntegrator(Integrator integrator) {
    params.integrator = integrator;
    system->settings.integrator = integrator;
}

void Ch14Scene::SetParticleContact(ParticleContact contact) {
    params.particleContact = contact;
    system->settings.particleContact = contact;
}
