#include "Physics/JobPool.h"

#include <chrono>
#include <memory>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace {

/// Spins the caller makes, waiting for a worker to finish its last job, before it yields its core; and the spins a
/// worker makes before it starts yielding its core between looks at the clock.
constexpr int kSpinsBeforeSleep = 4000;
/// How long a worker spins, waiting for the next job, before it sleeps. The jobs of one step follow each other
/// within microseconds to a few tenths of a millisecond (the serial passes: the grid's counting sort, the graph),
/// and a wake-up through the kernel costs tens of microseconds each time, more on a virtual machine. 4,000 pauses
/// (about 0.1 ms on the 2-core machine) let the worker fall asleep some twice a step of the 4,000-cube pile; 2 ms
/// covers every serial pass of a step, and a worker left without jobs still sleeps soon after the step.
constexpr std::chrono::microseconds kSpinBeforeSleep{2000};
/// Pauses between two looks at the clock while a worker spins.
constexpr int kPausesPerClockRead = 64;
/// Threads a pool may have (Shared, --threads).
constexpr int kMaxThreads = 256;

std::atomic<int> defaultThreads{0};

inline void Pause() {
#if defined(__SSE2__)
    _mm_pause();
#endif
}

}  // namespace

int DefaultThreadCount() {
    const int set = defaultThreads.load(std::memory_order_relaxed);
    if (set > 0) return set;
    // Read once: std::thread::hardware_concurrency opens and reads a /sys file on every call, and every world's
    // step asks (JobPool::Shared), which made the syscalls most of a microsecond step's CPU.
    static const unsigned hardware = std::thread::hardware_concurrency();
    return hardware == 0 ? 1 : static_cast<int>(hardware < kMaxThreads ? hardware : kMaxThreads);
}

void SetDefaultThreadCount(int threads) {
    defaultThreads.store(threads < 1 ? 0 : (threads < kMaxThreads ? threads : kMaxThreads), std::memory_order_relaxed);
}

JobPool& JobPool::Shared(int threads) {
    if (threads < 1) threads = DefaultThreadCount();
    if (threads > kMaxThreads) threads = kMaxThreads;
    static std::mutex poolsMutex;
    static std::unique_ptr<JobPool> pools[kMaxThreads + 1];
    std::lock_guard<std::mutex> lock(poolsMutex);
    std::unique_ptr<JobPool>& pool = pools[threads];
    if (!pool) pool = std::make_unique<JobPool>(threads);
    return *pool;
}

JobPool::JobPool(int threads) {
    for (int i = 1; i < threads && i < kMaxThreads; ++i) workers.emplace_back([this] { WorkerLoop(); });
}

JobPool::~JobPool() {
    {
        std::lock_guard<std::mutex> lock(mutex);
        stopping = true;
    }
    wake.notify_all();
    for (std::thread& worker : workers) worker.join();
}

void JobPool::Run(std::size_t jobs, Call job, void* jobContext) {
    if (jobs < 2 || workers.empty() || running.exchange(true, std::memory_order_acquire)) {
        for (std::size_t i = 0; i < jobs; ++i) job(jobContext, i);
        return;
    }
    // Publish: odd generation while writing (a worker arriving now backs out), wait out the workers still inside
    // the last job, write the fields, even generation again.
    const unsigned g = generation.load(std::memory_order_relaxed);
    generation.store(g + 1);
    while (users.load() != 0) Pause();
    call = job;
    context = jobContext;
    count = jobs;
    next.store(0, std::memory_order_relaxed);
    finished.store(0, std::memory_order_relaxed);
    generation.store(g + 2);
    {
        std::lock_guard<std::mutex> lock(mutex);  // a worker about to sleep sees the new generation or the notify
    }
    wake.notify_all();
    Work();
    for (int spins = 0; finished.load(std::memory_order_acquire) != jobs; ++spins) {
        if (spins < kSpinsBeforeSleep) {
            Pause();
        } else {
            std::this_thread::yield();  // a worker was preempted in the middle of a job
        }
    }
    running.store(false, std::memory_order_release);
}

void JobPool::Work() {
    for (;;) {
        const std::size_t i = next.fetch_add(1, std::memory_order_relaxed);
        if (i >= count) return;
        call(context, i);
        finished.fetch_add(1, std::memory_order_release);
    }
}

void JobPool::WorkerLoop() {
    unsigned seen = 0;
    for (;;) {
        unsigned g = generation.load();
        const auto spinEnd = std::chrono::steady_clock::now() + kSpinBeforeSleep;
        for (int spins = 1; g == seen || (g & 1u) != 0u; ++spins) {
            Pause();
            g = generation.load();
            if (spins % kPausesPerClockRead != 0 || spins < kSpinsBeforeSleep) continue;
            if (std::chrono::steady_clock::now() > spinEnd) break;
            std::this_thread::yield();  // past the first 0.1 ms: let a thread that waits for this core run
        }
        if (g == seen || (g & 1u) != 0u) {
            std::unique_lock<std::mutex> lock(mutex);
            wake.wait(lock, [&] {
                g = generation.load();
                return stopping || (g != seen && (g & 1u) == 0u);
            });
            if (stopping) return;
        }
        // Enter the job, unless the caller began to rewrite it meanwhile (then look again).
        users.fetch_add(1);
        if (generation.load() != g) {
            users.fetch_sub(1);
            continue;
        }
        seen = g;
        Work();
        users.fetch_sub(1);
    }
}
