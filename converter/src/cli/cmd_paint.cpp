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
#include "job/painterly_sequence.hpp"
#include "job/painterly_still.hpp"
#include "job/still_setup.hpp"
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

// Sequences and videos go to the video encoder (job/painterly_sequence.hpp).
int video_options(const PaintCommandOptions& o, video::VideoPaintOptions& v) {
    if (Status st = job::painterly_video_options(o, v); !st) return fail(st.error().message);
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
    return job::painting_metadata(o);
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
    PaintProgress progress(o.progress, o.paint.max_strokes, o.paint.target_psnr, int(job::still_set_count(o, W, H)));
    job::StillTarget to;
    to.path = o.output;
    to.metadata = still_metadata(o);
    to.progress = [&](uint64_t n, int set, double db) { progress.update(n, set, db); return true; };
    auto painted = job::paint_painterly_still(o, *img, to);
    if (!painted) {
        progress.finish(false, 0, 0, painted.error().message);
        return fail(painted.error().message);
    }
    const double paint_secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const paint::PaintStats& st = painted->stats;
    const Canvas& canvas = painted->canvas;
    const uint64_t bytes = painted->bytes;

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

int run_paint(const PaintCommandOptions& o, ShotRun* shot) {
    std::error_code ec;
    const bool clip = io::is_sequence_pattern(o.input) || io::is_video_file(o.input) || std::filesystem::is_directory(o.input, ec);
    switch (o.style) {
        case job::Style::Cartoon: return shot ? paint_cartoon_shot(o, shot->metadata, shot->frames) : paint_cartoon(o);
        case job::Style::Painterly: break;
    }
    if (!shot) return clip ? paint_sequence(o) : paint_still(o);
    video::VideoPaintOptions v;
    if (int rc = video_options(o, v); rc >= 0) return rc;
    v.detect_cuts = shot->detect_cuts;
    v.metadata = shot->metadata;
    io::Progress progress(o.progress, shot->label, 0);
    video::VideoPaintReport rep;
    const int rc = video::run_video_paint(v, progress, &rep);
    shot->frames = rep.frames;
    shot->interrupted = rep.interrupted;
    return rc;
}

int cmd_paint(int argc, char** argv) {
    for (int i = 1; i < argc; ++i)  // a farm plan's shots (plan_paint.cpp)
        if (std::string(argv[i]) == "--plan" || std::string(argv[i]).rfind("--plan=", 0) == 0) return paint_plan(argc, argv);
    PaintCommandOptions o;
    if (int rc = parse_paint_options(argc, argv, o); rc >= 0) return rc;
    return run_paint(o);
}

}  // namespace spt::cli
