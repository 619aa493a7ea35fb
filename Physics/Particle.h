#pragma once
// A point mass with no volume (book.md 3.2): falls under gravity, bounces off OBB constraints, never
// tunnels. `friction` is the book's per-step velocity damping factor, not contact friction.

#include <vector>

#include "Geometry3D.h"
#include "Integrator.h"
#include "Rigidbody.h"

class Particle : public Rigidbody {
public:
    Particle();

    /// forces = gravity * mass (the repo's fix of erratum 5.1-6).
    void ApplyForces() override;
    /// One step with the book's shipped integrator (semi-implicit Euler) using the current `forces`.
    void Update(float dt) override;
    /// Line-tests the segment travelled this step against each OBB in order; on the first hit the particle
    /// is put 0.003 m off the surface and the normal part of its velocity reflected with `bounce`.
    void SolveConstraints(const std::vector<OBB>& constraints) override;

    /// Sets position and oldPosition (the particle is at rest in the travelled-segment sense).
    void SetPosition(const vec3& pos);
    vec3 GetPosition() const { return position; }
    vec3 GetOldPosition() const { return oldPosition; }
    void SetBounce(float b) { bounce = b; }
    float GetBounce() const { return bounce; }
    /// Adds a velocity change (m/s), whatever the integrator.
    void AddImpulse(const vec3& impulse);
    /// 1/mass, 0 for mass 0 (immovable).
    float InvMass() const;
    void SetMass(float m) { mass = m; }
    float GetMass() const { return mass; }
    /// Velocity in m/s for every integrator (position Verlet derives it from the last step).
    vec3 GetVelocity() const { return velocity; }
    void SetVelocity(const vec3& v) { velocity = v; }
    void SetFriction(float f) { friction = f; }
    float GetFriction() const { return friction; }
    void SetGravity(const vec3& g) { gravity = g; }
    vec3 GetGravity() const { return gravity; }
    vec3 GetForces() const { return forces; }
    void AddForce(const vec3& f) { forces += f; }

protected:
    friend class PhysicsSystem;
    vec3 position;
    vec3 oldPosition;
    vec3 velocity;
    vec3 forces;
    vec3 gravity{0.0f, -9.82f, 0.0f};
    float friction = 0.95f;
    float bounce = 0.7f;
    float mass = 1.0f;
};
