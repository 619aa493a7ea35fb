// Rigid-volume stages of PhysicsSystem::Update (docs/book-reference.md §3.4 steps 1-5): pair search with manifolds,
// forces, settings.solverIterations passes of ApplyImpulse over every contact, integration, linear projection.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

namespace {

/// Smallest half extent: a sphere's radius, a box's smallest half size.
float HalfExtent(const RigidbodyVolume& body) {
    if (body.type == RigidbodyType::Sphere) return body.sphere.radius;
    return std::min(body.box.size.x, std::min(body.box.size.y, body.box.size.z));
}

/// Pairs of static bodies never move, so they are never tested.
bool CanInteract(const RigidbodyVolume& a, const RigidbodyVolume& b) {
    return a.HasVolume() && b.HasVolume() && (a.mass > 0.0f || b.mass > 0.0f);
}

}  // namespace

void PhysicsSystem::FindCollisions(const StepContext& ctx, Islands* sleep) {
    if (sleep == nullptr) {
        FindPairs(ctx, nullptr);
        return;
    }
    // A new contact of an active body with a sleeping one wakes that island; its bodies' contacts among themselves
    // (not tested while they slept) are then found by searching again. Each pass wakes at least one island.
    FindPairs(ctx, sleep->ActiveMask());
    while (sleep->WakeTouched(results.data(), resultCount) > 0) FindPairs(ctx, sleep->ActiveMask());
}

void PhysicsSystem::FindPairs(const StepContext& ctx, const unsigned char* active) {
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
    // With sleep, a pair is tested only when one of its bodies is active (dynamic and awake).
    auto wanted = [this, active](std::size_t i, std::size_t j) {
        return CanInteract(*volumes[i], *volumes[j]) && (active == nullptr || active[i] != 0 || active[j] != 0);
    };

    const std::size_t n = volumes.size();
    if (n < ctx.settings.broadphaseMinVolumes) {
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j)
                if (wanted(i, j)) test(i, j);
        return;
    }
    if (!broadphase.FindPairs(volumes, &candidatePairs, active, 0.0f, 0.0f, ctx.settings.maxPairs, ctx.jobs)) {
        StopAtPairLimit();
        return;
    }
    for (const std::pair<int, int>& p : candidatePairs) {
        const std::size_t i = static_cast<std::size_t>(p.first), j = static_cast<std::size_t>(p.second);
        if (wanted(i, j)) test(i, j);
    }
}

void PhysicsSystem::StopAtPairLimit() {
    char text[256];
    std::snprintf(text, sizeof text,
                  "step %lld: more than %zu pairs of volumes overlap, the limit of one pair search "
                  "(WorldSettings::maxPairs); stopped before allocating them (%zu volumes)",
                  stepCount + 1, settings.maxPairs, volumes.size());
    stopReason = text;
}

void PhysicsSystem::StepSoftVolumes(StepContext& ctx) {
    // The soft step (docs/soft-solver.md, "The soft-step solver"): pairs are found once per step, with every AABB grown
    // by the speculative margin and the body's travel over the step, so that contacts about to touch are solved
    // before they do; no travel split, no linear projection (the solver's substeps and soft bias replace both).
    const int n = std::max(settings.soft.substeps, 1);
    ctx.substepCount = n;
    ctx.h = ctx.dt / static_cast<float>(n);
    ctx.invH = 1.0f / ctx.h;
    ctx.substep = 0;
    ctx.substepSerial = volumeSubstepSerial;
    lastVolumeSubsteps = n;
    resultCount = 0;  // Collisions() turns the soft step's contacts into the book's form when asked

    // Islands and sleep (Islands.h): null while settings.sleep is off. Sleeping bodies are held like static ones;
    // a pair is searched only when one body is active, and a sleeping island whose grown AABB meets an active
    // body's is woken before the solve (then the search runs again for its own pairs).
    Islands* sleep = islands.BeginStep(volumes, settings.sleep) ? &islands : nullptr;
    const unsigned char* active = sleep != nullptr ? sleep->ActiveMask() : nullptr;
    const float margin = std::max(settings.soft.speculativeMargin, 0.0f);
    const std::size_t count = volumes.size();
    // The all-pairs loop asks for overlapping grown boxes, as the broadphase does: so a small world and a large
    // one find the same pairs, and the solver collides only pairs that can touch this step (in a column of 20
    // cubes, 19 + 1 of its 210 pairs). With sleep on, these pairs also decide which islands wake.
    // Each body's box grown by the margin and its travel over the step, once per search (not once per pair).
    auto near = [&](std::size_t i, std::size_t j) {
        const GrownBounds& a = smallWorldBounds[i];
        const GrownBounds& b = smallWorldBounds[j];
        for (int k = 0; k < 3; ++k)
            if (a.min[k] > b.max[k] || b.min[k] > a.max[k]) return false;
        return true;
    };
    auto search = [&] {
        candidatePairs.clear();
        if (count < settings.broadphaseMinVolumes) {
            smallWorldBounds.resize(count);
            for (std::size_t i = 0; i < count; ++i) {
                GrownBounds& g = smallWorldBounds[i];
                VolumeBounds(*volumes[i], &g.min, &g.max);
                const float grow = margin + Magnitude(volumes[i]->velocity) * ctx.dt;
                g.min -= vec3(grow, grow, grow);
                g.max += vec3(grow, grow, grow);
            }
            for (std::size_t i = 0; i < count; ++i)
                for (std::size_t j = i + 1; j < count; ++j)
                    if (CanInteract(*volumes[i], *volumes[j]) && (active == nullptr || active[i] || active[j]) &&
                        near(i, j))
                        candidatePairs.emplace_back(static_cast<int>(i), static_cast<int>(j));
        } else if (!broadphase.FindPairs(volumes, &candidatePairs, active, margin, ctx.dt, settings.maxPairs,
                                         ctx.jobs)) {
            StopAtPairLimit();
        }
    };
    // With every body asleep (or static) no pair can have an active body and nothing moves: the search and the
    // solver's pass over every body are skipped, and the solver only forgets its (already empty) contacts, which
    // is what its Step would leave. A settled world then costs the wake checks and the island update.
    if (sleep != nullptr && std::find(active, active + count, 1) == active + count) {
        candidatePairs.clear();
        softSolver.Clear();
    } else {
        search();
        if (sleep != nullptr)
            while (stopReason.empty() && sleep->WakeTouched(candidatePairs.data(), candidatePairs.size()) > 0) search();
        if (!stopReason.empty()) return;
        softSolver.Step(volumes, candidatePairs, ctx, active);
    }
    if (sleep != nullptr) {
        // Islands are linked over the same candidate pairs that wake them (grown boxes that meet), not only over
        // pairs with contact points: two islands near enough to wake each other are one island, so they fall
        // asleep together instead of waking each other in turn.
        islands.BeginUpdate(volumes, ctx.dt, settings.sleep);
        for (const std::pair<int, int>& p : candidatePairs) islands.LinkPair(p.first, p.second);
        islands.EndUpdate(volumes, settings.sleep);
    }
    volumeSubstepSerial += n;
    softCollisionsPending = true;
}

void PhysicsSystem::FillSoftCollisions() const {
    softCollisionsPending = false;
    resultCount = 0;
    const std::vector<SoftContactSolver::Pair>& pairs = softSolver.Pairs();
    const std::vector<SoftContactSolver::Contact>& contacts = softSolver.Contacts();
    for (const SoftContactSolver::Pair& pair : pairs) {
        const std::size_t a = static_cast<std::size_t>(pair.a), b = static_cast<std::size_t>(pair.b);
        if (b >= volumes.size() || volumes[a] != pair.bodyA || volumes[b] != pair.bodyB) continue;
        if (resultCount == results.size()) results.emplace_back();
        CollisionPair& slot = results[resultCount];
        CollisionManifold& m = slot.manifold;
        ResetCollisionManifold(&m);
        m.normal = pair.n;
        m.depth = 0.0f;
        // The anchors are from body a's centre at the start of the step, as the manifold found them.
        const vec3 start = softSolver.StartPosition(pair.a);
        for (std::size_t k = pair.first; k < pair.first + pair.count; ++k) {
            const SoftContactSolver::Contact& c = contacts[k];
            if (c.separation > 0.0f) continue;
            m.contacts.push_back(start + c.rA);
            m.depth = std::max(m.depth, -c.separation);
        }
        if (m.contacts.empty()) continue;
        m.colliding = true;
        slot.a = volumes[a];
        slot.b = volumes[b];
        slot.indexA = pair.a;
        slot.indexB = pair.b;
        ++resultCount;
    }
}

void PhysicsSystem::ApplyVolumeForces(const StepContext& ctx, const Islands* sleep) {
    // ch15 note N1 (docs/ERRATA.md, Chapter 15): the book applies the impulses to the velocity of the previous step
    // and only then adds this step's gravity and moves the body, so the tangential part of g dt always
    // reaches the position before friction can see it: a box creeps down any incline at about g sin(theta) dt
    // (0.056 m/s at 20 degrees, 60 Hz) however large mu is, and a resting box is never at rest. The stage
    // order is kept (forces, impulses, integration), but the forces stage already turns this step's forces
    // into velocity (semi-implicit Euler's first half), so the impulses act on the velocity that will move
    // the body.
    // Sleeping bodies get no forces (their velocities stay zero); static ones run as without sleep.
    for (std::size_t i = 0; i < volumes.size(); ++i) {
        if (sleep != nullptr && !sleep->IsAwake(static_cast<int>(i))) continue;
        volumes[i]->ApplyForces();
        volumes[i]->IntegrateVelocity(ctx.h);
    }
}

void PhysicsSystem::ApplyImpulses(const StepContext& ctx) {
    if (ctx.settings.contactSolver == ContactSolver::Accumulated) {
        // Sequential impulses with an arbiter (ContactSolver.h); results are in increasing (indexA, indexB)
        // order, which the arbiter's lookup relies on.
        // Impulses carry over between consecutive substeps (ctx.substepSerial).
        accumulatedSolver.Solve(volumes, results.data(), resultCount, ctx);
        return;
    }
    for (int k = 0; k < ctx.settings.solverIterations; ++k) {
        for (std::size_t i = 0; i < resultCount; ++i) {
            const CollisionPair& pair = results[i];
            const int contacts = static_cast<int>(pair.manifold.contacts.size());
            for (int c = 0; c < contacts; ++c) ApplyImpulse(*pair.a, *pair.b, pair.manifold, c);
        }
    }
}

int PhysicsSystem::VolumeSubsteps(float dt) {
    // Volumes have no continuous collision: contacts are found at the start of a step, so a body that moves
    // further than its own half extent plus the other's in one step passes a slab's mid plane, and the manifold
    // then pushes it out of the far side (a 0.5 s step drops a resting box 1.2 m). Per dynamic
    // volume, the travel bound |v| dt + |g| dt^2 / 2 is compared with its own half extent plus the thinnest half
    // extent in the world (the thinnest thing it could meet); n keeps every substep's travel within
    // settings.substepTravelFraction of that sum. Spin is not counted. One pass over the volumes; n = 1 at the book's
    // 0.03 s in all its demos (ch15: ratio 0.23, momentum: 0.52 at the 20 m/s launch).
    const int maxSubsteps = settings.maxVolumeSubsteps;
    if (maxSubsteps <= 1) return 1;
    float thinnest = std::numeric_limits<float>::infinity();
    for (const RigidbodyVolume* body : volumes) thinnest = std::min(thinnest, HalfExtent(*body));
    float ratio = 0.0f;
    for (const RigidbodyVolume* body : volumes) {
        if (!(body->mass > 0.0f)) continue;
        const float travel = Magnitude(body->velocity) * dt + 0.5f * Magnitude(body->gravity) * dt * dt;
        ratio = std::max(ratio, travel / (HalfExtent(*body) + thinnest));
    }
    const float wanted = std::ceil(ratio / settings.substepTravelFraction);
    if (!(wanted > 1.0f)) return 1;
    if (wanted <= static_cast<float>(maxSubsteps)) return static_cast<int>(wanted);
    char text[256];
    std::snprintf(text, sizeof text,
                  "Update: dt = %g s needs %g volume substeps (a volume travels %g times its half extent plus the "
                  "thinnest one); clamped to maxVolumeSubsteps = %d, so fast volumes may pass through thin ones",
                  static_cast<double>(dt), static_cast<double>(wanted), static_cast<double>(ratio), maxSubsteps);
    lastError.assign(text);  // capacity is reused: no allocation once the longest message has been written
    return maxSubsteps;
}

void PhysicsSystem::IntegrateVolumes(const StepContext& ctx, const Islands* sleep) {
    if (sleep == nullptr) {
        for (RigidbodyVolume* body : volumes) body->IntegratePosition(ctx.h);
        return;
    }
    for (std::size_t i = 0; i < volumes.size(); ++i)
        if (sleep->IsAwake(static_cast<int>(i))) volumes[i]->IntegratePosition(ctx.h);
}

void PhysicsSystem::ApplyLinearProjection(const StepContext& ctx) {
    // Positional correction (docs/book-reference.md §3.4 step 5) with the manifolds found before integration. Depth is
    // the full penetration for every pair type (CollisionManifold::depth).
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
        const float depth = std::max(m.depth - ctx.settings.penetrationSlop, 0.0f);
        const vec3 correction = m.normal * (depth / invSum * ctx.settings.projectionFraction);
        a.position -= correction * invA;
        b.position += correction * invB;
        a.SynchCollisionVolumes();
        b.SynchCollisionVolumes();
    }
}
