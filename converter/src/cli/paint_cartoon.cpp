#include "cli/paint_cartoon.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <future>
#include <string>

#include "cartoon/cartoon_paint.hpp"
#include "cartoon/cartoon_sequence.hpp"
#include "cli/commands.hpp"
#include "io/image_io.hpp"
#include "io/progress.hpp"
#include "io/sequence.hpp"
#include "io/template_loader.hpp"
#include "io/trial_output.hpp"
#include "paint/worker_pool.hpp"
#include "spt/version.hpp"
#include "spt/writer.hpp"
#include "video/video_paint.hpp"

namespace spt::cli {

namespace {

int fail(const std::string& msg) { return command_failed("paint", msg); }

cartoon::FillOptions fill_options(const PaintCommandOptions& o) {
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

Result<double> psnr_for_budget(const PaintCommandOptions& o, int steps,
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

Still paint_still(const PaintCommandOptions& o, const paint::ImageView& model, const paint::PaintSetup& setup,
                  const Renderer& renderer, const paint::PaintOptions& po) {
    Still p;
    p.canvas = Canvas(model.width, model.height, o.background);
    p.st = cartoon::paint_cartoon(model, p.canvas, renderer, setup, po, fill_options(o), p.strokes);
    return p;
}

// Writes `p` to o.output, or only to `trial` when given; returns the file's bytes.
Result<uint64_t> write_still(const PaintCommandOptions& o, const paint::PaintSetup& setup, const paint::PaintOptions& po,
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
    PaintCommandOptions meta = o;
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
    PaintCommandOptions opts;
    uint64_t bytes = 0;
};

Result<Searched> search_still(const PaintCommandOptions& o, const paint::ImageView& model, const paint::PaintSetup& setup,
                              const Renderer& renderer, const paint::PaintOptions& po) {
    Still best = paint_still(o, model, setup, renderer, po);
    PaintCommandOptions best_opts = o;
    // The polygons alone short of the target: stamps make up the rest, and which outline
    // tolerance trades vertices for stamps best depends on the picture (36 dB, bytes at 0.25 /
    // 0.35 / 0.5 px: taffy frame 30 25,931 / 29,760 / 39,899, frame 55 25,371 / 27,777 / 38,503,
    // frame 0 19,807 / 18,211 / 20,585; butterfly frame 40 27,604 / 25,778 / 24,789, frame 120
    // 29,603 / 27,773 / 26,344). The two others are painted too (side by side when there are
    // threads; each coded to a trial file of its own), and the smallest file is written.
    if (po.target_psnr > 0 && o.target_bytes == 0 && o.outline_tolerance == 0 && best.st.fill_psnr < po.target_psnr) {
        struct Trial {
            PaintCommandOptions opts;
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
        auto size_of = [&](const PaintCommandOptions& opts, const Still& s) -> Result<uint64_t> {
            auto out = io::TrialOutput::create(o.output);
            if (!out) return out.error();
            return write_still(opts, setup, po, s, &*out);
        };
        auto now = size_of(best_opts, best);
        if (!now) return now.error();
        uint64_t smallest = *now;
        auto attempt = [&](int pixels) {
            PaintCommandOptions t = best_opts;
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

int paint_cartoon_still(const PaintCommandOptions& o) {
    const auto t0 = std::chrono::steady_clock::now();
    io::ReadOptions ro;
    ro.background = o.background;
    auto img = io::read_image(o.input, ro);
    if (!img) return fail(img.error().message);
    const uint32_t W = img->width, H = img->height;
    auto templates = paint_templates(o.templates_dir);
    if (!templates) return fail(templates.error().message);
    std::vector<StrokeSet> sets = o.set_sizes.empty() ? paint::default_sets(W, H, o.sets) : o.set_sizes;
    paint::PaintSetup setup = paint::make_setup(W, H, o.background, std::move(sets), std::move(*templates));
    auto renderer = Renderer::create(setup.header, setup.templates);
    if (!renderer) return fail("cannot set up the renderer: " + renderer.error().message);

    const paint::ImageView model{W, H, img->rgb.data()};
    paint::PaintOptions po = o.paint;
    if (o.target_bytes > 0) {
        auto trial = io::TrialOutput::create(o.output);
        if (!trial) return fail(trial.error().message);
        auto psnr = psnr_for_budget(o, 8, [&](double target) -> Result<TrialSize> {
            po.target_psnr = target;
            auto b = write_still(o, setup, po, paint_still(o, model, setup, **renderer, po), &*trial);
            if (!b) return b.error();
            return TrialSize{*b, double(o.target_bytes)};
        });
        if (!psnr) return fail(psnr.error().message);
        po.target_psnr = *psnr;
    }
    auto searched = search_still(o, model, setup, **renderer, po);
    if (!searched) return fail(searched.error().message);
    const bool trials = po.target_psnr > 0 && o.target_bytes == 0;
    auto better = [&](const Result<Searched>& alt) {
        return alt->bytes < searched->bytes && alt->still.st.stamps.psnr >= po.target_psnr - 0.005;
    };
    // Still short: the whole search again with each sparser palette in turn
    // (cartoon::kSparsePaletteShares) while it leaves colours out and reaches the target in
    // fewer bytes.
    const cv::Mat src(int(H), int(W), CV_8UC3, img->rgb.data());
    if (trials && o.min_color_share == 0 && searched->still.st.fill_psnr < po.target_psnr) {
        for (double share : cartoon::kSparsePaletteShares) {
            if (!cartoon::sparser_palette_has_fewer_colours(src, fill_options(searched->opts).palette, share)) break;
            PaintCommandOptions sparse = o;
            sparse.min_color_share = share;
            auto alt = search_still(sparse, model, setup, **renderer, po);
            if (!alt) return fail(alt.error().message);
            if (!better(alt)) break;
            searched = std::move(alt);
        }
    }
    // A smoothed outline trial that won: smoothed twice as much (butterfly frame 40 at 0.25 px and
    // 1e-2: smoothed by 0.25 px 8,585 bytes, by 0.5 px 8,206), kept when smaller.
    if (trials && o.outline_smooth < 0 && searched->opts.outline_smooth > 0 && searched->still.st.fill_psnr < po.target_psnr) {
        PaintCommandOptions smoother = searched->opts;
        smoother.outline_smooth = std::min(2.0, 2 * smoother.outline_smooth);
        Still s = paint_still(smoother, model, setup, **renderer, po);
        auto out = io::TrialOutput::create(o.output);
        if (!out) return fail(out.error().message);
        auto bytes = write_still(smoother, setup, po, s, &*out);
        if (!bytes) return fail(bytes.error().message);
        Result<Searched> alt = Searched{std::move(s), smoother, *bytes};
        if (better(alt)) searched = std::move(alt);
    }
    Still best = std::move(searched->still);
    const PaintCommandOptions best_opts = std::move(searched->opts);
    auto written = write_still(best_opts, setup, po, best, nullptr);
    if (!written) return fail(written.error().message);
    const uint64_t bytes = *written;
    const Canvas& canvas = best.canvas;
    const cartoon::CartoonStats& st = best.st;
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!o.preview.empty())
        if (Status p = io::write_image(o.preview, canvas); !p) return fail(p.error().message);
    if (o.progress != io::ProgressMode::None)
        std::fprintf(stderr,
                     "spt paint: %s: %zu colours, %zu regions, %zu polygons (%zu vertices), %zu lines (%zu points), "
                     "grid %d, %.2f dB; %llu stamps; %.2f dB PSNR, %llu bytes, %.2f s\n",
                     o.output.c_str(), st.colors, st.regions, st.polygons, st.vertices, st.lines, st.line_points,
                     int(st.grid), st.fill_psnr,
                     (unsigned long long)st.stamps.strokes, st.stamps.psnr, (unsigned long long)bytes, secs);
    if (po.target_psnr > 0 && st.stamps.psnr < po.target_psnr - 0.005)
        std::fprintf(stderr, "spt paint: warning: %s is %.2f dB, short of --target-psnr %.2f: the residual stamps stopped "
                             "improving it\n", o.output.c_str(), st.stamps.psnr, po.target_psnr);
    return 0;
}

// The file's metadata; painter.options records the PSNR target a --target-bytes search chose.
std::vector<std::pair<std::string, std::string>> sequence_metadata(const PaintCommandOptions& o, double target_psnr) {
    PaintCommandOptions meta = o;
    meta.paint.target_psnr = target_psnr;
    return {{"software", std::string("spt ") + library_version()},
            {"source", std::filesystem::path(o.input).filename().string()},
            {"painter.seed", std::to_string(o.paint.seed)},
            {"painter.options", meta.canonical()}};
}

// --target-bytes for a sequence: each trial paints the whole sequence, with the file's real
// metadata (its bytes count too).
Result<double> search_sequence_psnr(const PaintCommandOptions& o, cartoon::SequenceOptions s) {
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
Result<cartoon::SequenceOptions> sequence_options(const PaintCommandOptions& o) {
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

// Paints the sequence of `o` (searching the PSNR target first for --target-bytes) with the
// file's metadata plus `extra` (entries of the same key replaced); returns the exit code.
int paint_cartoon_sequence(const PaintCommandOptions& o, const Metadata& extra, uint64_t* frames) {
    if (!o.preview.empty()) return fail("--preview is for still images; render a sequence with 'spt render'");
    auto so = sequence_options(o);
    if (!so) return fail(so.error().message);
    cartoon::SequenceOptions& s = *so;
    if (o.target_bytes > 0) {
        auto psnr = search_sequence_psnr(o, s);
        if (!psnr) return fail(psnr.error().message);
        s.paint.target_psnr = *psnr;
    }
    s.metadata = sequence_metadata(o, s.paint.target_psnr);
    video::merge_metadata(s.metadata, extra);
    io::Progress progress(o.progress, "paint", 0);
    s.progress = &progress;
    cartoon::SequenceReport r;
    const Status st = cartoon::paint_sequence(s, r);
    if (frames) *frames = r.frames;
    progress.finish(bool(st), st ? o.output : st.error().message);
    if (!st && r.interrupted) {  // stopped by a signal after a finished frame: the output is valid
        std::fprintf(stderr, "spt paint: %s\n", st.error().message.c_str());
        return video::kExitInterrupted;
    }
    if (!st) return fail(st.error().message);
    if (o.progress != io::ProgressMode::None)
        std::fprintf(stderr,
                     "spt paint: %s: %llu frames (%llu key, %llu with motion), polygons %llu added %llu kept, %llu stamps, %llu removed; "
                     "PSNR mean %.2f dB min %.2f; %llu bytes, %.2f s (%.3f s a frame)\n",
                     o.output.c_str(), (unsigned long long)r.frames, (unsigned long long)r.key_frames,
                     (unsigned long long)r.motion_frames,
                     (unsigned long long)r.polygons_added, (unsigned long long)r.polygons_kept,
                     (unsigned long long)r.stamps_added, (unsigned long long)r.removed, r.mean_psnr, r.min_psnr,
                     (unsigned long long)r.bytes, r.seconds, r.frames ? r.seconds / double(r.frames) : 0.0);
    if (r.frames_short > 0)
        std::fprintf(stderr, "spt paint: warning: %llu of %llu frames short of --target-psnr %.2f (lowest %.2f dB, frame %u "
                             "of the file): the residual stamps stopped improving them\n",
                     (unsigned long long)r.frames_short, (unsigned long long)r.frames, s.paint.target_psnr, r.min_psnr,
                     r.min_psnr_frame);
    return 0;
}

}  // namespace

int paint_cartoon(const PaintCommandOptions& o) {
    std::error_code ec;
    if (io::is_sequence_pattern(o.input) || io::is_video_file(o.input) || std::filesystem::is_directory(o.input, ec))
        return paint_cartoon_sequence(o, {}, nullptr);
    if (!o.side_by_side.empty()) return fail("--style cartoon: --side-by-side is not supported; use --preview");
    return paint_cartoon_still(o);
}

int paint_cartoon_shot(const PaintCommandOptions& o, const Metadata& metadata, uint64_t& frames) {
    frames = 0;
    return paint_cartoon_sequence(o, metadata, &frames);
}

}  // namespace spt::cli
