#pragma once
// Chapter 14 (docs/book-reference.md §2.1): particles spawned with the book's random sequence fall onto a ground box
// and three tilted boards. GL-free; shared by CH14Demo, the tests and bench/particles_bench.cpp.

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "Physics/Integrator.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"

/// The demo's panel and model values (--set particles=, integrator=, dt=, seed=).
struct Ch14Params {
    int particles = 50;  ///< the book's numParticles; the panel allows 1..300, the benchmark more
    Integrator integrator = Integrator::SemiImplicitEuler;  ///< the book's shipped integrator
    float dt = 0.03f;                                       ///< s per step (the book's 0.03, erratum 5.2-16)
    std::uint32_t seed = 1;                                 ///< MsvcRand seed; the book never seeds (1)
};

class Ch14Scene {
public:
    /// y below which a particle is put back (book: y < -5 gets y = -5 through SetPosition).
    static constexpr float kFloorClamp = -5.0f;
    /// Spawn box centre and half-size (docs/book-reference.md §2.1).
    static constexpr vec3 kSpawnCenter{-0.5f, 6.5f, -1.01f};
    static constexpr vec3 kSpawnHalfSize{3.8505f, 2.0f, 4.034834f};

    explicit Ch14Scene(const Ch14Params& params = {});
    /// Rebuilds the world from params (the book's ResetDemo): constraints, then the particles in order, each
    /// drawing x, y, z, bounce from a fresh MsvcRand(seed). particles < 1 is treated as 1.
    void Reset(const Ch14Params& params);
    /// One fixed step of Params().dt, then the book's y < -5 clamp.
    void Step();
    /// Switches the integrator without a reset (the particles keep their state).
    void SetIntegrator(Integrator integrator);
    /// Changes the step length used by Step(); non-positive or non-finite values are ignored.
    void SetDt(float dt);

    const Ch14Params& Params() const { return params; }
    PhysicsSystem& System() { return *system; }
    const PhysicsSystem& System() const { return *system; }
    const std::vector<Particle>& Particles() const { return bodies; }
    std::vector<Particle>& Particles() { return bodies; }

    /// The four constraints in the book's order: ground (drawn blue), obb1, obb2, obb3.
    static std::array<OBB, 4> Constraints();

private:
    Ch14Params params;
    std::unique_ptr<PhysicsSystem> system;
    std::vector<Particle> bodies;  // reserved before AddRigidbody so the stored pointers stay valid
};
