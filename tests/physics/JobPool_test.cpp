// The job pool (Physics/JobPool.h) and the promise it exists for: a world's state is the same bits on any number of
// threads (docs/threads.md). The peer scenes are large enough that every parallel pass has several chunks: a pile of
// 1,500 cubes (three chunks of bodies, dozens of candidate chunks, several blocks of the soft solve), a pyramid of 30
// (one island: one block) and a tower of 20.
#include "Physics/JobPool.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <thread>
#include <vector>

#include "Demos/Scenes/WorldBuilder.h"
#include "Physics/PhysicsSystem.h"
#include "Physics/RigidbodyVolume.h"
#include "tests/support/Volumes.h"

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

// A pool of two really runs two jobs at once: each job waits (up to 10 s) until the other has started, which a pool
// that ran its jobs one after the other on the caller would never let happen.
TEST(JobPool, TwoThreadsRunTwoJobsAtOnce) {
    JobPool pool(2);
    std::atomic<int> started{0};
    std::atomic<int> metTheOther{0};
    pool.ForEach(2, [&](std::size_t) {
        ++started;
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (started.load() < 2 && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
        if (started.load() == 2) ++metTheOther;
    });
    EXPECT_EQ(metTheOther.load(), 2);
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
    return Snapshot(world.Bodies());
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
