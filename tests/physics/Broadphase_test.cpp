// Grid broadphase: same pairs, in the same order, as a brute-force all-pairs AABB test (own and grown AABBs, huge,
// far, touching and sleeping bodies), and the same simulation as the all-pairs loop.
#include "Physics/Broadphase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Math/Random.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

namespace {

std::vector<RigidbodyVolume> RandomBodies(int count, uint32_t seed) {
    MsvcRand rng(seed);
    std::vector<BodySpec> specs = {GroundSpec(vec3(30, 0.5f, 30))};
    for (int i = 0; i < count; ++i) {
        BodySpec b;
        b.shape = i % 3 == 0 ? RigidbodyType::Sphere : RigidbodyType::Box;
        b.position = vec3(rng.Range(-6, 6), rng.Range(0.5f, 12), rng.Range(-6, 6));
        b.eulerRadians = vec3(rng.Range(-1, 1), rng.Range(-1, 1), rng.Range(-1, 1));
        b.mass = i % 10 == 9 ? 0.0f : 1.0f;  // a few static obstacles
        specs.push_back(b);
    }
    return MakeBodies(specs);
}

bool Overlap(const RigidbodyVolume& a, const RigidbodyVolume& b) {
    vec3 amin, amax, bmin, bmax;
    VolumeBounds(a, &amin, &amax);
    VolumeBounds(b, &bmin, &bmax);
    for (int i = 0; i < 3; ++i)
        if (amax[i] < bmin[i] || bmax[i] < amin[i]) return false;
    return true;
}

/// The all-pairs reference of FindPairs' contract: AABBs grown by margin + speed * sweepTime, touching counts,
/// at least one body moving (active byte, or mass > 0 without a mask), increasing (i, j).
std::vector<std::pair<int, int>> AllPairs(const std::vector<RigidbodyVolume*>& volumes, const unsigned char* active,
                                          float margin, float sweepTime) {
    const int n = static_cast<int>(volumes.size());
    std::vector<vec3> mins(volumes.size()), maxs(volumes.size());
    for (int i = 0; i < n; ++i) {
        VolumeBounds(*volumes[i], &mins[i], &maxs[i]);
        if (margin > 0.0f || sweepTime > 0.0f) {
            const float grow = margin + std::sqrt(MagnitudeSq(volumes[i]->velocity)) * sweepTime;
            mins[i] -= vec3(grow, grow, grow);
            maxs[i] += vec3(grow, grow, grow);
        }
    }
    auto moving = [&](int i) { return active != nullptr ? active[i] != 0 : volumes[i]->mass > 0.0f; };
    std::vector<std::pair<int, int>> out;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            if (!moving(i) && !moving(j)) continue;
            bool separated = false;
            for (int k = 0; k < 3; ++k) separated = separated || maxs[i][k] < mins[j][k] || maxs[j][k] < mins[i][k];
            if (!separated) out.emplace_back(i, j);
        }
    return out;
}

/// A randomized scene: a 100 m static ground and a few other huge plates and bars (static and dynamic), unit boxes
/// on an integer lattice so that many faces touch exactly, rotated boxes and spheres of mixed sizes, some static,
/// some far away, each with a random velocity (for the growth by speed * sweepTime).
std::vector<RigidbodyVolume> RandomScene(int count, uint32_t seed) {
    MsvcRand rng(seed);
    std::vector<BodySpec> specs = {GroundSpec(vec3(100, 0.5f, 100))};
    specs.push_back(BoxSpec(vec3(0, 3, 0), vec3(40, 0.2f, 0.2f), 0.0f));   // a long static bar
    specs.push_back(BoxSpec(vec3(5, 6, -5), vec3(0.3f, 0.3f, 30), 5.0f));  // a long dynamic bar
    for (int i = 0; i < count; ++i) {
        BodySpec b;
        const int kind = rng.Next() % 8;
        if (kind < 3) {  // lattice cube: faces touch their neighbours exactly
            b.position = vec3(static_cast<float>(rng.Next() % 10 - 5), static_cast<float>(rng.Next() % 6) + 0.5f,
                              static_cast<float>(rng.Next() % 10 - 5));
            b.halfExtents = vec3(0.5f, 0.5f, 0.5f);
        } else if (kind < 6) {
            b.shape = kind == 5 ? RigidbodyType::Sphere : RigidbodyType::Box;
            b.position = vec3(rng.Range(-8, 8), rng.Range(0, 8), rng.Range(-8, 8));
            b.halfExtents = vec3(rng.Range(0.1f, 1.0f), rng.Range(0.1f, 1.0f), rng.Range(0.1f, 1.0f));
            b.radius = rng.Range(0.1f, 1.2f);
            b.eulerRadians = vec3(rng.Range(-1, 1), rng.Range(-1, 1), rng.Range(-1, 1));
        } else if (kind == 6) {  // a big one, in or out of the grid depending on the cell size
            b.position = vec3(rng.Range(-8, 8), rng.Range(0, 8), rng.Range(-8, 8));
            b.halfExtents = vec3(rng.Range(1, 6), rng.Range(0.2f, 2), rng.Range(1, 6));
        } else {  // far away (cells clamped at the grid's border)
            const float side = rng.Next() % 2 == 0 ? 1.0f : -1.0f;
            b.position = vec3(side * rng.Range(1e7f, 1e9f), rng.Range(0, 8), rng.Range(-1e9f, 1e9f));
            b.halfExtents = vec3(rng.Range(0.5f, 4e7f), 0.5f, 0.5f);
        }
        b.velocity = vec3(rng.Range(-20, 20), rng.Range(-20, 20), rng.Range(-20, 20));
        b.mass = rng.Next() % 5 == 0 ? 0.0f : 1.0f;
        specs.push_back(b);
    }
    return MakeBodies(specs);
}

}  // namespace

TEST(Broadphase, BoundsOfARotatedBox) {
    RigidbodyVolume b(RigidbodyType::Box);
    b.box.size = vec3(2, 1, 0.5f);
    b.SetEulerOrientation(vec3(0, 0, 3.14159265f / 2));  // local x along world y
    vec3 mn, mx;
    VolumeBounds(b, &mn, &mx);
    EXPECT_NEAR(mx.x, 1.0f, 1e-5f);
    EXPECT_NEAR(mx.y, 2.0f, 1e-5f);
    EXPECT_NEAR(mx.z, 0.5f, 1e-5f);
    EXPECT_NEAR(mn.y, -2.0f, 1e-5f);
}

TEST(Broadphase, FindsExactlyTheOverlappingPairsWithADynamicBody) {
    std::vector<RigidbodyVolume> bodies = RandomBodies(120, 7);
    std::vector<RigidbodyVolume*> ptrs;
    for (RigidbodyVolume& b : bodies) ptrs.push_back(&b);
    std::vector<std::pair<int, int>> expected;
    for (int i = 0; i < static_cast<int>(bodies.size()); ++i)
        for (int j = i + 1; j < static_cast<int>(bodies.size()); ++j)
            if ((bodies[i].mass > 0 || bodies[j].mass > 0) && Overlap(bodies[i], bodies[j]))
                expected.emplace_back(i, j);
    ASSERT_GT(expected.size(), 50u);
    Broadphase bp;
    std::vector<std::pair<int, int>> pairs;
    bp.FindPairs(ptrs, &pairs);
    EXPECT_EQ(pairs, expected);
    // Move every body and search again with the carried-over order.
    for (RigidbodyVolume& b : bodies) {
        b.position.x = -b.position.x * 0.9f;
        b.SynchCollisionVolumes();
    }
    expected.clear();
    for (int i = 0; i < static_cast<int>(bodies.size()); ++i)
        for (int j = i + 1; j < static_cast<int>(bodies.size()); ++j)
            if ((bodies[i].mass > 0 || bodies[j].mass > 0) && Overlap(bodies[i], bodies[j]))
                expected.emplace_back(i, j);
    bp.FindPairs(ptrs, &pairs);
    EXPECT_EQ(pairs, expected);
}

// With an active mask (islands and sleep), exactly the overlapping pairs with an active body: a body that does not
// move (static, or inactive in the mask) is paired only with active ones, so its sweep may skip its x neighbours.
TEST(Broadphase, ActiveMaskKeepsExactlyThePairsWithAnActiveBody) {
    std::vector<RigidbodyVolume> bodies = RandomBodies(120, 11);
    std::vector<RigidbodyVolume*> ptrs;
    for (RigidbodyVolume& b : bodies) ptrs.push_back(&b);
    std::vector<unsigned char> active(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) active[i] = bodies[i].mass > 0 && i % 4 != 1 ? 1 : 0;
    std::vector<std::pair<int, int>> expected;
    for (int i = 0; i < static_cast<int>(bodies.size()); ++i)
        for (int j = i + 1; j < static_cast<int>(bodies.size()); ++j)
            if ((active[i] || active[j]) && Overlap(bodies[i], bodies[j])) expected.emplace_back(i, j);
    ASSERT_GT(expected.size(), 30u);
    Broadphase bp;
    std::vector<std::pair<int, int>> pairs;
    bp.FindPairs(ptrs, &pairs, active.data());
    EXPECT_EQ(pairs, expected);
    // Nothing active: no pair at all (a fully asleep world tests nothing).
    std::fill(active.begin(), active.end(), 0);
    bp.FindPairs(ptrs, &pairs, active.data());
    EXPECT_TRUE(pairs.empty());
}

// The broadphase returns pairs in all-pairs order, so a scene gives bit-identical results either way.
TEST(Broadphase, SimulationMatchesAllPairsBitwise) {
    auto run = [](std::size_t threshold) {
        std::vector<RigidbodyVolume> bodies = RandomBodies(60, 3);
        PhysicsSystem system;
        system.settings.broadphaseMinVolumes = threshold;
        for (RigidbodyVolume& b : bodies) system.AddRigidbody(&b);
        for (int i = 0; i < 120; ++i) system.Update(1.0f / 60.0f);
        std::vector<float> state;
        for (const RigidbodyVolume& b : bodies)
            for (float f : {b.position.x, b.position.y, b.position.z, b.velocity.x, b.velocity.y, b.velocity.z,
                            b.orientation.x, b.orientation.y, b.orientation.z, b.orientation.w})
                state.push_back(f);
        return state;
    };
    const std::vector<float> sweep = run(0);
    const std::vector<float> all = run(1000);
    ASSERT_EQ(sweep.size(), all.size());
    EXPECT_EQ(std::memcmp(sweep.data(), all.data(), sweep.size() * sizeof(float)), 0);
}

// Randomized scenes against the all-pairs reference: own AABBs, grown ones (margin, speed * sweepTime), with and
// without an active mask, over several seeds and sizes; the result does not depend on earlier calls.
TEST(Broadphase, RandomScenesMatchAllPairs) {
    Broadphase bp;  // one object for every call: buffers and any carried-over state are reused
    std::size_t totalPairs = 0, activeMasks = 0;
    for (uint32_t seed = 1; seed <= 12; ++seed) {
        const int count = 40 + static_cast<int>(seed) * 37;
        std::vector<RigidbodyVolume> bodies = RandomScene(count, seed);
        std::vector<RigidbodyVolume*> ptrs;
        for (RigidbodyVolume& b : bodies) ptrs.push_back(&b);
        MsvcRand rng(seed * 101u);
        std::vector<unsigned char> active(bodies.size());
        for (unsigned char& a : active) a = rng.Next() % 3 != 0 ? 1 : 0;
        for (const float margin : {0.0f, 0.02f, 0.5f, -0.3f})  // negative: shrunk, some inverted
            for (const float sweepTime : {0.0f, 1.0f / 60.0f, 0.25f})
                for (const bool masked : {false, true}) {
                    const unsigned char* mask = masked ? active.data() : nullptr;
                    std::vector<std::pair<int, int>> pairs;
                    bp.FindPairs(ptrs, &pairs, mask, margin, sweepTime);
                    const std::vector<std::pair<int, int>> expected = AllPairs(ptrs, mask, margin, sweepTime);
                    ASSERT_EQ(pairs, expected)
                        << "seed " << seed << " margin " << margin << " sweep " << sweepTime << " masked " << masked;
                    totalPairs += pairs.size();
                    activeMasks += masked ? 1 : 0;
                }
    }
    EXPECT_GT(totalPairs, 20000u);  // the scenes are dense enough to test something
    EXPECT_EQ(activeMasks, 12u * 12u);
}

// Exactly touching faces count as overlapping, on every axis, also where the touching face lies on a cell border.
TEST(Broadphase, TouchingLatticeCubesArePairs) {
    std::vector<BodySpec> specs;
    for (int x = 0; x < 6; ++x)
        for (int y = 0; y < 6; ++y)
            for (int z = 0; z < 6; ++z)
                specs.push_back(BoxSpec(vec3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)),
                                        vec3(0.5f, 0.5f, 0.5f), (x + y + z) % 2 == 0 ? 1.0f : 0.0f));
    std::vector<RigidbodyVolume> bodies = MakeBodies(specs);
    std::vector<RigidbodyVolume*> ptrs;
    for (RigidbodyVolume& b : bodies) ptrs.push_back(&b);
    Broadphase bp;
    std::vector<std::pair<int, int>> pairs;
    bp.FindPairs(ptrs, &pairs);
    // Every cube touches its 26 lattice neighbours (faces, edges, corners) and every pair has a moving cube or two
    // static ones of equal parity: count the pairs of neighbours with at least one dynamic cube.
    std::size_t expected = 0;
    for (std::size_t i = 0; i < specs.size(); ++i)
        for (std::size_t j = i + 1; j < specs.size(); ++j) {
            const vec3 d = specs[i].position - specs[j].position;
            if (std::fabs(d.x) <= 1 && std::fabs(d.y) <= 1 && std::fabs(d.z) <= 1 &&
                (specs[i].mass > 0 || specs[j].mass > 0))
                ++expected;
        }
    EXPECT_EQ(pairs.size(), expected);
    EXPECT_EQ(pairs, AllPairs(ptrs, nullptr, 0.0f, 0.0f));
}

// A body too wide for the grid (the ground) and one with an infinite AABB (an infinite speed grows it without
// bound) are paired with every body they touch, once.
TEST(Broadphase, WideAndUnboundedBodiesPairWithEverything) {
    std::vector<RigidbodyVolume> bodies = RandomScene(200, 99);
    bodies[5].velocity = vec3(INFINITY, 0, 0);
    std::vector<RigidbodyVolume*> ptrs;
    for (RigidbodyVolume& b : bodies) ptrs.push_back(&b);
    Broadphase bp;
    std::vector<std::pair<int, int>> pairs;
    bp.FindPairs(ptrs, &pairs, nullptr, 0.02f, 1.0f / 60.0f);
    EXPECT_EQ(pairs, AllPairs(ptrs, nullptr, 0.02f, 1.0f / 60.0f));
    const std::size_t withUnbounded = std::count_if(
        pairs.begin(), pairs.end(), [](const std::pair<int, int>& p) { return p.first == 5 || p.second == 5; });
    EXPECT_EQ(withUnbounded, bodies.size() - 1);  // body 5 moves, so every other body pairs with it
}

// A search that would find more than maxPairs pairs stops at the limit and reports it, with no pairs (100 spheres
// at one point overlap in 4950 pairs); at the limit exactly, every pair is found.
TEST(Broadphase, StopsAtMaxPairs) {
    std::vector<RigidbodyVolume> bodies;
    for (int i = 0; i < 100; ++i) bodies.push_back(MakeSphere(vec3(0, 0, 0), 0.5f));
    std::vector<RigidbodyVolume*> ptrs;
    for (RigidbodyVolume& b : bodies) ptrs.push_back(&b);
    Broadphase bp;
    std::vector<std::pair<int, int>> pairs;
    EXPECT_TRUE(bp.FindPairs(ptrs, &pairs, nullptr, 0.0f, 0.0f, 4950));
    EXPECT_EQ(pairs.size(), 4950u);
    EXPECT_FALSE(bp.FindPairs(ptrs, &pairs, nullptr, 0.0f, 0.0f, 4949));
    EXPECT_TRUE(pairs.empty());
    // A wide body (a slab over many cells) is paired outside the grid, under the same limit.
    bodies.push_back(MakeGround(vec3(500, 1, 500)));
    ptrs.clear();
    for (RigidbodyVolume& b : bodies) ptrs.push_back(&b);
    EXPECT_TRUE(bp.FindPairs(ptrs, &pairs, nullptr, 0.0f, 0.0f, 5050));
    EXPECT_EQ(pairs.size(), 5050u);
    EXPECT_FALSE(bp.FindPairs(ptrs, &pairs, nullptr, 0.0f, 0.0f, 5049));
}
