#pragma once
// Uniform-grid broadphase for scenes with many volumes: every grown AABB is entered into the cubic cells it covers
// (a hashed 3-D grid, rebuilt each call by a counting sort), and only bodies sharing a cell are compared, so a pile
// spread over x and z costs about O(n) instead of a sweep's O(n * bodies in the same x band). A body that covers
// too many cells (a ground plate, a non-finite AABB) is kept out of the grid and compared with every body.
// Small scenes never use it: PhysicsSystem tests all pairs below WorldSettings::broadphaseMinVolumes.

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "Physics/Geometry/Geometry3D.h"

class JobPool;
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
    /// own AABBs). The result depends only on the arguments (no state carries over between calls). Allocation-free
    /// once the capacities have grown. Returns false, with *pairs empty, once more than maxPairs pairs are found
    /// (the search stops there, so memory stays within the limit). With `jobs`, the bounds, cell ranges and cell
    /// scans run in fixed chunks on its threads; the pairs are the same for any thread count (docs/threads.md).
    bool FindPairs(const std::vector<RigidbodyVolume*>& volumes, std::vector<std::pair<int, int>>* pairs,
                   const unsigned char* active = nullptr, float margin = 0.0f, float sweepTime = 0.0f,
                   std::size_t maxPairs = static_cast<std::size_t>(-1), JobPool* jobs = nullptr);

private:
    struct Body {
        vec3 min, max;
        bool moving = false;  // dynamic, or active in the mask
        bool wide = false;    // out of the grid: compared with every body
    };
    struct CellRange {
        std::uint64_t min[3] = {0, 0, 0};  // first cell covered on each axis, offset to be non-negative
        std::uint64_t max[3] = {0, 0, 0};  // last cell covered on each axis
    };
    struct CellEntry {
        std::uint64_t key = 0;  // the cell's three coordinates, packed
        int body = 0;
        unsigned flags = 0;  // bit k (0-2): the body's range starts at this cell on axis k; bit 3: the body moves
    };
    void BuildGrid(int n, JobPool* jobs);
    /// The grid's cell entries grouped by hash bucket into cellEntries and bucketStart (BuildGrid's last part).
    void SortEntries(int n, std::size_t entryCount, JobPool* jobs);
    /// Pairs found in the cells of hash buckets [begin, end), appended to *out; stops once `found` (shared by every
    /// chunk of buckets) passes maxPairs (false then).
    bool PairsInBuckets(std::size_t begin, std::size_t end, std::vector<std::pair<int, int>>* out,
                        std::atomic<std::size_t>* found, std::size_t maxPairs) const;
    /// Every chunk of buckets on `jobs`, each into its own list, then the lists appended to *pairs in bucket
    /// order: the order a single scan gives. False once more than maxPairs pairs are found.
    bool PairsInCells(std::vector<std::pair<int, int>>* pairs, std::size_t maxPairs, JobPool* jobs);
    /// Appends to *pairs and stops once it holds more than maxPairs (false then).
    bool PairsWithWideBodies(int n, std::vector<std::pair<int, int>>* pairs, std::size_t maxPairs) const;

    std::vector<Body> bodies;                 // by volume index
    std::vector<CellRange> cellRanges;        // by volume index (grid bodies only)
    std::vector<float> extents;               // scratch: each body's largest AABB side, for the cell size
    std::vector<int> wide;                    // indices of the bodies kept out of the grid, increasing
    std::vector<int> bucketStart;             // per hash bucket: first slot in cellEntries (counting sort), + 1 end
    std::vector<CellEntry> cellEntries;       // (cell, body) for every covered cell, grouped by hash bucket
    std::vector<std::pair<int, int>> raw;     // pairs as found, before ordering
    std::vector<int> firstCount;              // scratch: pairs per first index, for the counting sort
    std::vector<std::size_t> cellCounts;      // per body: cells its range covers (0 for a wide body)
    std::vector<std::size_t> entryFirst;      // per body: its first entry in stagedEntries, + 1 end
    std::vector<CellEntry> stagedEntries;     // every body's entries in body order, before the counting sort
    std::vector<std::uint32_t> entryBuckets;  // per staged entry: its hash bucket
    std::vector<std::vector<std::pair<int, int>>> chunkPairs;  // per chunk of buckets: its pairs, capacity reused
};
