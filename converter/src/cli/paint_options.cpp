#include "cli/paint_options.hpp"

#include "io/roi_file.hpp"
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

const char* orient_name(paint::OrientMode m) {
    switch (m) {
        case paint::OrientMode::Edges: return "edges";
        case paint::OrientMode::Gradient: return "gradient";
        case paint::OrientMode::Random: return "random";
    }
    return "?";
}

}  // namespace

void print_paint_help(std::FILE* f) {
    std::fputs(
        "usage: spt paint IN -o OUT.spt [options]\n"
        "\n"
        "Paints an image with brush strokes (the Stochastic Paintbrush Transformation): random\n"
        "candidate strokes, coarse to fine, each kept only if it brings the painting closer to\n"
        "the image. Writes the strokes to OUT.spt (written atomically: no half-written file).\n"
        "\n"
        "IN is any image OpenImageIO reads (PNG, JPEG, TIFF, EXR, ...). 8/16-bit files are taken\n"
        "as sRGB; float files (EXR, float TIFF) as scene-linear Rec.709 and converted to sRGB with\n"
        "OpenImageIO's colour management (\"linear\" -> \"sRGB\"). Alpha is composited over\n"
        "--background.\n"
        "\n"
        "IN may also be an image sequence (shot.####.exr, shot.%04d.png, shot.1-120#.png, or a\n"
        "folder of frames) or a video file (mp4, mov, mkv, avi, mpg, ...). Then OUT.spt holds\n"
        "key frames (the first frame, the first after each detected cut, and at least every\n"
        "--keyframe-interval frames) painted fully, and inter frames in which the strokes travel\n"
        "with the optical flow and only the areas that changed are repainted.\n"
        "\n"
        "options:\n"
        "  -o, --output FILE      the .spt file to write (required)\n"
        "  --seed N               random seed (default 1); the same seed and options give the\n"
        "                         same bytes whatever --threads\n"
        "  --sets N               number of stroke sets, 3..10 (default 6), large to small,\n"
        "                         sized from the canvas\n"
        "  --set-sizes WxH,...    explicit set sizes in pixels, coarse to fine (overrides --sets)\n"
        "  --max-strokes N        stop after N strokes (default 100000)\n"
        "  --target-psnr DB       stop when the painting reaches DB dB PSNR (default: none)\n"
        "  --threshold X          switch to the next smaller set when the relative error\n"
        "                         improvement over a window (half a canvas coverage of the\n"
        "                         set's strokes) drops below X (default 0.01)\n"
        "  --lambda X             rate-distortion acceptance: a stroke must remove the error of\n"
        "                         X average pixels (0 = any improvement); default 24, or\n"
        "                         with --target-psnr 24 * 2^((28 - DB) / 4) in 8..64 (measured\n"
        "                         best per target); it halves whenever the painting stalls\n"
        "                         short of the target\n"
        "  --temperature X        Metropolis temperature at the start of a set, relative to the\n"
        "                         lambda cost (default 0.25; 0 = greedy)\n"
        "  --templates DIR        use the grayscale images of DIR (name order, up to 1024x1024,\n"
        "                         60x60 by convention) as stroke templates instead of the\n"
        "                         built-in rectangle, soft round and ellipse (textured\n"
        "                         brushes: converter/templates/brushes/)\n"
        "  --roi x,y,w,h          a region of interest painted down to the finest set (the\n"
        "                         finest set paints only there); repeatable\n"
        "  --roi-file F           regions of interest from JSON:\n"
        "                         {\"rois\":[{\"x\":..,\"y\":..,\"w\":..,\"h\":..}]}\n"
        "  --orient MODE          stroke orientation: edges (default; follow the nearest\n"
        "                         multiscale edge), gradient (local structure tensor), random\n"
        "  --threads N            worker threads (default: all cores)\n"
        "  --progress MODE        auto (a bar on a terminal), plain, json (one object per line\n"
        "                         on stdout), none\n"
        "  --preview FILE         also write the rendered painting (PNG, EXR, TIFF, ...)\n"
        "  --side-by-side FILE    also write source | painting in one image\n"
        "  --background R,G,B     canvas colour before any stroke (default 255,255,255)\n"
        "  --stored               write stored (coding 0) frames instead of range-coded ones\n"
        "  --coding 1|2           2 (default): code which of the painter's replayable random\n"
        "                         candidates were accepted (SPEC.md 7.7); 1: explicit positions\n"
        "  --color-step Q         choose colours on a lattice of step Q (1..32; default 12, or 4\n"
        "                         with --target-psnr above 33) around the canvas under the\n"
        "                         stroke: coding 2 spends fewer bits on them\n"
        "  --target-bytes N[/s]   search lambda so that the file is at most N bytes (N/s: per\n"
        "                         second of a clip); reports where it landed"
        "\n"
        "sequences and video:\n"
        "  --frames A-B           paint only these frames (sequence numbers, or 0-based video\n"
        "                         frames)\n"
        "  --fps R                frame rate, e.g. 24 or 30000/1001 (default: the video's, or 24)\n"
        "  --skip-bad-frames      repeat the previous frame for a missing or unreadable one\n"
        "                         instead of stopping\n"
        "  --keyframe-interval N  at most N frames from one key frame to the next (default 100)\n"
        "  --cut-threshold X      cut when the pixel x edge difference exceeds X times its\n"
        "                         recent average (default 6)\n"
        "  --flow METHOD          optical flow: dis-ultrafast (default), dis-fast, dis-medium,\n"
        "                         farneback\n"
        "  --max-inter-strokes N  at most N new strokes per inter frame (default 4000)\n"
        "  --motion-block N       motion block size in pixels, 8..256 (default 16)\n"
        "  --flow-orientation     lay new strokes along the optical flow where the picture\n"
        "                         moves (default: along the edges, as for key frames)\n"
        "  --roi-file F           for video, each ROI may have \"frames\": \"A-B\"\n"
        "  Ctrl-C / SIGTERM stops after the current frame and leaves a valid OUT.spt holding\n"
        "  every finished frame.\n"
        "\n"
        "  -h, --help             this help\n"
        "\n"
        "exit status: 0 success, 1 failure (unreadable input, write error), 2 bad usage\n",
        f);
}

ParseResult parse_paint_options(int argc, char** argv, PaintCommandOptions& o, std::string& err) {
    bool have_sets = false;
    // Defaults chosen by measurement (paint/rate_control.hpp rate_defaults, bench/rate_sweep.sh);
    // with --target-psnr they follow the target unless given.
    bool have_lambda = false, have_step = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&](std::string& v) -> bool {
            if (i + 1 >= argc) { err = "option " + a + " needs a value"; return false; }
            v = argv[++i];
            return true;
        };
        std::string v;
        if (a == "-h" || a == "--help") return ParseResult::Help;
        if (a == "-o" || a == "--output") {
            if (!value(o.output)) return ParseResult::Error;
        } else if (a == "--seed") {
            if (!value(v)) return ParseResult::Error;
            if (!parse_u64(v, o.paint.seed)) { err = "--seed: expected an unsigned integer, got '" + v + "'"; return ParseResult::Error; }
        } else if (a == "--sets") {
            long n;
            if (!value(v)) return ParseResult::Error;
            if (!parse_int(v, 3, 10, n)) { err = "--sets: expected 3..10, got '" + v + "'"; return ParseResult::Error; }
            o.sets = int(n);
            have_sets = true;
        } else if (a == "--set-sizes") {
            if (!value(v)) return ParseResult::Error;
            if (!parse_set_sizes(v, o.set_sizes) || o.set_sizes.size() > 16) {
                err = "--set-sizes: expected 1..16 sizes WxH (1..4096) separated by commas, got '" + v + "'";
                return ParseResult::Error;
            }
        } else if (a == "--max-strokes") {
            if (!value(v)) return ParseResult::Error;
            if (!parse_u64(v, o.paint.max_strokes) || o.paint.max_strokes == 0 || o.paint.max_strokes > (1u << 24)) {
                err = "--max-strokes: expected 1..16777216, got '" + v + "'";
                return ParseResult::Error;
            }
        } else if (a == "--target-psnr") {
            if (!value(v)) return ParseResult::Error;
            if (!parse_double(v, 1, 99, o.paint.target_psnr)) { err = "--target-psnr: expected 1..99 dB, got '" + v + "'"; return ParseResult::Error; }
        } else if (a == "--threshold") {
            if (!value(v)) return ParseResult::Error;
            if (!parse_double(v, 0, 1, o.paint.threshold)) { err = "--threshold: expected 0..1, got '" + v + "'"; return ParseResult::Error; }
        } else if (a == "--lambda") {
            if (!value(v)) return ParseResult::Error;
            if (!parse_double(v, 0, 1e6, o.paint.lambda)) { err = "--lambda: expected a number >= 0, got '" + v + "'"; return ParseResult::Error; }
            have_lambda = true;
        } else if (a == "--temperature") {
            if (!value(v)) return ParseResult::Error;
            if (!parse_double(v, 0, 1e3, o.paint.temperature)) { err = "--temperature: expected a number >= 0, got '" + v + "'"; return ParseResult::Error; }
        } else if (a == "--templates") {
            if (!value(o.templates_dir)) return ParseResult::Error;
        } else if (a == "--roi") {
            if (!value(v)) return ParseResult::Error;
            RoiSpec r;
            if (!parse_rect(v, r.rect)) { err = "--roi: expected x,y,w,h (w, h > 0), got '" + v + "'"; return ParseResult::Error; }
            o.rois.push_back(r);
        } else if (a == "--roi-file") {
            if (!value(o.roi_file)) return ParseResult::Error;
        } else if (a == "--orient") {
            if (!value(v)) return ParseResult::Error;
            if (v == "edges") o.paint.orient = paint::OrientMode::Edges;
            else if (v == "gradient") o.paint.orient = paint::OrientMode::Gradient;
            else if (v == "random") o.paint.orient = paint::OrientMode::Random;
            else { err = "--orient: expected edges, gradient or random, got '" + v + "'"; return ParseResult::Error; }
        } else if (a == "--threads") {
            long n;
            if (!value(v)) return ParseResult::Error;
            if (!parse_int(v, 1, 1024, n)) { err = "--threads: expected 1..1024, got '" + v + "'"; return ParseResult::Error; }
            o.paint.threads = int(n);
        } else if (a == "--progress") {
            if (!value(v)) return ParseResult::Error;
            if (!io::parse_progress_mode(v, o.progress)) { err = "--progress: expected auto, plain, json or none, got '" + v + "'"; return ParseResult::Error; }
        } else if (a == "--preview") {
            if (!value(o.preview)) return ParseResult::Error;
        } else if (a == "--side-by-side") {
            if (!value(o.side_by_side)) return ParseResult::Error;
        } else if (a == "--background") {
            if (!value(v)) return ParseResult::Error;
            if (!parse_rgb(v, o.background)) { err = "--background: expected R,G,B (0..255), got '" + v + "'"; return ParseResult::Error; }
        } else if (a == "--stored") {
            o.stored = true;
        } else if (a == "--coding") {
            if (!value(v)) return ParseResult::Error;
            if (v != "1" && v != "2") { err = "--coding: expected 1 or 2, got '" + v + "'"; return ParseResult::Error; }
            o.coding = v == "1" ? 1 : 2;
        } else if (a == "--color-step") {
            long n;
            if (!value(v)) return ParseResult::Error;
            if (!parse_int(v, 1, 32, n)) { err = "--color-step: expected 1..32, got '" + v + "'"; return ParseResult::Error; }
            o.paint.color_step = int(n);
            have_step = true;
        } else if (a == "--target-bytes") {
            if (!value(v)) return ParseResult::Error;
            std::string num = v;
            o.target_bytes_per_second = num.size() > 2 && num.compare(num.size() - 2, 2, "/s") == 0;
            if (o.target_bytes_per_second) num.resize(num.size() - 2);
            if (!parse_u64(num, o.target_bytes) || o.target_bytes < 64) {
                err = "--target-bytes: expected a size of at least 64 bytes, optionally /s, got '" + v + "'";
                return ParseResult::Error;
            }
        } else if (a == "--frames") {
            if (!value(o.frames)) return ParseResult::Error;
        } else if (a == "--fps") {
            if (!value(o.fps)) return ParseResult::Error;
        } else if (a == "--skip-bad-frames") {
            o.skip_bad_frames = true;
        } else if (a == "--keyframe-interval") {
            long n;
            if (!value(v)) return ParseResult::Error;
            if (!parse_int(v, 1, 1000000, n)) { err = "--keyframe-interval: expected 1..1000000, got '" + v + "'"; return ParseResult::Error; }
            o.keyframe_interval = int(n);
        } else if (a == "--cut-threshold") {
            if (!value(v)) return ParseResult::Error;
            if (!parse_double(v, 1, 1e6, o.cut_threshold)) { err = "--cut-threshold: expected a number >= 1, got '" + v + "'"; return ParseResult::Error; }
        } else if (a == "--flow") {
            if (!value(o.flow)) return ParseResult::Error;
        } else if (a == "--max-inter-strokes") {
            if (!value(v)) return ParseResult::Error;
            if (!parse_u64(v, o.max_inter_strokes) || o.max_inter_strokes > (1u << 24)) { err = "--max-inter-strokes: expected 0..16777216, got '" + v + "'"; return ParseResult::Error; }
        } else if (a == "--flow-orientation") {
            o.flow_orientation = true;
        } else if (a == "--motion-block") {
            long n;
            if (!value(v)) return ParseResult::Error;
            if (!parse_int(v, 8, 256, n)) { err = "--motion-block: expected 8..256, got '" + v + "'"; return ParseResult::Error; }
            o.block_size = int(n);
        } else if (a.size() > 1 && a[0] == '-') {
            err = "unknown option " + a;
            return ParseResult::Error;
        } else if (o.input.empty()) {
            o.input = a;
        } else {
            err = "more than one input ('" + o.input + "' and '" + a + "')";
            return ParseResult::Error;
        }
    }
    const paint::RateDefaults rd = paint::rate_defaults(o.paint.target_psnr);
    if (!have_lambda) o.paint.lambda = rd.lambda;
    if (!have_step) o.paint.color_step = rd.color_step;
    if (o.input.empty()) { err = "no input image given"; return ParseResult::Error; }
    if (o.output.empty()) { err = "no output given (-o OUT.spt)"; return ParseResult::Error; }
    if (have_sets && !o.set_sizes.empty()) { err = "give --sets or --set-sizes, not both"; return ParseResult::Error; }
    o.cli_roi_count = o.rois.size();
    if (!o.roi_file.empty()) {
        auto r = io::read_roi_file(o.roi_file);
        if (!r) { err = "--roi-file " + r.error().message; return ParseResult::Error; }
        for (const io::RoiRange& f : *r) {
            RoiSpec s;
            s.first_frame = f.first_frame;
            s.last_frame = f.last_frame;
            s.rect = paint::Rect{f.x, f.y, f.w, f.h};
            o.rois.push_back(s);
        }
    }
    return ParseResult::Ok;
}

std::string PaintCommandOptions::canonical() const {
    std::ostringstream s;
    s << "sets=";
    if (set_sizes.empty()) s << sets;
    else
        for (size_t i = 0; i < set_sizes.size(); ++i) s << (i ? "," : "") << set_sizes[i].width << 'x' << set_sizes[i].height;
    s << " max-strokes=" << paint.max_strokes << " target-psnr=" << paint.target_psnr
      << " threshold=" << paint.threshold << " lambda=" << paint.lambda << " color-step=" << paint.color_step << " temperature=" << paint.temperature
      << " orient=" << orient_name(paint.orient) << " templates=" << (templates_dir.empty() ? "builtin" : "custom")
      << " background=" << int(background.r) << ',' << int(background.g) << ',' << int(background.b)
      << " rois=" << rois.size();
    return s.str();
}

}  // namespace spt::cli
