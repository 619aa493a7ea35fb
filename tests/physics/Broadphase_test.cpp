// Sweep-and-prune: same pairs as a brute-force AABB test, and the same simulation as the all-pairs loop.
#include "Physics/Broadphase.h"

#include <gtest/gtest.h>

#include <algorithm>
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
