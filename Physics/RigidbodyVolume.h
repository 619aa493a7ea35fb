#pragma once
// A rigid sphere or box (book.md 3.3) with linear and angular state. Orientation is a unit quaternion
// integrated from angular velocity (erratum 5.2-12: the book adds angular velocity to Euler angles); the
// inverse inertia tensor is rotated into world space, R^T I^-1 R in row-vector form (erratum 5.2-11).

#include "Geometry3D.h"
#include "Rigidbody.h"
#include "quaternion.h"

/// The book's GRAVITY_CONST, m/s^2.
constexpr vec3 kVolumeGravity{0.0f, -9.82f, 0.0f};

class RigidbodyVolume : public Rigidbody {
public:
    vec3 position;
    vec3 velocity;
    quat orientation;  ///< body -> world
    vec3 angVel;       ///< world-space angular velocity, rad/s
    vec3 forces;
    vec3 torques;
    float mass = 1.0f;      ///< 0 = static
    float cor = 0.5f;       ///< coefficient of restitution
    float friction = 0.6f;  ///< Coulomb coefficient; pairs combine as sqrt(muA * muB)
    OBB box;
    Sphere sphere;
    vec3 gravity = kVolumeGravity;  ///< ApplyForces sets forces = gravity * mass
    /// The book's per-STEP velocity damping factor (not per second); 1 disables damping.
    float damping = 0.98f;
    /// Velocity components (linear and angular) below this magnitude are zeroed after damping (book: 0.001).
    float velocityEpsilon = 0.001f;

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
    /// velocity += impulse (the book's convention: mass is not divided out).
    void AddLinearImpulse(const vec3& impulse);
    /// angVel += I^-1_world ((point - position) x impulse); point in world space.
    void AddRotationalImpulse(const vec3& point, const vec3& impulse);
    /// Sets the orientation from the book's Euler angles in radians (x pitch, y yaw, z roll), converted as the
    /// book does (RAD2DEG then Rotation3x3), and syncs the volumes.
    void SetEulerOrientation(const vec3& radians);
};

/// Manifold for any sphere/box pair, normal from a to b. Depth is the FULL penetration for every pair type
/// (the geometry layer's sphere manifolds report half of it, erratum 5.2-32; doubled here so that linear
/// projection treats spheres and boxes alike). Non-volume bodies never collide.
CollisionManifold FindCollisionFeatures(RigidbodyVolume& ra, RigidbodyVolume& rb);
/// Allocation-free form: overwrites *out, reusing its contact storage.
void FindCollisionFeatures(RigidbodyVolume& ra, RigidbodyVolume& rb, CollisionManifold* out);
/// Normal and Coulomb friction impulse for contact c of manifold M (book.md 3.3, errata 5.2-14 fixed).
/// Velocities change in place; a pair of static bodies or a separating contact is left alone.
void ApplyImpulse(RigidbodyVolume& A, RigidbodyVolume& B, const CollisionManifold& M, int c);
