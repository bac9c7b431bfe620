// Importer for Lottie animations (bodymovin JSON, and .lottie zips): every frame of the
// composition evaluated (keyframes with their easing) and drawn as polygons and curves on an
// alpha canvas, so that players composite it as Lottie players do. The pieces are in lottie/
// (model.hpp says which file does what); this file reads the top level, bounds hostile input and
// registers the importer.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lottie/model.hpp"
#include "lottie/zip.hpp"
#include "spt_import/importer.hpp"

namespace spt::import {

namespace {

using namespace lottie;

// A Lottie file is larger than the shapes it draws; 64 MiB holds far more than any made by a
// tool, and the parse tree of that many values (about 100 bytes each) stays in memory bounds.
constexpr size_t kMaxLottieBytes = size_t(64) << 20;
constexpr size_t kMaxValues = size_t(1) << 22;

bool ends_with(const std::string& s, const char* suf) {
    const size_t n = std::char_traits<char>::length(suf);
    if (s.size() < n) return false;
    for (size_t k = 0; k < n; ++k)
        if (std::tolower((unsigned char)s[s.size() - n + k]) != suf[k]) return false;
    return true;
}

bool sniff(const std::string& path, std::string_view head) {
    if (ends_with(path, ".lottie")) return true;
    if (head.find("spt-strokes") != std::string_view::npos) return false;
    const size_t b = head.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
    if (b == std::string_view::npos || head[b] != '{') return false;
    auto has = [&](const char* k) { return head.find(k) != std::string_view::npos; };
    return (has("\"ks\"") && has("\"ty\"") && has("\"ddd\"")) || (has("\"fr\"") && has("\"ip\"") && has("\"op\"") && has("\"v\""));
}

double number(const Value& root, const char* key, const std::string& file, std::string& err) {
    const Value* v = root.find(key);
    if (!v || !v->is_number() || !std::isfinite(v->number)) {
        if (err.empty()) err = file + ": Lottie field \"" + key + "\" is missing or not a number";
        return 0;
    }
    return v->number;
}

Result<Document> load(const std::string& path, std::string text, const ImportOptions& opts) {
    const size_t cap = std::min(opts.max_file_bytes, kMaxLottieBytes);
    if (ends_with(path, ".lottie")) {
        auto a = dotlottie_animation(path, cap);
        if (!a) return a.error();
        text = std::move(*a);
    }
    if (text.size() > cap)
        return make_error(Code::LimitExceeded, path + ": " + std::to_string(text.size()) + " bytes is above the Lottie importer's " +
                                                   std::to_string(cap) + "-byte limit");
    json::ParseLimits pl;
    pl.max_bytes = cap;
    pl.max_values = kMaxValues;
    auto root = json::parse(text, path, pl);
    if (!root) return root.error();
    text.clear();
    text.shrink_to_fit();
    if (!root->is_object()) return make_error(Code::InvalidArgument, path + ": a Lottie file is a JSON object");

    std::string err;
    const double w = number(*root, "w", path, err), h = number(*root, "h", path, err);
    const double fr = number(*root, "fr", path, err), ip = number(*root, "ip", path, err), op = number(*root, "op", path, err);
    if (!err.empty()) return make_error(Code::InvalidArgument, err);
    if (w < 1 || h < 1 || w > opts.limits.max_width || h > opts.limits.max_height || w * h > double(opts.limits.max_pixels))
        return make_error(Code::LimitExceeded, path + ": canvas " + std::to_string(w) + "x" + std::to_string(h) + " is outside 1.." +
                                                   std::to_string(opts.limits.max_width) + "x" + std::to_string(opts.limits.max_height));
    if (!(fr > 0 && fr <= 1000)) return make_error(Code::InvalidArgument, path + ": frame rate \"fr\" must be in (0, 1000]");
    Ctx c;
    c.file = path;
    Document doc;
    c.report = &doc.report;
    const double frames = std::ceil(op - ip);
    if (!(frames >= 1)) return make_error(Code::InvalidArgument, path + ": \"op\" must be after \"ip\"");
    if (frames > c.bounds.max_frames || frames > opts.limits.max_frames)
    {
        char n[32];
        std::snprintf(n, sizeof n, "%.6g", frames);  // op - ip may be any double
        return make_error(Code::LimitExceeded, path + ": " + n + " frames is above the limit of " + std::to_string(c.bounds.max_frames));
    }

    Comp comp;
    comp.root = &*root;
    comp.fr = fr;
    if (const Value* as = root->find("assets"); as && as->is_array()) {
        size_t images = 0;
        for (const Value& a : as->items) {
            const Value* id = a.find("id");
            const Value* ls = a.find("layers");
            if (id && id->is_string() && ls && ls->is_array()) comp.assets[id->text] = ls;
            else ++images;
        }
        if (images) c.warn(std::to_string(images) + " image asset(s) are not held by the format (it has no image strokes)");
    }
    if (root->find("fonts") || root->find("chars")) c.warn("fonts and glyphs are not read (text layers are not drawn)");

    std::vector<std::vector<Stroke>> lists;
    for (uint32_t f = 0; f < uint32_t(frames); ++f) {
        std::vector<Stroke> list;
        if (!render_comp(c, comp, ip + f, list)) return make_error(Code::LimitExceeded, c.error);
        if (list.size() > opts.limits.max_strokes_per_frame)
            return make_error(Code::LimitExceeded, path + ": frame " + std::to_string(f) + " needs more strokes than the limit");
        lists.push_back(std::move(list));
    }
    doc.info.header = default_header(uint32_t(std::lround(w)), uint32_t(std::lround(h)), opts.background.value_or(Rgb8{255, 255, 255}));
    doc.info.header.alpha = true;  // Lottie has no background: players composite it
    doc.info.header.curve_grid = true;
    doc.info.header.version_minor = kCurveGridMinorVersion;
    // The rate as a fraction: 29.97 -> 2997/100.
    Rational r{uint32_t(std::lround(fr)), 1};
    if (std::fabs(fr - std::round(fr)) > 1e-9) r = {uint32_t(std::lround(fr * 1000)), 1000};
    doc.info.header.fps = opts.fps.value_or(r);
    doc.info.templates = default_templates();
    doc.frames = frames_from_lists(lists);
    doc.info.header.frame_count = uint32_t(doc.frames.size());
    doc.report.note("Beziers flattened within 1/64 px, vertices rounded to 1/16 px: every outline point within 1/16 px of its Lottie curve");
    return doc;
}

}  // namespace

extern const Importer kLottieImporter;
const Importer kLottieImporter = {"lottie", "Lottie animations (bodymovin .json, .lottie zips): shape layers as polygons and curves",
                                  sniff, load};

}  // namespace spt::import
