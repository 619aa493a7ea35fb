#pragma once
// Chapter 14 (docs/book-reference.md §2.1): particles spawned with the book's random sequence fall onto a ground box
// and three tilted boards. GL-free; shared by CH14Demo, the tests and bench/particles_bench.cpp.

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "Demos/Scenes/BookConstants.h"
#include "Demos/Scenes/Parameters.h"
#include "Demos/Scenes/Scene.h"
#include "Physics/Integrator.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"

/// The demo's panel and model values (--set particles=, integrator=, dt=, seed=).
struct Ch14Params {
    int particleCount = 50;  ///< the book's numParticles (the panel's range is CH14Demo's table; benchmarks go beyond)
    Integrator integrator = Integrator::SemiImplicitEuler;    ///< the book's shipped integrator
    ParticleContact particleContact = ParticleContact::Book;  ///< how particles meet the boards (book)
    /// s: the physics step the demo asks its host for (book: 0.03, erratum 5.2-16); Step(dt) takes the step.
    float dt = kBookStep;
    std::uint32_t seed = 1;  ///< MsvcRand seed; the book never seeds (1)
};

class Ch14Scene final : public Scene {
public:
    /// Spawn box centre and half-size (docs/book-reference.md §2.1).
    static constexpr vec3 kSpawnCenter{-0.5f, 6.5f, -1.01f};
    static constexpr vec3 kSpawnHalfSize{3.8505f, 2.0f, 4.034834f};

    explicit Ch14Scene(const Ch14Params& params = {});
    /// Rebuilds the world from params (the book's ResetDemo): constraints, then the particles in order, each
    /// drawing x, y, z, bounce from a fresh MsvcRand(seed). particles < 1 is treated as 1.
    void Reset(const Ch14Params& params);
    /// Rebuilds from the panel values (particles, integrator, particle-contact, seed): the panel's Reset.
    void Reset() override;
    /// One physics step of dt seconds, then the book's y < -5 clamp (Scene::Step; dt <= 0 or non-finite: nothing).
    bool Step(float dt) override;
    /// The panel's keys after the demo's delta row: particles (on a fresh scene: reset), reset, integrator (at
    /// once), dt (0 = the host's), particle-contact (at once), seed (on a fresh scene: reset).
    void AddParameters(ParameterSet* set) override;
    /// The `dt` parameter (s) if set, else 0: the host's own fixed step (book: 0.03).
    float PhysicsStep() const override { return stepDt; }
    /// Switches the integrator without a reset (the particles keep their state).
    void SetIntegrator(Integrator integrator);
    /// Switches how particles meet the boards without a reset (WorldSettings::particleContact).
    void SetParticleContact(ParticleContact contact);

    const Ch14Params& Params() const { return params; }
    PhysicsSystem& System() override { return *system; }
    const PhysicsSystem& System() const override { return *system; }
    const std::vector<Particle>& Particles() const { return bodies; }
    std::vector<Particle>& Particles() { return bodies; }

    /// The four constraints in the book's order: ground (drawn blue), obb1, obb2, obb3.
    static std::array<OBB, 4> Constraints();

private:
    Ch14Params params;
    // The panel values a Reset() reads (Reset(params) sets them too), and the step the scene asks for.
    int panelParticles = Ch14Params().particleCount;
    int integratorIndex = 0;  // index into kAllIntegrators
    int contactIndex = 0;     // index of the "particle-contact" choice (book)
    int panelSeed = static_cast<int>(Ch14Params().seed);
    float stepDt = 0.0f;  // 0: the host's fixed step
    std::unique_ptr<PhysicsSystem> system;
    std::vector<Particle> bodies;  // reserved before AddRigidbody so the stored pointers stay valid
};
