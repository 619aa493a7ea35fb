#include "Physics/RigidbodyVolume.h"

#include <cmath>
#include <cstdio>

#include "Physics/EnumIds.h"

namespace {

constexpr EnumId<VolumePositions> kVolumePositionsIds[] = {{VolumePositions::Euler, "euler"},
                                                           {VolumePositions::Average, "average"}};

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

const char* ToString(VolumePositions mode) { return IdOf(kVolumePositionsIds, mode); }

bool ParseVolumePositions(const std::string& text, VolumePositions* out) {
    return ParseId(kVolumePositionsIds, text, out);
}

std::string VolumePositionsIds() { return JoinIds(kVolumePositionsIds); }

void RigidbodyVolume::ApplyForces() { forces = gravity * mass; }

void RigidbodyVolume::Update(float dt) {
    IntegrateVelocity(dt);
    IntegratePosition(dt);
}

float RigidbodyVolume::StepRetention(float dt) const {
    if (!(referenceStep > 0.0f) || dt == referenceStep) return velocityRetention;
    if (retentionKey[0] != velocityRetention || retentionKey[1] != referenceStep || retentionKey[2] != dt) {
        retentionKey[0] = velocityRetention;
        retentionKey[1] = referenceStep;
        retentionKey[2] = dt;
        retentionValue = FactorOverStep(velocityRetention, referenceStep, dt);
    }
    return retentionValue;
}

float RigidbodyVolume::StepVelocityEpsilon(float dt) const {
    if (!(referenceStep > 0.0f) || dt == referenceStep) return velocityEpsilon;
    return velocityEpsilon * (dt / referenceStep);
}

void RigidbodyVolume::IntegrateVelocity(float dt) {
    // Book order (docs/book-reference.md §3.3): accelerate, damp, zero tiny components. The book's damping (0.98) and
    // threshold (0.001 m/s) are per step of its 0.03 s; applied per step at tiny dt they stop free motion: at dt = 1e-5
    // the threshold exceeds g dt and zeroes a body released from rest every step (it hangs in the air), and 0.98 per
    // step caps free fall at 49 g dt = 5 mm/s. At any step other than referenceStep (0.03 s) both are converted
    // to the same per-second rates; at it they are the book's values bit for bit (docs/ch15.md, "Extremes").
    const float stepDamping = StepRetention(dt);
    const float epsilon = StepVelocityEpsilon(dt);
    velocity += forces * InvMass() * dt;
    velocity *= stepDamping;
    ZeroSmall(velocity, epsilon);

    // erratum 5.2-13: the book integrates and damps angular velocity for boxes only, so a sphere keeps
    // whatever spin contacts gave it forever. Both shapes are treated alike here.
    if (HasVolume()) {
        angVel += MultiplyVector(torques, InvTensor()) * dt;
        angVel *= stepDamping;
        ZeroSmall(angVel, epsilon);
    }
}

void RigidbodyVolume::IntegratePosition(float dt) {
    position += velocity * dt;
    AdvanceOrientation(dt);
}

void RigidbodyVolume::IntegratePosition(float dt, VolumePositions mode) {
    if (mode == VolumePositions::Average && SmoothVolumeStep(startVelocity, velocity, gravity * dt)) {
        position += (startVelocity + velocity) * (0.5f * dt);
        AdvanceOrientation(dt);
        return;
    }
    IntegratePosition(dt);
}

void RigidbodyVolume::AdvanceOrientation(float dt) {
    if (InvMass() > 0.0f) {
        orientation = AdvanceRotation(orientation, &angVel, LocalInertia(), dt);
    } else if (MagnitudeSq(angVel) > 0.0f) {
        orientation = Integrate(orientation, angVel, dt);
    }
    SynchCollisionVolumes();
}

quat AdvanceRotation(const quat& orientation, vec3* angularVelocity, const vec3& inertia, float dt) {
    // erratum 5.2-12: orientation is a quaternion advanced by the world-space angular velocity (exponential
    // map), not Euler angles plus angVel*dt. For a body whose principal moments differ, the torque-free
    // motion keeps the world angular momentum L = I_world w while I_world turns with the body, so w is
    // re-derived from L (explicit midpoint on the rotation, L held fixed). Cubes and spheres skip this:
    // their world tensor is a multiple of the identity and w is already constant.
    const vec3 w = *angularVelocity;
    if (!(MagnitudeSq(w) > 0.0f)) return orientation;
    if (IsIsotropic(inertia)) return Integrate(orientation, w, dt);
    const vec3 invInertia(1.0f / inertia.x, 1.0f / inertia.y, 1.0f / inertia.z);
    const vec3 L = MultiplyVector(w, RotateDiagonal(ToMat3(orientation), inertia));
    const quat half = Integrate(orientation, w, dt * 0.5f);
    const vec3 wHalf = MultiplyVector(L, RotateDiagonal(ToMat3(half), invInertia));
    const quat next = Integrate(orientation, wHalf, dt);
    *angularVelocity = MultiplyVector(L, RotateDiagonal(ToMat3(next), invInertia));
    return next;
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

void RigidbodyVolume::AddVelocityChange(const vec3& deltaVelocity) {
    WakeUp();
    velocity += deltaVelocity;
}

void RigidbodyVolume::AddRotationalImpulse(const vec3& point, const vec3& impulse) {
    WakeUp();
    angVel += MultiplyVector(Cross(point - position, impulse), InvTensor());
}

void RigidbodyVolume::SetEulerOrientation(const vec3& radians) {
    orientation = FromEuler(RAD2DEG(radians.x), RAD2DEG(radians.y), RAD2DEG(radians.z));
    SynchCollisionVolumes();
}

namespace {

bool Refuse(std::string* error, const char* what, float value, const char* rule) {
    if (error != nullptr) {
        char text[160];
        std::snprintf(text, sizeof text, "%s = %g: %s", what, static_cast<double>(value), rule);
        *error = text;
    }
    return false;
}

bool CheckVector(std::string* error, const char* name, const vec3& v) {
    static const char* const kAxis[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(v[i])) {
            char what[64];
            std::snprintf(what, sizeof what, "%s.%s", name, kAxis[i]);
            return Refuse(error, what, v[i], "must be finite");
        }
    return true;
}

}  // namespace

// Validate at the boundary (docs/STYLE.md): a degenerate body is refused where it enters the world, with the bad
// value named, instead of being simulated into a wrong answer (a zero-size or flat box has no face the box-box
// manifold can report, so it falls through the ground for ever; a non-finite number spreads to every body it
// touches).
bool ValidateVolume(const RigidbodyVolume& body, std::string* error) {
    if (!body.HasVolume()) return Refuse(error, "type", static_cast<float>(body.type), "must be Sphere (2) or Box (3)");
    if (!std::isfinite(body.mass) || body.mass < 0.0f)
        return Refuse(error, "mass", body.mass, "must be finite and >= 0 (0 = static)");
    if (!CheckVector(error, "position", body.position) || !CheckVector(error, "velocity", body.velocity) ||
        !CheckVector(error, "angVel", body.angVel) || !CheckVector(error, "gravity", body.gravity) ||
        !CheckVector(error, "forces", body.forces) || !CheckVector(error, "torques", body.torques))
        return false;
    const quat& q = body.orientation;
    const float qc[4] = {q.x, q.y, q.z, q.w};
    static const char* const kQuat[4] = {"orientation.x", "orientation.y", "orientation.z", "orientation.w"};
    for (int i = 0; i < 4; ++i)
        if (!std::isfinite(qc[i])) return Refuse(error, kQuat[i], qc[i], "must be finite");
    const float qSq = q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w;
    if (!(qSq > 0.0f)) return Refuse(error, "|orientation|^2", qSq, "must be > 0 (a rotation)");
    if (body.type == RigidbodyType::Sphere) {
        if (!std::isfinite(body.sphere.radius) || !(body.sphere.radius > 0.0f))
            return Refuse(error, "sphere.radius", body.sphere.radius, "must be finite and > 0");
    } else {
        static const char* const kSize[3] = {"box.size.x", "box.size.y", "box.size.z"};
        for (int i = 0; i < 3; ++i)
            if (!std::isfinite(body.box.size[i]) || !(body.box.size[i] > 0.0f))
                return Refuse(error, kSize[i], body.box.size[i], "half size must be finite and > 0");
    }
    if (!std::isfinite(body.cor) || body.cor < 0.0f) return Refuse(error, "cor", body.cor, "must be finite and >= 0");
    if (!std::isfinite(body.friction) || body.friction < 0.0f)
        return Refuse(error, "friction", body.friction, "must be finite and >= 0");
    if (!(body.velocityRetention >= 0.0f && body.velocityRetention <= 1.0f))
        return Refuse(error, "velocityRetention", body.velocityRetention, "must be in [0, 1]");
    if (!std::isfinite(body.velocityEpsilon) || body.velocityEpsilon < 0.0f)
        return Refuse(error, "velocityEpsilon", body.velocityEpsilon, "must be finite and >= 0");
    if (!std::isfinite(body.referenceStep) || body.referenceStep < 0.0f)
        return Refuse(error, "referenceStep", body.referenceStep, "must be finite and >= 0 (0 = per step)");
    return true;
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
    }
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

    // Normal impulse (docs/book-reference.md §3.3 step 4): restitution is the smaller cor; the impulse is shared
    // between the contacts of the manifold (j / count), each solved on its own (erratum 5.2-15 is the book's design).
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
