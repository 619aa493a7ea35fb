// ContactSolver::Soft's narrow phase (SoftSolver.h, Collide): the manifolds of the candidate pairs and the pairs and
// contacts made from them, with last step's impulses matched by feature id; in chunks of kCandidateChunk candidates on
// the step's threads, each chunk writing only its own slots (docs/threads.md).
#include <algorithm>
#include <cmath>
#include <new>

#include "Physics/Geometry/ContactManifold.h"
#include "Physics/RigidbodyVolume.h"
#include "Physics/SoftSolver.h"
#include "Physics/WorldSettings.h"

namespace {

/// Orthonormal t1, t2 with n x t1 = t2, a fixed function of n (the same normal gives the same basis every step).
void TangentBasis(const vec3& n, vec3* t1, vec3* t2) {
    vec3 t = std::fabs(n.x) >= 0.57735f ? vec3(n.y, -n.x, 0.0f) : vec3(0.0f, n.z, -n.y);
    t = t * (1.0f / std::sqrt(MagnitudeSq(t)));
    *t1 = t;
    *t2 = Cross(n, t);
}

/// Pairs of static bodies never move, so they are never tested.
bool CanInteract(const RigidbodyVolume& a, const RigidbodyVolume& b) {
    return a.HasVolume() && b.HasVolume() && (a.mass > 0.0f || b.mass > 0.0f);
}

/// A static body and a dynamic one, or two dynamic ones whose masses differ by less than `ratio` (0: any): a pair
/// whose manifold may be reused. A heavy body on a light one is held by the shock pass (SoftSolverShock.cpp), which
/// measured deeper with reused manifolds (docs/soft-solver.md, "Manifold reuse").
bool AlikeMasses(const RigidbodyVolume& a, const RigidbodyVolume& b, float ratio) {
    if (!(a.mass > 0.0f) || !(b.mass > 0.0f) || !(ratio > 0.0f)) return true;
    return a.mass < ratio * b.mass && b.mass < ratio * a.mass;
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

// Inlined into MakePairs, its one caller (the calls were 3 % of the collide stage's instructions, callgrind).
__attribute__((always_inline)) inline bool SoftContactSolver::Inherit(const Pair& old, const Pair& pair,
                                                                      float warmStartFactor, Contact* c) const {
    const Contact* match = nullptr;
    for (std::size_t j = old.first; j < old.first + old.count; ++j)
        if (previousContacts[j].id == c->id) {
            match = &previousContacts[j];
            break;
        }
    if (match == nullptr) return false;
    const Contact& o = *match;
    // Last step's total re-expressed in this step's basis, so a slowly turning normal keeps most.
    const vec3 P =
        (old.n * o.normal.impulse + old.t1 * o.tangent1.impulse + old.t2 * o.tangent2.impulse) * warmStartFactor;
    c->normal.impulse = std::fmax(Dot(P, pair.n), 0.0f);
    c->support = c->normal.impulse;
    c->tangent1.impulse = Dot(P, pair.t1);
    c->tangent2.impulse = Dot(P, pair.t2);
    return true;
}

void SoftContactSolver::FindManifolds(const std::vector<RigidbodyVolume*>& volumes,
                                      const std::vector<std::pair<int, int>>& candidates, const StepContext& ctx,
                                      std::size_t chunk) {
    const float margin = ctx.settings.soft.speculativeMargin;
    const float reuseDistance = ctx.settings.soft.manifoldReuseDistance;
    ChunkCounts& counts = chunkCounts[chunk];
    const std::size_t begin = chunk * kCandidateChunk, end = std::min(candidates.size(), begin + kCandidateChunk);
    // previousKept is in the same increasing (a, b) order as the candidates: the chunk's cursor starts at the first
    // old candidate not before its first one.
    std::size_t cursor = 0;
    if (begin < end)
        cursor =
            static_cast<std::size_t>(std::lower_bound(previousKept.begin(), previousKept.end(), candidates[begin],
                                                      [](const KeptPair& p, const std::pair<int, int>& c) {
                                                          return p.a < c.first || (p.a == c.first && p.b < c.second);
                                                      }) -
                                     previousKept.begin());
    for (std::size_t k = begin; k < end; ++k) {
        const std::pair<int, int>& candidate = candidates[k];
        const RigidbodyVolume& A = *volumes[candidate.first];
        const RigidbodyVolume& B = *volumes[candidate.second];
        ContactManifold& manifold = manifolds[k];
        KeptPair& slot = kept[k];
        slot.a = candidate.first;
        slot.b = candidate.second;
        slot.bodyA = &A;
        slot.bodyB = &B;
        slot.local.pointCount = 0;
        manifold.pointCount = 0;
        if (!CanInteract(A, B)) continue;
        const bool boxes = A.type != RigidbodyType::Sphere && B.type != RigidbodyType::Sphere;
        // The same pair last step (same indices, same bodies): its manifold, if the pair has barely moved since.
        while (cursor < previousKept.size() && (previousKept[cursor].a < slot.a ||
                                                (previousKept[cursor].a == slot.a && previousKept[cursor].b < slot.b)))
            ++cursor;
        const KeptPair* old = nullptr;
        if (boxes && reuseDistance > 0.0f && AlikeMasses(A, B, ctx.settings.soft.shockMassRatio) &&
            cursor < previousKept.size() && previousKept[cursor].a == slot.a && previousKept[cursor].b == slot.b &&
            previousKept[cursor].bodyA == &A && previousKept[cursor].bodyB == &B)
            old = &previousKept[cursor];
        if (old != nullptr && ReuseLocal(A.box, B.box, old->local, reuseDistance, &manifold)) {
            slot.local = old->local;
            ++counts.reused;
        } else {
            // Speculative margin plus the distance the pair can close this step, so a fast body meets the surface
            // in the substep it reaches it instead of being pushed out from inside.
            const float closing = std::sqrt(MagnitudeSq(state[candidate.second].v - state[candidate.first].v));
            CollideVolumes(A, B, margin + closing * ctx.dt, &manifold);
            if (boxes && reuseDistance > 0.0f && manifold.pointCount > 0)
                KeepLocal(A.box, B.box, manifold, &slot.local);
        }
        if (manifold.pointCount <= 0) continue;
        ++counts.pairs;
        counts.contacts += static_cast<std::size_t>(std::min(manifold.pointCount, kMaxManifoldPoints));
    }
}

void SoftContactSolver::MakePairs(const std::vector<RigidbodyVolume*>& volumes,
                                  const std::vector<std::pair<int, int>>& candidates, const StepContext& ctx,
                                  std::size_t chunk) {
    ChunkCounts& counts = chunkCounts[chunk];
    std::size_t nextPair = counts.firstPair, nextContact = counts.firstContact;
    const std::size_t begin = chunk * kCandidateChunk, end = std::min(candidates.size(), begin + kCandidateChunk);
    // previousPairs is in the same increasing (a, b) order as the candidates: the chunk's cursor starts at the first
    // old pair not before its first candidate.
    std::size_t cursor = 0;
    if (begin < end) {
        const std::pair<int, int> first = candidates[begin];
        cursor =
            static_cast<std::size_t>(std::lower_bound(previousPairs.begin(), previousPairs.end(), first,
                                                      [](const Pair& p, const std::pair<int, int>& c) {
                                                          return p.a < c.first || (p.a == c.first && p.b < c.second);
                                                      }) -
                                     previousPairs.begin());
    }
    for (std::size_t at = begin; at < end; ++at) {
        const ContactManifold& manifold = manifolds[at];
        if (manifold.pointCount <= 0) continue;
        const std::pair<int, int>& candidate = candidates[at];
        const RigidbodyVolume& A = *volumes[candidate.first];
        const RigidbodyVolume& B = *volumes[candidate.second];

        Pair& pair = pairs[nextPair];
        pair = Pair();
        pair.a = candidate.first;
        pair.b = candidate.second;
        pair.bodyA = &A;
        pair.bodyB = &B;
        pair.n = Normalized(manifold.normal);
        TangentBasis(pair.n, &pair.t1, &pair.t2);
        pair.friction = std::sqrt(A.friction * B.friction);  // book §15: mu = sqrt(muA muB)
        pair.restitution = std::fmin(A.cor, B.cor);          // book: the smaller cor
        pair.touchesStatic = !(A.mass > 0.0f) || !(B.mass > 0.0f);
        pair.first = nextContact;
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
            // A new Contact made in its slot (assigning a temporary one zeroed it on the stack and copied it).
            Contact& c = *new (&contacts[nextContact++]) Contact();
            c.rA = mp.point - sim[pair.a].p;
            c.rB = mp.point - sim[pair.b].p;
            c.separation = mp.separation;
            c.id = mp.id;
            if (old != nullptr && Inherit(*old, pair, ctx.settings.soft.warmStartFactor, &c)) ++counts.matched;
        }
        pairEnds[nextPair] = {pair.a, pair.b};
        ++nextPair;
    }
}
