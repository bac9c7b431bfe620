// The SPT painting loop: batches of stochastic candidates, scored in parallel against the same
// canvas, committed in a fixed order under the dynamic acceptance rule (README.md beside this
// file explains the rule and why it is deterministic for any thread count).
#include "paint/painter.hpp"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "paint/orientation.hpp"
#include "paint/rng.hpp"
#include "paint/stamp_score.hpp"
#include "paint/worker_pool.hpp"

namespace spt::paint {

namespace {

// Where candidates may be centred: every pixel, or a list of allowed pixel indices.
struct Domain {
    bool all = true;
    uint64_t total = 0;             // number of pixels a candidate can land on
    std::vector<uint32_t> pixels;   // when !all
    uint32_t pick(uint64_t r) const {
        const uint64_t k = rng_below(r, total);
        return all ? uint32_t(k) : pixels[k];
    }
};

Domain make_domain(uint32_t w, uint32_t h, const std::vector<uint8_t>* region, const std::vector<Rect>* rects) {
    Domain d;
    if (!region && !rects) {
        d.total = uint64_t(w) * h;
        return d;
    }
    d.all = false;
    std::vector<uint8_t> in(size_t(w) * h, rects ? 0 : 1);
    if (rects)
        for (const Rect& r : *rects) {
            const int64_t x0 = std::max<int64_t>(0, r.x), y0 = std::max<int64_t>(0, r.y);
            const int64_t x1 = std::min<int64_t>(w, int64_t(r.x) + r.w), y1 = std::min<int64_t>(h, int64_t(r.y) + r.h);
            for (int64_t y = y0; y < y1; ++y)
                for (int64_t x = x0; x < x1; ++x) in[size_t(y) * w + size_t(x)] = 1;
        }
    for (size_t i = 0; i < in.size(); ++i)
        if (in[i] && (!region || (*region)[i])) d.pixels.push_back(uint32_t(i));
    d.total = d.pixels.size();
    return d;
}

int64_t sse_over(const Plane& p, const Domain& d) {
    auto px_err = [&](size_t i) {
        int64_t e = 0;
        for (int c = 0; c < 3; ++c) {
            const int v = int(p.canvas[i * 3 + c]) - int(p.model[i * 3 + c]);
            e += v * v;
        }
        return e;
    };
    int64_t e = 0;
    if (d.all)
        for (size_t i = 0; i < size_t(p.width) * p.height; ++i) e += px_err(i);
    else
        for (uint32_t i : d.pixels) e += px_err(i);
    return e;
}

double psnr_of(int64_t sse, double samples) {
    if (sse <= 0) return 99;
    return 10 * std::log10(255.0 * 255.0 * samples / double(sse));
}

struct Footprint {
    const Mask* mask = nullptr;
    Spans spans;
};

struct Candidate {
    int32_t px = 0, py = 0;
    uint8_t tmpl = 0, orient = 0;
    const Footprint* fp = nullptr;
    StampScore score;
};

// Footprints at least this large are scored one at a time with their rows split over the
// threads; smaller ones are scored many at a time, one per thread. Big strokes of one batch
// would nearly all overlap each other and have to be scored again anyway.
constexpr double kSplitArea = 6000;
constexpr int32_t kRowsPerTask = 8;

// Scores one big candidate with its rows spread over the pool. Integer partial sums make the
// result independent of how the rows were split.
StampScore score_split(WorkerPool& pool, const Plane& p, const Footprint& f, int32_t px, int32_t py) {
    StampScore s;
    const int32_t h = int32_t(f.mask->h);
    const size_t tasks = size_t((h + kRowsPerTask - 1) / kRowsPerTask);
    std::vector<ColourSums> part(tasks);
    pool.run(tasks, [&](size_t t) {
        part[t] = colour_sums(p, *f.mask, f.spans, px, py, int32_t(t) * kRowsPerTask,
                              std::min(h, int32_t(t + 1) * kRowsPerTask));
    });
    ColourSums all;
    for (const auto& c : part) all.add(c);
    if (!best_colour(all, s.color)) return s;
    std::vector<int64_t> err(tasks, 0);
    pool.run(tasks, [&](size_t t) {
        err[t] = new_error(p, *f.mask, f.spans, px, py, int32_t(t) * kRowsPerTask,
                           std::min(h, int32_t(t + 1) * kRowsPerTask), s.color);
    });
    int64_t e = 0;
    for (int64_t v : err) e += v;
    s.valid = true;
    s.delta = e - all.old_err;
    return s;
}

// Marks which 16x16 tiles strokes committed in the current batch touched, so that a candidate
// scored against the batch's starting canvas is scored again if the canvas under it changed.
class TileMarks {
public:
    TileMarks(uint32_t w, uint32_t h) : cols_((w + 15) / 16), rows_((h + 15) / 16), epoch_(size_t(cols_) * rows_, 0) {}
    void next_batch() { ++now_; }
    bool touched(const Mask& fp, int32_t px, int32_t py, uint32_t w, uint32_t h) const {
        int32_t c0, c1, r0, r1;
        if (!range(fp, px, py, w, h, c0, c1, r0, r1)) return false;
        for (int32_t r = r0; r <= r1; ++r)
            for (int32_t c = c0; c <= c1; ++c)
                if (epoch_[size_t(r) * cols_ + c] == now_) return true;
        return false;
    }
    void mark(const Mask& fp, int32_t px, int32_t py, uint32_t w, uint32_t h) {
        int32_t c0, c1, r0, r1;
        if (!range(fp, px, py, w, h, c0, c1, r0, r1)) return;
        for (int32_t r = r0; r <= r1; ++r)
            for (int32_t c = c0; c <= c1; ++c) epoch_[size_t(r) * cols_ + c] = now_;
    }
private:
    bool range(const Mask& fp, int32_t px, int32_t py, uint32_t w, uint32_t h,
               int32_t& c0, int32_t& c1, int32_t& r0, int32_t& r1) const {
        const Clip c = clip_footprint(fp, px, py, w, h);
        if (c.empty()) return false;
        c0 = (px + fp.x0 + c.i0) >> 4; c1 = (px + fp.x0 + c.i1 - 1) >> 4;
        r0 = (py + fp.y0 + c.j0) >> 4; r1 = (py + fp.y0 + c.j1 - 1) >> 4;
        return true;
    }
    uint32_t cols_, rows_;
    std::vector<uint32_t> epoch_;
    uint32_t now_ = 0;
};

}  // namespace

PaintStats paint(const ImageView& model, Canvas& canvas, const Renderer& renderer,
                 const PaintSetup& setup, const PaintOptions& opts, std::vector<Stroke>& out,
                 const std::vector<uint8_t>* region, const PaintProgressFn& progress) {
    PaintStats st;
    const Header& hd = setup.header;
    const uint32_t W = model.width, H = model.height;
    const size_t S = hd.sets.size(), T = setup.templates.size(), O = hd.orientations.size();
    st.strokes_per_set.assign(S, 0);
    if (W == 0 || H == 0 || canvas.width != W || canvas.height != H || S == 0 || T == 0 || O == 0 ||
        (region && region->size() != size_t(W) * H))
        return st;

    int threads = opts.threads > 0 ? opts.threads : int(std::thread::hardware_concurrency());
    WorkerPool pool(std::max(1, threads));
    const Plane plane{W, H, model.rgb, canvas.rgb.data()};
    const double samples = 3.0 * W * H;
    const std::vector<uint8_t> field = orientation_field(model, hd.orientations, opts.orient);

    const Domain base = make_domain(W, H, region, nullptr);
    Domain roi_domain;
    if (!opts.rois.empty()) roi_domain = make_domain(W, H, region, &opts.rois);

    int64_t err = sse_over(plane, Domain{true, uint64_t(W) * H, {}});
    TileMarks marks(W, H);
    std::vector<Candidate> batch;
    bool stop = false;
    // Falls by halves when the finest set stalls short of a PSNR target (see below).
    double lambda_scale = 1.0;

    for (size_t set = 0; set < S && !stop; ++set) {
        // Regions of interest: the finest set paints only inside them (elsewhere painting ends
        // with the set before), and it runs until the ROI's own error converges.
        const bool last = set + 1 == S;
        const Domain& dom = (last && !opts.rois.empty()) ? roi_domain : base;
        if (dom.total == 0) continue;

        // The renderer's cached footprints of this set, fetched once on this thread.
        std::vector<Footprint> fps(T * O);
        double area = 0;
        for (size_t t = 0; t < T; ++t)
            for (size_t o = 0; o < O; ++o) {
                Footprint& f = fps[t * O + o];
                f.mask = &renderer.stamp_footprint(uint8_t(set), uint8_t(t), uint8_t(o));
                f.spans = footprint_spans(*f.mask);
                area += double(f.mask->w) * f.mask->h;
            }
        area = std::max(1.0, area / double(T * O));
        const bool split = area >= kSplitArea && pool.threads() > 1;

        // The convergence window is half a coverage of the domain by this set's strokes: the
        // relative improvement over it is then comparable between sets and image sizes.
        const uint64_t window = std::max<uint64_t>(64, uint64_t(0.5 * double(dom.total) / area));
        // Batches hold about 64k footprint pixels of work: big enough to keep threads busy,
        // small enough that few candidates of a batch overlap an earlier commit.
        const size_t bsize = area >= kSplitArea ? 1 : size_t(std::clamp(65536.0 / area, 4.0, 512.0));
        int64_t dom_err = dom.all ? err : sse_over(plane, dom);
        int64_t win_start = dom_err;
        uint64_t win_count = 0, counter = 0;

        const auto set_t0 = std::chrono::steady_clock::now();
        for (;;) {
            batch.assign(bsize, Candidate{});
            auto draw = [&](size_t i) {
                const uint64_t n = counter + i;
                Candidate& c = batch[i];
                const uint32_t pix = dom.pick(rng_draw(opts.seed, uint32_t(set), n, RngStream::Position));
                c.px = int32_t(pix % W);
                c.py = int32_t(pix / W);
                c.tmpl = uint8_t(rng_below(rng_draw(opts.seed, uint32_t(set), n, RngStream::Template), T));
                c.orient = field.empty()
                               ? uint8_t(rng_below(rng_draw(opts.seed, uint32_t(set), n, RngStream::Orientation), O))
                               : field[pix];
                c.fp = &fps[size_t(c.tmpl) * O + c.orient];
            };
            if (split) {
                for (size_t i = 0; i < bsize; ++i) {
                    draw(i);
                    batch[i].score = score_split(pool, plane, *batch[i].fp, batch[i].px, batch[i].py);
                }
            } else {
                pool.run(bsize, [&](size_t i) {
                    draw(i);
                    batch[i].score = score_stamp(plane, *batch[i].fp->mask, batch[i].fp->spans, batch[i].px, batch[i].py);
                });
            }
            marks.next_batch();
            for (size_t i = 0; i < bsize && !stop; ++i) {
                Candidate& c = batch[i];
                if (marks.touched(*c.fp->mask, c.px, c.py, W, H)) {
                    c.score = score_stamp(plane, *c.fp->mask, c.fp->spans, c.px, c.py);
                    ++st.rescored;
                }
                if (!c.score.valid || c.score.delta >= 0) continue;
                // Dynamic acceptance (README.md): J = dE + lambda_eff, lambda_eff the error of
                // `lambda` average pixels now; accept J < 0, otherwise with the Metropolis
                // probability exp(-J / temp), the temperature falling over the set.
                const double lambda_eff = lambda_scale * opts.lambda * double(err) / (double(W) * H);
                const double j = double(c.score.delta) + lambda_eff;
                bool accept = j < 0;
                if (!accept && opts.temperature > 0 && lambda_eff > 0) {
                    const double temp = opts.temperature * lambda_eff *
                                        std::exp(-double(counter + i) / double(window));
                    const double u = rng_unit(rng_draw(opts.seed, uint32_t(set), counter + i, RngStream::Accept));
                    accept = temp > 0 && u < std::exp(-j / temp);
                }
                if (!accept) continue;
                commit_stamp(plane, *c.fp->mask, c.px, c.py, c.score.color);
                marks.mark(*c.fp->mask, c.px, c.py, W, H);
                err += c.score.delta;
                dom_err += c.score.delta;
                StampStroke s;
                s.set = uint8_t(set);
                s.tmpl = c.tmpl;
                s.orient = c.orient;
                s.x = c.px * kQ4 + kQ4 / 2;
                s.y = c.py * kQ4 + kQ4 / 2;
                s.color = Rgba8{c.score.color.r, c.score.color.g, c.score.color.b, 255};
                out.push_back(Stroke::make_stamp(s));
                ++st.strokes;
                ++st.strokes_per_set[set];
                if (st.strokes >= opts.max_strokes) { stop = true; st.stop = StopReason::MaxStrokes; }
                else if (opts.target_psnr > 0 && psnr_of(err, samples) >= opts.target_psnr) {
                    stop = true;
                    st.stop = StopReason::TargetPsnr;
                }
            }
            counter += bsize;
            st.candidates += bsize;
            win_count += bsize;
            if (progress && !progress(st.strokes, int(set), psnr_of(err, samples))) {
                stop = true;
                st.stop = StopReason::Cancelled;
            }
            if (stop) break;
            if (win_count >= window) {
                const double rel = win_start > 0 ? double(win_start - dom_err) / double(win_start) : 0;
                // The finest set keeps going towards a PSNR target while it still improves at a
                // tenth of the switching rate; when it stalls, the rate constraint is relaxed
                // (lambda halves, down to 1/64) so the target stays reachable.
                const bool chasing = last && opts.target_psnr > 0;
                if (rel < (chasing ? opts.threshold * 0.1 : opts.threshold)) {
                    if (!chasing || lambda_scale < 1.0 / 64 || opts.lambda == 0) break;
                    lambda_scale *= 0.5;
                }
                win_start = dom_err;
                win_count = 0;
            }
        }
        if (std::getenv("SPT_PAINT_DEBUG"))  // tuning aid: per-set work and yield
            std::fprintf(stderr, "set %zu (%ux%u): %llu candidates, %llu strokes, %.2f dB, %.3f s\n", set,
                         hd.sets[set].width, hd.sets[set].height, (unsigned long long)counter,
                         (unsigned long long)st.strokes_per_set[set], psnr_of(err, samples),
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - set_t0).count());
    }
    st.psnr = psnr_of(err, samples);
    return st;
}

}  // namespace spt::paint
