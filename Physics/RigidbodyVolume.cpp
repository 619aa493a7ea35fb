#include "RigidbodyVolume.h"

#include <cmath>

namespace {

/// sum_k d_k * axis_k^T axis_k for the rows axis_k of R: the row-vector form R^T diag(d) R.
mat3 RotateDiagonal(const mat3& R, const vec3& d) {
    mat3 out = ZeroMat3();
    for (int k = 0; k < 3; ++k) {
        const float* a = R[k];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) out[i][j] += d[k] * a[i] * a[j];
    }
    return out;
}

/// Zeroes every component with |x| < epsilon (the book's velocity thresholds).
void ZeroSmall(vec3& v, float epsilon) {
    for (int i = 0; i < 3; ++i)
        if (std::fabs(v[i]) < epsilon) v[i] = 0.0f;
}

bool IsIsotropic(const vec3& inertia) { return inertia.x == inertia.y && inertia.y == inertia.z; }

}  // namespace

void RigidbodyVolume::ApplyForces() { forces = gravity * mass; }

void RigidbodyVolume::Update(float dt) {
    IntegrateVelocity(dt);
    IntegratePosition(dt);
}

void RigidbodyVolume::IntegrateVelocity(float dt) {
    // Book order (book.md 3.3): accelerate, damp per step, zero tiny components.
    velocity += forces * InvMass() * dt;
    velocity *= damping;
    ZeroSmall(velocity, velocityEpsilon);

    // erratum 5.2-13: the book integrates and damps angular velocity for boxes only, so a sphere keeps
    // whatever spin contacts gave it forever. Both shapes are treated alike here.
    if (HasVolume()) {
        angVel += MultiplyVector(torques, InvTensor()) * dt;
        angVel *= damping;
        ZeroSmall(angVel, velocityEpsilon);
    }
}

void RigidbodyVolume::IntegratePosition(float dt) {
    position += velocity * dt;

    // erratum 5.2-12: orientation is a quaternion advanced by the world-space angular velocity (exponential
    // map), not Euler angles plus angVel*dt. For a body whose principal moments differ, the torque-free
    // motion keeps the world angular momentum L = I_world w while I_world turns with the body, so w is
    // re-derived from L (explicit midpoint on the rotation, L held fixed). Cubes and spheres skip this:
    // their world tensor is a multiple of the identity and w is already constant.
    const vec3 inertia = LocalInertia();
    if (MagnitudeSq(angVel) > 0.0f) {
        if (InvMass() > 0.0f && !IsIsotropic(inertia)) {
            const vec3 invInertia(1.0f / inertia.x, 1.0f / inertia.y, 1.0f / inertia.z);
            const vec3 L = MultiplyVector(angVel, RotateDiagonal(ToMat3(orientation), inertia));
            const quat half = Integrate(orientation, angVel, dt * 0.5f);
            const vec3 wHalf = MultiplyVector(L, RotateDiagonal(ToMat3(half), invInertia));
            orientation = Integrate(orientation, wHalf, dt);
            angVel = MultiplyVector(L, RotateDiagonal(ToMat3(orientation), invInertia));
        } else {
            orientation = Integrate(orientation, angVel, dt);
        }
    }
    SynchCollisionVolumes();
}

void RigidbodyVolume::SynchCollisionVolumes() {
    sphere.position = position;
    box.position = position;
    box.orientation = ToMat3(orientation);
}

float RigidbodyVolume::InvMass() const { return mass > 0.0f ? 1.0f / mass : 0.0f; }

vec3 RigidbodyVolume::LocalInertia() const {
    if (!(mass > 0.0f)) return vec3();
    if (type == RigidbodyType::Sphere) {
        const float i = 0.4f * mass * sphere.radius * sphere.radius;
        return vec3(i, i, i);
    }
    if (type == RigidbodyType::Box) {
        const vec3 s = box.size * 2.0f;  // full edge lengths
        const float k = mass / 12.0f;
        return vec3(k * (s.y * s.y + s.z * s.z), k * (s.x * s.x + s.z * s.z), k * (s.x * s.x + s.y * s.y));
    }
    return vec3();
}

mat3 RigidbodyVolume::InertiaTensor() const { return RotateDiagonal(ToMat3(orientation), LocalInertia()); }

mat3 RigidbodyVolume::InvTensor() const {
    // erratum 5.2-10: the book inverts diag(Ix, Iy, Iz, 1) with the general 4x4 inverse, which returns the
    // IDENTITY when |det| <= 0.005 (e.g. a half-size 0.5 box of mass 1). The tensor is diagonal in the body
    // frame, so each element is inverted on its own; a zero moment (degenerate size) gives a zero row.
    const vec3 inertia = LocalInertia();
    vec3 inv;
    for (int i = 0; i < 3; ++i) inv[i] = inertia[i] > 0.0f ? 1.0f / inertia[i] : 0.0f;
    // erratum 5.2-11: the book uses the body-frame tensor in world space.
    return RotateDiagonal(ToMat3(orientation), inv);
}

void RigidbodyVolume::AddLinearImpulse(const vec3& impulse) { velocity += impulse; }

void RigidbodyVolume::AddRotationalImpulse(const vec3& point, const vec3& impulse) {
    angVel += MultiplyVector(Cross(point - position, impulse), InvTensor());
}

void RigidbodyVolume::SetEulerOrientation(const vec3& radians) {
    orientation = FromEuler(RAD2DEG(radians.x), RAD2DEG(radians.y), RAD2DEG(radians.z));
    SynchCollisionVolumes();
}

void FindCollisionFeatures(RigidbodyVolume& ra, RigidbodyVolume& rb, CollisionManifold* out) {
    ResetCollisionManifold(out);
    if (!ra.HasVolume() || !rb.HasVolume()) return;
    const bool sphereA = ra.type == RigidbodyType::Sphere;
    const bool sphereB = rb.type == RigidbodyType::Sphere;
    if (sphereA && sphereB) {
        FindCollisionFeatures(ra.sphere, rb.sphere, out);
    } else if (sphereA) {
        // The geometry layer only has box-sphere: swap, then flip the normal back to point from a to b.
        FindCollisionFeatures(rb.box, ra.sphere, out);
        out->normal = -out->normal;
    } else if (sphereB) {
        FindCollisionFeatures(ra.box, rb.sphere, out);
    } else {
        FindCollisionFeatures(ra.box, rb.box, out);
        return;
    }
    // Sphere manifolds carry half the penetration (book.md 3.5, erratum 5.2-32); box-box carries all of it.
    if (out->colliding) out->depth *= 2.0f;
}

CollisionManifold FindCollisionFeatures(RigidbodyVolume& ra, RigidbodyVolume& rb) {
    CollisionManifold result;
    FindCollisionFeatures(ra, rb, &result);
    return result;
}

namespace {

/// 1/m_A + 1/m_B + n . ((I_A^-1 (r_A x n)) x r_A + (I_B^-1 (r_B x n)) x r_B): the effective inverse mass
/// of the contact along direction d.
float EffectiveInvMass(float invSum, const mat3& iA, const mat3& iB, const vec3& rA, const vec3& rB, const vec3& d) {
    const vec3 termA = Cross(MultiplyVector(Cross(rA, d), iA), rA);
    const vec3 termB = Cross(MultiplyVector(Cross(rB, d), iB), rB);
    return invSum + Dot(d, termA + termB);
}

void ApplyPairImpulse(RigidbodyVolume& A, RigidbodyVolume& B, float invA, float invB, const mat3& iA, const mat3& iB,
                      const vec3& rA, const vec3& rB, const vec3& impulse) {
    A.velocity -= impulse * invA;
    B.velocity += impulse * invB;
    A.angVel -= MultiplyVector(Cross(rA, impulse), iA);
    B.angVel += MultiplyVector(Cross(rB, impulse), iB);
}

vec3 RelativeVelocity(const RigidbodyVolume& A, const RigidbodyVolume& B, const vec3& rA, const vec3& rB) {
    return (B.velocity + Cross(B.angVel, rB)) - (A.velocity + Cross(A.angVel, rA));
}

}  // namespace

void ApplyImpulse(RigidbodyVolume& A, RigidbodyVolume& B, const CollisionManifold& M, int c) {
    const float invA = A.InvMass();
    const float invB = B.InvMass();
    const float invSum = invA + invB;
    if (invSum == 0.0f) return;
    if (c < 0 || c >= static_cast<int>(M.contacts.size())) return;

    const vec3 rA = M.contacts[c] - A.position;
    const vec3 rB = M.contacts[c] - B.position;
    const mat3 iA = A.InvTensor();
    const mat3 iB = B.InvTensor();
    const float contactCount = static_cast<float>(M.contacts.size());

    // Normal impulse (book.md 3.3 step 4): restitution is the smaller cor; the impulse is shared between the
    // contacts of the manifold (j / count), each solved on its own (erratum 5.2-15 is the book's design).
    vec3 vr = RelativeVelocity(A, B, rA, rB);
    const vec3 n = Normalized(M.normal);
    const float vn = Dot(vr, n);
    if (vn > 0.0f) return;  // separating
    const float e = std::fmin(A.cor, B.cor);
    const float kn = EffectiveInvMass(invSum, iA, iB, rA, rB, n);
    float j = kn == 0.0f ? 0.0f : -(1.0f + e) * vn / kn;
    j /= contactCount;
    if (j != 0.0f) ApplyPairImpulse(A, B, invA, invB, iA, iB, rA, rB, n * j);

    // erratum 5.2-14: friction acts on the relative velocity AFTER the normal impulse; the book reuses the
    // pre-impulse vr, so a contact whose sliding is created by the normal impulse (an off-centre hit that
    // spins the body) gets no friction. The book also skips friction when |t|^2 <= 0.005 and |jt| <= 0.005
    // (Compare.h CMP), which lets slow sliding (< 0.07 m/s) creep for free; only a negligible tangent is skipped.
    vr = RelativeVelocity(A, B, rA, rB);
    // A tangent below 1e-4 of |vr| is rounding noise from subtracting two nearly equal vectors: its direction is
    // arbitrary (not even perpendicular to n), so it is skipped rather than normalised.
    vec3 t = vr - n * Dot(vr, n);
    const float tSq = MagnitudeSq(t);
    if (!(tSq > 1e-8f * MagnitudeSq(vr) + 1e-12f)) return;
    t = t * (1.0f / std::sqrt(tSq));
    const float kt = EffectiveInvMass(invSum, iA, iB, rA, rB, t);
    if (kt == 0.0f) return;
    float jt = -Dot(vr, t) / kt;
    jt /= contactCount;
    if (jt == 0.0f) return;

    // Coulomb clamp, book §15 Angular Impulse: |jt| <= mu * j with mu = sqrt(muA * muB).
    const float mu = std::sqrt(A.friction * B.friction);
    const float limit = j * mu;
    if (jt > limit) jt = limit;
    if (jt < -limit) jt = -limit;
    ApplyPairImpulse(A, B, invA, invB, iA, iB, rA, rB, t * jt);
}
