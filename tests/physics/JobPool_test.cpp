// The job pool (Physics/JobPool.h) and the promise it exists for: a world's state is the same bits on any number of
// threads (docs/threads.md). The peer scenes are large enough that every parallel pass has several chunks: a pile of
// 1,500 cubes (three chunks of bodies, dozens of candidate chunks, several blocks of the soft solve), a pyramid of 30
// (one island: one block) and a tower of 20.
#include "Physics/JobPool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"

namespace {

TEST(JobPool, RunsEveryJobExactlyOnceOnAnyThreadCount) {
    for (int threads = 1; threads <= 4; ++threads) {
        JobPool pool(threads);
        EXPECT_EQ(pool.Threads(), threads);
        for (std::size_t count : {0u, 1u, 2u, 7u, 1000u}) {
            std::vector<std::atomic<int>> runs(count);
            for (int round = 0; round < 3; ++round) pool.ForEach(count, [&](std::size_t i) { ++runs[i]; });
            for (std::size_t i = 0; i < count; ++i) EXPECT_EQ(runs[i].load(), 3) << threads << " threads, job " << i;
        }
    }
}

TEST(JobPool, OneThreadRunsTheJobsInOrderOnTheCaller) {
    JobPool pool(1);
    std::vector<std::size_t> order;
    pool.ForEach(5, [&](std::size_t i) { order.push_back(i); });
    EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
}

TEST(JobPool, ACallFromInsideAJobRunsInlineInsteadOfWaitingOnItself) {
    JobPool pool(3);
    std::atomic<int> inner{0};
    pool.ForEach(4, [&](std::size_t) { pool.ForEach(10, [&](std::size_t) { ++inner; }); });
    EXPECT_EQ(inner.load(), 40);
}

TEST(JobPool, ChunksCoverTheRangeOnceWhateverThePool) {
    JobPool pool(3);
    for (JobPool* jobs : {static_cast<JobPool*>(nullptr), &pool}) {
        std::vector<std::atomic<int>> hits(1001);
        ForEachChunk(jobs, hits.size(), 64, [&](std::size_t begin, std::size_t end) {
            EXPECT_EQ(begin % 64, 0u);
            for (std::size_t i = begin; i < end; ++i) ++hits[i];
        });
        for (const std::atomic<int>& h : hits) EXPECT_EQ(h.load(), 1);
    }
    EXPECT_EQ(ChunkCount(0, 64), 0u);
    EXPECT_EQ(ChunkCount(64, 64), 1u);
    EXPECT_EQ(ChunkCount(65, 64), 2u);
}

/// Every body's position, orientation and velocities after `steps` steps of 1/60 s on `threads` threads, as bytes.
std::vector<unsigned char> StateAfter(const std::vector<BodySpec>& specs, ContactSolver solver, int threads,
                                      int steps) {
    RigidWorld world(specs);
    world.system.settings.contactSolver = solver;
    world.system.settings.threads = threads;
    for (int s = 0; s < steps; ++s) world.system.Update(1.0f / 60.0f);
    std::vector<unsigned char> bytes;
    for (std::size_t i = 0; i < world.Bodies().size(); ++i) {
        const RigidbodyVolume& b = world.Body(i);
        const float values[13] = {b.position.x,    b.position.y,    b.position.z, b.orientation.x, b.orientation.y,
                                  b.orientation.z, b.orientation.w, b.velocity.x, b.velocity.y,    b.velocity.z,
                                  b.angVel.x,      b.angVel.y,      b.angVel.z};
        const unsigned char* p = reinterpret_cast<const unsigned char*>(values);
        bytes.insert(bytes.end(), p, p + sizeof values);
    }
    return bytes;
}

void ExpectSameBitsOnOneTwoAndThreeThreads(const std::vector<BodySpec>& specs, ContactSolver solver, int steps) {
    const std::vector<unsigned char> one = StateAfter(specs, solver, 1, steps);
    EXPECT_EQ(StateAfter(specs, solver, 2, steps), one) << "2 threads";
    EXPECT_EQ(StateAfter(specs, solver, 3, steps), one) << "3 threads";
}

TEST(Threads, ABoxPileOfSoftContactsEndsInTheSameBitsOnOneTwoAndThreeThreads) {
    ExpectSameBitsOnOneTwoAndThreeThreads(PeerBoxpile(1500), ContactSolver::Soft, 90);
}

TEST(Threads, ABoxPileOfAccumulatedContactsEndsInTheSameBitsOnOneTwoAndThreeThreads) {
    ExpectSameBitsOnOneTwoAndThreeThreads(PeerBoxpile(1500), ContactSolver::Accumulated, 40);
}

TEST(Threads, APyramidAndATowerEndInTheSameBitsOnOneTwoAndThreeThreads) {
    ExpectSameBitsOnOneTwoAndThreeThreads(PeerPyramid(30), ContactSolver::Soft, 60);
    ExpectSameBitsOnOneTwoAndThreeThreads(PeerTower(20), ContactSolver::Soft, 60);
}

TEST(Threads, ThePileUsesSeveralBlocksSoTheSolveIsSplit) {
    RigidWorld world(PeerBoxpile(1500));
    world.system.settings.contactSolver = ContactSolver::Soft;
    for (int s = 0; s < 90; ++s) world.system.Update(1.0f / 60.0f);
    EXPECT_GE(world.system.SoftSolver().Blocks().size(), 3u);
}

}  // namespace
