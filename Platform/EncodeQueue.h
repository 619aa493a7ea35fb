#pragma once
// A bounded FIFO of frame jobs (encode a PNG, write it, compare it) run on a second thread, so encoding
// overlaps the rendering of the next frames. Jobs run strictly in order, and each job's output depends only
// on its inputs, so the files are identical to running the same jobs inline (threaded = false).

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

class EncodeQueue {
public:
    /// A job returns false and sets its error message on failure.
    using Job = std::function<bool(std::string* error)>;

    /// capacity: jobs waiting at most (the producer blocks beyond it); threaded = false runs jobs in Push.
    EncodeQueue(std::size_t capacity, bool threaded);
    ~EncodeQueue();
    EncodeQueue(const EncodeQueue&) = delete;
    EncodeQueue& operator=(const EncodeQueue&) = delete;

    /// Queues a job (or runs it, unthreaded). Returns false, without queueing, once any job has failed;
    /// later jobs are then dropped, so the first failure is the one reported.
    bool Push(Job job);
    /// Waits until every queued job has run; false with the first failure's message.
    bool Finish(std::string* error);
    /// Seconds the producer spent blocked on a full queue (steady clock; for the summary and benchmark).
    double ProducerWaitSeconds() const { return waitSeconds; }

private:
    void WorkerLoop();

    const std::size_t capacity;
    const bool threaded;
    std::mutex mutex;
    std::condition_variable changed;
    std::deque<Job> jobs;
    bool running = false;  // worker is executing a job taken off the queue
    bool stopping = false;
    bool failed = false;
    std::string firstError;
    double waitSeconds = 0.0;
    std::thread worker;
};
