#include "cli/paint_options.hpp"

#include "cli/args.hpp"

#include "io/color_config.hpp"
#include "io/roi_file.hpp"
#include "io/template_loader.hpp"
#include "paint/rate_control.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace spt::cli {

namespace {

bool parse_u64(const std::string& s, uint64_t& v) {
    if (s.empty() || s[0] == '-' || s[0] == '+') return false;
    char* end = nullptr;
    errno = 0;
    const unsigned long long x = std::strtoull(s.c_str(), &end, 10);
    if (errno || *end) return false;
    v = x;
    return true;
}

bool parse_int(const std::string& s, long lo, long hi, long& v) {
    char* end = nullptr;
    errno = 0;
    const long x = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || errno || *end || x < lo || x > hi) return false;
    v = x;
    return true;
}

bool parse_double(const std::string& s, double lo, double hi, double& v) {
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(s.c_str(), &end);
    if (s.empty() || errno || *end || !std::isfinite(x) || x < lo || x > hi) return false;
    v = x;
    return true;
}

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out;
    std::string cur;
    for (char c : s) {
        if (c == sep) { out.push_back(cur); cur.clear(); } else cur += c;
    }
    out.push_back(cur);
    return out;
}

bool parse_set_sizes(const std::string& s, std::vector<StrokeSet>& out) {
    out.clear();
    for (const auto& item : split(s, ',')) {
        const auto wh = split(item, 'x');
        long w, h;
        if (wh.size() != 2 || !parse_int(wh[0], 1, 4096, w) || !parse_int(wh[1], 1, 4096, h)) return false;
        out.push_back(StrokeSet{uint16_t(w), uint16_t(h)});
    }
    return !out.empty();
}

bool parse_rect(const std::string& s, paint::Rect& r) {
    const auto p = split(s, ',');
    long v[4];
    if (p.size() != 4) return false;
    for (int i = 0; i < 4; ++i)
        if (!parse_int(p[size_t(i)], 0, 1L << 24, v[i])) return false;
    if (v[2] <= 0 || v[3] <= 0) return false;
    r = paint::Rect{int32_t(v[0]), int32_t(v[1]), int32_t(v[2]), int32_t(v[3])};
    return true;
}

bool parse_rgb(const std::string& s, Rgb8& c) {
    const auto p = split(s, ',');
    long v[3];
    if (p.size() != 3) return false;
    for (int i = 0; i < 3; ++i)
        if (!parse_int(p[size_t(i)], 0, 255, v[i])) return false;
    c = Rgb8{uint8_t(v[0]), uint8_t(v[1]), uint8_t(v[2])};
    return true;
}


}  // namespace

namespace {

// The options of `spt paint`, declared once: CLI11 parses them and writes --help from them.
void declare(Args& a, bool plan) {
    a.positional("IN", "an image, an image sequence (shot.####.exr, shot.%04d.png, shot.1-120#.png), a folder "
                       "of frames, or a video file")
        .option("output", "FILE", plan ? "the plan to write, JSON (required); its tasks paint with the options below"
                                       : "the .spt file to write (required)", 'o')
        .option("style", "NAME", "painterly: stamps everywhere (the paper's painter); cartoon: flat-colour "
                                 "regions as anti-aliased filled polygons, stamps only where they leave an error; "
                                 "with --target-psnr never larger than the default painter, whose painting is "
                                 "written instead where smaller (said on stderr)",
                0, "painterly")
        .option("seed", "N", "random seed; the same seed and options give the same bytes whatever --threads", 0, "1")
        .option("sets", "N", "number of stroke sets, 3..10, large to small, sized from the canvas", 0, "6")
        .option("set-sizes", "WxH,...", "explicit set sizes in pixels, coarse to fine (overrides --sets)")
        .option("max-strokes", "N", "stop after N strokes", 0, "100000")
        .option("target-psnr", "DB", "stop when the painting reaches DB dB PSNR (default: none)")
        .option("threshold", "X", "switch to the next smaller set when the relative error improvement over a "
                                  "window (half a canvas coverage of the set's strokes) drops below X", 0, "0.01")
        .option("lambda", "X", "rate-distortion acceptance: a stroke must remove the error of X average pixels "
                               "(0 = any improvement); default 24, or with --target-psnr 24 * 2^((28 - DB) / 4) "
                               "in 8..64 (measured best per target); it halves whenever the painting stalls short "
                               "of the target")
        .option("temperature", "X", "Metropolis temperature at the start of a set, relative to the lambda cost "
                                    "(0 = greedy)", 0, "0.25")
        .option("templates", "DIR", "use the grayscale images of DIR (name order, up to 1024x1024, 60x60 by "
                                    "convention) as stroke templates instead of the built-in rectangle, soft round "
                                    "and ellipse (textured brushes: converter/templates/brushes/)")
        .multi("roi", "x,y,w,h", "a region of interest painted down to the finest set (the finest set paints only there)")
        .option("roi-file", "F", "regions of interest from JSON: {\"rois\":[{\"x\":..,\"y\":..,\"w\":..,\"h\":..}]}; "
                                 "for video, each ROI may have \"frames\": \"A-B\"")
        .option("orient", "MODE", "stroke orientation: edges (follow the nearest multiscale edge), gradient "
                                  "(local structure tensor), random", 0, "edges")
        .option("threads", "N", "worker threads (default: all cores)")
        .option("progress", "MODE", io::kProgressHelp, 0, "auto")
        .option("preview", "FILE", "also write the rendered painting (PNG, EXR, TIFF, ...)")
        .option("side-by-side", "FILE", "also write source | painting in one image")
        .option("background", "R,G,B", "canvas colour before any stroke", 0, "255,255,255")
        .flag("stored", "write stored (coding 0) frames instead of range-coded ones")
        .option("coding", "1|2", "2: code which of the painter's replayable random candidates were accepted "
                                 "(SPEC.md 7.7); 1: explicit positions", 0, "2")
        .option("color-step", "Q", "choose colours on a lattice of step Q (1..32; default 12, or 4 with "
                                   "--target-psnr above 33) around the canvas under the stroke: coding 2 spends "
                                   "fewer bits on them")
        .option("target-bytes", "N[/s]", "search lambda (--style cartoon: the PSNR target) so that the file is at "
                                         "most N bytes (N/s: per second of a clip); reports where it landed")
        .option("outline-tolerance", "PX", "--style cartoon: how far (pixels) a polygon's outline may leave "
                                           "the traced edge. Default: with --target-psnr the coarsest of 1, 0.7 and 0.5 whose polygons reach "
                                           "it; short of it, the smallest file of 0.25, 0.35 and 0.5 for a still, 0.35 or 0.5 "
                                           "for a sequence's key frame; 0.35 otherwise. Inter frames follow their key frame's, and with "
                                           "--target-psnr the regions one traces anew also try 1.2 and 1.4 times it")
        .option("outline-smooth", "PX", "--style cartoon: average a traced edge over +-PX pixels (0..2) before "
                                        "its outline is simplified: a blurred or noisy edge takes fewer vertices. "
                                        "Default: unsmoothed, but short of --target-psnr a still smooths its 0.25 "
                                        "and 0.5 px outline trials by as much as their tolerance, and a sequence's "
                                        "key frame also tries 0.25 px of smoothing; the smallest is kept")
        .option("min-region", "PX", "--style cartoon: colour regions smaller than PX pixels (1..100000) join "
                                    "their neighbours before they are traced. Default: 3, but short of "
                                    "--target-psnr a still and a sequence's key frame also try 1 and 12 and keep "
                                    "the smallest: compressed video's noise makes many small regions, whose "
                                    "polygons cost more than the stamps that replace them; text's are parts of "
                                    "its letters")
        .option("min-color-share", "F", "--style cartoon: a flat colour covers at least this share of the "
                                        "pixels (0.000001..0.5, and 8 pixels). Default: 0.0001, but short of "
                                        "--target-psnr a still and a sequence's key frame also try 0.001, then 0.01, "
                                        "while that leaves colours out and the file comes out smaller: compressed "
                                        "video's ringing and blends make colours of their own that take pixels from "
                                        "the flat fills")
        .flag("no-lines", "--style cartoon: trace thin regions as polygons only. By default a thin region "
                          "whose centreline curves are as close and smaller is drawn as lines: anti-aliased "
                          "curves with widths (format 1.4; Grease Pencil line strokes)")
        .group("colour and alpha")
        .option("color-encoding", "MODE", "stroke colours: srgb8 (8-bit sRGB, as before format 1.3), linear (half "
                                          "floats of scene-linear Rec.709: values above 1 and smooth darks, for "
                                          "render output), auto: linear for float input (EXR, float TIFF), else srgb8",
                0, "auto")
        .option("alpha", "MODE", "on: paint an RGBA canvas, transparent where the input is, strokes with painted "
                                 "edges; off: flatten the input's alpha over --background; auto: on when the input "
                                 "has an alpha channel that is not opaque everywhere (a sequence: its first file)",
                0, "auto")
        .option("colorspace", "NAME", "the input's colour space, a name, alias or role of the OCIO config (e.g. "
                                      "ACEScg, sRGB, lin_rec709); default: lin_rec709 for float files, sRGB for 8- "
                                      "and 16-bit files")
        .option("ocio", "FILE", "the OCIO config that --colorspace names come from (default: $OCIO, else "
                                "OpenImageIO's built-in config, which knows linear, sRGB and Rec709)")
        .option("layer", "NAME", "the EXR layer to paint, as its channels are prefixed (e.g. ViewLayer.Combined for "
                                 "ViewLayer.Combined.R, G, B, A); default: the unnamed R, G, B, A, else the first "
                                 "layer with R, G, B")
        .group("sequences and video")
        .option("frames", "A-B", "paint only these frames (sequence numbers, or 0-based video frames)")
        .option("fps", "R", "frame rate, e.g. 24 or 30000/1001 (default: the video's, or 24)")
        .flag("skip-bad-frames", "repeat the previous frame for a missing or unreadable one instead of stopping")
        .option("keyframe-interval", "N", "at most N frames from one key frame to the next", 0, "100")
        .option("cut-threshold", "X", "cut when the pixel x edge difference exceeds X times its recent average", 0, "6")
        .option("flow", "METHOD", "optical flow: dis-ultrafast, dis-fast, dis-medium, farneback", 0, "dis-ultrafast")
        .option("max-inter-strokes", "N", "at most N new strokes per inter frame", 0, "4000")
        .option("motion-block", "N", "motion block size in pixels, 8..256", 0, "16")
        .flag("flow-orientation", "lay new strokes along the optical flow where the picture moves (default: "
                                  "along the edges, as for key frames)")
        .epilog(
            "Paints an image with brush strokes (the Stochastic Paintbrush Transformation): random\n"
            "candidate strokes, coarse to fine, each kept only if it brings the painting closer to\n"
            "the image. Writes the strokes to OUT.spt (written atomically: no half-written file).\n"
            "\n"
            "IN is any image OpenImageIO reads (PNG, JPEG, TIFF, EXR, ...), in the colour space that\n"
            "--colorspace names (default: sRGB for 8/16-bit files, scene-linear Rec.709 for float files),\n"
            "converted through OpenImageIO's colour management (OCIO: --ocio or $OCIO). The srgb8\n"
            "encoding paints in 8-bit sRGB (\"linear\" -> \"sRGB\", values above 1 clip); linear keeps\n"
            "scene-linear values. With --alpha on the canvas is transparent where IN is; otherwise alpha\n"
            "is composited over --background. NaN, infinite and negative input values are replaced\n"
            "(with a warning).\n"
            "\n"
            "For an image sequence or a video, OUT.spt holds key frames (the first frame, the first\n"
            "after each detected cut, and at least every --keyframe-interval frames) painted fully,\n"
            "and inter frames in which the strokes travel with the optical flow and only the areas\n"
            "that changed are repainted. Ctrl-C / SIGTERM stops after the current frame and leaves a\n"
            "valid OUT.spt holding every finished frame.\n"
            "\n"
            "exit status: 0 success, 1 failure (unreadable input, write error), 2 bad usage\n");
}

// --color-encoding, --alpha, --colorspace, --ocio, --layer. A config or colour space name that
// cannot work is a usage error now rather than a failure after the first frame is read.
int parse_color_options(Args& a, PaintCommandOptions& o) {
    auto bad = [&](const std::string& msg) { return a.usage_error(msg); };
    if (a.has("color-encoding")) {
        o.color_encoding = a.get("color-encoding");
        if (o.color_encoding != "auto" && o.color_encoding != "srgb8" && o.color_encoding != "linear")
            return bad("--color-encoding: expected auto, srgb8 or linear, got '" + o.color_encoding + "'");
    }
    if (a.has("alpha")) {
        o.alpha = a.get("alpha");
        if (o.alpha != "auto" && o.alpha != "on" && o.alpha != "off")
            return bad("--alpha: expected auto, on or off, got '" + o.alpha + "'");
    }
    if (a.has("layer")) {
        o.layer = a.get("layer");
        if (o.layer.empty()) return bad("--layer: expected a layer name, got ''");
    }
    if (a.has("colorspace") && a.get("colorspace").empty()) return bad("--colorspace: expected a colour space name, got ''");
    if (a.has("ocio") && a.get("ocio").empty()) return bad("--ocio: expected an OCIO config file, got ''");
    o.colorspace = a.get("colorspace");
    o.ocio_config = a.get("ocio");
    if (!o.colorspace.empty() || !o.ocio_config.empty()) {
        auto cs = io::color_config(o.ocio_config);
        if (!cs) return bad((o.ocio_config.empty() ? "--colorspace: " : "--ocio: ") + cs.error().message);
        if (!o.colorspace.empty())
            if (auto n = io::find_colorspace(*cs, o.colorspace); !n)
                return bad("--colorspace: " + n.error().message + (cs->warning.empty() ? "" : " (" + cs->warning + ")"));
    }
    return -1;
}

}  // namespace

int parse_paint_options(int argc, char** argv, PaintCommandOptions& o, const char* command) {
    const bool plan = std::string(command) == "plan";
    Args a(command, plan ? "plan a farm job: shots of a sequence or video, each a task" : "paint an image, an image sequence or a video into a .spt file",
           plan ? "spt plan IN -o PLAN.json [--max-task-frames N] [paint options]" : "spt paint IN -o OUT.spt [options]");
    declare(a, plan);
    if (plan)
        a.group("farm plan")
            .option("max-task-frames", "N", "split shots longer than N frames into tasks of at most N, at forced key "
                                            "frames (whole --keyframe-interval steps when one fits); 0 = at cuts only",
                    0, "240")
            .option("cut-scan", "MODE", "sampled: judge frame pairs only where frames sampled every --cut-step "
                                        "frames show a change a cut can hide in; full: judge every pair (reads every "
                                        "frame); tasks: no scan, each task finds the cuts in its own frames as it "
                                        "paints them (the plan decodes one frame); auto: tasks for a video file "
                                        "(which any scan decodes whole), sampled otherwise",
                    0, "auto")
            .option("cut-step", "K", "the sampled cut scan's step (frames)", 0, "16")
            .option("cut-history", "N", "the sampled cut scan weighs a pair against the N pairs before it (1..12; "
                                        "12 is the full scan's own rule, and reads more frames)",
                    0, "4");
    if (int rc = a.parse(argc, argv); rc >= 0) return rc;
    if (plan && a.has("cut-scan")) {
        const std::string m = a.get("cut-scan");
        if (m != "auto" && m != "full" && m != "sampled" && m != "tasks")
            return a.usage_error("--cut-scan: expected auto, sampled, full or tasks, got '" + m + "'");
        o.cut_scan = m;
    }
    if (plan && a.has("cut-step")) {
        long k = 0;
        if (!a.get_long("cut-step", k, 1, 1000000)) return 2;
        o.cut_step = int(k);
    }
    if (plan && a.has("cut-history")) {
        long h = 0;
        if (!a.get_long("cut-history", h, 1, 12)) return 2;
        o.cut_history = int(h);
    }
    if (plan && a.has("max-task-frames")) {
        long m = 0;
        if (!a.get_long("max-task-frames", m, 0, 100000000)) return 2;
        o.max_task_frames = m;
    }
    auto bad = [&](const std::string& msg) { return a.usage_error(msg); };
    auto v = [&](const char* name) { return a.get(name); };
    o.input = a.pos("IN");
    o.output = a.get("output");
    if (a.has("style")) {
        o.style = v("style");
        if (o.style != "painterly" && o.style != "cartoon")
            return bad("--style: expected painterly or cartoon, got '" + o.style + "'");
    }
    if (a.has("outline-tolerance") && !parse_double(v("outline-tolerance"), 0.01, 100, o.outline_tolerance))
        return bad("--outline-tolerance: expected 0.01..100 pixels, got '" + v("outline-tolerance") + "'");
    if (a.has("outline-smooth") && !parse_double(v("outline-smooth"), 0, 2, o.outline_smooth))
        return bad("--outline-smooth: expected 0..2 pixels, got '" + v("outline-smooth") + "'");
    if (a.has("min-region")) {
        long m = 0;
        if (!parse_int(v("min-region"), 1, 100000, m))
            return bad("--min-region: expected 1..100000 pixels, got '" + v("min-region") + "'");
        o.min_region = int(m);
    }
    if (a.has("min-color-share") && !parse_double(v("min-color-share"), 1e-6, 0.5, o.min_color_share))
        return bad("--min-color-share: expected 0.000001..0.5, got '" + v("min-color-share") + "'");
    o.lines = !a.has("no-lines");
    // The cartoon painter's options do nothing for the default painter: said, not ignored.
    for (const char* f : {"outline-tolerance", "outline-smooth", "min-region", "min-color-share", "no-lines"})
        if (a.has(f) && o.style != "cartoon") return bad(std::string("--") + f + " applies to --style cartoon only");
    long n = 0;
    if (a.has("seed") && !parse_u64(v("seed"), o.paint.seed))
        return bad("--seed: expected an unsigned integer, got '" + v("seed") + "'");
    // Defaults chosen by measurement (paint/rate_control.hpp rate_defaults, bench/rate_sweep.sh);
    // with --target-psnr they follow the target unless given.
    const bool have_sets = a.has("sets"), have_lambda = a.has("lambda"), have_step = a.has("color-step");
    if (have_sets) {
        if (!parse_int(v("sets"), 3, 10, n)) return bad("--sets: expected 3..10, got '" + v("sets") + "'");
        o.sets = int(n);
    }
    if (a.has("set-sizes") && (!parse_set_sizes(v("set-sizes"), o.set_sizes) || o.set_sizes.size() > 16))
        return bad("--set-sizes: expected 1..16 sizes WxH (1..4096) separated by commas, got '" + v("set-sizes") + "'");
    if (a.has("max-strokes") && (!parse_u64(v("max-strokes"), o.paint.max_strokes) || o.paint.max_strokes == 0 ||
                                 o.paint.max_strokes > (1u << 24)))
        return bad("--max-strokes: expected 1..16777216, got '" + v("max-strokes") + "'");
    if (a.has("target-psnr") && !parse_double(v("target-psnr"), 1, 99, o.paint.target_psnr))
        return bad("--target-psnr: expected 1..99 dB, got '" + v("target-psnr") + "'");
    if (a.has("threshold") && !parse_double(v("threshold"), 0, 1, o.paint.threshold))
        return bad("--threshold: expected 0..1, got '" + v("threshold") + "'");
    if (have_lambda && !parse_double(v("lambda"), 0, 1e6, o.paint.lambda))
        return bad("--lambda: expected a number >= 0, got '" + v("lambda") + "'");
    if (a.has("temperature") && !parse_double(v("temperature"), 0, 1e3, o.paint.temperature))
        return bad("--temperature: expected a number >= 0, got '" + v("temperature") + "'");
    o.templates_dir = v("templates");
    for (const std::string& r : a.all("roi")) {
        RoiSpec spec;
        if (!parse_rect(r, spec.rect)) return bad("--roi: expected x,y,w,h (w, h > 0), got '" + r + "'");
        o.rois.push_back(spec);
    }
    o.roi_file = v("roi-file");
    if (a.has("orient")) {
        const std::string m = v("orient");
        if (m == "edges") o.paint.orient = paint::OrientMode::Edges;
        else if (m == "gradient") o.paint.orient = paint::OrientMode::Gradient;
        else if (m == "random") o.paint.orient = paint::OrientMode::Random;
        else return bad("--orient: expected edges, gradient or random, got '" + m + "'");
    }
    if (a.has("threads")) {
        if (!parse_int(v("threads"), 1, 1024, n)) return bad("--threads: expected 1..1024, got '" + v("threads") + "'");
        o.paint.threads = int(n);
    }
    if (!io::parse_progress_mode(v("progress"), o.progress))
        return bad("--progress: expected auto, plain, json or none, got '" + v("progress") + "'");
    o.preview = v("preview");
    o.side_by_side = v("side-by-side");
    if (a.has("background") && !parse_rgb(v("background"), o.background))
        return bad("--background: expected R,G,B (0..255), got '" + v("background") + "'");
    o.stored = a.has("stored");
    if (a.has("coding")) {
        if (v("coding") != "1" && v("coding") != "2") return bad("--coding: expected 1 or 2, got '" + v("coding") + "'");
        o.coding = v("coding") == "1" ? 1 : 2;
    }
    if (have_step) {
        if (!parse_int(v("color-step"), 1, 32, n)) return bad("--color-step: expected 1..32, got '" + v("color-step") + "'");
        o.paint.color_step = int(n);
    }
    if (a.has("target-bytes")) {
        std::string num = v("target-bytes");
        o.target_bytes_per_second = num.size() > 2 && num.compare(num.size() - 2, 2, "/s") == 0;
        if (o.target_bytes_per_second) num.resize(num.size() - 2);
        if (!parse_u64(num, o.target_bytes) || o.target_bytes < 64)
            return bad("--target-bytes: expected a size of at least 64 bytes, optionally /s, got '" + v("target-bytes") + "'");
    }
    if (int rc = parse_color_options(a, o); rc >= 0) return rc;
    o.frames = v("frames");
    o.fps = v("fps");
    o.skip_bad_frames = a.has("skip-bad-frames");
    if (a.has("keyframe-interval")) {
        if (!parse_int(v("keyframe-interval"), 1, 1000000, n))
            return bad("--keyframe-interval: expected 1..1000000, got '" + v("keyframe-interval") + "'");
        o.keyframe_interval = int(n);
    }
    if (a.has("cut-threshold") && !parse_double(v("cut-threshold"), 1, 1e6, o.cut_threshold))
        return bad("--cut-threshold: expected a number >= 1, got '" + v("cut-threshold") + "'");
    o.flow = v("flow");
    if (a.has("max-inter-strokes") && (!parse_u64(v("max-inter-strokes"), o.max_inter_strokes) || o.max_inter_strokes > (1u << 24)))
        return bad("--max-inter-strokes: expected 0..16777216, got '" + v("max-inter-strokes") + "'");
    o.flow_orientation = a.has("flow-orientation");
    if (a.has("motion-block")) {
        if (!parse_int(v("motion-block"), 8, 256, n)) return bad("--motion-block: expected 8..256, got '" + v("motion-block") + "'");
        o.block_size = int(n);
    }
    const paint::RateDefaults rd = paint::rate_defaults(o.paint.target_psnr);
    if (!have_lambda) o.paint.lambda = rd.lambda;
    if (!have_step) o.paint.color_step = rd.color_step;
    if (o.output.empty()) return bad("no output given (-o OUT.spt)");
    if (have_sets && !o.set_sizes.empty()) return bad("give --sets or --set-sizes, not both");
    o.cli_roi_count = o.rois.size();
    if (!o.roi_file.empty()) {
        auto r = io::read_roi_file(o.roi_file);
        if (!r) return bad("--roi-file " + r.error().message);
        for (const io::RoiRange& f : *r) {
            RoiSpec s;
            s.first_frame = f.first_frame;
            s.last_frame = f.last_frame;
            s.rect = paint::Rect{f.x, f.y, f.w, f.h};
            o.rois.push_back(s);
        }
    }
    // What the cartoon painter does not do is said, not ignored: it paints the whole frame in
    // 8-bit sRGB over --background.
    if (o.style == "cartoon") {
        std::string no;
        if (o.alpha == "on") no = "--alpha on (it paints over --background; --alpha off flattens the input's alpha)";
        else if (o.color_encoding == "linear") no = "--color-encoding linear (it paints 8-bit sRGB)";
        else if (!o.colorspace.empty()) no = "--colorspace (it reads the input as 8-bit sRGB)";
        else if (!o.ocio_config.empty()) no = "--ocio (it reads the input as 8-bit sRGB)";
        else if (!o.layer.empty()) no = "--layer (it reads the input's RGBA channels)";
        else if (!o.rois.empty()) no = a.has("roi") ? "--roi" : "--roi-file";
        else if (o.flow_orientation) no = "--flow-orientation";
        if (!no.empty()) return bad("--style cartoon does not support " + no);
    }
    return -1;
}

}  // namespace spt::cli
