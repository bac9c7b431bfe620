// Work items 0, 1, 2, ... computed on several threads ahead of a consumer that takes them in
// order: the consumer sees exactly the sequence one thread would give, whatever the
// scheduling, because each item is a function of its index alone and lands in its own slot.
// At most `ahead` items exist beyond the one being taken (bounded memory); each thread keeps
// one `Scratch` for all its items (decode buffers reused, not reallocated per item).
#pragma once

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace spt::plan {

template <class T, class Scratch>
class OrderedPrefetch {
public:
    using Work = std::function<T(size_t index, Scratch& scratch)>;

    OrderedPrefetch(size_t count, int threads, size_t ahead, Work work)
        : count_(count), ahead_(ahead < 1 ? 1 : ahead), work_(std::move(work)), slots_(ahead_) {
        for (int t = 0; t < (threads < 1 ? 1 : threads); ++t) workers_.emplace_back([this] { loop(); });
    }
    ~OrderedPrefetch() {
        {
            std::lock_guard<std::mutex> l(mu_);
            stop_ = true;
        }
        wake_.notify_all();
        for (auto& w : workers_) w.join();
    }
    OrderedPrefetch(const OrderedPrefetch&) = delete;
    OrderedPrefetch& operator=(const OrderedPrefetch&) = delete;

    // Item `taken()`; call at most `count` times.
    T take() {
        std::unique_lock<std::mutex> l(mu_);
        auto& slot = slots_[taken_ % ahead_];
        done_.wait(l, [&] { return slot.has_value(); });
        T v = std::move(*slot);
        slot.reset();
        ++taken_;
        l.unlock();
        wake_.notify_all();
        return v;
    }
    size_t taken() const { return taken_; }

private:
    void loop() {
        Scratch scratch{};
        std::unique_lock<std::mutex> l(mu_);
        for (;;) {
            wake_.wait(l, [&] { return stop_ || (next_ < count_ && next_ < taken_ + ahead_); });
            if (stop_) return;
            const size_t i = next_++;
            l.unlock();
            T v = work_(i, scratch);
            l.lock();
            slots_[i % ahead_] = std::move(v);
            done_.notify_all();
        }
    }

    const size_t count_, ahead_;
    Work work_;
    std::vector<std::optional<T>> slots_;
    std::vector<std::thread> workers_;
    std::mutex mu_;
    std::condition_variable wake_, done_;
    size_t next_ = 0, taken_ = 0;
    bool stop_ = false;
};

}  // namespace spt::plan
