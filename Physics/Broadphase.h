#pragma once
// Sweep-and-prune on the world x axis (Baraff's sort-and-sweep) for scenes with many volumes. The sort order is
// kept between steps, so an insertion sort of a nearly sorted list costs O(n). Small scenes never use it:
// PhysicsSystem tests all pairs below WorldSettings::broadphaseMinVolumes.

#include <utility>
#include <vector>

#include "Physics/Geometry/Geometry3D.h"

class RigidbodyVolume;

/// World-space AABB of a sphere or box volume (min, max); a Base-type body gets an empty box at its position.
void VolumeBounds(const RigidbodyVolume& body, vec3* outMin, vec3* outMax);

class Broadphase {
public:
    /// Replaces *pairs with every (i, j), i < j, whose world AABBs overlap (touching counts) and where at least
    /// one body moves: is dynamic (mass > 0), or, when `active` is given (one byte per volume, islands and sleep),
    /// has active[i] != 0. In increasing (i, j) order so the solver sees the same order as an all-pairs loop.
    /// Indices are into `volumes`. Every AABB is first grown on each side by `margin` (m) plus the body's speed
    /// times `sweepTime` (s): the soft solver's speculative margin and the step's travel (both 0 test the bodies'
    /// own AABBs). Allocation-free once the capacities have grown.
    void FindPairs(const std::vector<RigidbodyVolume*>& volumes, std::vector<std::pair<int, int>>* pairs,
                   const unsigned char* active = nullptr, float margin = 0.0f, float sweepTime = 0.0f);

private:
    struct Entry {
        vec3 min, max;
        int index = 0;
        bool dynamic = false;
    };
    std::vector<Entry> entries;   // sorted by min.x; order carried over between calls
    std::vector<int> nextMoving;  // per sorted position k: the first position >= k whose body moves (n if none)
};
