// Rigid-volume stages of PhysicsSystem::Update (book.md 3.4 steps 1-5): pair search with manifolds, forces,
// ImpulseIteration passes of ApplyImpulse over every contact, integration, linear projection.
#include <algorithm>

#include "PhysicsSystem.h"
#include "RigidbodyVolume.h"

namespace {

/// Pairs of static bodies never move, so they are never tested.
bool CanInteract(const RigidbodyVolume& a, const RigidbodyVolume& b) {
    return a.HasVolume() && b.HasVolume() && (a.mass > 0.0f || b.mass > 0.0f);
}

}  // namespace

void PhysicsSystem::FindCollisions() {
    resultCount = 0;
    // Test one pair, writing into the next slot of `results`; a slot is kept (with its contact capacity) even
    // when the pair does not collide, so the steady state allocates nothing.
    auto test = [this](std::size_t i, std::size_t j) {
        if (resultCount == results.size()) results.emplace_back();
        CollisionPair& slot = results[resultCount];
        FindCollisionFeatures(*volumes[i], *volumes[j], &slot.manifold);
        if (!slot.manifold.colliding || slot.manifold.contacts.empty()) return;
        slot.a = volumes[i];
        slot.b = volumes[j];
        slot.indexA = static_cast<int>(i);
        slot.indexB = static_cast<int>(j);
        ++resultCount;
    };

    const std::size_t n = volumes.size();
    if (n < BroadphaseMinVolumes) {
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                if (CanInteract(*volumes[i], *volumes[j])) test(i, j);
        return;
    }
    broadphase.FindPairs(volumes, &candidatePairs);
    for (const std::pair<int, int>& p : candidatePairs)
        if (CanInteract(*volumes[p.first], *volumes[p.second]))
            test(static_cast<std::size_t>(p.first), static_cast<std::size_t>(p.second));
}

void PhysicsSystem::ApplyVolumeForces(float dt) {
    // ch15 note N1 (docs/ERRATA.md, Chapter 15): the book applies the impulses to the velocity of the previous step
    // and only then adds this step's gravity and moves the body, so the tangential part of g dt always
    // reaches the position before friction can see it: a box creeps down any incline at about g sin(theta) dt
    // (0.056 m/s at 20 degrees, 60 Hz) however large mu is, and a resting box is never at rest. The stage
    // order is kept (forces, impulses, integration), but the forces stage already turns this step's forces
    // into velocity (semi-implicit Euler's first half), so the impulses act on the velocity that will move
    // the body.
    volumeStepDt = dt;
    for (RigidbodyVolume* body : volumes) {
        body->ApplyForces();
        body->IntegrateVelocity(dt);
    }
}

void PhysicsSystem::ApplyImpulses() {
    if (contactSolver == ContactSolver::Accumulated) {
        // Sequential impulses with an arbiter (ContactSolver.h); results are in increasing (indexA, indexB)
        // order, which the arbiter's lookup relies on.
        accumulatedSolver.Solve(volumes, results.data(), resultCount, ImpulseIteration, volumeStepDt, PenetrationSlack,
                                stepCount, accumulated);
        return;
    }
    for (int k = 0; k < ImpulseIteration; ++k) {
        for (std::size_t i = 0; i < resultCount; ++i) {
            const CollisionPair& pair = results[i];
            const int contacts = static_cast<int>(pair.manifold.contacts.size());
            for (int c = 0; c < contacts; ++c) ApplyImpulse(*pair.a, *pair.b, pair.manifold, c);
        }
    }
}

void PhysicsSystem::IntegrateVolumes(float dt) {
    for (RigidbodyVolume* body : volumes) body->IntegratePosition(dt);
}

void PhysicsSystem::ApplyLinearProjection() {
    // Positional correction (book.md 3.4 step 5) with the manifolds found before integration. Depth is the
    // full penetration for every pair type (see FindCollisionFeatures(RigidbodyVolume&, ...)).
    for (std::size_t i = 0; i < resultCount; ++i) {
        RigidbodyVolume& a = *results[i].a;
        RigidbodyVolume& b = *results[i].b;
        // erratum 5.2-17: the book skips a pair only when NEITHER body has a volume (&&); either one is enough.
        if (!a.HasVolume() || !b.HasVolume()) continue;
        const float invA = a.InvMass();
        const float invB = b.InvMass();
        const float invSum = invA + invB;
        if (invSum == 0.0f) continue;
        const CollisionManifold& m = results[i].manifold;
        const float depth = std::max(m.depth - PenetrationSlack, 0.0f);
        const vec3 correction = m.normal * (depth / invSum * LinearProjectionPercent);
        a.position -= correction * invA;
        b.position += correction * invB;
        a.SynchCollisionVolumes();
        b.SynchCollisionVolumes();
    }
}
