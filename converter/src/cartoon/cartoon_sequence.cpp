#include "cartoon/cartoon_sequence.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <optional>

#include <opencv2/imgproc.hpp>

#include "cartoon/cartoon_paint.hpp"
#include "cartoon/inter_frame.hpp"
#include "cartoon/memory_bound.hpp"
#include "cartoon/retrace_outline.hpp"
#include "frames/frame_rate.hpp"
#include "frames/frame_source.hpp"
#include "frames/stop_signal.hpp"
#include "paint/frame_seed.hpp"
#include "paint/rate_control.hpp"
#include "paint/worker_pool.hpp"
#include "spt/concat.hpp"
#include "spt/reader.hpp"
#include "spt/writer.hpp"

namespace spt::cartoon {

namespace {

// The outline tolerance a key frame also tries when its polygons fall short of the target (the
// search's finest, 0.35 px, comes first). Only a coarser one: a finer outline follows noise from
// frame to frame, and the inter frames trace it again (the grain test: 3 polygons added a frame
// at 0.25 px, chosen for its key frame's 2% fewer bytes). Key frames alone at 36 dB (--frames
// 0-0), bytes at 0.25 / 0.35 / 0.5 px: taffy 20,434 / 18,039 / 18,867, butterfly 31,029 /
// 29,934 / 27,313; the 12 frames: taffy 287,908 / 258,230 / 305,577, butterfly 59,729 / 56,775 /
// 55,822.
constexpr double kCoarserKeyTolerance = 0.5;
// The contour smoothing (TraceOptions::smooth, pixels) a key frame short of its target also
// tries, with the default tolerance and the coarser one; the cheapest key frame sets the
// interval's. Blurred and noisy edges zigzag at sub-pixel scale, and each zigzag is a vertex.
// 12 frames at 36 dB with every frame smoothed by 0 / 0.25 / 0.5 px: taffy 213,850 / 208,274 /
// 222,837, butterfly 42,641 / 40,912 / 41,775, star 3,871 / 7,435 / 10,436 (its polygons reach
// the target unsmoothed, so it never tries).
constexpr double kShortKeySmooth = 0.25;

struct KeyFrame {
    Frame frame;            // the key frame: polygons and lines, then stamps
    Canvas canvas;          // as a decoder renders it
    FillLayer fill;         // its palette, grid and tolerance (strokes moved into `frame`)
    bool short_of_target = false;  // the polygons alone missed the PSNR target
    uint64_t polygons = 0, stamps = 0;
};

// A key frame painted with the fill options `fo` (palette, grid and tolerance searched).
Result<KeyFrame> paint_key(const cv::Mat& rgb, const paint::ImageView& model, const Renderer& renderer,
                           const paint::PaintSetup& setup, const SequenceOptions& opts, const FillOptions& fo,
                           uint32_t index) {
    KeyFrame k;
    k.canvas = Canvas(model.width, model.height, opts.background);
    double p = 0;
    k.fill = fill_for_target(rgb, opts.background, renderer, fo, opts.paint.target_psnr, nullptr, k.canvas, p);
    Frame& f = k.frame;
    f.type = FrameType::Key;
    f.added = std::move(k.fill.strokes);
    k.fill.strokes.clear();
    k.polygons = f.added.size();
    // The canvas before the residual stamps: the polygons as a decoder draws them.
    if (Status s = renderer.render(k.canvas, f.added); !s) return s.error();
    paint::PaintOptions po = opts.paint;
    po.seed = paint::frame_seed(opts.paint.seed, index);
    // As on inter frames (inter_frame.hpp). Key frame lambda times 1 / 8 / 16 / 32, with inter
    // frames' at 16, 12 frames at 36 dB: butterfly 78,028 / 62,804 / 61,559 / 59,860 bytes (its
    // key frame 55,475 -> 35,359 at 16), taffy 399,014 / 386,954 / 384,468 / 384,329, star 3,982
    // throughout (its polygons reach the target).
    if (po.target_psnr > 0) po.lambda *= kResidualLambdaScale;
    k.short_of_target = po.target_psnr > 0 && p < po.target_psnr;
    if (!(po.target_psnr > 0 && paint::psnr(model, k.canvas.rgb.data()) >= po.target_psnr)) {
        const std::vector<uint8_t> region = residual_region(model, k.canvas, 24, 2);
        if (!region.empty()) {
            std::vector<Stroke> stamps;
            paint::paint(model, k.canvas, renderer, setup, po, stamps, &region);
            k.stamps = stamps.size();
            if (!stamps.empty()) f.replay = paint::replay_info(setup, po, model.width, model.height, &region);
            f.added.insert(f.added.end(), stamps.begin(), stamps.end());
        }
    }
    return k;
}

// A key frame, which chooses the palette, grid and outline tolerance for its interval, so that
// what stays still traces the same in the frames after. One short of its target is also painted
// with a coarser outline (kCoarserKeyTolerance) and, with smooth_short_keys, smoothed
// (kShortKeySmooth): stamps make up what the polygons miss, and which outline trades vertices for
// stamps best depends on the picture; the cheapest key frame decides it for the interval. With
// threads the coarser painting runs beside the first (unused when that one reaches the target).
Result<KeyFrame> choose_outline(const cv::Mat& rgb, const paint::ImageView& model, const Renderer& renderer,
                                const paint::PaintSetup& setup, const SequenceOptions& opts, uint32_t index, bool parallel) {
    const bool may_try = opts.fill.search_tolerance && opts.paint.target_psnr > 0;
    auto coarser = std::async(parallel && may_try ? std::launch::async : std::launch::deferred, [&] {
        FillOptions t = opts.fill;
        t.search_tolerance = false;
        t.trace.epsilon = kCoarserKeyTolerance;
        if (opts.smooth_short_keys) t.trace.smooth = kShortKeySmooth;
        return paint_key(rgb, model, renderer, setup, opts, t, index);
    });
    auto painted = paint_key(rgb, model, renderer, setup, opts, opts.fill, index);
    if (!painted) return painted.error();
    KeyFrame k = std::move(*painted);
    if (k.short_of_target && may_try) {
        // The default tolerance smoothed, beside the coarser painting when it still runs.
        std::optional<Result<KeyFrame>> smoothed;
        if (opts.smooth_short_keys) {
            FillOptions t = opts.fill;
            t.search_tolerance = false;
            t.trace.smooth = kShortKeySmooth;
            smoothed = paint_key(rgb, model, renderer, setup, opts, t, index);
            if (!*smoothed) return smoothed->error();
        }
        auto c = coarser.get();
        if (!c) return c.error();
        if (std::getenv("SPT_CARTOON_DEBUG"))
            std::fprintf(stderr, "key frame %u: tolerance %.2f cost %.0f, %.2f cost %.0f, smoothed %.0f\n", index,
                         k.fill.tolerance, frame_cost(k.frame), c->fill.tolerance, frame_cost(c->frame),
                         smoothed ? frame_cost((**smoothed).frame) : 0.0);
        if (frame_cost(c->frame) < frame_cost(k.frame)) k = std::move(*c);
        if (smoothed && frame_cost((**smoothed).frame) < frame_cost(k.frame)) k = std::move(**smoothed);
    }  // else an asynchronous coarser painting is waited for, unused, when `coarser` goes
    if (k.short_of_target && opts.fill.search_min_region && opts.paint.target_psnr > 0) {
        // The cheapest outline again with each of kMinRegionTrials (side by side with threads).
        auto with_min_region = [&](int pixels) {
            FillOptions t = opts.fill;
            t.search_tolerance = false;
            t.trace.epsilon = k.fill.tolerance;
            t.trace.smooth = k.fill.smooth;
            t.min_region_pixels = pixels;
            return paint_key(rgb, model, renderer, setup, opts, t, index);
        };
        auto first = std::async(parallel ? std::launch::async : std::launch::deferred, with_min_region, kMinRegionTrials[0]);
        auto second = with_min_region(kMinRegionTrials[1]);
        auto tried = first.get();
        for (Result<KeyFrame>* t : {&tried, &second}) {
            if (!*t) return t->error();
            if (std::getenv("SPT_CARTOON_DEBUG"))
                std::fprintf(stderr, "key frame %u: min region %d cost %.0f, %d cost %.0f\n", index, k.fill.min_region,
                             frame_cost(k.frame), (**t).fill.min_region, frame_cost((**t).frame));
            if (frame_cost((**t).frame) < frame_cost(k.frame)) k = std::move(**t);
        }
    }
    return k;
}

// A key frame: its outline and smallest region chosen (choose_outline), and, short of its target,
// the same choice with each sparser palette in turn (kSparsePaletteShares) while it leaves
// colours out and reaches the target in fewer estimated bytes. The interval takes its palette.
Result<KeyFrame> choose_key(const cv::Mat& rgb, const paint::ImageView& model, const Renderer& renderer,
                            const paint::PaintSetup& setup, const SequenceOptions& opts, uint32_t index, bool parallel) {
    auto k = choose_outline(rgb, model, renderer, setup, opts, index, parallel);
    if (!k || !k->short_of_target || !opts.fill.search_palette || !(opts.paint.target_psnr > 0)) return k;
    SequenceOptions sparse = opts;
    for (double share : kSparsePaletteShares) {
        if (!sparser_palette_has_fewer_colours(rgb, sparse.fill.palette, share)) break;
        sparse.fill.palette.min_share = share;
        auto alt = choose_outline(rgb, model, renderer, setup, sparse, index, parallel);
        if (!alt) return alt.error();
        const double p = paint::psnr(model, alt->canvas.rgb.data());
        if (std::getenv("SPT_CARTOON_DEBUG"))
            std::fprintf(stderr, "key frame %u: %zu colours cost %.0f, %zu colours cost %.0f at %.2f dB\n", index,
                         k->fill.palette.size(), frame_cost(k->frame), alt->fill.palette.size(), frame_cost(alt->frame), p);
        if (!(frame_cost(alt->frame) < frame_cost(k->frame) && paint::reaches_target(p, opts.paint.target_psnr))) break;
        k = std::move(alt);
    }
    return k;
}

}  // namespace

Status paint_sequence(const SequenceOptions& opts, SequenceReport& rep) {
    const auto t0 = std::chrono::steady_clock::now();
    video::StopSignals stop(opts.install_signal_handlers);
    auto src = video::open_source(opts.input, opts.frames, opts.skip_bad_frames);
    if (!src) return src.error();
    video::FrameSource& source = **src;
    Rational fps{24, 1};
    if (!opts.fps.empty()) {
        auto f = video::parse_fps(opts.fps);
        if (!f) return f.error();
        fps = *f;
    } else if (source.has_fps()) {
        fps = source.fps();
    }
    video::SourceFrame frame;
    auto got = source.next(frame);
    if (!got) return got.error();
    if (!*got) {
        const std::string why = source.shortfall();
        return make_error(Code::IoError, why.empty() ? source.describe() + ": no frames to paint" : why);
    }
    const uint32_t W = frame.image.width, H = frame.image.height;
    if (Status m = check_memory(source.describe(), W, H, kSequenceBytesPerPixel, opts.max_memory); !m) return m;

    paint::PaintSetup setup = paint::make_setup(W, H, opts.background, paint::default_sets(W, H, opts.sets),
                                                opts.templates.empty() ? paint::default_templates() : opts.templates);
    setup.header.fps = fps;
    rep.fps = fps;
    setup.header.frame_count = kUnknownFrameCount;
    // Lines are curves with a grid (format 1.4); decided before the first frame is painted.
    setup.header.curve_grid = opts.fill.lines;
    auto renderer = Renderer::create(setup.header, setup.templates);
    if (!renderer) return renderer.error();
    StreamInfo info;
    info.header = setup.header;
    info.templates = setup.templates;
    info.metadata = opts.metadata;
    // SPEC.md 3.3: the source's own number of frame 0, so that farm shots join in order.
    if (frame.number > 0 && video::frames_consecutive(opts.frames))
        info.metadata.emplace_back(kFirstFrameKey, std::to_string(frame.number));
    WriterOptions wo;
    wo.coding = opts.stored ? Coding::Stored : Coding::Replay;  // stamps after polygons: SPEC.md 7.7.5
    wo.atomic_rename = opts.atomic_rename;
    auto writer = Writer::create(opts.output, info, wo);
    if (!writer) return writer.error();

    if (opts.progress) opts.progress->set_total(double(source.expected_frames()));
    const bool parallel = paint::resolve_threads(opts.paint.threads) > 1;
    std::vector<Stroke> live;
    std::vector<cv::Vec3b> palette;
    FillOptions fo = opts.fill;
    RetraceTrials retrace;
    io::Image prev;
    Canvas canvas(W, H, opts.background);
    double psnr_sum = 0;
    uint32_t index = 0, since_key = 0;
    double key_cost = 0;  // the interval's key frame, estimated bytes (frame_cost)
    for (;;) {
        if (frame.repeated)  // --skip-bad-frames, as the video painter says it
            std::fprintf(stderr, "spt paint: warning: %s; repeating the previous frame\n", frame.problem.c_str());
        const io::Image& img = frame.image;
        const cv::Mat rgb(int(H), int(W), CV_8UC3, const_cast<uint8_t*>(img.rgb.data()));
        const paint::ImageView model{W, H, img.rgb.data()};
        const bool key = index == 0 || since_key >= uint32_t(opts.keyframe_interval);
        Frame f;
        // A key frame starts an interval: its palette, grid and outline for the frames after.
        auto take_key = [&](KeyFrame&& k) {
            palette = k.fill.palette;
            fo = opts.fill;
            fo.grids = {k.fill.grid ? k.fill.grid : uint8_t(4)};
            fo.trace.epsilon = k.fill.tolerance;
            fo.trace.smooth = k.fill.smooth;
            fo.min_region_pixels = k.fill.min_region;
            retrace = {};
            f = std::move(k.frame);
            key_cost = frame_cost(f);
            canvas = std::move(k.canvas);
            rep.polygons_added += k.polygons;
            rep.stamps_added += k.stamps;
            ++rep.key_frames;
            since_key = 0;
        };
        if (key) {
            auto chosen = choose_key(rgb, model, **renderer, setup, opts, index, parallel);
            if (!chosen) return chosen.error();
            take_key(std::move(*chosen));
        } else {
            const FillLayer fill = build_fill_layer(rgb, opts.background, **renderer, fo, &palette, &live);
            InterInput in;
            in.live = &live;
            in.polygons = &fill.strokes;
            in.cur = rgb;
            in.prev = cv::Mat(int(H), int(W), CV_8UC3, prev.rgb.data());
            in.model = model;
            in.shown = &canvas;
            in.renderer = renderer->get();
            in.setup = &setup;
            in.motion = opts.motion;
            in.paint = opts.paint;
            in.paint.seed = paint::frame_seed(opts.paint.seed, index);
            auto r = paint_inter_frame(in);
            if (!r) return r.error();
            if (opts.fill.search_tolerance && !r->unchanged && !r->patched) {
                // The regions it traced anew may take a coarser outline.
                const std::vector<bool> retraced = retraced_regions(fill, r->frame);
                auto paint_at = [&](double tolerance) -> Result<InterFrame> {
                    FillOptions t = fo;
                    t.trace.epsilon = tolerance;
                    const FillLayer coarse = build_fill_layer(rgb, opts.background, **renderer, t, &palette, &live);
                    const std::vector<Stroke> mixed = with_coarser_regions(fill, coarse, retraced);
                    InterInput at = in;
                    at.polygons = &mixed;
                    return paint_inter_frame(at);
                };
                const bool any = std::find(retraced.begin(), retraced.end(), true) != retraced.end();
                r = choose_retrace_outline(std::move(*r), any, fo.trace.epsilon, opts.paint.target_psnr, model, retrace,
                                           paint_at, parallel);
                if (!r) return r.error();
            }
            if (std::getenv("SPT_CARTOON_DEBUG"))  // tuning aid: what each frame keeps and adds
                std::fprintf(stderr, "frame %u: %s, removed %zu, polygons added %llu (stood in %u, left out %u), kept %.2f dB, stamps %llu, cost %.0f\n",
                             index, r->lenient ? "lenient" : "strict", r->frame.removed.size(),
                             (unsigned long long)r->polygons_added, r->stood_in, r->left_out, r->kept_psnr,
                             (unsigned long long)r->stamps, r->cost);
            // An inter frame short of the target (the stamps stop improving a canvas that
            // many frames of kept and added strokes built) is painted again as a key frame,
            // kept when it comes closer.
            const double target = opts.paint.target_psnr;
            // So is one that costs more than twice its key frame (what the issue-34 budget
            // allows when every pixel changed): a key frame painted now may be the cheaper, as
            // when a fade leaves the interval's tiny key frame far behind. Kept when it reaches
            // the target for fewer estimated bytes.
            std::optional<KeyFrame> fresh;
            const bool short_of_target =
                target > 0 && !paint::reaches_target(paint::psnr(model, r->canvas.rgb.data()), target);
            const bool dearer_than_keys = target > 0 && r->cost > 2 * key_cost + 64;
            if (!r->unchanged && (short_of_target || dearer_than_keys)) {
                auto chosen = choose_key(rgb, model, **renderer, setup, opts, index, parallel);
                if (!chosen) return chosen.error();
                const double pk = paint::psnr(model, chosen->canvas.rgb.data());
                if (short_of_target ? pk > paint::psnr(model, r->canvas.rgb.data())
                                    : paint::reaches_target(pk, target) && frame_cost(chosen->frame) < r->cost)
                    fresh = std::move(*chosen);
            }
            if (fresh) {
                take_key(std::move(*fresh));
            } else {
                f = std::move(r->frame);
                canvas = std::move(r->canvas);
                if (!f.motion.empty()) ++rep.motion_frames;
                rep.polygons_kept += r->polygons_kept;
                rep.polygons_added += r->polygons_added;
                rep.stamps_added += r->stamps;
                rep.removed += f.removed.size();
            }
        }
        f.index = index;
        if (Status s = (*writer)->append(f); !s) {
            (*writer)->abort();
            return s;
        }
        // The live list as a decoder keeps it.
        if (Status s = apply_frame(live, f, setup.header); !s) return s;
        const double p = paint::psnr(model, canvas.rgb.data());
        if (opts.progress) {
            char detail[160];
            std::snprintf(detail, sizeof detail, "%s frame %u, %zu strokes added, %zu live, %.1f dB",
                          f.type == FrameType::Key ? "key" : "inter", index, f.added.size(), live.size(), p);
            opts.progress->update(double(index + 1), detail);
        }
        psnr_sum += p;
        if (p < rep.min_psnr) {
            rep.min_psnr = p;
            rep.min_psnr_frame = uint32_t(rep.frames);
        }
        if (!paint::reaches_target(p, opts.paint.target_psnr)) ++rep.frames_short;
        ++rep.frames;
        ++index;
        ++since_key;
        prev = img;
        if (video::StopSignals::requested()) {
            rep.interrupted = true;
            break;
        }
        got = source.next(frame);
        if (!got) {
            (*writer)->abort();
            return got.error();
        }
        if (!*got) {
            if (const std::string why = source.shortfall(); !why.empty())
                std::fprintf(stderr, "spt paint: warning: %s\n", why.c_str());
            break;
        }
    }
    if (Status s = (*writer)->finish(); !s) return s;
    rep.bytes = (*writer)->stats().total_bytes;
    rep.mean_psnr = rep.frames ? psnr_sum / double(rep.frames) : 0;
    rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (rep.interrupted)
        return make_error(Code::BadState, "interrupted: " + opts.output + " holds the " + std::to_string(rep.frames) +
                                              " finished frames");
    return {};
}

}  // namespace spt::cartoon
