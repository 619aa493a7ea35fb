// The Accumulated contact solver: sequential impulses (Catto, "Iterative Dynamics with Temporal Coherence",
// GDC 2005; "Fast and Simple Physics using Sequential Impulses", GDC 2006) written from the published idea:
// accumulated impulses clamped as totals, warm starting from persistent contacts, effective masses computed
// once per step. The book's solver is ApplyImpulse in RigidbodyVolume.cpp.
#include "Physics/ContactSolver.h"

#include <algorithm>
#include <cmath>

#include "Physics/RigidbodyVolume.h"
#include "Physics/VolumeStages.h"
#include "Physics/WorldSettings.h"

namespace {

/// Orthonormal t1, t2 with n x t1 = t2, a fixed function of n: the same normal gives the same basis every step.
void TangentBasis(const vec3& n, vec3* t1, vec3* t2) {
    // Build t1 from the two largest components of n, so it never degenerates (|n| = 1 has one >= 1/sqrt 3).
    vec3 t = std::fabs(n.x) >= 0.57735f ? vec3(n.y, -n.x, 0.0f) : vec3(0.0f, n.z, -n.y);
    t = t * (1.0f / std::sqrt(MagnitudeSq(t)));
    *t1 = t;
    *t2 = Cross(n, t);
}

/// 1 / (1/mA + 1/mB + (rA x d) . IA^-1 (rA x d) + (rB x d) . IB^-1 (rB x d)): the mass the contact has along d
/// (the effective-mass term of the book's impulse denominator, with the symmetric world inverse inertia).
float EffectiveMass(float invSum, const mat3& iA, const mat3& iB, const vec3& rA, const vec3& rB, const vec3& d) {
    const vec3 a = Cross(rA, d);
    const vec3 b = Cross(rB, d);
    const float k = invSum + Dot(a, MultiplyVector(a, iA)) + Dot(b, MultiplyVector(b, iB));
    return k > 0.0f ? 1.0f / k : 0.0f;
}

/// Clamps the friction pair (jt1, jt2) into the Coulomb cone |jt| <= limit.
void ClampToCone(float limit, float* jt1, float* jt2) {
    const float sq = *jt1 * *jt1 + *jt2 * *jt2;
    if (sq > limit * limit) {
        const float s = limit > 0.0f ? limit / std::sqrt(sq) : 0.0f;
        *jt1 *= s;
        *jt2 *= s;
    }
}

bool KeyLess(const AccumulatedContactSolver::Arbiter& arbiter, const std::pair<int, int>& key) {
    return arbiter.indexA != key.first ? arbiter.indexA < key.first : arbiter.indexB < key.second;
}

}  // namespace

void AccumulatedContactSolver::Clear() {
    arbiters.clear();
    contacts.clear();
    previousArbiters.clear();
    previousContacts.clear();
    warmStarted = 0;
    lastSubstep = -2;
}

float AccumulatedContactSolver::TotalNormalImpulse() const {
    float sum = 0.0f;
    for (const Contact& c : contacts) sum += c.jn;
    return sum;
}

void AccumulatedContactSolver::BeginPrepare(const std::vector<RigidbodyVolume*>& volumes, bool carryOver) {
    // Per-body data once per step: inverse mass and the world inverse inertia R^T I^-1 R.
    if (invMass.size() < volumes.size()) {
        invMass.resize(volumes.size());
        invInertia.resize(volumes.size());
    }
    for (std::size_t i = 0; i < volumes.size(); ++i) {
        invMass[i] = volumes[i]->InvMass();
        invInertia[i] = volumes[i]->InvTensor();
    }

    // This step's buffers become last step's; capacities are kept, so nothing is allocated once they have grown.
    arbiters.swap(previousArbiters);
    contacts.swap(previousContacts);
    arbiters.clear();
    contacts.clear();
    if (!carryOver) {
        previousArbiters.clear();
        previousContacts.clear();
    }
    warmStarted = 0;
}

bool AccumulatedContactSolver::Inherit(const Arbiter& old, const Arbiter& arb, float matchSq, float warmStartFactor,
                                       Contact* c) {
    // Warm start: the nearest unclaimed contact of last step within matchDistance (first wins a tie). Its total
    // impulse is re-expressed in this step's basis, so a slowly turning normal keeps most of it.
    std::size_t best = old.count;
    float bestSq = matchSq;
    for (std::size_t k = 0; k < old.count; ++k) {
        if (matchedScratch[k]) continue;
        const float d = DistanceSq(c->point, previousContacts[old.first + k].point);
        if (d <= matchSq && (best == old.count || d < bestSq)) {
            best = k;
            bestSq = d;
        }
    }
    if (best == old.count) return false;
    matchedScratch[best] = 1;
    const Contact& o = previousContacts[old.first + best];
    const vec3 P = (old.n * o.jn + old.t1 * o.jt1 + old.t2 * o.jt2) * warmStartFactor;
    c->jn = std::fmax(Dot(P, arb.n), 0.0f);
    c->jt1 = Dot(P, arb.t1);
    c->jt2 = Dot(P, arb.t2);
    ClampToCone(arb.mu * c->jn, &c->jt1, &c->jt2);
    return true;
}

void AccumulatedContactSolver::Prepare(const std::vector<RigidbodyVolume*>& volumes, const CollisionPair* pairs,
                                       std::size_t count, float dt, float slop, bool carryOver,
                                       const AccumulatedSolverSettings& settings) {
    BeginPrepare(volumes, carryOver);
    const float baumgarte = dt > 0.0f ? settings.baumgarte / dt : 0.0f;
    const float matchSq = settings.matchDistance * settings.matchDistance;

    for (std::size_t p = 0; p < count; ++p) {
        const CollisionPair& pair = pairs[p];
        RigidbodyVolume& A = *pair.a;
        RigidbodyVolume& B = *pair.b;
        const int ia = pair.indexA, ib = pair.indexB;
        const float invA = invMass[ia], invB = invMass[ib];
        const float invSum = invA + invB;
        if (invSum == 0.0f || pair.manifold.contacts.empty()) continue;
        const mat3& iA = invInertia[ia];
        const mat3& iB = invInertia[ib];

        Arbiter arb;
        arb.indexA = ia;
        arb.indexB = ib;
        arb.a = &A;
        arb.b = &B;
        arb.n = Normalized(pair.manifold.normal);
        TangentBasis(arb.n, &arb.t1, &arb.t2);
        arb.mu = std::sqrt(A.friction * B.friction);  // book §15: mu = sqrt(muA muB)
        arb.first = contacts.size();
        arb.count = pair.manifold.contacts.size();
        const float e = std::fmin(A.cor, B.cor);  // book: restitution is the smaller cor
        // Position error as a velocity target (Baumgarte with slop); depth is the manifold's full penetration.
        const float positionBias = baumgarte * std::fmax(pair.manifold.depth - slop, 0.0f);

        // The same pair last step (same indices and same bodies): its contacts are warm-start candidates.
        const Arbiter* old = nullptr;
        const auto it =
            std::lower_bound(previousArbiters.begin(), previousArbiters.end(), std::make_pair(ia, ib), KeyLess);
        if (it != previousArbiters.end() && it->indexA == ia && it->indexB == ib && it->a == &A && it->b == &B)
            old = &*it;
        if (old != nullptr) matchedScratch.assign(old->count, 0);  // capacity reused

        for (const vec3& point : pair.manifold.contacts) {
            Contact c;
            c.point = point;
            c.rA = point - A.position;
            c.rB = point - B.position;
            c.massN = EffectiveMass(invSum, iA, iB, c.rA, c.rB, arb.n);
            c.massT1 = EffectiveMass(invSum, iA, iB, c.rA, c.rB, arb.t1);
            c.massT2 = EffectiveMass(invSum, iA, iB, c.rA, c.rB, arb.t2);
            // Restitution from the closing speed before any impulse of this step, only for a real impact.
            const float vn = Dot(RelativeVelocity(A, B, c.rA, c.rB), arb.n);
            const float restitutionBias = -vn > settings.restitutionThreshold ? -e * vn : 0.0f;
            c.bias = std::fmax(restitutionBias, positionBias);
            c.jn = c.jt1 = c.jt2 = 0.0f;
            if (old != nullptr && Inherit(*old, arb, matchSq, settings.warmStartFactor, &c)) ++warmStarted;
            contacts.push_back(c);
        }
        arbiters.push_back(arb);
    }
}

void AccumulatedContactSolver::Solve(const std::vector<RigidbodyVolume*>& volumes, const CollisionPair* pairs,
                                     std::size_t count, const StepContext& ctx) {
    // Impulses carry over only between consecutive substeps: after one without contacts (Solve not called)
    // the kept contacts describe an older state.
    const WorldSettings& world = ctx.settings;
    Prepare(volumes, pairs, count, ctx.h, world.penetrationSlop, ctx.substepSerial == lastSubstep + 1,
            world.accumulated);
    lastSubstep = ctx.substepSerial;
    const int iterations = world.solverIterations;

    // Warm start: apply last step's matched totals once, before the passes.
    for (const Arbiter& arb : arbiters) {
        RigidbodyVolume& A = *volumes[arb.indexA];
        RigidbodyVolume& B = *volumes[arb.indexB];
        for (std::size_t k = arb.first; k < arb.first + arb.count; ++k) {
            const Contact& c = contacts[k];
            if (c.jn == 0.0f && c.jt1 == 0.0f && c.jt2 == 0.0f) continue;
            ApplyPairImpulse(A, B, invMass[arb.indexA], invMass[arb.indexB], invInertia[arb.indexA],
                             invInertia[arb.indexB], c.rA, c.rB, arb.n * c.jn + arb.t1 * c.jt1 + arb.t2 * c.jt2);
        }
    }

    for (int pass = 0; pass < iterations; ++pass) {
        for (const Arbiter& arb : arbiters) {
            RigidbodyVolume& A = *volumes[arb.indexA];
            RigidbodyVolume& B = *volumes[arb.indexB];
            const float invA = invMass[arb.indexA], invB = invMass[arb.indexB];
            const mat3& iA = invInertia[arb.indexA];
            const mat3& iB = invInertia[arb.indexB];
            for (std::size_t k = arb.first; k < arb.first + arb.count; ++k) {
                Contact& c = contacts[k];
                // Normal: drive the separating speed to the bias; the TOTAL impulse stays >= 0 (contacts push).
                const float vn = Dot(RelativeVelocity(A, B, c.rA, c.rB), arb.n);
                const float jn = std::fmax(c.jn + c.massN * (c.bias - vn), 0.0f);
                const float dn = jn - c.jn;
                c.jn = jn;
                if (dn != 0.0f) ApplyPairImpulse(A, B, invA, invB, iA, iB, c.rA, c.rB, arb.n * dn);

                // Friction: stop the tangential motion (two rows, along t1 and t2, each with its own effective mass);
                // the TOTAL stays inside the Coulomb cone mu * jn. A contact that slides (the two rows would leave the
                // cone) is solved as one row along its slip instead, so its impulse opposes the slip: the two rows'
                // masses differ wherever the contact is off the body's axes, and their clamped sum pushed a sliding
                // box sideways, so a box sliding at a yaw curved and slid too far, by the same amount at every step
                // (docs/soft-solver.md, "Convergence of the contact solvers"). Sticking contacts are solved as before.
                const vec3 vr = RelativeVelocity(A, B, c.rA, c.rB);
                const float v1 = Dot(vr, arb.t1), v2 = Dot(vr, arb.t2);
                const float limit = arb.mu * c.jn;
                float jt1 = c.jt1 - c.massT1 * v1;
                float jt2 = c.jt2 - c.massT2 * v2;
                const float slip = std::sqrt(v1 * v1 + v2 * v2);
                if (jt1 * jt1 + jt2 * jt2 > limit * limit && slip > 0.0f) {
                    const vec3 along = (arb.t1 * v1 + arb.t2 * v2) * (1.0f / slip);
                    const float mass = EffectiveMass(invA + invB, iA, iB, c.rA, c.rB, along);
                    jt1 = c.jt1 - mass * v1;
                    jt2 = c.jt2 - mass * v2;
                }
                ClampToCone(limit, &jt1, &jt2);
                const float d1 = jt1 - c.jt1, d2 = jt2 - c.jt2;
                c.jt1 = jt1;
                c.jt2 = jt2;
                if (d1 != 0.0f || d2 != 0.0f)
                    ApplyPairImpulse(A, B, invA, invB, iA, iB, c.rA, c.rB, arb.t1 * d1 + arb.t2 * d2);
            }
        }
    }
}
