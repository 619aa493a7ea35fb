// The rigid-volume stages the contact solvers share (VolumeStages.h; docs/book-reference.md §3.4 steps 1, 2, 4, 5):
// pair search with manifolds, forces, integration, linear projection; the soft step's grown-box search.
#include "Physics/VolumeStages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "Physics/RigidbodyVolume.h"
#include "Physics/WorldSettings.h"

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

void VolumeStages::FindCollisions(const StepContext& ctx, Islands* sleep) {
    if (sleep == nullptr) {
        FindPairs(ctx, nullptr);
        return;
    }
    // A new contact of an active body with a sleeping one wakes that island; its bodies' contacts among themselves
    // (not tested while they slept) are then found by searching again. Each pass wakes at least one island.
    FindPairs(ctx, sleep->ActiveMask());
    while (sleep->WakeTouched(results.data(), resultCount) > 0) FindPairs(ctx, sleep->ActiveMask());
}

void VolumeStages::FindPairs(const StepContext& ctx, const unsigned char* active) {
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
        StopAtPairLimit(ctx);
        return;
    }
    for (const std::pair<int, int>& p : candidatePairs) {
        const std::size_t i = static_cast<std::size_t>(p.first), j = static_cast<std::size_t>(p.second);
        if (wanted(i, j)) test(i, j);
    }
}

void VolumeStages::StopAtPairLimit(const StepContext& ctx) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "step %lld: more than %zu pairs of volumes overlap, the limit of one pair search "
                  "(WorldSettings::maxPairs); stopped before allocating them (%zu volumes)",
                  ctx.step + 1, ctx.settings.maxPairs, volumes.size());
    stopReason = text;
}

void VolumeStages::FindGrownPairs(const StepContext& ctx, const unsigned char* active, float margin) {
    // The all-pairs loop asks for overlapping grown boxes, as the broadphase does: so a small world and a large
    // one find the same pairs, and the solver collides only pairs that can touch this step (in a column of 20
    // cubes, 19 + 1 of its 210 pairs). With sleep on, these pairs also decide which islands wake.
    candidatePairs.clear();
    const std::size_t count = volumes.size();
    if (count >= ctx.settings.broadphaseMinVolumes) {
        if (!broadphase.FindPairs(volumes, &candidatePairs, active, margin, ctx.dt, ctx.settings.maxPairs, ctx.jobs))
            StopAtPairLimit(ctx);
        return;
    }
    // Each body's box grown by the margin and its travel over the step, once per search (not once per pair).
    smallWorldBounds.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
        GrownBounds& g = smallWorldBounds[i];
        VolumeBounds(*volumes[i], &g.min, &g.max);
        const float grow = margin + Magnitude(volumes[i]->velocity) * ctx.dt;
        g.min -= vec3(grow, grow, grow);
        g.max += vec3(grow, grow, grow);
        g.hasVolume = volumes[i]->HasVolume();
        g.dynamic = volumes[i]->mass > 0.0f;
    }
    auto near = [&](std::size_t i, std::size_t j) {
        const GrownBounds& a = smallWorldBounds[i];
        const GrownBounds& b = smallWorldBounds[j];
        for (int k = 0; k < 3; ++k)
            if (a.min[k] > b.max[k] || b.min[k] > a.max[k]) return false;
        return true;
    };
    // CanInteract from the flags kept above (the same pairs in the same order).
    for (std::size_t i = 0; i < count; ++i) {
        const GrownBounds& a = smallWorldBounds[i];
        if (!a.hasVolume) continue;
        for (std::size_t j = i + 1; j < count; ++j) {
            const GrownBounds& b = smallWorldBounds[j];
            if (b.hasVolume && (a.dynamic || b.dynamic) && (active == nullptr || active[i] || active[j]) && near(i, j))
                candidatePairs.emplace_back(static_cast<int>(i), static_cast<int>(j));
        }
    }
}

void VolumeStages::ApplyVolumeForces(const StepContext& ctx, const Islands* sleep) {
    // ch15 note N1 (docs/ERRATA.md, Chapter 15): the book applies the impulses to the velocity of the previous step
    // and only then adds this step's gravity and moves the body, so the tangential part of g dt always
    // reaches the position before friction can see it: a box creeps down any incline at about g sin(theta) dt
    // (0.056 m/s at 20 degrees, 60 Hz) however large mu is, and a resting box is never at rest. The stage
    // order is kept (forces, impulses, integration), but the forces stage already turns this step's forces
    // into velocity (semi-implicit Euler's first half), so the impulses act on the velocity that will move
    // the body.
    // Sleeping bodies get no forces (their velocities stay zero); static ones run as without sleep.
    // VolumePositions::Average needs the velocity each body starts the substep with (IntegrateVolumes).
    const bool average = ctx.settings.volumePositions == VolumePositions::Average;
    for (std::size_t i = 0; i < volumes.size(); ++i) {
        if (sleep != nullptr && !sleep->IsAwake(static_cast<int>(i))) continue;
        volumes[i]->ApplyForces();
        if (average) volumes[i]->startVelocity = volumes[i]->velocity;
        volumes[i]->IntegrateVelocity(ctx.h);
    }
}

int VolumeStages::VolumeSubsteps(const StepContext& ctx) {
    // Volumes have no continuous collision: contacts are found at the start of a step, so a body that moves
    // further than its own half extent plus the other's in one step passes a slab's mid plane, and the manifold
    // then pushes it out of the far side (a 0.5 s step drops a resting box 1.2 m). Per dynamic
    // volume, the travel bound |v| dt + |g| dt^2 / 2 is compared with its own half extent plus the thinnest half
    // extent in the world (the thinnest thing it could meet); n keeps every substep's travel within
    // settings.substepTravelFraction of that sum. Spin is not counted. One pass over the volumes; n = 1 at the book's
    // 0.03 s in all its demos (ch15: ratio 0.23, momentum: 0.52 at the 20 m/s launch).
    const WorldSettings& settings = ctx.settings;
    const float dt = ctx.dt;
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

void VolumeStages::IntegrateVolumes(const StepContext& ctx, const Islands* sleep) {
    const VolumePositions mode = ctx.settings.volumePositions;
    if (sleep == nullptr) {
        for (RigidbodyVolume* body : volumes) body->IntegratePosition(ctx.h, mode);
        return;
    }
    for (std::size_t i = 0; i < volumes.size(); ++i)
        if (sleep->IsAwake(static_cast<int>(i))) volumes[i]->IntegratePosition(ctx.h, mode);
}

void VolumeStages::ApplyLinearProjection(const StepContext& ctx) {
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

void VolumeStages::SkipStep() {
    resultCount = 0;
    lastVolumeSubsteps = 1;
    ++substepSerial;
}

void VolumeStages::Reset() {
    resultCount = 0;
    collisionsPending = false;
    stopReason.clear();  // a new world may run again
}
