// ContactSolver::Soft (SoftSolver.h): soft contact constraints solved in substeps with a relax pass; the design and
// the measured figures are in docs/ch15.md, "The soft-step solver".
#include "Physics/SoftSolver.h"

#include <algorithm>
#include <cmath>

#include "Physics/Geometry/ContactManifold.h"
#include "Physics/RigidbodyVolume.h"
#include "Physics/WorldSettings.h"

namespace {

constexpr float kPi = 3.14159265358979f;

/// v M in the row-vector convention (MultiplyVector), inline for the solver's inner loops.
inline vec3 Mul(const vec3& v, const mat3& m) {
    return {v.x * m[0][0] + v.y * m[1][0] + v.z * m[2][0], v.x * m[0][1] + v.y * m[1][1] + v.z * m[2][1],
            v.x * m[0][2] + v.y * m[1][2] + v.z * m[2][2]};
}

/// Orthonormal t1, t2 with n x t1 = t2, a fixed function of n (the same normal gives the same basis every step).
void TangentBasis(const vec3& n, vec3* t1, vec3* t2) {
    vec3 t = std::fabs(n.x) >= 0.57735f ? vec3(n.y, -n.x, 0.0f) : vec3(0.0f, n.z, -n.y);
    t = t * (1.0f / std::sqrt(MagnitudeSq(t)));
    *t1 = t;
    *t2 = Cross(n, t);
}

/// Fills a constraint row along d: Jacobians, their images under the inverse inertias and the effective mass.
void MakeRow(const vec3& rA, const vec3& rB, const vec3& d, float invSum, const mat3& iA, const mat3& iB,
             SoftContactSolver::Row* row) {
    row->rAxD = Cross(rA, d);
    row->rBxD = Cross(rB, d);
    row->iArAxD = Mul(row->rAxD, iA);
    row->iBrBxD = Mul(row->rBxD, iB);
    const float k = invSum + Dot(row->rAxD, row->iArAxD) + Dot(row->rBxD, row->iBrBxD);
    row->mass = k > 0.0f ? 1.0f / k : 0.0f;
}

/// A body's velocities held in locals while one pair is solved.
struct BodyVelocity {
    vec3 v, w;
};

/// Relative speed of B's contact point against A's along the row's direction d.
template <class Body>
inline float RowSpeed(const Body& A, const Body& B, const vec3& d, const SoftContactSolver::Row& row) {
    return Dot(B.v - A.v, d) + Dot(B.w, row.rBxD) - Dot(A.w, row.rAxD);
}

/// Applies an impulse of magnitude j along the row (to B, and its opposite to A).
template <class Body>
inline void ApplyRow(Body& A, Body& B, float invA, float invB, const vec3& d, const SoftContactSolver::Row& row,
                     float j) {
    A.v -= d * (invA * j);
    B.v += d * (invB * j);
    A.w -= row.iArAxD * j;
    B.w += row.iBrBxD * j;
}

/// Pairs of static bodies never move, so they are never tested.
bool CanInteract(const RigidbodyVolume& a, const RigidbodyVolume& b) {
    return a.HasVolume() && b.HasVolume() && (a.mass > 0.0f || b.mass > 0.0f);
}

/// Solver manifold of any sphere/box pair, normal from a to b (the sphere-box case is swapped and flipped).
void CollideVolumes(const RigidbodyVolume& a, const RigidbodyVolume& b, float margin, ContactManifold* out) {
    out->pointCount = 0;
    const bool sphereA = a.type == RigidbodyType::Sphere;
    const bool sphereB = b.type == RigidbodyType::Sphere;
    if (sphereA && sphereB) {
        CollideSpheres(a.sphere, b.sphere, margin, out);
    } else if (sphereA) {
        CollideBoxSphere(b.box, a.sphere, margin, out);
        out->normal = -out->normal;
    } else if (sphereB) {
        CollideBoxSphere(a.box, b.sphere, margin, out);
    } else {
        CollideBoxes(a.box, b.box, margin, out);
    }
}

}  // namespace

Softness MakeSoftness(float hertz, float zeta, float h) {
    // Implicit spring-damper over one step (docs/ch15.md, "The soft-step solver"): omega = 2 pi f, a1 = 2 zeta + h
    // omega, a2 = h omega a1, a3 = 1 / (1 + a2); bias rate omega / a1, mass scale a2 a3, impulse scale a3.
    Softness s;
    if (!(hertz > 0.0f) || !(h > 0.0f)) return s;
    const float omega = 2.0f * kPi * hertz;
    const float a1 = 2.0f * zeta + h * omega;
    const float a2 = h * omega * a1;
    const float a3 = 1.0f / (1.0f + a2);
    s.biasRate = omega / a1;
    s.massScale = a2 * a3;
    s.impulseScale = a3;
    return s;
}

void SoftContactSolver::Clear() {
    pairs.clear();
    contacts.clear();
    previousPairs.clear();
    previousContacts.clear();
    warmStarted = 0;
    inheritedNormal = 0.0f;
    lastStep = -2;
}

float SoftContactSolver::TotalNormalImpulse() const {
    float sum = 0.0f;
    for (const Contact& c : contacts) sum += c.normal.impulse;
    return sum;
}

float SoftContactSolver::DeepestPenetration() const {
    float deepest = 0.0f;
    for (const Contact& c : contacts) deepest = std::max(deepest, -c.separation);
    return deepest;
}

void SoftContactSolver::Step(const std::vector<RigidbodyVolume*>& volumes,
                             const std::vector<std::pair<int, int>>& candidates, const StepContext& ctx,
                             const unsigned char* active) {
    const SoftSolverSettings& soft = ctx.settings.soft;
    const bool carryOver = ctx.step == lastStep + 1;
    lastStep = ctx.step;

    LoadBodies(volumes, ctx, active);
    Collide(volumes, candidates, ctx, carryOver);
    Prepare(volumes, ctx);

    // Softness from the contact stiffness, capped at a quarter of the substep rate (a stiffer spring than the
    // substep can resolve would overshoot).
    const float hertz = std::min(soft.contactHertz, 0.25f * ctx.invH);
    const Softness softness = MakeSoftness(hertz, soft.contactDampingRatio, ctx.h);
    // A contact with a static body has only one body to move, so it is made twice as stiff.
    const Softness staticSoftness = MakeSoftness(2.0f * hertz, soft.contactDampingRatio, ctx.h);
    UpdateSeparations();
    for (int s = 0; s < ctx.substepCount; ++s) {
        IntegrateVelocities(ctx);
        WarmStart();
        for (int k = 0; k < soft.iterations; ++k)
            Solve(ctx.invH, softness, staticSoftness, soft.maxPushoutSpeed, soft.linearSlop, true);
        IntegratePositions(ctx);
        UpdateSeparations();
        for (int k = 0; k < soft.relaxIterations; ++k)
            Solve(ctx.invH, softness, staticSoftness, soft.maxPushoutSpeed, soft.linearSlop, false);
    }
    ApplyRestitution(soft.restitutionThreshold);
    StoreBodies(volumes);
}

void SoftContactSolver::LoadBodies(const std::vector<RigidbodyVolume*>& volumes, const StepContext& ctx,
                                   const unsigned char* active) {
    const std::size_t n = volumes.size();
    if (state.size() != n) {
        state.resize(n);
        sim.resize(n);
    }
    for (std::size_t i = 0; i < n; ++i) {
        const RigidbodyVolume& body = *volumes[i];
        BodyState& st = state[i];
        BodySim& bs = sim[i];
        // A sleeping body (active[i] == 0) is held like a static one and StoreBodies leaves it untouched.
        bs.dynamic = body.HasVolume() && body.mass > 0.0f && (active == nullptr || active[i] != 0);
        bs.p = body.position;
        bs.q = body.orientation;
        bs.q0 = body.orientation;
        st.dp = vec3();
        st.dR = mat3();
        if (!bs.dynamic) {
            // Static bodies are immovable here: no velocity, never integrated.
            st.v = vec3();
            st.w = vec3();
            bs.invMass = 0.0f;
            bs.invI = ZeroMat3();
            bs.gravity = vec3();
            bs.angularAccel = vec3();
            bs.retention = 1.0f;
            bs.epsilon = 0.0f;
            continue;
        }
        st.v = body.velocity;
        st.w = body.angVel;
        bs.invMass = body.InvMass();
        bs.invI = body.InvTensor();
        bs.inertia = body.LocalInertia();
        // The book's force model: forces = gravity * mass (ApplyForces), plus any torque the body carries.
        bs.gravity = body.gravity;
        bs.angularAccel = Mul(body.torques, bs.invI);
        bs.retention = body.StepRetention(ctx.h);
        bs.epsilon = body.StepVelocityEpsilon(ctx.h);
    }
}

void SoftContactSolver::Collide(const std::vector<RigidbodyVolume*>& volumes,
                                const std::vector<std::pair<int, int>>& candidates, const StepContext& ctx,
                                bool carryOver) {
    // This step's buffers become last step's; capacities are kept, so nothing is allocated once they have grown.
    pairs.swap(previousPairs);
    contacts.swap(previousContacts);
    pairs.clear();
    contacts.clear();
    if (!carryOver) {
        previousPairs.clear();
        previousContacts.clear();
    }
    warmStarted = 0;
    inheritedNormal = 0.0f;
    const SoftSolverSettings& soft = ctx.settings.soft;
    std::size_t cursor = 0;  // previousPairs is in the same increasing (a, b) order as the candidates
    ContactManifold manifold;
    for (const std::pair<int, int>& candidate : candidates) {
        const RigidbodyVolume& A = *volumes[candidate.first];
        const RigidbodyVolume& B = *volumes[candidate.second];
        if (!CanInteract(A, B)) continue;
        // Speculative margin plus the distance the pair can close this step, so a fast body meets the surface
        // in the substep it reaches it instead of being pushed out from inside.
        const float closing = std::sqrt(MagnitudeSq(state[candidate.second].v - state[candidate.first].v));
        CollideVolumes(A, B, soft.speculativeMargin + closing * ctx.dt, &manifold);
        if (manifold.pointCount <= 0) continue;

        Pair pair;
        pair.a = candidate.first;
        pair.b = candidate.second;
        pair.bodyA = &A;
        pair.bodyB = &B;
        pair.n = Normalized(manifold.normal);
        TangentBasis(pair.n, &pair.t1, &pair.t2);
        pair.friction = std::sqrt(A.friction * B.friction);  // book §15: mu = sqrt(muA muB)
        pair.restitution = std::fmin(A.cor, B.cor);          // book: the smaller cor
        pair.touchesStatic = !(A.mass > 0.0f) || !(B.mass > 0.0f);
        pair.first = contacts.size();
        pair.count = static_cast<std::size_t>(std::min(manifold.pointCount, kMaxManifoldPoints));

        // The same pair last step (same indices, same bodies): its contacts are matched by feature id.
        const Pair* old = nullptr;
        while (cursor < previousPairs.size() &&
               (previousPairs[cursor].a < pair.a ||
                (previousPairs[cursor].a == pair.a && previousPairs[cursor].b < pair.b)))
            ++cursor;
        if (cursor < previousPairs.size() && previousPairs[cursor].a == pair.a && previousPairs[cursor].b == pair.b &&
            previousPairs[cursor].bodyA == &A && previousPairs[cursor].bodyB == &B)
            old = &previousPairs[cursor];

        for (std::size_t k = 0; k < pair.count; ++k) {
            const ManifoldPoint& mp = manifold.points[k];
            Contact c;
            c.rA = mp.point - sim[pair.a].p;
            c.rB = mp.point - sim[pair.b].p;
            c.separation = mp.separation;
            c.id = mp.id;
            if (old != nullptr) {
                const Contact* match = nullptr;
                for (std::size_t j = old->first; j < old->first + old->count; ++j)
                    if (previousContacts[j].id == mp.id) {
                        match = &previousContacts[j];
                        break;
                    }
                if (match != nullptr) {
                    const Contact& o = *match;
                    // Last step's total re-expressed in this step's basis, so a slowly turning normal keeps most.
                    const vec3 P =
                        (old->n * o.normal.impulse + old->t1 * o.tangent1.impulse + old->t2 * o.tangent2.impulse) *
                        soft.warmStartFactor;
                    c.normal.impulse = std::fmax(Dot(P, pair.n), 0.0f);
                    c.tangent1.impulse = Dot(P, pair.t1);
                    c.tangent2.impulse = Dot(P, pair.t2);
                    inheritedNormal += c.normal.impulse;
                    ++warmStarted;
                }
            }
            contacts.push_back(c);
        }
        pairs.push_back(pair);
    }
}

void SoftContactSolver::Prepare(const std::vector<RigidbodyVolume*>& /*volumes*/, const StepContext& /*ctx*/) {
    for (const Pair& pair : pairs) {
        const BodySim& A = sim[pair.a];
        const BodySim& B = sim[pair.b];
        const BodyState& sA = state[pair.a];
        const BodyState& sB = state[pair.b];
        const float invSum = A.invMass + B.invMass;
        for (std::size_t k = pair.first; k < pair.first + pair.count; ++k) {
            Contact& c = contacts[k];
            MakeRow(c.rA, c.rB, pair.n, invSum, A.invI, B.invI, &c.normal);
            MakeRow(c.rA, c.rB, pair.t1, invSum, A.invI, B.invI, &c.tangent1);
            MakeRow(c.rA, c.rB, pair.t2, invSum, A.invI, B.invI, &c.tangent2);
            // The separation is tracked through the step from the bodies' motion (Solve), not re-collided.
            c.baseSeparation = c.separation - Dot(c.rB - c.rA, pair.n);
            c.relativeVelocity = RowSpeed(sA, sB, pair.n, c.normal);
            c.maxNormalImpulse = 0.0f;
        }
    }
}

void SoftContactSolver::IntegrateVelocities(const StepContext& ctx) {
    const float h = ctx.h;
    const std::size_t n = state.size();
    for (std::size_t i = 0; i < n; ++i) {
        const BodySim& bs = sim[i];
        if (!bs.dynamic) continue;
        BodyState& st = state[i];
        // Semi-implicit Euler, then the body's velocity retention and threshold per substep (RigidbodyVolume).
        st.v = (st.v + bs.gravity * h) * bs.retention;
        st.w = (st.w + bs.angularAccel * h) * bs.retention;
        if (bs.epsilon > 0.0f) {
            for (int a = 0; a < 3; ++a) {
                if (std::fabs(st.v[a]) < bs.epsilon) st.v[a] = 0.0f;
                if (std::fabs(st.w[a]) < bs.epsilon) st.w[a] = 0.0f;
            }
        }
    }
}

void SoftContactSolver::IntegratePositions(const StepContext& ctx) {
    const float h = ctx.h;
    const std::size_t n = state.size();
    for (std::size_t i = 0; i < n; ++i) {
        BodySim& bs = sim[i];
        if (!bs.dynamic) continue;
        BodyState& st = state[i];
        st.dp += st.v * h;
        bs.p += st.v * h;
        // Orientation advanced by the world angular velocity (exponential map, normalised), keeping the world
        // angular momentum of a body whose principal moments differ (AdvanceRotation: between contacts a box turns
        // as a free body does, not at a constant w); the rotation since the step began moves the fixed anchors
        // (Solve).
        if (MagnitudeSq(st.w) > 0.0f) {
            bs.q = AdvanceRotation(bs.q, &st.w, bs.inertia, h);
            st.dR = ToMat3(bs.q * Conjugate(bs.q0));
        }
    }
}

void SoftContactSolver::UpdateSeparations() {
    for (const Pair& pair : pairs) {
        const BodyState& A = state[pair.a];
        const BodyState& B = state[pair.b];
        const vec3 dp = B.dp - A.dp;
        for (std::size_t k = pair.first; k < pair.first + pair.count; ++k) {
            Contact& c = contacts[k];
            // The base separation plus the motion of both anchors since the step began.
            const vec3 d = dp + Mul(c.rB, B.dR) - Mul(c.rA, A.dR);
            c.current = Dot(d, pair.n) + c.baseSeparation;
        }
    }
}

void SoftContactSolver::WarmStart() {
    for (const Pair& pair : pairs) {
        // The pair's two bodies are worked on in locals (no other pair touches them meanwhile): the contacts'
        // stores cannot alias them, so they stay in registers.
        BodyState& A = state[pair.a];
        BodyState& B = state[pair.b];
        BodyVelocity vA{A.v, A.w}, vB{B.v, B.w};
        const float invA = sim[pair.a].invMass, invB = sim[pair.b].invMass;
        for (std::size_t k = pair.first; k < pair.first + pair.count; ++k) {
            const Contact& c = contacts[k];
            ApplyRow(vA, vB, invA, invB, pair.n, c.normal, c.normal.impulse);
            ApplyRow(vA, vB, invA, invB, pair.t1, c.tangent1, c.tangent1.impulse);
            ApplyRow(vA, vB, invA, invB, pair.t2, c.tangent2, c.tangent2.impulse);
        }
        A.v = vA.v;
        A.w = vA.w;
        B.v = vB.v;
        B.w = vB.w;
    }
}

void SoftContactSolver::Solve(float invH, const Softness& dynamicSoftness, const Softness& staticSoftness,
                              float maxPushout, float slop, bool useBias) {
    for (const Pair& pair : pairs) {
        const Softness& softness = pair.touchesStatic ? staticSoftness : dynamicSoftness;
        BodyState& bodyA = state[pair.a];
        BodyState& bodyB = state[pair.b];
        BodyVelocity A{bodyA.v, bodyA.w}, B{bodyB.v, bodyB.w};
        const float invA = sim[pair.a].invMass, invB = sim[pair.b].invMass;
        for (std::size_t k = pair.first; k < pair.first + pair.count; ++k) {
            Contact& c = contacts[k];
            const float s = c.current;
            float bias = 0.0f, massScale = 1.0f, impulseScale = 0.0f;
            if (s > 0.0f) {
                bias = s * invH;  // speculative: may close the gap this substep, no more
            } else if (useBias) {
                bias = std::max(softness.biasRate * std::min(s + slop, 0.0f), -maxPushout);
                massScale = softness.massScale;
                impulseScale = softness.impulseScale;
            }
            // Normal: the TOTAL impulse stays >= 0 (contacts push).
            const float vn = RowSpeed(A, B, pair.n, c.normal);
            // Restitution works from the fastest closing speed met before solving (the impact substep), not from
            // the step's start, which misses up to g dt of the fall.
            if (useBias) c.relativeVelocity = std::min(c.relativeVelocity, vn);
            const float jn = std::max(
                c.normal.impulse - c.normal.mass * massScale * (vn + bias) - impulseScale * c.normal.impulse, 0.0f);
            const float dn = jn - c.normal.impulse;
            c.normal.impulse = jn;
            c.maxNormalImpulse = std::max(c.maxNormalImpulse, jn);
            ApplyRow(A, B, invA, invB, pair.n, c.normal, dn);
        }
        for (std::size_t k = pair.first; k < pair.first + pair.count; ++k) {
            Contact& c = contacts[k];
            // Friction: the TOTAL stays inside the Coulomb cone mu * jn (book §15, Coulomb clamp).
            const float limit = pair.friction * c.normal.impulse;
            float j1 = c.tangent1.impulse - c.tangent1.mass * RowSpeed(A, B, pair.t1, c.tangent1);
            float j2 = c.tangent2.impulse - c.tangent2.mass * RowSpeed(A, B, pair.t2, c.tangent2);
            const float sq = j1 * j1 + j2 * j2;
            if (sq > limit * limit) {
                const float scale = limit > 0.0f ? limit / std::sqrt(sq) : 0.0f;
                j1 *= scale;
                j2 *= scale;
            }
            const float d1 = j1 - c.tangent1.impulse, d2 = j2 - c.tangent2.impulse;
            c.tangent1.impulse = j1;
            c.tangent2.impulse = j2;
            ApplyRow(A, B, invA, invB, pair.t1, c.tangent1, d1);
            ApplyRow(A, B, invA, invB, pair.t2, c.tangent2, d2);
        }
        bodyA.v = A.v;
        bodyA.w = A.w;
        bodyB.v = B.v;
        bodyB.w = B.w;
    }
}

void SoftContactSolver::ApplyRestitution(float threshold) {
    for (const Pair& pair : pairs) {
        if (pair.restitution == 0.0f) continue;
        BodyState& A = state[pair.a];
        BodyState& B = state[pair.b];
        const float invA = sim[pair.a].invMass, invB = sim[pair.b].invMass;
        for (std::size_t k = pair.first; k < pair.first + pair.count; ++k) {
            Contact& c = contacts[k];
            // Only a real impact (closing faster than the threshold before solving) that the solver pushed on.
            if (c.relativeVelocity > -threshold || c.maxNormalImpulse == 0.0f) continue;
            const float vn = RowSpeed(A, B, pair.n, c.normal);
            const float jn =
                std::max(c.normal.impulse - c.normal.mass * (vn + pair.restitution * c.relativeVelocity), 0.0f);
            const float dn = jn - c.normal.impulse;
            c.normal.impulse = jn;
            c.maxNormalImpulse = std::max(c.maxNormalImpulse, jn);
            ApplyRow(A, B, invA, invB, pair.n, c.normal, dn);
        }
    }
}

void SoftContactSolver::StoreBodies(const std::vector<RigidbodyVolume*>& volumes) {
    for (std::size_t i = 0; i < volumes.size(); ++i) {
        const BodySim& bs = sim[i];
        if (!bs.dynamic) continue;
        RigidbodyVolume& body = *volumes[i];
        body.velocity = state[i].v;
        body.angVel = state[i].w;
        body.position = bs.p;
        body.orientation = bs.q;
        body.SynchCollisionVolumes();
    }
}
