#include "cli/paint_scene_still.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <OpenImageIO/imageio.h>

#include "cli/commands.hpp"
#include "cli/paint_progress.hpp"
#include "job/still_setup.hpp"
#include "io/image_io.hpp"
#include "io/trial_output.hpp"
#include "spt/color.hpp"
#include "paint/rate_control.hpp"
#include "spt/writer.hpp"

namespace spt::cli {

namespace {

int fail(const std::string& msg) { return command_failed("paint", msg); }

io::SceneReadOptions read_options(const PaintCommandOptions& o) {
    io::SceneReadOptions r;
    r.colorspace = o.colorspace;
    r.ocio_config = o.ocio_config;
    r.layer = o.layer;
    return r;
}

// The 8-bit sRGB view of a premultiplied linear pixel over an sRGB background (what --preview
// and --side-by-side show: the sRGB curve, values above 1 clipped).
void view_pixel(const double lin[3], double a, Rgb8 bg, uint8_t* out) {
    const uint8_t b[3] = {bg.r, bg.g, bg.b};
    for (int c = 0; c < 3; ++c) {
        const double v = lin[c] + (1.0 - a) * paint::srgb_decode(b[c] / 255.0);
        out[c] = uint8_t(std::lround(255.0 * paint::srgb_encode(std::min(1.0, v))));
    }
}

// A painting as 8-bit sRGB over the background. sRGB8 alpha canvases are flattened in their own
// (premultiplied 8-bit) values, as a viewer composites them.
std::vector<uint8_t> painting_view(const Canvas& c, const Header& h, Rgb8 bg) {
    const size_t n = size_t(c.width) * c.height;
    std::vector<uint8_t> out(n * 3);
    const uint8_t b[3] = {bg.r, bg.g, bg.b};
    for (size_t i = 0; i < n; ++i) {
        const double a = c.alpha.empty() ? 1.0 : c.alpha[i] / 255.0;
        if (h.color == ColorEncoding::LinearHalf) {
            const double lin[3] = {half_to_float(c.rgb16[3 * i]), half_to_float(c.rgb16[3 * i + 1]),
                                   half_to_float(c.rgb16[3 * i + 2])};
            view_pixel(lin, a, bg, &out[3 * i]);
        } else {
            const uint32_t na = c.alpha.empty() ? 0 : 255u - c.alpha[i];
            for (int k = 0; k < 3; ++k) out[3 * i + k] = uint8_t(std::min<uint32_t>(255, c.rgb[3 * i + k] + (b[k] * na + 127) / 255));
        }
    }
    return out;
}


}  // namespace

std::vector<uint8_t> source_view(const io::SceneImage& img, Rgb8 bg) {
    const size_t n = size_t(img.width) * img.height;
    std::vector<uint8_t> out(n * 3);
    for (size_t i = 0; i < n; ++i) {
        const double lin[3] = {img.rgba[4 * i], img.rgba[4 * i + 1], img.rgba[4 * i + 2]};
        view_pixel(lin, img.rgba[4 * i + 3], bg, &out[3 * i]);
    }
    return out;
}

Result<std::optional<paint::SceneTarget>> scene_target(const PaintCommandOptions& o, std::optional<io::SceneImage>& img) {
    const std::string& ce = o.color_encoding;
    const std::string& al = o.alpha;
    if (ce != "auto" && ce != "srgb8" && ce != "linear")
        return make_error(Code::InvalidArgument, "--color-encoding: expected auto, srgb8 or linear, got '" + ce + "'");
    if (al != "auto" && al != "on" && al != "off")
        return make_error(Code::InvalidArgument, "--alpha: expected auto, on or off, got '" + al + "'");
    // --colorspace and --layer need the colour-managed reader, whatever the painting becomes.
    const bool managed = !o.colorspace.empty() || !o.layer.empty();
    if (ce == "srgb8" && al == "off" && !managed) return std::optional<paint::SceneTarget>{};
    if (ce != "linear" && al != "on" && !managed) {
        // Auto: the file's header decides, before any pixel is read, so that a plain painting
        // costs what it did (reading the pixels twice cost ~15% of a 768x512 paint).
        // Unreadable here: the plain path reports the problem exactly as it always did.
        auto in = OIIO::ImageInput::open(o.input);
        if (!in) {
            (void)OIIO::geterror();
            return std::optional<paint::SceneTarget>{};
        }
        const OIIO::ImageSpec& spec = in->spec();
        const bool is_float = spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF;
        const bool has_alpha = spec.alpha_channel >= 0 || spec.nchannels == 4 || spec.nchannels == 2;
        if (!(ce == "auto" && is_float) && !(al == "auto" && has_alpha)) return std::optional<paint::SceneTarget>{};
    }
    Result<io::SceneImage> r = io::read_scene_image(o.input, read_options(o));
    if (!r) {
        // Nothing asked for format 1.3 explicitly: the plain path reports the input's problem
        // exactly as it always did.
        if (ce == "linear" || al == "on" || managed) return r.error();
        return std::optional<paint::SceneTarget>{};
    }
    paint::SceneTarget t;
    t.linear = ce == "linear" || (ce == "auto" && r->is_float);
    t.alpha = al == "on" || (al == "auto" && r->has_alpha &&
                             paint::has_transparency(paint::LinearView{r->width, r->height, r->rgba.data()}));
    if (!t.linear && !t.alpha && !managed) return std::optional<paint::SceneTarget>{};
    img = std::move(*r);
    if (!t.linear && !t.alpha) return std::optional<paint::SceneTarget>{};  // 8-bit, from img
    return std::optional<paint::SceneTarget>{t};
}

std::string scene_options_text(const paint::SceneTarget& t) {
    std::string s = std::string(" alpha=") + (t.alpha ? "on" : "off") + " color-encoding=" + (t.linear ? "linear" : "srgb8");
    if (t.linear) s += " mantissa-bits=" + std::to_string(t.refit.mantissa_bits) + (t.refit.highlight_weight ? "" : " refit=linear");
    return s;
}

int paint_scene_still(const PaintCommandOptions& o, const io::SceneImage& img, const paint::SceneTarget& target,
                      std::vector<std::pair<std::string, std::string>> metadata) {
    const auto t0 = std::chrono::steady_clock::now();
    for (const std::string& w : img.warnings) std::fprintf(stderr, "spt paint: warning: %s\n", w.c_str());
    const uint32_t W = img.width, H = img.height;
    auto still = job::still_setup(o, W, H);
    if (!still) return fail(still.error().message);
    const paint::PaintSetup setup = std::move(still->setup);
    paint::PaintOptions po = std::move(still->paint);
    StreamInfo info;
    info.rois = std::move(still->rois);
    info.header = paint::scene_header(setup.header, target);
    info.templates = setup.templates;
    for (auto& [k, v] : metadata)
        if (k == "painter.options") v += scene_options_text(target);
    info.metadata = std::move(metadata);
    WriterOptions wo;
    // Coding 2 predicts from an 8-bit canvas: the writer codes such frames with coding 1.
    wo.coding = o.stored ? Coding::Stored : o.coding == 1 ? Coding::Range : Coding::Replay;
    const paint::LinearView view{W, H, img.rgba.data()};

    auto write = [&](const std::string& path, const paint::ScenePainting& sp, const paint::PaintOptions& opts,
                     uint64_t& bytes, const WriterOptions& how) -> Status {
        auto w = Writer::create(path, info, how);
        if (!w) return w.error();
        Frame f;
        f.added = sp.strokes;
        f.replay = paint::replay_info(setup, opts, W, H);
        Status s = (*w)->append(f);
        if (s) s = (*w)->finish();
        if (!s) {
            (*w)->abort();
            return s;
        }
        bytes = (*w)->stats().total_bytes;
        return {};
    };
    if (o.target_bytes > 0) {
        // Trials go to an unnamed file that is never linked (io/trial_output.hpp): nothing is
        // left behind, and no file of the user's is touched.
        auto trial_file = io::TrialOutput::create(o.output);
        if (!trial_file) return fail(trial_file.error().message);
        WriterOptions two = wo;
        two.atomic_rename = false;
        auto trial = [&](double lambda) {
            paint::PaintOptions tp = po;
            tp.lambda = lambda;
            tp.target_psnr = 0;
            paint::RatePoint p{lambda, ~uint64_t(0), 0};
            auto sp = paint::paint_scene(view, setup, tp, target);
            if (!sp) return p;
            p.psnr = sp->stats.psnr;
            uint64_t bytes = 0;
            if (write(trial_file->path(), *sp, tp, bytes, two)) p.bytes = bytes;
            return p;
        };
        po.lambda = job::search_target_bytes(o, trial, po.lambda);
    }

    PaintProgress progress(o.progress, po.max_strokes, po.target_psnr, int(setup.header.sets.size()));
    auto sp = paint::paint_scene(view, setup, po, target, 0,
                                 [&](uint64_t n, int set, double db) { progress.update(n, set, db); return true; });
    if (!sp) {
        progress.finish(false, 0, 0, sp.error().message);
        return fail(sp.error().message);
    }
    uint64_t bytes = 0;
    if (Status s = write(o.output, *sp, po, bytes, wo); !s) {
        progress.finish(false, sp->stats.strokes, sp->stats.psnr, s.error().message);
        return fail(s.error().message);
    }
    // Previews: the 8-bit sRGB view over --background (spt render writes the canvas itself).
    if (!o.preview.empty() || !o.side_by_side.empty()) {
        const std::vector<uint8_t> painted = painting_view(sp->canvas, sp->header, o.background);
        if (!o.preview.empty())
            if (Status p = io::write_image(o.preview, W, H, painted.data()); !p)
                return extra_output_failed("--preview", o.output, p.error().message);
        if (!o.side_by_side.empty()) {
            const std::vector<uint8_t> src = source_view(img, o.background);
            std::vector<uint8_t> both(size_t(2) * W * H * 3);
            for (uint32_t y = 0; y < H; ++y) {
                std::copy_n(src.data() + size_t(y) * W * 3, size_t(W) * 3, both.data() + size_t(y) * 2 * W * 3);
                std::copy_n(painted.data() + size_t(y) * W * 3, size_t(W) * 3, both.data() + (size_t(y) * 2 * W + W) * 3);
            }
            if (Status p = io::write_image(o.side_by_side, 2 * W, H, both.data()); !p)
                return extra_output_failed("--side-by-side", o.output, p.error().message);
        }
    }
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    char detail[320];
    std::snprintf(detail, sizeof detail,
                  "%llu strokes, %.2f dB PSNR (%s proxy%s), %llu bytes (%.2f bytes/stroke), %.2f s, stopped: %s",
                  (unsigned long long)sp->stats.strokes, sp->stats.psnr, target.linear ? "8-bit log" : "sRGB",
                  target.alpha ? ", RGBA" : "", (unsigned long long)bytes,
                  sp->stats.strokes ? double(bytes) / double(sp->stats.strokes) : 0.0, secs,
                  paint::stop_reason_name(sp->stats.stop));
    progress.finish(true, sp->stats.strokes, sp->stats.psnr, detail);
    if (o.progress != io::ProgressMode::Json) std::fprintf(stderr, "spt paint: %s: %s\n", o.output.c_str(), detail);
    // A mostly translucent input: the stamps cannot paint it (scene_paint.hpp), said rather than
    // reported as converged. A quarter: a soft matte's edge is far less.
    if (const double share = target.alpha ? paint::partial_alpha_share(view) : 0; share >= 0.25)
        std::fprintf(stderr, "spt paint: warning: %s: %.0f%% of its pixels are partly transparent; stamps composite "
                             "over and only raise alpha, so the default painter cannot paint inside them (%.2f dB): "
                             "--style cartoon paints them as one layer of polygons, --alpha off over --background\n",
                     o.input.c_str(), 100 * share, sp->stats.psnr);
    return 0;
}

}  // namespace spt::cli
