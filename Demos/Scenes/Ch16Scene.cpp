#include "Demos/Scenes/Ch16Scene.h"

#include <cmath>

#include "Physics/Spring.h"

Ch16Scene::Ch16Scene(const Ch16Params& p) { Reset(p); }

OBB Ch16Scene::Ground() { return OBB(vec3(0.0f, 0.0f, 0.0f), vec3(10.0f, 0.1f, 10.0f)); }

const std::array<vec3, 4>& Ch16Scene::PostPositions() {
    // docs/book-reference.md §2.7: two posts at height 2.4 and two at 2.3, at (+-0.5, +-0.5).
    static const std::array<vec3, 4> posts = {vec3(0.5f, 2.4f, 0.5f), vec3(-0.5f, 2.3f, 0.5f), vec3(-0.5f, 2.4f, -0.5f),
                                              vec3(0.5f, 2.3f, -0.5f)};
    return posts;
}

OBB Ch16Scene::PostCollider(int i) {
    return OBB(PostPositions()[i], vec3(kPostCollisionHalf, kPostHalfHeight, kPostCollisionHalf));
}

OBB Ch16Scene::PostVisual(int i) {
    return OBB(PostPositions()[i], vec3(kPostDrawHalf, kPostHalfHeight, kPostDrawHalf));
}

void Ch16Scene::Reset(const Ch16Params& p) {
    params = p;
    stepping.Select(params.integrator);
    Build();
}

void Ch16Scene::Reset() {
    params.integrator = stepping.Chosen();
    Build();
}

void Ch16Scene::Build() {
    system = std::make_unique<PhysicsSystem>();
    system->settings.integrator = params.integrator;
    system->settings.particleContact = stepping.Contact();
    cloth = std::make_unique<Cloth>();
    cloth->Initialize(params.particlesPerSide, params.particleSpacing, vec3(0.0f, kClothHeight, 0.0f));
    const float k = FromBookSpringConstant(params.springK);
    const float b = FromBookSpringConstant(params.springDamping);
    // The book's order: structural, bend, shear.
    cloth->SetStructuralSprings(k, b);
    cloth->SetBendSprings(k, b);
    cloth->SetShearSprings(k, b);
    system->AddCloth(cloth.get());
    system->AddConstraint(Ground());
    for (int i = 0; i < 4; ++i) system->AddConstraint(PostCollider(i));
    monitor.Start(*system);
}

bool Ch16Scene::Step(float dt) {
    if (!monitor.Stable() || !(dt > 0.0f) || !std::isfinite(dt)) return false;
    system->Update(dt);
    return monitor.Check(*system);
}

void Ch16Scene::AddParameters(ParameterSet* set) {
    // The panel (docs/book-reference.md §2.7): three 50 px sliders on one line, then Reset.
    using Widget = ParameterSet::Widget;
    auto reset = [this] { Reset(); };
    set->AddInt("count", &params.particlesPerSide, 5, 30, "cloth particles per side; applied on reset", reset)
        .OnPanel(Widget::Slider("Count").Width(50.0f));
    set->AddFloat("distance", &params.particleSpacing, 0.1f, 1.0f, "cloth particle spacing in m; applied on reset",
                  reset)
        .OnPanel(Widget::Slider("Distance").Width(50.0f).SameLine());
    set->AddFloat("k", &params.springK, -5.0f, 0.0f, "book spring k of every cloth spring; applied on reset", reset)
        .OnPanel(Widget::Slider("Spring k").Width(50.0f).SameLine());
    set->AddFloat("spring-damping", &params.springDamping, 0.0f, 1.0f,
                  "book spring damping d of every cloth spring (no widget in the book); applied on reset", reset)
        .Alias("damping");
    set->AddAction("reset", reset, "rebuild the scene with the panel values").OnPanel(Widget::Button("Reset"));
    stepping.AddParameters(set, &params.dt, reset);
    stepping.AddContactParameter(set, [this] { system->settings.particleContact = stepping.Contact(); });
}
