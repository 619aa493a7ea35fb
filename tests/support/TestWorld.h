#pragma once
// One world fixture for the physics tests: a PhysicsSystem together with the bodies it points at, which it owns.
// Add bodies (from a BodySpec of Demos/Scenes/WorldBuilder.h, or built by the test), set system.settings, change a
// body's fields if the test needs to, then Join() hands them to the system in the order they were added (volumes
// get SynchCollisionVolumes first) and Step() runs it; read back through the bodies and the measures below.
// Bodies live in deques, so a reference returned by Add stays valid as more are added.

#include <cmath>
#include <cstddef>
#include <deque>
#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/Particle.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"
#include "tests/support/Volumes.h"

class TestWorld {
public:
    TestWorld() = default;
    /// One volume per spec, joined at once (what Demos/Scenes/WorldBuilder.h's RigidWorld builds, for tests).
    explicit TestWorld(const std::vector<BodySpec>& specs) {
        AddAll(specs);
        Join();
    }
    TestWorld(const TestWorld&) = delete;
    TestWorld& operator=(const TestWorld&) = delete;

    /// A volume built from spec (MakeBody); it joins the system at the next Join or Step.
    RigidbodyVolume& Add(const BodySpec& spec) { return Add(MakeBody(spec)); }
    /// A volume built by the test; it joins the system at the next Join or Step.
    RigidbodyVolume& Add(const RigidbodyVolume& body) {
        volumes.push_back(body);
        pending.push_back({&volumes.back(), nullptr});
        return volumes.back();
    }
    /// One volume per spec, in order.
    void AddAll(const std::vector<BodySpec>& specs) {
        for (const BodySpec& spec : specs) Add(spec);
    }
    /// A particle (a default one: 1 kg at the origin, the book's gravity); it joins at the next Join or Step.
    Particle& AddParticle(const Particle& particle = Particle()) {
        particles.push_back(particle);
        pending.push_back({nullptr, &particles.back()});
        return particles.back();
    }

    /// Hands the next body added and not yet joined to the system (a volume's collision shape synchronised with its
    /// pose first; its position kept as its start). False when there is none or the system refused it
    /// (system.LastError() says which and why).
    bool JoinNext() {
        if (joined == pending.size()) return false;
        const Pending& p = pending[joined++];
        if (p.particle != nullptr) return system.AddRigidbody(p.particle);
        p.volume->SynchCollisionVolumes();
        volumeStart.push_back(p.volume->position);
        return system.AddRigidbody(p.volume);
    }
    /// Hands every body added and not yet joined to the system, in the order added (JoinNext); false when the
    /// system refused one (the others are still added).
    bool Join() {
        bool all = true;
        while (joined < pending.size()) all = JoinNext() && all;
        return all;
    }
    /// Join, then `steps` steps of dt.
    void Step(float dt, int steps = 1) {
        Join();
        for (int i = 0; i < steps; ++i) system.Update(dt);
    }
    /// Join, then up to `steps` steps of dt; false at the first step after which a body is not finite.
    bool StepWhileFinite(float dt, int steps) {
        Join();
        for (int i = 0; i < steps; ++i) {
            system.Update(dt);
            if (!AllFinite()) return false;
        }
        return true;
    }

    /// The volumes in the order added.
    std::size_t VolumeCount() const { return volumes.size(); }
    RigidbodyVolume& Volume(std::size_t i) { return volumes[i]; }
    const RigidbodyVolume& Volume(std::size_t i) const { return volumes[i]; }
    /// Every volume in the order added (the names below are RigidWorld's, so a test reads the same with either).
    const std::deque<RigidbodyVolume>& Bodies() const { return volumes; }
    /// Volume(i), under RigidWorld's name.
    RigidbodyVolume& Body(std::size_t i) { return volumes[i]; }
    const RigidbodyVolume& Body(std::size_t i) const { return volumes[i]; }
    /// The particles in the order added.
    Particle& ParticleAt(std::size_t i) { return particles[i]; }
    /// Volume i's position when it joined the system, m.
    const vec3& StartOf(std::size_t i) const { return volumeStart[i]; }

    /// Every body's position, velocity (and a volume's angular velocity and orientation) is finite.
    bool AllFinite() const {
        for (const RigidbodyVolume& b : volumes)
            if (!IsFinite(b.position) || !IsFinite(b.velocity) || !IsFinite(b.angVel) || !IsFinite(b.orientation))
                return false;
        for (const Particle& p : particles)
            if (!IsFinite(p.GetPosition()) || !IsFinite(p.GetVelocity())) return false;
        return true;
    }
    /// Largest distance of a dynamic volume (mass > 0) from its start, m; 0 if there is none.
    float MaxDisplacement() const {
        float d = 0.0f;
        for (std::size_t i = 0; i < volumeStart.size(); ++i)
            if (volumes[i].mass > 0.0f) d = std::fmax(d, Magnitude(volumes[i].position - volumeStart[i]));
        return d;
    }
    /// Largest horizontal (x, z) distance of a dynamic volume (mass > 0) from its start, m.
    float MaxHorizontalDrift() const {
        float d = 0.0f;
        for (std::size_t i = 0; i < volumeStart.size(); ++i) {
            if (!(volumes[i].mass > 0.0f)) continue;
            const vec3 s = volumes[i].position - volumeStart[i];
            d = std::fmax(d, std::sqrt(s.x * s.x + s.z * s.z));
        }
        return d;
    }
    /// Largest |y - y0| of a dynamic volume, m.
    float MaxVerticalMove() const {
        float d = 0.0f;
        for (std::size_t i = 0; i < volumeStart.size(); ++i)
            if (volumes[i].mass > 0.0f) d = std::fmax(d, std::fabs(volumes[i].position.y - volumeStart[i].y));
        return d;
    }
    /// Linear plus rotational kinetic energy of the dynamic volumes, J.
    float KineticEnergy() const {
        float e = 0.0f;
        for (const RigidbodyVolume& b : volumes)
            if (b.mass > 0.0f)
                e += 0.5f * b.mass * MagnitudeSq(b.velocity) +
                     0.5f * Dot(b.angVel, MultiplyVector(b.angVel, b.InertiaTensor()));
        return e;
    }
    /// Position, velocity, angular velocity and orientation of every volume as raw bytes, for bitwise comparison.
    std::vector<unsigned char> Snapshot() const { return ::Snapshot(volumes); }

private:
    struct Pending {
        RigidbodyVolume* volume;
        Particle* particle;
    };
    std::deque<RigidbodyVolume> volumes;  // declared before `system`, which holds pointers to them
    std::deque<Particle> particles;
    std::vector<Pending> pending;  // every body in the order added; the first `joined` are in the system
    std::size_t joined = 0;
    std::vector<vec3> volumeStart;

public:
    PhysicsSystem system;
};
