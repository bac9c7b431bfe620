// The SPT painting loop: batches of stochastic candidates, scored in parallel against the same
// canvas, committed in a fixed order under the dynamic acceptance rule (README.md beside this
// file explains the rule and why it is deterministic for any thread count).
#include "paint/painter.hpp"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "paint/orientation.hpp"
#include "paint/rng.hpp"
#include "paint/stamp_score.hpp"
#include "paint/worker_pool.hpp"

namespace spt::paint {

namespace {

// Where candidates may be centred: the generator's candidate domain (SPEC.md 7.7.2), so that
// a decoder can replay the draws, plus a pixel mask for measuring the domain's error.
struct Domain {
    bool all = true;
    uint64_t total = 0;             // number of pixels a candidate can land on
    replay::CandidateDomain cd;
    std::vector<uint8_t> in;        // when !all: 1 where a candidate can land
    uint32_t width = 0;
    uint32_t pick(uint64_t r) const {
        uint32_t x, y;
        cd.pixel(rng_below(r, total), x, y);
        return y * width + x;
    }
};

Domain make_domain(uint32_t w, uint32_t h, const ReplayRegion& region) {
    Domain d;
    d.width = w;
    d.cd = replay::CandidateDomain(w, h, region);
    d.total = d.cd.size();
    d.all = !region.use_rects && !region.use_blocks;
    if (d.all) return d;
    d.in.assign(size_t(w) * h, 0);
    for (uint64_t k = 0; k < d.total; ++k) {
        uint32_t x, y;
        d.cd.pixel(k, x, y);
        d.in[size_t(y) * w + x] = 1;
    }
    return d;
}

int64_t sse_over(const Plane& p, const Domain& d) {
    auto px_err = [&](size_t i) {
        int64_t e = 0;
        for (int c = 0; c < 3; ++c) {
            const int v = int(p.canvas[i * 3 + c]) - int(p.model[i * 3 + c]);
            e += v * v;
        }
        if (p.has_alpha()) {
            const int v = int(p.canvas_a[i]) - int(p.model_a[i]);
            e += (v > 0 ? p.alpha_weight : 1) * v * v;
        }
        return e;
    };
    int64_t e = 0;
    if (d.all)
        for (size_t i = 0; i < size_t(p.width) * p.height; ++i) e += px_err(i);
    else
        for (size_t i = 0; i < d.in.size(); ++i)
            if (d.in[i]) e += px_err(i);
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
StampScore score_split(WorkerPool& pool, const Plane& p, const Footprint& f, int32_t px, int32_t py, int step) {
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
    if (!best_colour(all, s.color, step)) return s;
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

ReplayInfo replay_info(const PaintSetup& setup, const PaintOptions& opts, uint32_t width, uint32_t height,
                       const std::vector<uint8_t>* region) {
    ReplayInfo ri;
    ri.present = true;
    ri.seed = opts.seed;
    ri.random_orientation = opts.orient == OrientMode::Random;
    ri.color_step = uint8_t(std::clamp(opts.color_step, 1, 32));
    ReplayRegion base;
    if (region && region->size() == size_t(width) * height) {
        // A repaint mask becomes the blocks it touches: a block mask codes in a few bits per
        // block, a pixel mask would cost more than the strokes it allows.
        base.use_blocks = true;
        base.block_size = kRegionBlock;
        const uint32_t cols = (width + kRegionBlock - 1) / kRegionBlock, rows = (height + kRegionBlock - 1) / kRegionBlock;
        base.blocks.assign(size_t(cols) * rows, 0);
        for (uint32_t y = 0; y < height; ++y)
            for (uint32_t x = 0; x < width; ++x)
                if ((*region)[size_t(y) * width + x]) base.blocks[size_t(y / kRegionBlock) * cols + x / kRegionBlock] = 1;
    }
    ri.regions.assign(setup.header.sets.size(), base);
    if (!opts.rois.empty() && !ri.regions.empty()) {
        ReplayRegion& last = ri.regions.back();
        last.use_rects = true;
        for (const Rect& r : opts.rois) {
            const int64_t x0 = std::max<int64_t>(0, r.x), y0 = std::max<int64_t>(0, r.y);
            const int64_t x1 = std::min<int64_t>(width, int64_t(r.x) + r.w), y1 = std::min<int64_t>(height, int64_t(r.y) + r.h);
            if (x0 < x1 && y0 < y1 && last.rects.size() < 4096)
                last.rects.push_back({uint32_t(x0), uint32_t(y0), uint32_t(x1 - x0), uint32_t(y1 - y0)});
        }
        // No rectangle on the canvas: an empty domain (a 1x1 rectangle in an empty block mask
        // cannot be expressed, so the set is skipped by giving it an all-zero mask).
        if (last.rects.empty()) {
            last.use_rects = false;
            last.use_blocks = true;
            last.block_size = kRegionBlock;
            last.blocks.assign(size_t((width + kRegionBlock - 1) / kRegionBlock) * ((height + kRegionBlock - 1) / kRegionBlock), 0);
        }
    }
    return ri;
}

PaintStats paint(const ImageView& model, Canvas& canvas, const Renderer& renderer,
                 const PaintSetup& setup, const PaintOptions& opts, std::vector<Stroke>& out,
                 const std::vector<uint8_t>* region, const PaintProgressFn& progress) {
    PaintStats st;
    const Header& hd = setup.header;
    const uint32_t W = model.width, H = model.height;
    const size_t S = hd.sets.size(), T = setup.templates.size(), O = hd.orientations.size();
    st.strokes_per_set.assign(S, 0);
    const bool alpha = hd.alpha;
    if (W == 0 || H == 0 || canvas.width != W || canvas.height != H || S == 0 || T == 0 || O == 0 ||
        canvas.rgb.size() != size_t(W) * H * 3 || (region && region->size() != size_t(W) * H) ||
        (alpha && (!model.alpha || canvas.alpha.size() != size_t(W) * H)))
        return st;

    const int step = std::clamp(opts.color_step, 1, 32);
    WorkerPool pool(resolve_threads(opts.threads));
    Plane plane{W, H, model.rgb, canvas.rgb.data()};
    if (alpha) {
        plane.model_a = model.alpha;
        plane.canvas_a = canvas.alpha.data();
        plane.alpha_weight = std::clamp(opts.alpha_weight, 1, 1024);
    }
    const double samples = (alpha ? 4.0 : 3.0) * W * H;
    // A caller's field is used when it fits (right size, valid indices); otherwise our own.
    const std::vector<uint8_t>* given = opts.orient == OrientMode::Random ? nullptr : opts.orientation_field;
    if (given && (given->size() != size_t(W) * H ||
                  std::any_of(given->begin(), given->end(), [&](uint8_t o) { return o >= O; })))
        given = nullptr;
    const std::vector<uint8_t> own = given ? std::vector<uint8_t>{} : orientation_field(model, hd.orientations, opts.orient);
    const std::vector<uint8_t>& field = given ? *given : own;

    const ReplayInfo ri = replay_info(setup, opts, W, H, region);
    const Domain base = make_domain(W, H, ri.regions.empty() ? ReplayRegion{} : ri.regions.front());
    Domain roi_domain;
    if (!opts.rois.empty()) roi_domain = make_domain(W, H, ri.regions.back());

    Domain whole;
    whole.total = uint64_t(W) * H;
    int64_t err = sse_over(plane, whole);
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
                    batch[i].score = score_split(pool, plane, *batch[i].fp, batch[i].px, batch[i].py, step);
                }
            } else {
                pool.run(bsize, [&](size_t i) {
                    draw(i);
                    batch[i].score = score_stamp(plane, *batch[i].fp->mask, batch[i].fp->spans, batch[i].px, batch[i].py, step);
                });
            }
            marks.next_batch();
            for (size_t i = 0; i < bsize && !stop; ++i) {
                Candidate& c = batch[i];
                if (marks.touched(*c.fp->mask, c.px, c.py, W, H)) {
                    c.score = score_stamp(plane, *c.fp->mask, c.fp->spans, c.px, c.py, step);
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
