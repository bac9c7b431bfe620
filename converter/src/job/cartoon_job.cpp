#include "job/cartoon_job.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <future>
#include <optional>
#include <string>

#include "io/image_io.hpp"
#include "io/template_loader.hpp"
#include "io/trial_output.hpp"
#include "job/painterly_sequence.hpp"
#include "job/painterly_still.hpp"
#include "paint/rate_control.hpp"
#include "paint/worker_pool.hpp"
#include "spt/version.hpp"
#include "spt/writer.hpp"
#include "video/video_paint.hpp"

namespace spt::job {

namespace {

cartoon::FillOptions fill_options(const PaintJob& o) {
    cartoon::FillOptions f;
    f.lines = o.lines;
    f.threads = paint::resolve_threads(o.paint.threads);
    if (o.outline_tolerance > 0) {
        f.trace.epsilon = o.outline_tolerance;
        f.search_tolerance = false;
    }
    f.trace.smooth = std::max(0.0, o.outline_smooth);
    if (o.min_region > 0) {
        f.min_region_pixels = o.min_region;
        f.search_min_region = false;
    }
    if (o.min_color_share > 0) {
        f.palette.min_share = o.min_color_share;
        f.search_palette = false;
    }
    return f;
}

// --target-bytes for the cartoon painter: bisection on the PSNR target between 15 and 60 dB,
// `steps` trials, each a whole painting (`trial`) coded to a trial file that has no name
// (io/trial_output.hpp); the fill layer's tolerance follows the target. Said on stderr as it
// goes; a budget below the smallest painting is said and that painting chosen.
struct TrialSize {
    uint64_t bytes = 0;
    double budget = 0;  // what --target-bytes allows this painting (N/s: its length at N a second)
};

Result<double> psnr_for_budget(const PaintJob& o, int steps,
                               const std::function<Result<TrialSize>(double psnr)>& trial) {
    double lo = 15, hi = 60, best = 0;
    uint64_t smallest = UINT64_MAX;
    for (int i = 0; i < steps; ++i) {
        const double mid = 0.5 * (lo + hi);
        auto t = trial(mid);
        if (!t) return t.error();
        if (o.progress != io::ProgressMode::None)
            std::fprintf(stderr, "spt paint: --target-bytes %llu: trial %d/%d at %.2f dB: %llu bytes\n",
                         (unsigned long long)o.target_bytes, i + 1, steps, mid, (unsigned long long)t->bytes);
        if (double(t->bytes) <= t->budget) { best = mid; lo = mid; } else { hi = mid; }
        smallest = std::min(smallest, t->bytes);
    }
    if (best == 0)
        std::fprintf(stderr, "spt paint: warning: --target-bytes %llu is below the smallest cartoon painting (%llu bytes); painting that\n",
                     (unsigned long long)o.target_bytes, (unsigned long long)smallest);
    const double psnr = best > 0 ? best : lo;
    std::fprintf(stderr, "spt paint: --target-bytes %llu: --target-psnr %.2f\n", (unsigned long long)o.target_bytes, psnr);
    return psnr;
}

// A still painting: its strokes, the canvas a decoder shows and the painter's figures.
struct Still {
    std::vector<Stroke> strokes;
    Canvas canvas;
    cartoon::CartoonStats st;
};

Still paint_still(const PaintJob& o, const paint::ImageView& model, const paint::PaintSetup& setup,
                  const Renderer& renderer, const paint::PaintOptions& po) {
    Still p;
    p.canvas = Canvas(model.width, model.height, o.background);
    p.st = cartoon::paint_cartoon(model, p.canvas, renderer, setup, po, fill_options(o), p.strokes);
    return p;
}

// Writes `p` to o.output, or only to `trial` when given; returns the file's bytes.
Result<uint64_t> write_still(const PaintJob& o, const paint::PaintSetup& setup, const paint::PaintOptions& po,
                             const Still& p, const io::TrialOutput* trial) {
    StreamInfo info;
    info.header = setup.header;
    info.templates = setup.templates;
    // Lines are curves with a grid (format 1.4); a painting without them stays 1.2.
    for (const Stroke& s : p.strokes) info.header.curve_grid = info.header.curve_grid || (s.kind == StrokeKind::Curve && s.curve.supersample);
    if (p.st.stamps.strokes == 0) {
        // Polygons only: the stamps' sets, orientations and templates (about 400 bytes, a
        // third of a flat cartoon frame) are not needed to decode it.
        info.templates.clear();
        info.header.sets.resize(1);
        info.header.orientations.resize(1);
    }
    PaintJob meta = o;
    meta.paint.target_psnr = po.target_psnr;
    info.metadata = {{"software", std::string("spt ") + library_version()},
                     {"source", std::filesystem::path(o.input).filename().string()},
                     {"painter.seed", std::to_string(o.paint.seed)},
                     {"painter.options", meta.canonical()}};
    WriterOptions wo;
    // The polygons and lines lead a coding-2 frame, and the stamps are coded as the candidates
    // they were drawn from (SPEC.md 7.7.5, format 1.5); without stamps the frame is coding 1.
    wo.coding = o.stored ? Coding::Stored : Coding::Replay;
    wo.atomic_rename = trial == nullptr;  // the trial file is never linked anywhere
    const std::string& path = trial ? trial->path() : o.output;
    auto explain = [&](Error e) {
        if (trial) e.message = trial->explain(e.message);
        return e;
    };
    auto writer = Writer::create(path, info, wo);
    if (!writer) return explain(writer.error());
    Frame frame;
    frame.added = p.strokes;
    frame.replay = p.st.replay;
    Status s = (*writer)->append(frame);
    if (s) s = (*writer)->finish();
    if (!s) {
        (*writer)->abort();
        Error e = s.error();
        e.message = path + ": " + e.message;
        return explain(e);
    }
    return (*writer)->stats().total_bytes;
}

// The still painting of `o`'s options and, short of the target, the smallest file of the outline
// and smallest-region trials below (each painted, coded to a trial file of its own and measured).
struct Searched {
    Still still;
    PaintJob opts;
    uint64_t bytes = 0;
    bool hopeless = false;  // given up: the default painter's file is far smaller
};

// The trials recorded in cartoon/README.md save at most about a third of the first painting's
// bytes, so a first painting over twice `give_up_above` (when not 0) cannot come under it: it is
// returned at once, `hopeless` set, the trials not made.
constexpr double kTrialsGainAtMost = 2.0;

Result<Searched> search_still(const PaintJob& o, const paint::ImageView& model, const paint::PaintSetup& setup,
                              const Renderer& renderer, const paint::PaintOptions& po, uint64_t give_up_above = 0) {
    Still best = paint_still(o, model, setup, renderer, po);
    PaintJob best_opts = o;
    if (give_up_above > 0) {
        auto out = io::TrialOutput::create(o.output);
        if (!out) return out.error();
        auto bytes = write_still(o, setup, po, best, &*out);
        if (!bytes) return bytes.error();
        if (double(*bytes) > kTrialsGainAtMost * double(give_up_above))
            return Searched{std::move(best), std::move(best_opts), *bytes, true};
    }
    // The polygons alone short of the target: stamps make up the rest, and which outline
    // tolerance trades vertices for stamps best depends on the picture (36 dB, bytes at 0.25 /
    // 0.35 / 0.5 px: taffy frame 30 25,931 / 29,760 / 39,899, frame 55 25,371 / 27,777 / 38,503,
    // frame 0 19,807 / 18,211 / 20,585; butterfly frame 40 27,604 / 25,778 / 24,789, frame 120
    // 29,603 / 27,773 / 26,344). The two others are painted too (side by side when there are
    // threads; each coded to a trial file of its own), and the smallest file is written.
    if (po.target_psnr > 0 && o.target_bytes == 0 && o.outline_tolerance == 0 && best.st.fill_psnr < po.target_psnr) {
        struct Trial {
            PaintJob opts;
            Still still;
            Result<uint64_t> bytes = uint64_t(0);
        };
        auto attempt = [&](double tol) {
            Trial t{o, {}, uint64_t(0)};
            t.opts.outline_tolerance = tol;  // 0: the default search, as painted above
            // Smoothed by their tolerance unless told (36 dB, bytes unsmoothed / smoothed:
            // taffy frame 30 at 0.25 px 23,202 / 21,667, butterfly frame 40 at 0.5 px 20,642 /
            // 19,359; the 0.35 px default loses when smoothed, 22,923 / 24,365 on taffy).
            if (tol > 0 && o.outline_smooth < 0) t.opts.outline_smooth = tol;
            if (tol > 0) t.still = paint_still(t.opts, model, setup, renderer, po);
            const Still& s = tol > 0 ? t.still : best;
            auto out = io::TrialOutput::create(o.output);
            t.bytes = out ? write_still(t.opts, setup, po, s, &*out) : Result<uint64_t>(out.error());
            return t;
        };
        const bool parallel = paint::resolve_threads(o.paint.threads) > 1;
        auto coarse = std::async(parallel ? std::launch::async : std::launch::deferred, attempt, 0.5);
        Trial trials[3] = {attempt(0), attempt(0.25), coarse.get()};
        size_t pick = 0;
        for (size_t i = 0; i < 3; ++i) {
            if (!trials[i].bytes) return trials[i].bytes.error();
            if (*trials[i].bytes < *trials[pick].bytes) pick = i;
        }
        if (pick > 0) {
            best = std::move(trials[pick].still);
            best_opts = trials[pick].opts;
        }
    }
    // Still short: the chosen outline again with each of cartoon::kMinRegionTrials (side by side
    // with threads), the smallest file written.
    if (po.target_psnr > 0 && o.target_bytes == 0 && o.min_region == 0 && best.st.fill_psnr < po.target_psnr) {
        auto size_of = [&](const PaintJob& opts, const Still& s) -> Result<uint64_t> {
            auto out = io::TrialOutput::create(o.output);
            if (!out) return out.error();
            return write_still(opts, setup, po, s, &*out);
        };
        auto now = size_of(best_opts, best);
        if (!now) return now.error();
        uint64_t smallest = *now;
        auto attempt = [&](int pixels) {
            PaintJob t = best_opts;
            t.min_region = pixels;
            return std::make_pair(t, paint_still(t, model, setup, renderer, po));
        };
        const bool parallel = paint::resolve_threads(o.paint.threads) > 1;
        auto first = std::async(parallel ? std::launch::async : std::launch::deferred, attempt, cartoon::kMinRegionTrials[0]);
        auto second = attempt(cartoon::kMinRegionTrials[1]);
        auto tried = first.get();
        for (auto* t : {&tried, &second}) {
            auto bytes = size_of(t->first, t->second);
            if (!bytes) return bytes.error();
            if (*bytes < smallest) {
                smallest = *bytes;
                best = std::move(t->second);
                best_opts = t->first;
            }
        }
    }
    auto out = io::TrialOutput::create(o.output);
    if (!out) return out.error();
    auto bytes = write_still(best_opts, setup, po, best, &*out);
    if (!bytes) return bytes.error();
    return Searched{std::move(best), std::move(best_opts), *bytes};
}

// The file's metadata; painter.options records the PSNR target a --target-bytes search chose.
std::vector<std::pair<std::string, std::string>> sequence_metadata(const PaintJob& o, double target_psnr) {
    PaintJob meta = o;
    meta.paint.target_psnr = target_psnr;
    return {{"software", std::string("spt ") + library_version()},
            {"source", std::filesystem::path(o.input).filename().string()},
            {"painter.seed", std::to_string(o.paint.seed)},
            {"painter.options", meta.canonical()}};
}

// --target-bytes for a sequence: each trial paints the whole sequence, with the file's real
// metadata (its bytes count too).
Result<double> search_sequence_psnr(const PaintJob& o, cartoon::SequenceOptions s) {
    auto trial = io::TrialOutput::create(o.output);
    if (!trial) return trial.error();
    s.output = trial->path();
    s.atomic_rename = false;
    constexpr int kSteps = 7;  // 45 dB / 2^7: the target within 0.4 dB
    return psnr_for_budget(o, kSteps, [&](double target) -> Result<TrialSize> {
        s.paint.target_psnr = target;
        s.metadata = sequence_metadata(o, target);
        cartoon::SequenceReport r;
        if (Status st = cartoon::paint_sequence(s, r); !st) {
            Error e = st.error();
            e.message = trial->explain(e.message);
            return e;
        }
        // N/s: the budget of the clip's length (frames / fps) at N bytes a second
        const double budget = o.target_bytes_per_second
                                  ? double(o.target_bytes) * double(r.frames) * r.fps.den / std::max<uint32_t>(1, r.fps.num)
                                  : double(o.target_bytes);
        return TrialSize{r.bytes, budget};
    });
}

// The sequence painter's options from the command's (no --target-bytes search yet).
Result<cartoon::SequenceOptions> sequence_options(const PaintJob& o) {
    cartoon::SequenceOptions s;
    s.input = o.input;
    s.output = o.output;
    s.frames = o.frames;
    s.fps = o.fps;
    s.skip_bad_frames = o.skip_bad_frames;
    s.keyframe_interval = o.keyframe_interval;
    s.paint = o.paint;
    s.sets = o.sets;
    s.background = o.background;
    s.stored = o.stored;
    s.fill = fill_options(o);
    s.smooth_short_keys = o.outline_smooth < 0;  // --outline-smooth: that smoothing, every frame
    // Sequences trace on 4x4 sub-pixels: with 8x8 the butterfly clip (frames 0-23, 36 dB)
    // took 580 KB instead of 469 KB (fewer still outlines matched frame to frame).
    s.fill.trace.upsample = 4;
    if (!o.templates_dir.empty()) {
        auto t = io::load_templates(o.templates_dir);
        if (!t) return t.error();
        s.templates = std::move(t.value());
    }
    return s;
}

}  // namespace

bool compares_with_default(const PaintJob& o) { return o.paint.target_psnr > 0 && o.target_bytes == 0; }

bool no_worse_at_target(double default_psnr, double cartoon_psnr, double target_psnr) {
    return default_psnr >= std::min(target_psnr, cartoon_psnr) - kDefaultPsnrSlackDb;
}

Result<CartoonStill> paint_cartoon_still(const PaintJob& o) {
    const auto t0 = std::chrono::steady_clock::now();
    io::ReadOptions ro;
    ro.background = o.background;
    auto img = io::read_image(o.input, ro);
    if (!img) return img.error();
    const uint32_t W = img->width, H = img->height;
    auto templates = paint_templates(o.templates_dir);
    if (!templates) return templates.error();
    std::vector<StrokeSet> sets = o.set_sizes.empty() ? paint::default_sets(W, H, o.sets) : o.set_sizes;
    paint::PaintSetup setup = paint::make_setup(W, H, o.background, std::move(sets), std::move(*templates));
    auto renderer = Renderer::create(setup.header, setup.templates);
    if (!renderer) return make_error(renderer.error().code, "cannot set up the renderer: " + renderer.error().message);

    const paint::ImageView model{W, H, img->rgb.data()};
    paint::PaintOptions po = o.paint;
    if (o.target_bytes > 0) {
        auto trial = io::TrialOutput::create(o.output);
        if (!trial) return trial.error();
        auto psnr = psnr_for_budget(o, 8, [&](double target) -> Result<TrialSize> {
            po.target_psnr = target;
            auto b = write_still(o, setup, po, paint_still(o, model, setup, **renderer, po), &*trial);
            if (!b) return b.error();
            return TrialSize{*b, double(o.target_bytes)};
        });
        if (!psnr) return psnr.error();
        po.target_psnr = *psnr;
    }
    // The default painter's painting first (it is quick): the cartoon search gives up when its
    // first painting is far larger, and the smaller of the two files is written.
    std::optional<io::TrialOutput> default_trial;
    std::optional<PainterlyStill> def;
    if (compares_with_default(o)) {
        PaintJob d = o;
        d.style = Style::Painterly;
        auto trial = io::TrialOutput::create(o.output);
        if (!trial) return trial.error();
        StillTarget to;
        to.path = trial->path();
        to.atomic_rename = false;
        to.metadata = painting_metadata(d);
        auto painted = paint_painterly_still(d, *img, to);
        if (!painted) return make_error(painted.error().code, trial->explain(painted.error().message));
        default_trial = std::move(*trial);
        def = std::move(*painted);
    }
    auto searched = search_still(o, model, setup, **renderer, po, def ? def->bytes : 0);
    if (!searched) return searched.error();
    const bool trials = po.target_psnr > 0 && o.target_bytes == 0 && !searched->hopeless;
    auto better = [&](const Result<Searched>& alt) {
        return alt->bytes < searched->bytes && paint::reaches_target(alt->still.st.stamps.psnr, po.target_psnr);
    };
    // Still short: the whole search again with each sparser palette in turn
    // (cartoon::kSparsePaletteShares) while it leaves colours out and reaches the target in
    // fewer bytes.
    const cv::Mat src(int(H), int(W), CV_8UC3, img->rgb.data());
    if (trials && o.min_color_share == 0 && searched->still.st.fill_psnr < po.target_psnr) {
        for (double share : cartoon::kSparsePaletteShares) {
            if (!cartoon::sparser_palette_has_fewer_colours(src, fill_options(searched->opts).palette, share)) break;
            PaintJob sparse = o;
            sparse.min_color_share = share;
            auto alt = search_still(sparse, model, setup, **renderer, po);
            if (!alt) return alt.error();
            if (!better(alt)) break;
            searched = std::move(alt);
        }
    }
    // A smoothed outline trial that won: smoothed twice as much (butterfly frame 40 at 0.25 px and
    // 1e-2: smoothed by 0.25 px 8,585 bytes, by 0.5 px 8,206), kept when smaller.
    if (trials && o.outline_smooth < 0 && searched->opts.outline_smooth > 0 && searched->still.st.fill_psnr < po.target_psnr) {
        PaintJob smoother = searched->opts;
        smoother.outline_smooth = std::min(2.0, 2 * smoother.outline_smooth);
        Still s = paint_still(smoother, model, setup, **renderer, po);
        auto out = io::TrialOutput::create(o.output);
        if (!out) return out.error();
        auto bytes = write_still(smoother, setup, po, s, &*out);
        if (!bytes) return bytes.error();
        Result<Searched> alt = Searched{std::move(s), smoother, *bytes};
        if (better(alt)) searched = std::move(alt);
    }
    CartoonStill r;
    if (def) {
        r.default_bytes = def->bytes;
        r.default_psnr = def->stats.psnr;
        r.cartoon_bytes = searched->bytes;
        if (no_worse_at_target(def->stats.psnr, searched->still.st.stamps.psnr, po.target_psnr) &&
            (searched->hopeless || def->bytes < searched->bytes)) {
            if (Status k = default_trial->keep(); !k) return k.error();
            r.used_default = true;
            r.canvas = std::move(def->canvas);
            r.bytes = def->bytes;
            r.target_psnr = po.target_psnr;
            r.stats = searched->still.st;
            r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            return r;
        }
    }
    auto written = write_still(searched->opts, setup, po, searched->still, nullptr);
    if (!written) return written.error();
    r.stats = searched->still.st;
    r.canvas = std::move(searched->still.canvas);
    r.bytes = *written;
    r.target_psnr = po.target_psnr;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

Status paint_cartoon_sequence(const PaintJob& o, const Metadata& extra, io::Progress* progress, CartoonSequence& out) {
    auto so = sequence_options(o);
    if (!so) return so.error();
    cartoon::SequenceOptions& s = *so;
    if (o.target_bytes > 0) {
        auto psnr = search_sequence_psnr(o, s);
        if (!psnr) return psnr.error();
        s.paint.target_psnr = *psnr;
    }
    out.target_psnr = s.paint.target_psnr;
    s.metadata = sequence_metadata(o, s.paint.target_psnr);
    video::merge_metadata(s.metadata, extra);
    s.progress = progress;
    if (Status st = cartoon::paint_sequence(s, out.report); !st) return st;
    out.cartoon_bytes = out.report.bytes;
    if (!compares_with_default(o)) return {};
    PaintJob d = o;
    d.style = Style::Painterly;
    video::VideoPaintOptions v;
    if (Status st = painterly_video_options(d, v); !st) return st;
    auto trial = io::TrialOutput::create(o.output);
    if (!trial) return trial.error();
    v.output = trial->path();
    v.atomic_rename = false;
    v.metadata = extra;
    io::Progress quiet(io::ProgressMode::None, "paint", 0);
    if (Status st = video::video_paint(v, progress ? *progress : quiet, &out.default_report); !st)
        return make_error(st.error().code, trial->explain(st.error().message));
    const video::VideoPaintReport& dr = out.default_report;
    if (dr.bytes < out.report.bytes && no_worse_at_target(dr.mean_psnr, out.report.mean_psnr, s.paint.target_psnr)) {
        if (Status k = trial->keep(); !k) return k;
        out.used_default = true;
    }
    return {};
}

}  // namespace spt::job
