#include "paint/worker_pool.hpp"

#include <algorithm>

namespace spt::paint {

namespace {
// Items are handed out in small chunks: enough to amortise the atomic, small enough to balance
// candidates whose footprints are clipped differently.
constexpr size_t kChunk = 4;
}

int resolve_threads(int requested) {
    return requested > 0 ? requested : int(std::max(1u, std::thread::hardware_concurrency()));
}

WorkerPool::WorkerPool(int threads) {
    for (int i = 1; i < threads; ++i) workers_.emplace_back([this] { worker_loop(); });
}

WorkerPool::~WorkerPool() {
    {
        std::lock_guard<std::mutex> lk(mu_);
        stop_ = true;
    }
    wake_.notify_all();
    for (auto& t : workers_) t.join();
}

void WorkerPool::drain() {
    for (;;) {
        size_t begin = next_.fetch_add(kChunk, std::memory_order_relaxed);
        if (begin >= n_) return;
        size_t end = begin + kChunk < n_ ? begin + kChunk : n_;
        for (size_t i = begin; i < end; ++i) (*fn_)(i);
    }
}

void WorkerPool::worker_loop() {
    uint64_t seen = 0;
    for (;;) {
        {
            std::unique_lock<std::mutex> lk(mu_);
            wake_.wait(lk, [&] { return stop_ || generation_ != seen; });
            if (stop_) return;
            seen = generation_;
        }
        drain();
        {
            std::lock_guard<std::mutex> lk(mu_);
            if (--busy_ == 0) done_.notify_one();
        }
    }
}

void WorkerPool::run(size_t n, const std::function<void(size_t)>& fn) {
    if (workers_.empty() || n <= kChunk) {
        for (size_t i = 0; i < n; ++i) fn(i);
        return;
    }
    {
        std::lock_guard<std::mutex> lk(mu_);
        fn_ = &fn;
        n_ = n;
        next_.store(0, std::memory_order_relaxed);
        busy_ = int(workers_.size());
        ++generation_;
    }
    wake_.notify_all();
    drain();
    std::unique_lock<std::mutex> lk(mu_);
    done_.wait(lk, [&] { return busy_ == 0; });
    fn_ = nullptr;
}

}  // namespace spt::paint
