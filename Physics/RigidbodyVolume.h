#pragma once
// A rigid sphere or box (book.md 3.3) with linear and angular state. Orientation is a unit quaternion
// integrated from angular velocity (erratum 5.2-12: the book adds angular velocity to Euler angles); the
// inverse inertia tensor is rotated into world space, R^T I^-1 R in row-vector form (erratum 5.2-11).

#include "Geometry3D.h"
#include "Rigidbody.h"
#include "quaternion.h"

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

    RigidbodyVolume() = default;
    explicit RigidbodyVolume(RigidbodyType bodyType) : Rigidbody(bodyType) {}

    void ApplyForces() override;
    void Update(float dt) override;
    void SynchCollisionVolumes();
    float InvMass() const;
    /// World-space inverse inertia tensor (zero for static bodies).
    mat3 InvTensor() const;
    /// velocity += impulse (the book's convention: mass is not divided out).
    void AddLinearImpulse(const vec3& impulse);
    void AddRotationalImpulse(const vec3& point, const vec3& impulse);
    /// Sets the orientation from the book's Euler angles in radians (x pitch, y yaw, z roll).
    void SetEulerOrientation(const vec3& radians);
};

/// Manifold for any sphere/box pair, normal from a to b.
CollisionManifold FindCollisionFeatures(RigidbodyVolume& ra, RigidbodyVolume& rb);
void FindCollisionFeatures(RigidbodyVolume& ra, RigidbodyVolume& rb, CollisionManifold* out);
/// Normal and Coulomb friction impulse for contact c of manifold M (book.md 3.3, errata 5.2-14 fixed).
void ApplyImpulse(RigidbodyVolume& A, RigidbodyVolume& B, const CollisionManifold& M, int c);
