#pragma once
// A rigid sphere or box (docs/book-reference.md §3.3) with linear and angular state. Orientation is a unit quaternion
// integrated from angular velocity (erratum 5.2-12: the book adds angular velocity to Euler angles); the
// inverse inertia tensor is rotated into world space, R^T I^-1 R in row-vector form (erratum 5.2-11).

#include <string>

#include "Math/quaternion.h"
#include "Physics/Geometry/Geometry3D.h"
#include "Physics/Rigidbody.h"
#include "Physics/StepFactor.h"
#include "Physics/VolumePositions.h"

/// The book's GRAVITY_CONST, m/s^2.
constexpr vec3 kVolumeGravity{0.0f, -9.82f, 0.0f};

class RigidbodyVolume : public Rigidbody {
public:
    vec3 position;
    vec3 velocity;
    quat orientation;  ///< body -> world
    /// m/s: the linear velocity the current (sub)step began with, before forces and impulses; set by the volume
    /// stages for VolumePositions::Average, unused otherwise.
    vec3 startVelocity;
    vec3 angVel;  ///< world-space angular velocity, rad/s
    vec3 forces;
    vec3 torques;
    float mass = 1.0f;      ///< 0 = static
    float cor = 0.5f;       ///< coefficient of restitution
    float friction = 0.6f;  ///< Coulomb coefficient; pairs combine as sqrt(muA * muB)
    OBB box;
    Sphere sphere;
    vec3 gravity = kVolumeGravity;  ///< ApplyForces sets forces = gravity * mass
    /// Fraction of linear and angular velocity kept per step of referenceStep (book: 0.98 per 0.03 s, its
    /// "damping"); 1 keeps all of it. The same concept as Particle::velocityRetention.
    float velocityRetention = 0.98f;
    /// m/s (rad/s): velocity components below this are zeroed after the retention, per step of referenceStep
    /// (book: 0.001).
    float velocityEpsilon = 0.001f;
    /// s: the step at which velocityRetention and velocityEpsilon are defined (book: 0.03, its fixed step). A step
    /// of exactly referenceStep applies them as they are; any other step of dt uses
    /// velocityRetention^(dt/referenceStep) and velocityEpsilon * dt/referenceStep, the same per-second rates, so
    /// a body neither freezes as dt -> 0 (per step, the threshold exceeds g dt below dt = 1.02e-4 s and 0.98
    /// caps free fall at 49 g dt) nor moves in slow motion or damps faster at another step. 0 applies them per
    /// step at every dt (the book).
    float referenceStep = kBookStep;

    RigidbodyVolume() = default;
    explicit RigidbodyVolume(RigidbodyType bodyType) : Rigidbody(bodyType) {}

    /// forces = gravity * mass (book: torques are never set).
    void ApplyForces() override;
    /// Semi-implicit Euler step of dt seconds with the book's damping and thresholds, then syncs the volumes:
    /// IntegrateVelocity then IntegratePosition (the book's Update).
    void Update(float dt) override;
    /// v += F/m dt, w += I^-1 torque dt, both damped and thresholded (the first half of the book's Update).
    void IntegrateVelocity(float dt);
    /// x += v dt, orientation advanced by w (momentum-preserving for anisotropic bodies), volumes synced.
    void IntegratePosition(float dt);
    /// IntegratePosition with the linear part chosen by `mode` (VolumePositions.h): Average moves the body by
    /// (startVelocity + velocity) dt / 2.
    void IntegratePosition(float dt, VolumePositions mode);
    /// Copies position and orientation into `box` and `sphere`.
    void SynchCollisionVolumes();
    /// 0 for a static body (mass <= 0), else 1/mass.
    float InvMass() const;
    /// Principal moments of inertia (body frame, kg m^2): solid sphere 2/5 m r^2, box m(b^2+c^2)/12 with full
    /// edges; zero for a static body or a Base-type body.
    vec3 LocalInertia() const;
    /// World-space inertia tensor R^T I R (row vectors: MultiplyVector(w, InertiaTensor()) = I w).
    mat3 InertiaTensor() const;
    /// World-space inverse inertia tensor R^T I^-1 R (zero for static bodies); the diagonal is inverted per
    /// element, so small or light bodies keep their true inverse (erratum 5.2-10).
    mat3 InvTensor() const;
    /// velocity += deltaVelocity (m/s): a velocity change, the mass is not divided out (the book's
    /// AddLinearImpulse, which is not an impulse; docs/STYLE.md, "Renames in the engine").
    void AddVelocityChange(const vec3& deltaVelocity);
    /// angVel += I^-1_world ((point - position) x impulse); point in world space.
    void AddRotationalImpulse(const vec3& point, const vec3& impulse);
    /// Fraction of velocity kept over a step of dt seconds: velocityRetention itself when dt == referenceStep or
    /// referenceStep <= 0, else velocityRetention^(dt/referenceStep) (FactorOverStep).
    float StepRetention(float dt) const;
    /// Velocity threshold for a step of dt seconds (m/s, rad/s): velocityEpsilon itself when dt == referenceStep
    /// or referenceStep <= 0, else velocityEpsilon * dt/referenceStep.
    float StepVelocityEpsilon(float dt) const;
    /// Sets the orientation from the book's Euler angles in radians (x pitch, y yaw, z roll), converted as the
    /// book does (RAD2DEG then Rotation3x3), and syncs the volumes.
    void SetEulerOrientation(const vec3& radians);

    /// True while this body's island sleeps (WorldSettings::sleep; Islands.h): it is neither moved nor tested
    /// against other sleeping or static bodies. Always false with sleep off.
    bool IsSleeping() const { return sleeping; }
    /// Asks the world to wake this body and its whole island at the start of the next step (AddVelocityChange and
    /// AddRotationalImpulse call it). Nothing for an awake body.
    void WakeUp() { sleeping = false; }
    /// s this body has been slow (below SleepSettings' speeds) while awake; 0 with sleep off.
    float SleepTime() const { return sleepTime; }

private:
    /// The orientation part of IntegratePosition, then SynchCollisionVolumes.
    void AdvanceOrientation(float dt);
    friend class Islands;  // keeps `sleeping` and `sleepTime`
    bool sleeping = false;
    float sleepTime = 0.0f;
    // StepRetention's last (velocityRetention, referenceStep, dt) and result: pow once per body per distinct
    // step, not per step.
    mutable float retentionKey[3] = {-1.0f, -1.0f, -1.0f};
    mutable float retentionValue = 1.0f;
};

/// Advances an orientation (body -> world) by dt seconds of torque-free motion with world angular velocity *w
/// (rad/s): the exponential map, and for a body whose principal moments (kg m^2, `inertia`) differ, with its world
/// angular momentum held fixed (explicit midpoint), *w re-derived from it. Shared by IntegratePosition and the soft
/// step (SoftSolver.cpp).
quat AdvanceRotation(const quat& orientation, vec3* angularVelocity, const vec3& inertia, float dt);

/// VolumePositions::Average's test of a (sub)step: its velocity changed from `start` to `end` by no more than twice
/// `gravityStep` (g h). An impact is not a constant acceleration: it changes the velocity by more than gravity and
/// friction can over a step, and the mean of the velocities before and after it would carry the body half a step into
/// what stopped it, so such a step moves by the end velocity (x += v h). Shared by IntegratePosition and the soft step.
inline bool SmoothVolumeStep(const vec3& start, const vec3& end, const vec3& gravityStep) {
    return MagnitudeSq(end - start) <= 4.0f * MagnitudeSq(gravityStep);
}

/// True when `body` can be simulated: a sphere or box with finite, non-negative mass (0 = static); finite
/// position, velocity, angular velocity, gravity, forces and torques; a finite, non-zero orientation; finite,
/// strictly positive half sizes (box) or radius (sphere); finite cor, friction >= 0, damping in [0, 1], finite
/// velocityEpsilon >= 0 and referenceStep >= 0. Otherwise false, with *error (if given) naming the field and value.
bool ValidateVolume(const RigidbodyVolume& body, std::string* error);

/// Manifold for any sphere/box pair, normal from a to b. Depth is the FULL penetration for every pair type
/// (the geometry layer's sphere manifolds report half of it, erratum 5.2-32; doubled here so that linear
/// projection treats spheres and boxes alike). Non-volume bodies never collide.
CollisionManifold FindCollisionFeatures(RigidbodyVolume& ra, RigidbodyVolume& rb);
/// Allocation-free form: overwrites *out, reusing its contact storage.
void FindCollisionFeatures(RigidbodyVolume& ra, RigidbodyVolume& rb, CollisionManifold* out);
/// Normal and Coulomb friction impulse for contact c of manifold M (docs/book-reference.md §3.3, errata 5.2-14 fixed).
/// Velocities change in place; a pair of static bodies or a separating contact is left alone.
void ApplyImpulse(RigidbodyVolume& A, RigidbodyVolume& B, const CollisionManifold& M, int c);

/// Velocity of B's contact point relative to A's (world, m/s): (vB + wB x rB) - (vA + wA x rA), with rA and rB
/// the contact point relative to each centre of mass. Shared by the book's solver and the Accumulated one.
inline vec3 RelativeVelocity(const RigidbodyVolume& A, const RigidbodyVolume& B, const vec3& rA, const vec3& rB) {
    return (B.velocity + Cross(B.angVel, rB)) - (A.velocity + Cross(A.angVel, rA));
}
/// Applies the world impulse P to B and -P to A at rA, rB, given inverse masses and world inverse inertias.
inline void ApplyPairImpulse(RigidbodyVolume& A, RigidbodyVolume& B, float invA, float invB, const mat3& iA,
                             const mat3& iB, const vec3& rA, const vec3& rB, const vec3& P) {
    A.velocity -= P * invA;
    B.velocity += P * invB;
    A.angVel -= MultiplyVector(Cross(rA, P), iA);
    B.angVel += MultiplyVector(Cross(rB, P), iB);
}
