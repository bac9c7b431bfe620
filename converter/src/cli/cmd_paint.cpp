// spt paint: an image to a .spt painting. Options are parsed into PaintCommandOptions
// (paint_options.hpp) so that the video encoder can take the same struct; a sequence or video
// input is routed to paint_sequence(), which the video path will fill in.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "cli/commands.hpp"
#include "cli/paint_cartoon.hpp"
#include "cli/paint_options.hpp"
#include "cli/paint_plan.hpp"
#include "cli/paint_progress.hpp"
#include "cli/paint_scene_still.hpp"
#include "cli/still_setup.hpp"
#include "io/image_io.hpp"
#include "io/trial_output.hpp"
#include "io/sequence.hpp"
#include "io/template_loader.hpp"
#include "paint/painter.hpp"
#include "paint/rate_control.hpp"
#include "spt/render.hpp"
#include "spt/version.hpp"
#include "spt/atomic_file.hpp"
#include "spt/utf8.hpp"
#include "spt/writer.hpp"
#include "video/video_paint.hpp"

namespace spt::cli {

namespace {

int fail(const std::string& msg) { return command_failed("paint", msg); }

}  // namespace

// Sequences and videos go to the video encoder (converter/src/video), with the same painting
// options as a still.
int video_options(const PaintCommandOptions& o, video::VideoPaintOptions& v) {
    if (!o.preview.empty() || !o.side_by_side.empty())
        return fail("--preview and --side-by-side are for still images; render a sequence with "
                    "'spt render " + o.output + " -o frame.####.png'");
    if (!o.set_sizes.empty())
        return fail("--set-sizes is not supported for sequences yet; use --sets N");
    v.input = o.input;
    v.output = o.output;
    v.frames = o.frames;
    v.fps = o.fps;
    v.skip_bad_frames = o.skip_bad_frames;
    v.keyframe_interval = o.keyframe_interval;
    v.roi_file = o.roi_file;
    v.cut_threshold = o.cut_threshold;
    if (!video::parse_flow_method(o.flow, v.flow))
        return fail("--flow: unknown method '" + o.flow + "' (dis-ultrafast, dis-fast, dis-medium, farneback)");
    v.block_size = o.block_size;
    v.flow_orientation = o.flow_orientation;
    v.max_inter_strokes = o.max_inter_strokes;
    v.paint = o.paint;
    v.paint.rois.clear();  // --roi rectangles apply to every frame; --roi-file ones per frame range
    for (size_t i = 0; i < o.cli_roi_count && i < o.rois.size(); ++i) v.paint.rois.push_back(o.rois[i].rect);
    v.sets = o.sets;
    v.background = o.background;
    v.stored_coding = o.stored;
    v.coding = o.coding;
    v.target_bytes = o.target_bytes;
    v.target_bytes_per_second = o.target_bytes_per_second;
    v.color_encoding = o.color_encoding;
    v.alpha = o.alpha;
    v.scene_read.colorspace = o.colorspace;
    v.scene_read.ocio_config = o.ocio_config;
    v.scene_read.layer = o.layer;
    if (!o.templates_dir.empty()) {
        auto t = io::load_templates(o.templates_dir);
        if (!t) return fail(t.error().message);
        v.templates = std::move(t.value());
    }
    return -1;
}

namespace {

int paint_sequence(const PaintCommandOptions& o) {
    video::VideoPaintOptions v;
    if (int rc = video_options(o, v); rc >= 0) return rc;
    io::Progress progress(o.progress, "paint", 0);
    return video::run_video_paint(v, progress);
}

Status write_side_by_side(const std::string& path, const io::Image& src, const Canvas& painted) {
    const uint32_t w = src.width, h = src.height;
    std::vector<uint8_t> both(size_t(2) * w * h * 3);
    for (uint32_t y = 0; y < h; ++y) {
        std::copy_n(src.rgb.data() + size_t(y) * w * 3, size_t(w) * 3, both.data() + size_t(y) * 2 * w * 3);
        std::copy_n(painted.row(y), size_t(w) * 3, both.data() + (size_t(y) * 2 * w + w) * 3);
    }
    return io::write_image(path, 2 * w, h, both.data());
}

std::vector<std::pair<std::string, std::string>> still_metadata(const PaintCommandOptions& o) {
    return {
        {"software", std::string("spt ") + library_version()},
        {"source", printable_text(std::filesystem::path(o.input).filename().string())},  // names need not be UTF-8
        {"painter.seed", std::to_string(o.paint.seed)},
        {"painter.options", printable_text(o.canonical())},
    };
}

int paint_still(const PaintCommandOptions& o) {
    const auto t0 = std::chrono::steady_clock::now();
    io::ReadOptions ro;
    ro.background = o.background;
    // Every output is checked before the work: a folder, a missing folder or an unknown image
    // extension fails now, not after the paint, and leaves nothing.
    if (Status c = check_output_path(o.output); !c) return fail(c.error().message);
    if (!o.preview.empty())
        if (Status c = io::check_image_output(o.preview); !c) return fail("--preview " + c.error().message);
    if (!o.side_by_side.empty())
        if (Status c = io::check_image_output(o.side_by_side); !c) return fail("--side-by-side " + c.error().message);
    // Format 1.3 (alpha canvas, scene-linear colour) when the options and the input ask for
    // it; otherwise the 8-bit path below, byte for byte as before.
    std::optional<io::SceneImage> scene;
    auto target = scene_target(o, scene);
    if (!target) return fail(target.error().message);
    if (*target) return paint_scene_still(o, *scene, **target, still_metadata(o));
    // --colorspace / --layer: the colour-managed read, as 8-bit sRGB over the background.
    Result<io::Image> img = scene ? io::Image{scene->width, scene->height, source_view(*scene, o.background)}
                                  : io::read_image(o.input, ro);
    if (!img) return fail(img.error().message);
    if (scene)
        for (const std::string& w : scene->warnings) std::fprintf(stderr, "spt paint: warning: %s\n", w.c_str());
    const uint32_t W = img->width, H = img->height;

    auto still = still_setup(o, W, H);
    if (!still) return fail(still.error().message);
    paint::PaintSetup setup = std::move(still->setup);
    paint::PaintOptions po = std::move(still->paint);
    StreamInfo info;
    info.rois = std::move(still->rois);

    auto renderer = Renderer::create(setup.header, setup.templates);
    if (!renderer) return fail("cannot set up the renderer: " + renderer.error().message);

    info.header = setup.header;
    info.templates = setup.templates;
    info.metadata = still_metadata(o);
    WriterOptions wo;
    wo.coding = o.stored ? Coding::Stored : o.coding == 1 ? Coding::Range : Coding::Replay;
    const paint::ImageView model0{W, H, img->rgb.data()};
    if (o.target_bytes > 0) {
        // Rate control (paint/rate_control.hpp): full paints at searched lambdas, each coded to
        // a trial file that has no name (io/trial_output.hpp) to measure its exact size.
        auto trial_file = io::TrialOutput::create(o.output);
        if (!trial_file) return fail(trial_file.error().message);
        WriterOptions two = wo;
        two.atomic_rename = false;  // the trial file is never linked anywhere
        auto trial = [&](double lambda) {
            paint::PaintOptions tp = po;
            tp.lambda = lambda;
            tp.target_psnr = 0;
            Canvas c(W, H, o.background);
            std::vector<Stroke> out;
            const paint::PaintStats ts = paint::paint(model0, c, **renderer, setup, tp, out);
            paint::RatePoint p{lambda, ~uint64_t(0), ts.psnr};
            auto w = Writer::create(trial_file->path(), info, two);
            if (!w) return p;
            Frame f;
            f.added = std::move(out);
            f.replay = paint::replay_info(setup, tp, W, H);
            if ((*w)->append(f) && (*w)->finish()) p.bytes = (*w)->stats().total_bytes;
            return p;
        };
        po.lambda = search_target_bytes(o, trial, po.lambda);
    }

    Canvas canvas(W, H, o.background);
    std::vector<Stroke> strokes;
    PaintProgress progress(o.progress, po.max_strokes, po.target_psnr, int(setup.header.sets.size()));
    const paint::ImageView model{W, H, img->rgb.data()};
    const paint::PaintStats st = paint::paint(
        model, canvas, **renderer, setup, po, strokes, nullptr,
        [&](uint64_t n, int set, double db) { progress.update(n, set, db); return true; });
    const double paint_secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    auto writer = Writer::create(o.output, info, wo);
    if (!writer) {
        progress.finish(false, st.strokes, st.psnr, writer.error().message);
        return fail(writer.error().message);
    }
    Frame frame;
    frame.index = 0;
    frame.type = FrameType::Key;
    frame.added = std::move(strokes);
    frame.replay = paint::replay_info(setup, po, W, H);  // coding 2 replays the painter's candidates
    Status s = (*writer)->append(frame);
    if (s) s = (*writer)->finish();
    if (!s) {
        (*writer)->abort();
        progress.finish(false, st.strokes, st.psnr, s.error().message);
        return fail(s.error().message);  // names the file
    }
    const uint64_t bytes = (*writer)->stats().total_bytes;

    if (!o.preview.empty()) {
        if (Status p = io::write_image(o.preview, canvas); !p) return fail(p.error().message);
    }
    if (!o.side_by_side.empty()) {
        if (Status p = write_side_by_side(o.side_by_side, *img, canvas); !p) return fail(p.error().message);
    }
    char detail[256];
    std::snprintf(detail, sizeof detail, "%llu strokes, %.2f dB PSNR, %llu bytes (%.2f bytes/stroke), %.2f s, stopped: %s",
                  static_cast<unsigned long long>(st.strokes), st.psnr, static_cast<unsigned long long>(bytes),
                  st.strokes ? double(bytes) / double(st.strokes) : 0.0, paint_secs, paint::stop_reason_name(st.stop));
    progress.finish(true, st.strokes, st.psnr, detail);
    if (o.progress != io::ProgressMode::Json) std::fprintf(stderr, "spt paint: %s: %s\n", o.output.c_str(), detail);
    return 0;
}

}  // namespace

int cmd_paint(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)  // a farm plan's shots (plan_paint.cpp)
        if (std::string(argv[i]) == "--plan" || std::string(argv[i]).rfind("--plan=", 0) == 0) return paint_plan(argc, argv);
    PaintCommandOptions o;
    if (int rc = parse_paint_options(argc, argv, o); rc >= 0) return rc;
    if (o.style == "cartoon") return paint_cartoon(o);
    std::error_code ec;
    if (io::is_sequence_pattern(o.input) || io::is_video_file(o.input) || std::filesystem::is_directory(o.input, ec))
        return paint_sequence(o);
    return paint_still(o);
}

}  // namespace spt::cli
