// A small persistent thread pool for the painter's batches: run(n, fn) calls fn(i) for
// i in [0, n) spread over the workers and the calling thread, and returns when all are done.
// Work items write only their own result slot, so the outcome never depends on scheduling.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace spt::paint {

// The threads a --threads value asks for: itself when positive, else one per hardware thread
// (at least 1).
int resolve_threads(int requested);

class WorkerPool {
public:
    explicit WorkerPool(int threads);  // total threads including the caller; <= 1: inline
    ~WorkerPool();
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    void run(size_t n, const std::function<void(size_t)>& fn);
    int threads() const { return int(workers_.size()) + 1; }

private:
    void worker_loop();
    void drain();

    std::vector<std::thread> workers_;
    std::mutex mu_;
    std::condition_variable wake_, done_;
    uint64_t generation_ = 0;
    bool stop_ = false;
    const std::function<void(size_t)>* fn_ = nullptr;
    size_t n_ = 0;
    std::atomic<size_t> next_{0};
    int busy_ = 0;
};

}  // namespace spt::paint
