#include "plan/cut_frame_stores.hpp"

#include <algorithm>
#include <optional>
#include <thread>
#include <vector>

#include "plan/ordered_prefetch.hpp"

namespace spt::plan {

namespace {

struct Analysed {
    video::CutFrame frame;
    int cols = 0, rows = 0;
    std::string problem;
};

// The positions sampled_cuts asks for as samples, in its order: 0, the multiples of `step`
// among the source numbers, the last.
std::vector<size_t> sample_positions(long first, size_t count, int step_in) {
    const long step = std::max(1, step_in);
    std::vector<size_t> s{0};
    for (size_t a = 0;;) {
        const long rem = (((first + long(a)) % step) + step) % step;
        size_t b = a + size_t(step - rem);
        if (b >= count) {
            if (count >= 1 && count - 1 > a) s.push_back(count - 1);
            break;
        }
        s.push_back(b);
        a = b;
    }
    return s;
}

class FileFrames final : public PlanCutFrames {
public:
    FileFrames(std::unique_ptr<GrayFrameFiles> files, const SampledCutOptions& o, bool skip, int threads)
        : files_(std::move(files)), detector_(o.detector), skip_(skip),
          samples_(sample_positions(files_->first(), files_->count(), o.step)) {
        first_ = files_->first();
        if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
        // The samples are most of what is read: they decode on every thread, a few ahead.
        if (threads > 1 && samples_.size() > 1)
            ahead_ = std::make_unique<Prefetch>(samples_.size(), threads, size_t(2 * threads),
                                                [this](size_t i, int&) { return analyse(samples_[i]); });
    }

    size_t count() const override { return files_->count(); }

    Result<const video::CutFrame*> at(size_t pos) override {
        if (pos >= files_->count()) return static_cast<const video::CutFrame*>(nullptr);
        if (auto k = kept_.find(pos); k != kept_.end()) return &k->second;
        Analysed a = take_or_read(pos);
        if (problem_of(pos, a)) {
            if (!skip_ || pos == 0)
                return make_error(Code::IoError, a.problem + (skip_ ? " (the first frame cannot be skipped)" : ""));
            // --skip-bad-frames: the nearest good frame before it.
            for (size_t j = pos; j-- > 0;) {
                if (auto k = kept_.find(j); k != kept_.end()) {
                    a.frame = k->second;
                    break;
                }
                Analysed b = read_now(j);
                if (!problem_of(j, b)) {
                    a.frame = std::move(b.frame);
                    break;
                }
            }
        }
        return &kept_.emplace(pos, std::move(a.frame)).first->second;
    }

private:
    using Prefetch = OrderedPrefetch<Analysed, int>;

    Analysed analyse(size_t pos) const {
        Analysed a;
        GrayFrameFiles::Frame f = files_->read(pos);
        a.problem = std::move(f.problem);
        if (a.problem.empty()) {
            a.cols = f.gray.cols, a.rows = f.gray.rows;
            a.frame = video::analyse_cut_frame(f.gray, detector_);
        }
        return a;
    }
    Analysed read_now(size_t pos) {
        ++decoded_;
        return analyse(pos);
    }
    Analysed take_or_read(size_t pos) {
        // Samples are asked for in order; anything else is read here and now.
        while (next_sample_ < samples_.size() && samples_[next_sample_] <= pos) {
            const size_t s = samples_[next_sample_++];
            Analysed a = ahead_ ? (++decoded_, ahead_->take()) : read_now(s);
            if (s == pos) return a;
            if (!problem_of(s, a)) kept_.emplace(s, std::move(a.frame));  // not expected: keep it
        }
        return read_now(pos);
    }
    // Fills in the size check (every frame the size of the first, as in the full scan).
    bool problem_of(size_t pos, Analysed& a) {
        if (a.problem.empty() && pos == 0) width_ = a.cols, height_ = a.rows;
        if (a.problem.empty() && (a.cols != width_ || a.rows != height_))
            a.problem = files_->path(pos) + ": frame " + std::to_string(first_ + long(pos)) + " is " +
                        std::to_string(a.cols) + "x" + std::to_string(a.rows) + ", the sequence is " +
                        std::to_string(width_) + "x" + std::to_string(height_);
        return !a.problem.empty();
    }

    std::unique_ptr<GrayFrameFiles> files_;
    video::CutOptions detector_;
    bool skip_;
    std::vector<size_t> samples_;
    size_t next_sample_ = 0;
    std::unique_ptr<Prefetch> ahead_;  // last: its threads stop before the members they read go
};

class InOrderFrames final : public PlanCutFrames {
public:
    InOrderFrames(std::unique_ptr<GrayFrames> src, const SampledCutOptions& o)
        : src_(std::move(src)), detector_(o.detector) {}

    size_t count() const override { return read_; }
    std::string shortfall() const override { return ended_ ? src_->shortfall() : std::string(); }

    Result<const video::CutFrame*> at(size_t pos) override {
        while (!ended_ && read_ <= pos) {
            long number = 0;
            Result<bool> got = src_->next(number, gray_);
            if (!got) return got.error();
            if (!*got) {
                ended_ = true;
                break;
            }
            if (read_ == 0) {
                first_ = number;
                width_ = gray_.cols, height_ = gray_.rows;
            } else if (number != prev_ + 1) {
                return make_error(Code::InvalidArgument, src_->describe() + ": frame " + std::to_string(number) +
                                                             " follows frame " + std::to_string(prev_) +
                                                             ": a plan needs consecutive frame numbers");
            }
            prev_ = number;
            ++decoded_;
            kept_.emplace(read_++, video::analyse_cut_frame(gray_, detector_));
        }
        if (pos >= read_) return static_cast<const video::CutFrame*>(nullptr);
        auto k = kept_.find(pos);
        if (k == kept_.end())
            return make_error(Code::BadState, src_->describe() + ": the cut scan went back to a frame it no longer keeps");
        return &k->second;
    }

private:
    std::unique_ptr<GrayFrames> src_;
    video::CutOptions detector_;
    cv::Mat gray_;
    size_t read_ = 0;
    long prev_ = -1;
    bool ended_ = false;
};

}  // namespace

std::unique_ptr<PlanCutFrames> cut_frames_of_files(std::unique_ptr<GrayFrameFiles> files, const SampledCutOptions& o,
                                                   bool skip_bad_frames, int threads) {
    return std::make_unique<FileFrames>(std::move(files), o, skip_bad_frames, threads);
}

std::unique_ptr<PlanCutFrames> cut_frames_in_order(std::unique_ptr<GrayFrames> frames, const SampledCutOptions& o) {
    return std::make_unique<InOrderFrames>(std::move(frames), o);
}

}  // namespace spt::plan
