#pragma once
// The rigid volumes' part of a step that the contact solvers share (docs/architecture.md, "One step"): pair search
// (exact, or with boxes grown for the soft step), gravity, integration, linear projection, the volume substep count,
// islands and sleep, and the colliding pairs a step found. PhysicsSystem owns one and hands it to its contact solver
// (IContactSolver.h), which steps the volumes with these stages; neither includes PhysicsSystem.h.
//
// Stages run once per volume substep of ctx.h seconds. `sleep` is null with settings.sleep off; otherwise sleeping
// volumes are not moved and only pairs with an active body are tested.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "Math/vectors.h"
#include "Physics/Broadphase.h"
#include "Physics/Geometry/Geometry3D.h"
#include "Physics/Islands.h"

class RigidbodyVolume;
struct StepContext;

/// A colliding pair found this step, with its manifold (normal from a to b).
struct CollisionPair {
    RigidbodyVolume* a = nullptr;
    RigidbodyVolume* b = nullptr;
    int indexA = -1, indexB = -1;  ///< positions of a and b in PhysicsSystem::Volumes() (indexA < indexB)
    CollisionManifold manifold;
};

class VolumeStages {
public:
    /// `volumes` is the world's list (kept by reference, in the world's order); warnings go to `lastError`.
    VolumeStages(const std::vector<RigidbodyVolume*>& volumes, std::string& lastError)
        : volumes(volumes), lastError(lastError) {}
    VolumeStages(const VolumeStages&) = delete;
    VolumeStages& operator=(const VolumeStages&) = delete;

    /// Pair search with manifolds; fills results[0..resultCount). With sleep, a contact between an active and a
    /// sleeping body wakes the sleeping island and the search runs again.
    void FindCollisions(const StepContext& ctx, Islands* sleep);
    /// One pair search: every pair that can interact and, when `active` is given (one byte per volume), has an active
    /// body; fills results[0..resultCount) in increasing (indexA, indexB) order. Over settings.maxPairs: no
    /// results, and stopReason set.
    void FindPairs(const StepContext& ctx, const unsigned char* active);
    /// The soft step's search: candidatePairs gets every pair that can interact, has an active body (`active`, as
    /// above) and whose boxes, each grown by `margin` and its body's travel over ctx.dt, overlap; in increasing order.
    /// Over settings.maxPairs: stopReason set.
    void FindGrownPairs(const StepContext& ctx, const unsigned char* active, float margin);
    /// Gravity on every volume, turned into this substep's velocity change before the impulses (ch15 note N1).
    void ApplyVolumeForces(const StepContext& ctx, const Islands* sleep);
    void IntegrateVolumes(const StepContext& ctx, const Islands* sleep);
    /// Positional correction of results[0..resultCount) (docs/book-reference.md §3.4 step 5).
    void ApplyLinearProjection(const StepContext& ctx);
    /// Number of equal volume substeps for a step of ctx.dt (1..settings.maxVolumeSubsteps); writes a warning to
    /// lastError when clamped.
    int VolumeSubsteps(const StepContext& ctx);
    /// A step of a world without volumes: no pairs, one substep counted.
    void SkipStep();
    /// Forgets the last step's pairs and any stop (the world's bodies were cleared).
    void Reset();

    const std::vector<RigidbodyVolume*>& volumes;
    // Capacity reused; only [0, resultCount) is valid. Mutable: a solver may fill them when Collisions() is first
    // read after its step (collisionsPending; IContactSolver::FillCollisions).
    mutable std::vector<CollisionPair> results;
    mutable std::size_t resultCount = 0;
    mutable bool collisionsPending = false;
    std::vector<std::pair<int, int>> candidatePairs;  // broadphase output, capacity reused
    Islands islands;                                  // settings.sleep: islands, sleep times, sleeping bodies
    long long substepSerial = 0;  // volume substeps so far (one per step without volumes): StepContext::substepSerial
    int lastVolumeSubsteps = 1;
    /// Why the world stopped (a pair search passed settings.maxPairs); empty while it runs.
    std::string stopReason;

private:
    /// Sets stopReason for a search that passed settings.maxPairs.
    void StopAtPairLimit(const StepContext& ctx);

    std::string& lastError;
    Broadphase broadphase;  // used only from settings.broadphaseMinVolumes volumes up
    struct GrownBounds {
        vec3 min, max;
        bool hasVolume = false, dynamic = false;  // CanInteract's two tests of the body, once per search
    };
    std::vector<GrownBounds> smallWorldBounds;  // soft step below broadphaseMinVolumes: grown boxes, capacity reused
};
