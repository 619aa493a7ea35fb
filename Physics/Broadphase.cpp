#include "Physics/Broadphase.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "Physics/JobPool.h"
#include "Physics/RigidbodyVolume.h"

void VolumeBounds(const RigidbodyVolume& body, vec3* outMin, vec3* outMax) {
    vec3 extent;
    if (body.type == RigidbodyType::Sphere) {
        const float r = body.sphere.radius;
        extent = vec3(r, r, r);
        *outMin = body.sphere.position - extent;
        *outMax = body.sphere.position + extent;
        return;
    }
    if (body.type == RigidbodyType::Box) {
        // Half extent along world axis i: sum over local axes k of |axis_k[i]| * size_k.
        const mat3& R = body.box.orientation;
        for (int i = 0; i < 3; ++i)
            extent[i] = std::fabs(R[0][i]) * body.box.size.x + std::fabs(R[1][i]) * body.box.size.y +
                        std::fabs(R[2][i]) * body.box.size.z;
        *outMin = body.box.position - extent;
        *outMax = body.box.position + extent;
        return;
    }
    *outMin = body.position;
    *outMax = body.position;
}

namespace {

/// Cell side over the median body's largest AABB side: most bodies then cover one or two cells per axis.
constexpr float kCellScale = 1.0f;
/// Cells per axis a body may cover and still enter the grid; a wider one is compared with every body.
constexpr float kMaxCellSpan = 4.0f;
/// Cell coordinates are clamped to [-kCellLimit, kCellLimit - 1] (21 bits each in a cell key), so far bodies
/// share border cells instead of overflowing.
constexpr int kCellBits = 21;
constexpr float kCellLimit = static_cast<float>(1 << (kCellBits - 1));
/// Bodies per job of the per-body loops, and hash buckets per job of the cell scan: fixed sizes, never derived
/// from the thread count (docs/threads.md).
constexpr std::size_t kBodyChunk = 512;
constexpr std::size_t kBucketChunk = 2048;

/// Runs body(i) for every i in [0, n), in chunks of kBodyChunk on `jobs` (in order on this thread without).
template <typename Body>
void ForEachBody(JobPool* jobs, int n, Body&& body) {
    ForEachChunk(jobs, static_cast<std::size_t>(n), kBodyChunk, [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) body(static_cast<int>(i));
    });
}

/// Resizes *v to `size`, growing its capacity geometrically so a count that creeps up step by step does not
/// reallocate every step.
template <typename T>
void GrowTo(std::vector<T>* v, std::size_t size) {
    if (v->capacity() < size) v->reserve(std::max(size, 2 * v->capacity()));
    v->resize(size);
}

/// Cell coordinate of a finite x, offset to be non-negative.
std::uint64_t CellCoordinate(float x, float inverseCell) {
    float c = std::floor(x * inverseCell);
    c = c < -kCellLimit ? -kCellLimit : c;
    c = c > kCellLimit - 1.0f ? kCellLimit - 1.0f : c;
    return static_cast<std::uint64_t>(c + kCellLimit);
}

std::uint64_t CellKey(std::uint64_t x, std::uint64_t y, std::uint64_t z) {
    return x << (2 * kCellBits) | y << kCellBits | z;
}

/// The AABB test of an all-pairs loop (separated on an axis when one box ends before the other begins), without
/// branches.
template <typename B>
bool Overlap(const B& a, const B& b) {
    return (static_cast<int>(!(a.max.x < b.min.x)) & static_cast<int>(!(b.max.x < a.min.x)) &
            static_cast<int>(!(a.max.y < b.min.y)) & static_cast<int>(!(b.max.y < a.min.y)) &
            static_cast<int>(!(a.max.z < b.min.z)) & static_cast<int>(!(b.max.z < a.min.z))) != 0;
}

}  // namespace

bool Broadphase::FindPairs(const std::vector<RigidbodyVolume*>& volumes, std::vector<std::pair<int, int>>* pairs,
                           const unsigned char* active, float margin, float sweepTime, std::size_t maxPairs,
                           JobPool* jobs) {
    pairs->clear();
    raw.clear();
    const int n = static_cast<int>(volumes.size());
    // A body moves when it is active (with sleep) or dynamic. Every pair needs a moving body: a world that is all
    // asleep (or all static) has none, and costs one pass.
    auto moves = [&](int i) {
        return active != nullptr ? active[i] != 0 : volumes[static_cast<std::size_t>(i)]->mass > 0.0f;
    };
    bool anyMoving = false;
    for (int i = 0; i < n && !anyMoving; ++i) anyMoving = moves(i);
    if (!anyMoving) return true;
    bodies.resize(static_cast<std::size_t>(n));
    cellRanges.resize(static_cast<std::size_t>(n));
    ForEachBody(jobs, n, [&](int i) {
        const RigidbodyVolume& volume = *volumes[static_cast<std::size_t>(i)];
        Body& body = bodies[static_cast<std::size_t>(i)];
        VolumeBounds(volume, &body.min, &body.max);
        if (margin > 0.0f || sweepTime > 0.0f) {
            const float grow = margin + std::sqrt(MagnitudeSq(volume.velocity)) * sweepTime;
            body.min -= vec3(grow, grow, grow);
            body.max += vec3(grow, grow, grow);
        }
        body.moving = moves(i);
    });
    BuildGrid(n, jobs);
    if (!PairsInCells(&raw, maxPairs, jobs) || !PairsWithWideBodies(n, &raw, maxPairs)) {
        raw.clear();
        return false;
    }

    // Increasing (i, j) order: a counting sort on i, then each i's few partners sorted by j.
    firstCount.assign(static_cast<std::size_t>(n) + 1, 0);
    for (const std::pair<int, int>& p : raw) ++firstCount[static_cast<std::size_t>(p.first) + 1];
    for (int i = 0; i < n; ++i) firstCount[static_cast<std::size_t>(i) + 1] += firstCount[static_cast<std::size_t>(i)];
    GrowTo(pairs, raw.size());
    for (const std::pair<int, int>& p : raw)
        (*pairs)[static_cast<std::size_t>(firstCount[static_cast<std::size_t>(p.first)]++)] = p;
    // firstCount[i] is now the end of i's run.
    int runBegin = 0;
    for (int i = 0; i < n; ++i) {
        const int runEnd = firstCount[static_cast<std::size_t>(i)];
        if (runEnd - runBegin > 1) std::sort(pairs->begin() + runBegin, pairs->begin() + runEnd);
        runBegin = runEnd;
    }
    return true;
}

void Broadphase::BuildGrid(int n, JobPool* jobs) {
    // Cell side: kCellScale times the median largest AABB side of the bodies with finite bounds (1 m if none
    // has a positive one), a pure function of the bounds.
    extents.clear();
    for (const Body& body : bodies) {
        const float side =
            std::fmax(body.max.x - body.min.x, std::fmax(body.max.y - body.min.y, body.max.z - body.min.z));
        if (std::isfinite(side)) extents.push_back(side);
    }
    float cell = 0.0f;
    if (!extents.empty()) {
        const auto middle = extents.begin() + static_cast<std::ptrdiff_t>(extents.size() / 2);
        std::nth_element(extents.begin(), middle, extents.end());
        cell = kCellScale * *middle;
    }
    if (!(cell > 0.0f) || !std::isfinite(cell)) cell = 1.0f;
    const float inverseCell = 1.0f / cell;

    // Cell ranges. Floor and clamp are monotonic, so two AABBs that overlap on an axis get cell ranges that
    // overlap there too. A body whose range is wider than kMaxCellSpan cells on an axis, inverted (min > max, from
    // a negative growth) or not finite (the test below fails for NaN and infinity) is compared with every body.
    cellCounts.resize(static_cast<std::size_t>(n));
    ForEachBody(jobs, n, [&](int i) {
        Body& body = bodies[static_cast<std::size_t>(i)];
        body.wide = false;
        for (int k = 0; k < 3; ++k) {
            const float first = std::floor(body.min[k] * inverseCell), last = std::floor(body.max[k] * inverseCell);
            if (!(last - first >= 0.0f && last - first < kMaxCellSpan)) body.wide = true;
        }
        std::size_t cells = 0;
        if (!body.wide) {
            CellRange& range = cellRanges[static_cast<std::size_t>(i)];
            cells = 1;
            for (int k = 0; k < 3; ++k) {
                range.min[k] = CellCoordinate(body.min[k], inverseCell);
                range.max[k] = CellCoordinate(body.max[k], inverseCell);
                cells *= static_cast<std::size_t>(range.max[k] - range.min[k] + 1);
            }
        }
        cellCounts[static_cast<std::size_t>(i)] = cells;
    });
    wide.clear();
    entryFirst.resize(static_cast<std::size_t>(n) + 1);
    std::size_t entryCount = 0;
    for (int i = 0; i < n; ++i) {
        if (bodies[static_cast<std::size_t>(i)].wide) wide.push_back(i);
        entryFirst[static_cast<std::size_t>(i)] = entryCount;
        entryCount += cellCounts[static_cast<std::size_t>(i)];
    }
    entryFirst[static_cast<std::size_t>(n)] = entryCount;
    SortEntries(n, entryCount, jobs);
}

void Broadphase::SortEntries(int n, std::size_t entryCount, JobPool* jobs) {
    // Counting sort of the (cell, body) entries by a hash of the cell, so that each bucket lists its bodies in
    // increasing index order. An entry's flags say on which axes the body's range starts at this cell (bits 0-2)
    // and whether the body moves (bit 3). Each body's entries and their buckets are made first, in chunks of bodies
    // on the step's threads (body i's at entryFirst[i]); the count and the placing stay on one thread, and read
    // them in order: the same buckets, in the same order, as one pass computing them gives.
    int bucketBits = 4;
    while ((std::size_t{1} << bucketBits) < entryCount) ++bucketBits;
    const std::size_t bucketCount = std::size_t{1} << bucketBits;
    if (stagedEntries.size() < entryCount) GrowTo(&stagedEntries, entryCount);
    if (entryBuckets.size() < entryCount) GrowTo(&entryBuckets, entryCount);
    ForEachBody(jobs, n, [&](int i) {
        const Body& body = bodies[static_cast<std::size_t>(i)];
        if (body.wide) return;
        const CellRange& range = cellRanges[static_cast<std::size_t>(i)];
        const unsigned moving = body.moving ? 8u : 0u;
        std::size_t e = entryFirst[static_cast<std::size_t>(i)];
        for (std::uint64_t z = range.max[2] + 1; z-- > range.min[2];)
            for (std::uint64_t y = range.max[1] + 1; y-- > range.min[1];)
                for (std::uint64_t x = range.max[0] + 1; x-- > range.min[0];) {
                    const unsigned starts = static_cast<unsigned>(x == range.min[0]) |
                                            static_cast<unsigned>(y == range.min[1]) << 1 |
                                            static_cast<unsigned>(z == range.min[2]) << 2;
                    const std::uint64_t key = CellKey(x, y, z);
                    stagedEntries[e] = {key, i, starts | moving};
                    entryBuckets[e++] = static_cast<std::uint32_t>((key * 0x9E3779B97F4A7C15ull) >> (64 - bucketBits));
                }
    });
    bucketStart.assign(bucketCount + 1, 0);
    for (std::size_t e = 0; e < entryCount; ++e) ++bucketStart[entryBuckets[e]];
    for (std::size_t b = 1; b <= bucketCount; ++b) bucketStart[b] += bucketStart[b - 1];
    if (cellEntries.size() < entryCount) GrowTo(&cellEntries, entryCount);
    // Filled backwards by body (each body's own entries in their order), so each bucket lists its bodies in
    // increasing index order.
    for (int i = n - 1; i >= 0; --i) {
        const std::size_t last = entryFirst[static_cast<std::size_t>(i) + 1];
        for (std::size_t e = entryFirst[static_cast<std::size_t>(i)]; e < last; ++e)
            cellEntries[static_cast<std::size_t>(--bucketStart[entryBuckets[e]])] = stagedEntries[e];
    }
    // bucketStart[b] is now the first entry of bucket b, bucketStart[bucketCount] the entry count.
}

bool Broadphase::PairsInCells(std::vector<std::pair<int, int>>* out, std::size_t maxPairs, JobPool* jobs) {
    const std::size_t bucketCount = bucketStart.size() - 1;
    std::atomic<std::size_t> found{out->size()};
    if (jobs == nullptr || jobs->Threads() == 1) return PairsInBuckets(0, bucketCount, out, &found, maxPairs);
    const std::size_t chunks = ChunkCount(bucketCount, kBucketChunk);
    if (chunkPairs.size() < chunks) chunkPairs.resize(chunks);
    std::atomic<bool> over{false};
    jobs->ForEach(chunks, [&](std::size_t c) {
        std::vector<std::pair<int, int>>& list = chunkPairs[c];
        list.clear();
        if (!PairsInBuckets(c * kBucketChunk, std::min(bucketCount, (c + 1) * kBucketChunk), &list, &found, maxPairs))
            over.store(true, std::memory_order_relaxed);
    });
    if (over.load()) return false;
    for (std::size_t c = 0; c < chunks; ++c) out->insert(out->end(), chunkPairs[c].begin(), chunkPairs[c].end());
    return true;
}

bool Broadphase::PairsInBuckets(std::size_t begin, std::size_t end, std::vector<std::pair<int, int>>* out,
                                std::atomic<std::size_t>* found, std::size_t maxPairs) const {
    // Two bodies sharing several cells are reported once, from the low corner of their common range: the cell
    // where, on every axis, one of the two ranges starts. With the moving bit, the two entries' flags together
    // must have all four bits set. `found` counts every chunk's pairs, bucket by bucket, so the search stops soon
    // after the limit is passed in any chunk.
    for (std::size_t b = begin; b < end; ++b) {
        const std::size_t before = out->size();
        const int last = bucketStart[b + 1];
        for (int p = bucketStart[b]; p < last; ++p) {
            const CellEntry& ea = cellEntries[static_cast<std::size_t>(p)];
            const Body& a = bodies[static_cast<std::size_t>(ea.body)];
            for (int q = p + 1; q < last; ++q) {
                const CellEntry& eb = cellEntries[static_cast<std::size_t>(q)];
                if ((ea.flags | eb.flags) != 15u || ea.key != eb.key) continue;
                if (!Overlap(a, bodies[static_cast<std::size_t>(eb.body)])) continue;
                out->emplace_back(ea.body, eb.body);
                if (out->size() - before > maxPairs) return false;
            }
        }
        const std::size_t added = out->size() - before;
        if (added > 0 && found->fetch_add(added, std::memory_order_relaxed) + added > maxPairs) return false;
    }
    return true;
}

bool Broadphase::PairsWithWideBodies(int n, std::vector<std::pair<int, int>>* out, std::size_t maxPairs) const {
    for (const int w : wide) {
        const Body& a = bodies[static_cast<std::size_t>(w)];
        for (int j = 0; j < n; ++j) {
            const Body& b = bodies[static_cast<std::size_t>(j)];
            if (j == w || (b.wide && j < w) || (!a.moving && !b.moving)) continue;  // a wide pair once, from its first
            if (!Overlap(a, b)) continue;
            out->emplace_back(std::min(w, j), std::max(w, j));
            if (out->size() > maxPairs) return false;
        }
    }
    return true;
}
