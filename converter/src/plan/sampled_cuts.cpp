#include "plan/sampled_cuts.hpp"

#include <algorithm>
#include <deque>

namespace spt::plan {

size_t keep_behind(const SampledCutOptions& o) {
    return size_t(std::clamp(o.history, 1, std::max(2, o.detector.window))) + 2;
}

namespace {

class Scan {
public:
    Scan(CutFrames& f, const SampledCutOptions& o) : f_(f), o_(o) {
        o_.detector.window = std::max(2, o_.detector.window);
        history_ = std::clamp(o_.history, 1, o_.detector.window);
    }

    // The span a..b (both read): its pairs a..a+1, ..., b-1..b, left to right.
    Status span(size_t a, size_t b) {
        if (b == a + 1) return judge(b);
        Result<const video::CutFrame*> fa = f_.at(a), fb = f_.at(b);
        if (!fa) return fa.error();
        if (!fb) return fb.error();
        const video::CutChange c = video::cut_change(**fa, **fb);
        // A cut within a..b differs from what precedes it by at least the floors; the frames on
        // either side of it move less than the rest of the floors in a few frames (the mean
        // absolute difference obeys the triangle inequality), so the span's change stays above
        // `loose` times the floors (the edge ratio obeys no such inequality: its margin is
        // measured, README.md). Spans below are taken to hold no cut and are skipped unread.
        if (c.pixel_diff < o_.loose * o_.detector.min_pixel_diff || c.edge_diff < o_.loose * o_.detector.min_edge_diff)
            return {};
        const size_t m = a + (b - a) / 2;
        if (Status st = span(a, m); !st) return st;
        return span(m, b);
    }

    std::vector<size_t> cuts;
    size_t judged = 0;

private:
    // The detector's verdict on the pair t-1..t with the history the full scan has there (the
    // products of the pairs since the last cut; no cut was found among them, so the full scan
    // pushed them all), its last `history` pairs.
    Status judge(size_t t) {
        Result<const video::CutFrame*> p = f_.at(t - 1), q = f_.at(t);
        if (!p) return p.error();
        if (!q) return q.error();
        ++judged;
        const video::CutChange c = video::cut_change(**p, **q);
        const video::CutOptions& d = o_.detector;
        // Below a floor the verdict is "no cut" whatever the history: do not read it.
        if (c.pixel_diff < d.min_pixel_diff || c.edge_diff < d.min_edge_diff ||
            c.pixel_diff * c.edge_diff <= d.min_pixel_diff * d.min_edge_diff)
            return {};
        const size_t h = size_t(history_);
        const size_t from = std::max(last_cut_ + 1, t > h ? t - h : size_t(1));
        std::deque<double> history;
        for (size_t j = from; j < t; ++j) {
            Result<const video::CutFrame*> x = f_.at(j - 1), y = f_.at(j);
            if (!x) return x.error();
            if (!y) return y.error();
            const video::CutChange h = video::cut_change(**x, **y);
            history.push_back(h.pixel_diff * h.edge_diff);
        }
        if (video::judge_cut(c, history, d).cut) {
            cuts.push_back(t);
            last_cut_ = t;
        }
        return {};
    }

    CutFrames& f_;
    SampledCutOptions o_;
    size_t last_cut_ = 0;
    int history_ = 0;
};

}  // namespace

Result<std::vector<size_t>> sampled_cuts(CutFrames& frames, long first_number, const SampledCutOptions& o,
                                         const std::function<void(size_t pos)>& on_sample, SampledCutStats* stats) {
    const size_t step = size_t(std::max(1, o.step));
    Scan scan(frames, o);
    Result<const video::CutFrame*> f0 = frames.at(0);
    if (!f0) return f0.error();
    if (!*f0) return std::vector<size_t>{};
    if (on_sample) on_sample(0);
    size_t a = 0;
    for (;;) {
        // The next multiple of `step` among the source numbers, or the last frame.
        const long na = first_number + long(a);
        const long rem = ((na % long(step)) + long(step)) % long(step);
        size_t b = a + step - size_t(rem);
        Result<const video::CutFrame*> fb = frames.at(b);
        if (!fb) return fb.error();
        if (!*fb) {
            const size_t n = frames.count();
            if (n == 0 || n - 1 <= a) break;
            b = n - 1;
        }
        if (on_sample) on_sample(b);
        if (Status st = scan.span(a, b); !st) return st.error();
        a = b;
        frames.forget_before(a > keep_behind(o) ? a - keep_behind(o) : 0);
    }
    if (stats) stats->judged = scan.judged;
    return scan.cuts;
}

}  // namespace spt::plan
