#pragma once
// A small persistent pool of worker threads for the volume step (docs/threads.md). The caller hands it `count`
// independent jobs, job(0) .. job(count - 1), and takes part itself; the call returns when every job has run. Which
// thread runs which job is left to scheduling, so a job may only write to what belongs to it alone (its own chunk of
// an array, its own output slot); the caller merges the slots in job order afterwards. Callers cut their work into
// chunks of a fixed size (never a size derived from the thread count), so the results are the same bits for any
// thread count.
//
// A pool of one thread runs the jobs inline, in order, with no synchronisation: the single-thread path. So does a
// pool that is already running jobs (a call from inside a job, or from a second thread): the pool never nests and
// never blocks on itself.

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

class JobPool {
public:
    /// A pool that runs jobs on `threads` threads: the caller and threads - 1 workers (values below 1 count as 1).
    explicit JobPool(int threads);
    ~JobPool();
    JobPool(const JobPool&) = delete;
    JobPool& operator=(const JobPool&) = delete;

    /// Threads jobs run on, the caller included (>= 1).
    int Threads() const { return static_cast<int>(workers.size()) + 1; }

    /// Runs job(i) once for every i in [0, count), each on some thread of the pool, and returns when all have run.
    /// Inline and in order when count < 2, the pool has one thread, or the pool is already running jobs.
    template <typename Job>
    void ForEach(std::size_t count, Job&& job) {
        auto call = [](void* context, std::size_t i) { (*static_cast<std::remove_reference_t<Job>*>(context))(i); };
        Run(count, call, &job);
    }

    /// The process's pool of `threads` threads (threads < 1: DefaultThreadCount()), made on first use and kept
    /// until exit, so worlds that ask for the same count share one set of workers.
    static JobPool& Shared(int threads);

private:
    using Call = void (*)(void*, std::size_t);
    void Run(std::size_t count, Call call, void* context);
    /// Claims and runs jobs of the published job until none is left.
    void Work();
    void WorkerLoop();

    std::vector<std::thread> workers;
    std::mutex mutex;
    std::condition_variable wake;
    std::atomic<bool> running{false};  // a caller is inside Run
    bool stopping = false;             // guarded by mutex
    // The published job. `generation` is even while the fields below are stable and odd while the caller writes
    // them; `users` counts workers inside Work, which the caller waits out before rewriting the fields.
    std::atomic<unsigned> generation{0};
    std::atomic<int> users{0};
    Call call = nullptr;
    void* context = nullptr;
    std::size_t count = 0;
    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> finished{0};
};

/// Threads a world uses when its settings ask for 0 (WorldSettings::threads): the count the host set with
/// SetDefaultThreadCount (physics-sandbox --threads), else std::thread::hardware_concurrency() (1 if unknown).
int DefaultThreadCount();
/// Sets DefaultThreadCount() for the process (values below 1: back to the hardware's concurrency). A host calls it
/// once, before it steps any world; like oneTBB's global_control it limits a process resource, not a result.
void SetDefaultThreadCount(int threads);

/// Number of chunks of `chunk` items that cover n items (0 for n = 0).
inline std::size_t ChunkCount(std::size_t n, std::size_t chunk) { return (n + chunk - 1) / chunk; }

/// Runs job(i) for every i in [0, count): on the threads of `jobs`, or in order on this thread when it is null.
template <typename Job>
void ForEachJob(JobPool* jobs, std::size_t count, Job&& job) {
    if (jobs == nullptr) {
        for (std::size_t i = 0; i < count; ++i) job(i);
    } else {
        jobs->ForEach(count, job);
    }
}

/// Runs range(begin, end) for the consecutive chunks of `chunk` items (> 0) that cover [0, n): on the threads of
/// `jobs`, or in order on this thread when it is null. The chunks depend on n and chunk only.
template <typename Range>
void ForEachChunk(JobPool* jobs, std::size_t n, std::size_t chunk, Range&& range) {
    ForEachJob(jobs, ChunkCount(n, chunk),
               [&](std::size_t c) { range(c * chunk, c * chunk + chunk < n ? c * chunk + chunk : n); });
}
