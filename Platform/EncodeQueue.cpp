#include "Platform/EncodeQueue.h"

#include <pthread.h>
#include <signal.h>

#include <chrono>
#include <exception>
#include <new>

namespace {

// A job that throws (std::bad_alloc on a huge frame) fails like one that returns false; nothing escapes the
// worker thread, where an exception would end the process.
bool RunJob(const EncodeQueue::Job& job, std::string* error) {
    try {
        return job(error);
    } catch (const std::bad_alloc&) {
        *error = "out of memory while encoding or comparing a frame";
    } catch (const std::exception& e) {
        *error = std::string("frame job failed: ") + e.what();
    }
    return false;
}

}  // namespace

EncodeQueue::EncodeQueue(std::size_t cap, bool useThread) : capacity(cap < 1 ? 1 : cap), threaded(useThread) {
    if (threaded) worker = std::thread(&EncodeQueue::WorkerLoop, this);
}

EncodeQueue::~EncodeQueue() {
    {
        std::lock_guard<std::mutex> lock(mutex);
        stopping = true;
    }
    changed.notify_all();
    if (worker.joinable()) worker.join();
}

bool EncodeQueue::Push(Job job) {
    if (!threaded) {
        if (failed) return false;
        std::string error;
        if (!RunJob(job, &error)) {
            failed = true;
            firstError = error;
        }
        return !failed;
    }
    std::unique_lock<std::mutex> lock(mutex);
    if (jobs.size() >= capacity) {
        const auto start = std::chrono::steady_clock::now();
        changed.wait(lock, [this] { return jobs.size() < capacity || failed; });
        waitSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    if (failed) return false;
    jobs.push_back(std::move(job));
    changed.notify_all();
    return true;
}

bool EncodeQueue::Finish(std::string* error) {
    if (threaded) {
        std::unique_lock<std::mutex> lock(mutex);
        changed.wait(lock, [this] { return (jobs.empty() && !running) || failed; });
        // After a failure let the job in flight end before reporting, so no temporary file is left behind.
        changed.wait(lock, [this] { return !running; });
    }
    if (failed && error) *error = firstError;
    return !failed;
}

void EncodeQueue::WorkerLoop() {
    // SIGINT and SIGTERM are handled on the main thread (Platform/Files/TempRegistry.h), never while this
    // thread is half-way through registering a temporary.
    sigset_t block;
    sigemptyset(&block);
    sigaddset(&block, SIGINT);
    sigaddset(&block, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &block, nullptr);
    std::unique_lock<std::mutex> lock(mutex);
    for (;;) {
        changed.wait(lock, [this] { return !jobs.empty() || stopping; });
        if (jobs.empty()) return;  // stopping with nothing left
        Job job = std::move(jobs.front());
        jobs.pop_front();
        if (failed) continue;  // drop jobs queued before the failure was seen
        running = true;
        lock.unlock();
        std::string error;
        const bool ok = RunJob(job, &error);
        lock.lock();
        running = false;
        if (!ok && !failed) {
            failed = true;
            firstError = error;
        }
        changed.notify_all();
    }
}
