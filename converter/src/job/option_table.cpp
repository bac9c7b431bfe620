// The rows of the option table (option_table.hpp): one per option of `spt paint` and `spt plan`.
#include "job/option_table.hpp"

#include <filesystem>

#include "io/progress.hpp"
#include "job/option_text.hpp"

namespace spt::job {

namespace {

using Rows = std::vector<OptionRow>;
using Get = std::function<std::vector<std::string>(const PaintJob&)>;
using Canon = std::function<void(std::ostream&, const PaintJob&)>;

constexpr unsigned kPainterlyOnly = style_bit(Style::Painterly);
constexpr unsigned kCartoonOnly = style_bit(Style::Cartoon);

// A row under construction: the table below reads as one line of facts per option.
struct Row {
    OptionRow r;
    Row(std::string name, std::string metavar, OptionKind kind, std::string help) {
        r.name = std::move(name);
        r.metavar = std::move(metavar);
        r.kind = kind;
        r.help = std::move(help);
    }
    Row& def(std::string d) { r.def = std::move(d); return *this; }
    Row& range(double lo, double hi, std::string unit = {}) { r.lo = lo; r.hi = hi; r.unit = std::move(unit); return *this; }
    Row& choices(std::vector<std::string> c) { r.choices = std::move(c); return *this; }
    Row& styles(unsigned s) { r.styles = s; return *this; }
    Row& scope(OptionScope s) { r.scope = s; return *this; }
    Row& only(unsigned commands) { r.commands = commands; return *this; }
    Row& group(std::string g) { r.group = std::move(g); return *this; }
    Row& addon() { r.addon = true; return *this; }
    Row& set(std::function<std::string(PaintJob&, const std::string&)> f) { r.set = std::move(f); return *this; }
    Row& get(Get f) { r.get = std::move(f); return *this; }
    Row& check(std::function<std::string(const PaintJob&)> f) { r.check = std::move(f); return *this; }
    Row& canon(int rank, Canon f) { r.canon_rank = rank; r.canon = std::move(f); return *this; }
};

std::vector<std::string> one(std::string v) { return {std::move(v)}; }
std::vector<std::string> none() { return {}; }

std::string absolute(const std::string& p) {
    std::error_code ec;
    const auto a = std::filesystem::absolute(p, ec);
    return ec ? p : a.lexically_normal().string();
}

bool cartoon(const PaintJob& j) { return j.style == Style::Cartoon; }

const char* kCartoonGroup = "";  // the cartoon options sit with the painter's
const char* kColour = "colour and alpha";
const char* kVideo = "sequences and video";
const char* kPlan = "farm plan";

Rows painter_rows() {
    Rows t;
    auto add = [&](Row& b) { t.push_back(std::move(b.r)); };
    Row rows[] = {
        Row("style", "NAME", OptionKind::Choice,
            "painterly: stamps everywhere (the paper's painter); cartoon: flat-colour regions as anti-aliased filled "
            "polygons, stamps only where they leave an error; with --target-psnr never larger than the default "
            "painter, whose painting is written instead where smaller (said on stderr)")
            .def("painterly").choices({"painterly", "cartoon"}).addon()
            .set([](PaintJob& j, const std::string& v) { j.style = v == "cartoon" ? Style::Cartoon : Style::Painterly; return std::string(); })
            .get([](const PaintJob& j) { return cartoon(j) ? one(style_name(j.style)) : none(); })
            .canon(12, [](std::ostream& s, const PaintJob& j) { if (cartoon(j)) s << " style=" << style_name(j.style); }),
        Row("seed", "N", OptionKind::Text, "random seed; the same seed and options give the same bytes whatever --threads")
            .def("1").scope(OptionScope::Shot).addon()
            .set([](PaintJob& j, const std::string& v) { return parse_u64(v, j.paint.seed) ? "" : "expected an unsigned integer"; }),
        Row("sets", "N", OptionKind::Integer, "number of stroke sets, 3..10, large to small, sized from the canvas")
            .def("6").range(3, 10).addon()
            .set([](PaintJob& j, const std::string& v) { j.sets = std::stoi(v); return std::string(); })
            .get([](const PaintJob& j) { return j.set_sizes.empty() ? one(std::to_string(j.sets)) : none(); })
            .canon(1, [](std::ostream& s, const PaintJob& j) {
                s << " sets=";
                if (j.set_sizes.empty()) s << j.sets;
                else s << set_sizes_text(j.set_sizes);
            }),
        Row("set-sizes", "WxH,...", OptionKind::Text, "explicit set sizes in pixels, coarse to fine (overrides --sets)")
            .set([](PaintJob& j, const std::string& v) {
                return parse_set_sizes(v, j.set_sizes) && j.set_sizes.size() <= 16
                           ? "" : "expected 1..16 sizes WxH (1..4096) separated by commas";
            })
            .get([](const PaintJob& j) { return j.set_sizes.empty() ? none() : one(set_sizes_text(j.set_sizes)); }),
        Row("max-strokes", "N", OptionKind::Integer, "stop after N strokes")
            .def("100000").range(1, 1 << 24).addon()
            .set([](PaintJob& j, const std::string& v) { j.paint.max_strokes = std::stoull(v); return std::string(); })
            .get([](const PaintJob& j) { return one(std::to_string(j.paint.max_strokes)); })
            .canon(2, [](std::ostream& s, const PaintJob& j) { s << " max-strokes=" << j.paint.max_strokes; }),
        Row("target-psnr", "DB", OptionKind::Number, "stop when the painting reaches DB dB PSNR (default: none)")
            .range(1, 99, "dB").addon()
            .set([](PaintJob& j, const std::string& v) { j.paint.target_psnr = std::stod(v); return std::string(); })
            .get([](const PaintJob& j) { return j.paint.target_psnr > 0 ? one(exact(j.paint.target_psnr)) : none(); })
            .canon(3, [](std::ostream& s, const PaintJob& j) { s << " target-psnr=" << j.paint.target_psnr; }),
        Row("threshold", "X", OptionKind::Number,
            "switch to the next smaller set when the relative error improvement over a window (half a canvas coverage "
            "of the set's strokes) drops below X")
            .def("0.01").range(0, 1)
            .set([](PaintJob& j, const std::string& v) { j.paint.threshold = std::stod(v); return std::string(); })
            .get([](const PaintJob& j) { return one(exact(j.paint.threshold)); })
            .canon(4, [](std::ostream& s, const PaintJob& j) { s << " threshold=" << j.paint.threshold; }),
        Row("lambda", "X", OptionKind::Number,
            "rate-distortion acceptance: a stroke must remove the error of X average pixels (0 = any improvement); "
            "default 24, or with --target-psnr 24 * 2^((28 - DB) / 4) in 8..64 (measured best per target); it halves "
            "whenever the painting stalls short of the target")
            .range(0, 1e6)
            .set([](PaintJob& j, const std::string& v) { j.paint.lambda = std::stod(v); return std::string(); })
            .get([](const PaintJob& j) { return one(exact(j.paint.lambda)); })
            .canon(5, [](std::ostream& s, const PaintJob& j) { s << " lambda=" << j.paint.lambda; }),
        Row("temperature", "X", OptionKind::Number,
            "Metropolis temperature at the start of a set, relative to the lambda cost (0 = greedy)")
            .def("0.25").range(0, 1e3)
            .set([](PaintJob& j, const std::string& v) { j.paint.temperature = std::stod(v); return std::string(); })
            .get([](const PaintJob& j) { return one(exact(j.paint.temperature)); })
            .canon(7, [](std::ostream& s, const PaintJob& j) { s << " temperature=" << j.paint.temperature; }),
        Row("templates", "DIR", OptionKind::Path,
            "use the grayscale images of DIR (name order, up to 1024x1024, 60x60 by convention) as stroke templates "
            "instead of the built-in rectangle, soft round and ellipse (textured brushes: converter/templates/brushes/)")
            .addon()
            .set([](PaintJob& j, const std::string& v) { j.templates_dir = v; return std::string(); })
            .get([](const PaintJob& j) { return j.templates_dir.empty() ? none() : one(absolute(j.templates_dir)); })
            .canon(9, [](std::ostream& s, const PaintJob& j) { s << " templates=" << (j.templates_dir.empty() ? "builtin" : "custom"); }),
        Row("roi", "x,y,w,h", OptionKind::List,
            "a region of interest painted down to the finest set (the finest set paints only there)")
            .styles(kPainterlyOnly)
            .set([](PaintJob& j, const std::string& v) {
                RoiSpec spec;
                if (!parse_rect(v, spec.rect)) return "expected x,y,w,h (w, h > 0)";
                j.rois.push_back(spec);
                j.cli_roi_count = j.rois.size();
                return "";
            })
            .get([](const PaintJob& j) {
                std::vector<std::string> v;
                for (size_t i = 0; i < j.cli_roi_count && i < j.rois.size(); ++i) v.push_back(rect_text(j.rois[i].rect));
                return v;
            })
            .canon(11, [](std::ostream& s, const PaintJob& j) { s << " rois=" << j.rois.size(); }),
        Row("roi-file", "F", OptionKind::Path,
            "regions of interest from JSON: {\"rois\":[{\"x\":..,\"y\":..,\"w\":..,\"h\":..}]}; for video, each ROI may "
            "have \"frames\": \"A-B\"")
            .styles(kPainterlyOnly).addon()
            .set([](PaintJob& j, const std::string& v) { j.roi_file = v; return std::string(); })
            .get([](const PaintJob& j) { return j.roi_file.empty() ? none() : one(absolute(j.roi_file)); }),
        Row("orient", "MODE", OptionKind::Choice,
            "stroke orientation: edges (follow the nearest multiscale edge), gradient (local structure tensor), random")
            .def("edges").choices({"edges", "gradient", "random"})
            .set([](PaintJob& j, const std::string& v) {
                j.paint.orient = v == "gradient" ? paint::OrientMode::Gradient
                                 : v == "random" ? paint::OrientMode::Random : paint::OrientMode::Edges;
                return std::string();
            })
            .get([](const PaintJob& j) { return one(orient_name(j.paint.orient)); })
            .canon(8, [](std::ostream& s, const PaintJob& j) { s << " orient=" << orient_name(j.paint.orient); }),
        Row("threads", "N", OptionKind::Integer, "worker threads (default: all cores)")
            .range(1, 1024).scope(OptionScope::Run)
            .set([](PaintJob& j, const std::string& v) { j.paint.threads = std::stoi(v); return std::string(); }),
        Row("progress", "MODE", OptionKind::Choice, io::kProgressHelp)
            .def("auto").choices({"auto", "plain", "json", "none"}).scope(OptionScope::Run)
            .set([](PaintJob& j, const std::string& v) { io::parse_progress_mode(v, j.progress); return std::string(); }),
        Row("preview", "FILE", OptionKind::Path, "also write the rendered painting (PNG, EXR, TIFF, ...)")
            .scope(OptionScope::Run).only(kForPaint)
            .set([](PaintJob& j, const std::string& v) { j.preview = v; return std::string(); }),
        Row("side-by-side", "FILE", OptionKind::Path, "also write source | painting in one image")
            .scope(OptionScope::Run).only(kForPaint)
            .set([](PaintJob& j, const std::string& v) { j.side_by_side = v; return std::string(); }),
        Row("background", "R,G,B", OptionKind::Text, "canvas colour before any stroke")
            .def("255,255,255")
            .set([](PaintJob& j, const std::string& v) { return parse_rgb(v, j.background) ? "" : "expected R,G,B (0..255)"; })
            .get([](const PaintJob& j) { return one(rgb_text(j.background)); })
            .canon(10, [](std::ostream& s, const PaintJob& j) { s << " background=" << rgb_text(j.background); }),
        Row("stored", "", OptionKind::Flag, "write stored (coding 0) frames instead of range-coded ones")
            .set([](PaintJob& j, const std::string&) { j.stored = true; return std::string(); })
            .get([](const PaintJob& j) { return j.stored ? one("true") : none(); }),
        Row("coding", "1|2", OptionKind::Choice,
            "2: code which of the painter's replayable random candidates were accepted (SPEC.md 7.7); 1: explicit positions")
            .def("2").choices({"1", "2"})
            .set([](PaintJob& j, const std::string& v) { j.coding = v == "1" ? 1 : 2; return std::string(); })
            .get([](const PaintJob& j) { return one(std::to_string(j.coding)); }),
        Row("color-step", "Q", OptionKind::Integer,
            "choose colours on a lattice of step Q (1..32; default 12, or 4 with --target-psnr above 33) around the "
            "canvas under the stroke: coding 2 spends fewer bits on them")
            .range(1, 32)
            .set([](PaintJob& j, const std::string& v) { j.paint.color_step = std::stoi(v); return std::string(); })
            .get([](const PaintJob& j) { return one(std::to_string(j.paint.color_step)); })
            .canon(6, [](std::ostream& s, const PaintJob& j) { s << " color-step=" << j.paint.color_step; }),
        Row("target-bytes", "N[/s]", OptionKind::Text,
            "search lambda (--style cartoon: the PSNR target) so that the file is at most N bytes (N/s: per second of "
            "a clip); reports where it landed")
            .set([](PaintJob& j, const std::string& v) {
                return parse_target_bytes(v, j.target_bytes, j.target_bytes_per_second)
                           ? "" : "expected a size of at least 64 bytes, optionally /s";
            })
            .get([](const PaintJob& j) {
                return j.target_bytes > 0 ? one(std::to_string(j.target_bytes) + (j.target_bytes_per_second ? "/s" : "")) : none();
            }),
    };
    for (Row& b : rows) add(b);
    return t;
}

Rows cartoon_rows() {
    Rows t;
    Row rows[] = {
        Row("outline-tolerance", "PX", OptionKind::Number,
            "--style cartoon: how far (pixels) a polygon's outline may leave the traced edge. Default: with "
            "--target-psnr the coarsest of 1, 0.7 and 0.5 whose polygons reach it; short of it, the smallest file of "
            "0.25, 0.35 and 0.5 for a still, 0.35 or 0.5 for a sequence's key frame; 0.35 otherwise. Inter frames "
            "follow their key frame's, and with --target-psnr the regions one traces anew also try 1.2 and 1.4 times it")
            .range(0.01, 100, "pixels").styles(kCartoonOnly).group(kCartoonGroup)
            .set([](PaintJob& j, const std::string& v) { j.outline_tolerance = std::stod(v); return std::string(); })
            .get([](const PaintJob& j) { return j.outline_tolerance > 0 ? one(exact(j.outline_tolerance)) : none(); })
            .canon(13, [](std::ostream& s, const PaintJob& j) { if (cartoon(j)) s << " outline-tolerance=" << j.outline_tolerance; }),
        Row("outline-smooth", "PX", OptionKind::Number,
            "--style cartoon: average a traced edge over +-PX pixels (0..2) before its outline is simplified: a "
            "blurred or noisy edge takes fewer vertices. Default: unsmoothed, but short of --target-psnr a still "
            "smooths its 0.25 and 0.5 px outline trials by as much as their tolerance, and a sequence's key frame "
            "also tries 0.25 px of smoothing; the smallest is kept")
            .range(0, 2, "pixels").styles(kCartoonOnly)
            .set([](PaintJob& j, const std::string& v) { j.outline_smooth = std::stod(v); return std::string(); })
            .get([](const PaintJob& j) { return j.outline_smooth >= 0 ? one(exact(j.outline_smooth)) : none(); })
            .canon(15, [](std::ostream& s, const PaintJob& j) {
                if (cartoon(j) && j.outline_smooth >= 0) s << " outline-smooth=" << j.outline_smooth;
            }),
        Row("min-region", "PX", OptionKind::Integer,
            "--style cartoon: colour regions smaller than PX pixels (1..100000) join their neighbours before they are "
            "traced. Default: 3, but short of --target-psnr a still and a sequence's key frame also try 1 and 12 and "
            "keep the smallest: compressed video's noise makes many small regions, whose polygons cost more than the "
            "stamps that replace them; text's are parts of its letters")
            .range(1, 100000, "pixels").styles(kCartoonOnly)
            .set([](PaintJob& j, const std::string& v) { j.min_region = std::stoi(v); return std::string(); })
            .get([](const PaintJob& j) { return j.min_region > 0 ? one(std::to_string(j.min_region)) : none(); })
            .canon(16, [](std::ostream& s, const PaintJob& j) { if (cartoon(j) && j.min_region > 0) s << " min-region=" << j.min_region; }),
        Row("min-color-share", "F", OptionKind::Number,
            "--style cartoon: a flat colour covers at least this share of the pixels (0.000001..0.5, and 8 pixels). "
            "Default: 0.0001, but short of --target-psnr a still and a sequence's key frame also try 0.001, then 0.01, "
            "while that leaves colours out and the file comes out smaller: compressed video's ringing and blends make "
            "colours of their own that take pixels from the flat fills")
            .range(1e-6, 0.5).styles(kCartoonOnly)
            .set([](PaintJob& j, const std::string& v) { j.min_color_share = std::stod(v); return std::string(); })
            .get([](const PaintJob& j) { return j.min_color_share > 0 ? one(exact(j.min_color_share)) : none(); })
            .canon(17, [](std::ostream& s, const PaintJob& j) {
                if (cartoon(j) && j.min_color_share > 0) s << " min-color-share=" << j.min_color_share;
            }),
        Row("no-lines", "", OptionKind::Flag,
            "--style cartoon: trace thin regions as polygons only. By default a thin region whose centreline curves "
            "are as close and smaller is drawn as lines: anti-aliased curves with widths (format 1.4; Grease Pencil "
            "line strokes)")
            .styles(kCartoonOnly)
            .set([](PaintJob& j, const std::string&) { j.lines = false; return std::string(); })
            .get([](const PaintJob& j) { return j.lines ? none() : one("true"); })
            .canon(14, [](std::ostream& s, const PaintJob& j) { if (cartoon(j)) s << " lines=" << (j.lines ? 1 : 0); }),
    };
    for (Row& b : rows) t.push_back(std::move(b.r));
    return t;
}

Rows colour_rows() {
    Rows t;
    Row rows[] = {
        Row("color-encoding", "MODE", OptionKind::Choice,
            "stroke colours: srgb8 (8-bit sRGB, as before format 1.3), linear (half floats of scene-linear Rec.709: "
            "values above 1 and smooth darks, for render output), auto: linear for float input (EXR, float TIFF), else srgb8")
            .def("auto").choices({"auto", "srgb8", "linear"}).group(kColour)
            .set([](PaintJob& j, const std::string& v) { j.color_encoding = v; return std::string(); })
            .check([](const PaintJob& j) {
                return cartoon(j) && j.color_encoding == "linear"
                           ? "--style cartoon does not support --color-encoding linear (it paints 8-bit sRGB)" : "";
            })
            .get([](const PaintJob& j) { return j.color_encoding != "auto" ? one(j.color_encoding) : none(); })
            .canon(18, [](std::ostream& s, const PaintJob& j) { if (j.color_encoding != "auto") s << " color-encoding=" << j.color_encoding; }),
        Row("alpha", "MODE", OptionKind::Choice,
            "on: paint an RGBA canvas, transparent where the input is, strokes with painted edges; off: flatten the "
            "input's alpha over --background; auto: on when the input has an alpha channel that is not opaque "
            "everywhere (a sequence: its first file)")
            .def("auto").choices({"auto", "on", "off"}).group(kColour)
            .set([](PaintJob& j, const std::string& v) { j.alpha = v; return std::string(); })
            .check([](const PaintJob& j) {
                return cartoon(j) && j.alpha == "on" ? "--style cartoon does not support --alpha on (it paints over "
                                                       "--background; --alpha off flattens the input's alpha)" : "";
            })
            .get([](const PaintJob& j) { return j.alpha != "auto" ? one(j.alpha) : none(); })
            .canon(19, [](std::ostream& s, const PaintJob& j) { if (j.alpha != "auto") s << " alpha=" << j.alpha; }),
        Row("colorspace", "NAME", OptionKind::Text,
            "the input's colour space, a name, alias or role of the OCIO config (e.g. ACEScg, sRGB, lin_rec709); "
            "default: lin_rec709 for float files, sRGB for 8- and 16-bit files")
            .styles(kPainterlyOnly).group(kColour)
            .set([](PaintJob& j, const std::string& v) { j.colorspace = v; return v.empty() ? "expected a colour space name" : ""; })
            .get([](const PaintJob& j) { return j.colorspace.empty() ? none() : one(j.colorspace); })
            .canon(20, [](std::ostream& s, const PaintJob& j) { if (!j.colorspace.empty()) s << " colorspace=" << j.colorspace; }),
        Row("ocio", "FILE", OptionKind::Path,
            "the OCIO config that --colorspace names come from (default: $OCIO, else OpenImageIO's built-in config, "
            "which knows linear, sRGB and Rec709)")
            .styles(kPainterlyOnly).group(kColour)
            .set([](PaintJob& j, const std::string& v) { j.ocio_config = v; return v.empty() ? "expected an OCIO config file" : ""; })
            .get([](const PaintJob& j) { return j.ocio_config.empty() ? none() : one(absolute(j.ocio_config)); })
            .canon(21, [](std::ostream& s, const PaintJob& j) { if (!j.ocio_config.empty()) s << " ocio=custom"; }),
        Row("layer", "NAME", OptionKind::Text,
            "the EXR layer to paint, as its channels are prefixed (e.g. ViewLayer.Combined for ViewLayer.Combined.R, "
            "G, B, A); default: the unnamed R, G, B, A, else the first layer with R, G, B")
            .styles(kPainterlyOnly).group(kColour)
            .set([](PaintJob& j, const std::string& v) { j.layer = v; return v.empty() ? "expected a layer name" : ""; })
            .get([](const PaintJob& j) { return j.layer.empty() ? none() : one(j.layer); })
            .canon(22, [](std::ostream& s, const PaintJob& j) { if (!j.layer.empty()) s << " layer=" << j.layer; }),
    };
    for (Row& b : rows) t.push_back(std::move(b.r));
    return t;
}

Rows video_rows() {
    Rows t;
    Row rows[] = {
        Row("frames", "A-B", OptionKind::Text, "paint only these frames (sequence numbers, or 0-based video frames)")
            .scope(OptionScope::Shot).group(kVideo)
            .set([](PaintJob& j, const std::string& v) { j.frames = v; return std::string(); }),
        Row("fps", "R", OptionKind::Text, "frame rate, e.g. 24 or 30000/1001 (default: the video's, or 24)")
            .scope(OptionScope::Shot).group(kVideo)
            .set([](PaintJob& j, const std::string& v) { j.fps = v; return std::string(); }),
        Row("skip-bad-frames", "", OptionKind::Flag,
            "repeat the previous frame for a missing or unreadable one instead of stopping")
            .group(kVideo)
            .set([](PaintJob& j, const std::string&) { j.skip_bad_frames = true; return std::string(); })
            .get([](const PaintJob& j) { return j.skip_bad_frames ? one("true") : none(); }),
        Row("keyframe-interval", "N", OptionKind::Integer, "at most N frames from one key frame to the next")
            .def("100").range(1, 1000000).group(kVideo).addon()
            .set([](PaintJob& j, const std::string& v) { j.keyframe_interval = std::stoi(v); return std::string(); })
            .get([](const PaintJob& j) { return one(std::to_string(j.keyframe_interval)); }),
        Row("cut-threshold", "X", OptionKind::Number,
            "cut when the pixel x edge difference exceeds X times its recent average")
            .def("6").range(1, 1e6).group(kVideo)
            .set([](PaintJob& j, const std::string& v) { j.cut_threshold = std::stod(v); return std::string(); })
            .get([](const PaintJob& j) { return one(exact(j.cut_threshold)); }),
        Row("flow", "METHOD", OptionKind::Text, "optical flow: dis-ultrafast, dis-fast, dis-medium, farneback")
            .def("dis-ultrafast").group(kVideo)
            .set([](PaintJob& j, const std::string& v) { j.flow = v; return std::string(); })
            .get([](const PaintJob& j) { return one(j.flow); }),
        Row("max-inter-strokes", "N", OptionKind::Integer, "at most N new strokes per inter frame")
            .def("4000").range(0, 1 << 24).group(kVideo)
            .set([](PaintJob& j, const std::string& v) { j.max_inter_strokes = std::stoull(v); return std::string(); })
            .get([](const PaintJob& j) { return one(std::to_string(j.max_inter_strokes)); }),
        Row("motion-block", "N", OptionKind::Integer, "motion block size in pixels, 8..256")
            .def("16").range(8, 256, "pixels").group(kVideo)
            .set([](PaintJob& j, const std::string& v) { j.block_size = std::stoi(v); return std::string(); })
            .get([](const PaintJob& j) { return one(std::to_string(j.block_size)); }),
        Row("flow-orientation", "", OptionKind::Flag,
            "lay new strokes along the optical flow where the picture moves (default: along the edges, as for key frames)")
            .styles(kPainterlyOnly).group(kVideo)
            .set([](PaintJob& j, const std::string&) { j.flow_orientation = true; return std::string(); })
            .get([](const PaintJob& j) { return j.flow_orientation ? one("true") : none(); }),
    };
    for (Row& b : rows) t.push_back(std::move(b.r));
    return t;
}

Rows planning_rows() {
    Rows t;
    Row rows[] = {
        Row("max-task-frames", "N", OptionKind::Integer,
            "split shots longer than N frames into tasks of at most N, at forced key frames (whole --keyframe-interval "
            "steps when one fits); 0 = at cuts only")
            .def("240").range(0, 100000000).scope(OptionScope::Planning).only(kForPlan).group(kPlan)
            .set([](PaintJob& j, const std::string& v) { j.max_task_frames = std::stol(v); return std::string(); }),
        Row("cut-scan", "MODE", OptionKind::Choice,
            "sampled: judge frame pairs only where frames sampled every --cut-step frames show a change a cut can hide "
            "in; full: judge every pair (reads every frame); tasks: no scan, each task finds the cuts in its own frames "
            "as it paints them (the plan decodes one frame); auto: tasks for a video file (which any scan decodes "
            "whole), sampled otherwise")
            .def("auto").choices({"auto", "sampled", "full", "tasks"}).scope(OptionScope::Planning).only(kForPlan).group(kPlan)
            .set([](PaintJob& j, const std::string& v) { j.cut_scan = v; return std::string(); }),
        Row("cut-step", "K", OptionKind::Integer, "the sampled cut scan's step (frames)")
            .def("16").range(1, 1000000).scope(OptionScope::Planning).only(kForPlan).group(kPlan)
            .set([](PaintJob& j, const std::string& v) { j.cut_step = std::stoi(v); return std::string(); }),
        Row("cut-history", "N", OptionKind::Integer,
            "the sampled cut scan weighs a pair against the N pairs before it (1..12; 12 is the full scan's own rule, "
            "and reads more frames)")
            .def("4").range(1, 12).scope(OptionScope::Planning).only(kForPlan).group(kPlan)
            .set([](PaintJob& j, const std::string& v) { j.cut_history = std::stoi(v); return std::string(); }),
    };
    for (Row& b : rows) t.push_back(std::move(b.r));
    return t;
}

Rows all_rows() {
    Rows t;
    for (Rows part : {painter_rows(), cartoon_rows(), colour_rows(), video_rows(), planning_rows()})
        for (OptionRow& r : part) t.push_back(std::move(r));
    return t;
}

}  // namespace

const char* style_name(Style s) { return s == Style::Cartoon ? "cartoon" : "painterly"; }

std::vector<OptionRow>& option_rows() {
    static std::vector<OptionRow> rows = all_rows();
    return rows;
}

const OptionRow* find_option(const std::string& name) {
    for (const OptionRow& r : option_rows())
        if (r.name == name) return &r;
    return nullptr;
}

}  // namespace spt::job
