#pragma once
// A point mass with no volume (docs/book-reference.md §3.2): falls under gravity, bounces off OBB constraints, never
// tunnels. `velocityRetention` is the book's particle "friction": the fraction of velocity kept per book step
// (0.03 s), not contact friction (docs/STYLE.md, "Renames in the engine").

#include <cstddef>
#include <string>
#include <vector>

#include "Physics/Geometry/Geometry3D.h"
#include "Physics/ParticleContact.h"
#include "Physics/Rigidbody.h"

/// An OBB constraint prepared once per step for particle tests: its world AABB (a cheap reject) and the box.
struct ParticleConstraint {
    OBB box;
    vec3 boundsMin, boundsMax;
    float placement = 0.003f;  ///< m off the tested surface a hit particle is put (Particle::kContactOffset, or 0)
    bool reflect = false;      ///< ParticleContact::Reflect: the step's remainder is reflected (Particle::ReflectHit)
};
/// Copies the box and computes its world-space AABB (half-extents projected on the world axes). With
/// ParticleContact::Skin the box is inflated by Particle::kContactOffset on every side and hits are placed on it;
/// with ParticleContact::Reflect the box is tested as it is and hits are reflected.
ParticleConstraint PrepareParticleConstraint(const OBB& box, ParticleContact contact = ParticleContact::Book);
/// m: how far off the box's true surface `contact` puts a particle that hits it, a bias no step removes
/// (Particle::kContactOffset for book and skin, 0 for reflect).
float ContactOffsetOf(ParticleContact contact);

class Particle : public Rigidbody {
public:
    /// Distance (m) a resolved particle is put off the surface (the repo's 0.003; erratum 5.1-7).
    static constexpr float kContactOffset = 0.003f;

    Particle();

    /// forces = gravity * mass (the repo's fix of erratum 5.1-6).
    void ApplyForces() override;
    /// One step with the book's shipped integrator (semi-implicit Euler) using the current `forces`, retaining
    /// FactorOverStep(velocityRetention, kBookStep, dt) of the velocity.
    void Update(float dt) override;
    /// Tests the segment travelled this step (oldPosition -> position, world space) against every OBB and
    /// resolves the earliest hit: the particle is put kContactOffset off the surface and the approaching normal
    /// part of its velocity reflected with `bounce`. A start inside a box leaves through the nearest face; a
    /// zero-length segment is a point test (no NaN). At most one box per call, as the book.
    void SolveConstraints(const std::vector<OBB>& constraints) override;
    /// The same on prepared constraints (PhysicsSystem's per-step path: AABB reject, no per-box setup). `dt` is the
    /// step just taken (s): only a reflect constraint reads it, to time its impact inside the step (0: at its end).
    void SolveConstraints(const ParticleConstraint* constraints, std::size_t count, float dt = 0.0f);

    /// Sets position and oldPosition (the particle is at rest in the travelled-segment sense).
    void SetPosition(const vec3& pos);
    vec3 GetPosition() const { return position; }
    vec3 GetOldPosition() const { return oldPosition; }
    void SetBounce(float b) { bounce = b; }
    float GetBounce() const { return bounce; }
    /// Adds a velocity change (m/s), whatever the integrator; the mass is not divided out (the book's
    /// AddImpulse, which is not an impulse).
    void AddVelocityChange(const vec3& deltaVelocity);
    /// 1/mass, 0 for mass 0 (immovable).
    float InvMass() const;
    void SetMass(float m) { mass = m; }
    float GetMass() const { return mass; }
    /// Velocity in m/s for every integrator (position Verlet derives it from the last step).
    vec3 GetVelocity() const { return velocity; }
    void SetVelocity(const vec3& v) { velocity = v; }
    /// Fraction of velocity kept per step of WorldSettings::particleRetentionStep (book: 0.95 per 0.03 s, its
    /// "friction"); 1 keeps all of it. Other steps keep the same fraction per second.
    void SetVelocityRetention(float retention) { velocityRetention = retention; }
    float GetVelocityRetention() const { return velocityRetention; }
    void SetGravity(const vec3& g) { gravity = g; }
    vec3 GetGravity() const { return gravity; }
    vec3 GetForces() const { return forces; }
    void AddForce(const vec3& f) { forces += f; }

protected:
    friend class PhysicsSystem;
    friend struct ParticleIntegrators;  // IntegrateParticleStates' one function per method (Physics/Integrator.cpp)
    vec3 position;
    vec3 oldPosition;
    vec3 velocity;
    vec3 forces;
    vec3 gravity{0.0f, -9.82f, 0.0f};
    float velocityRetention = 0.95f;  ///< per book step (0.03 s); the book's "friction"
    float bounce = 0.7f;
    float mass = 1.0f;

private:
    void ResolveHit(const vec3& point, const vec3& normal, float offset);
    /// ParticleContact::Reflect: the segment oldPosition -> position entered the box through the face through
    /// `point` with outward `normal` at fraction `t` of it (< 0: it started on or inside that face).
    void ReflectHit(const vec3& point, const vec3& normal, float t, float dt);
};
