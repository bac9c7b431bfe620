// Importer for geometrize's JSON shape export: {"shapes":[{"type":T,"data":[...],"color":[r,g,b,a]}]}.
// geometrize rasterizes on whole pixels: its coordinates are pixel indices, so a shape at
// index x is centred on the pixel centre x + 0.5 (see importers/README.md for each type).
#include <cmath>

#include "spt_import/geometrize.hpp"
#include "spt_import/importer.hpp"
#include "spt_json/json.hpp"
#include "spt_import/shapes.hpp"

namespace spt::import {

namespace {

using json::Type;
using json::Value;

constexpr double kHalf = 0.5;  // pixel index -> pixel centre

struct TypeInfo { int type; const char* name; size_t min_data, max_data; };
constexpr TypeInfo kTypes[] = {
    {1, "rectangle", 4, 4}, {2, "rotated rectangle", 5, 5}, {4, "triangle", 6, 6}, {8, "ellipse", 4, 4},
    {16, "rotated ellipse", 5, 5}, {32, "circle", 3, 3}, {64, "line", 4, 4}, {128, "quadratic bezier", 6, 6},
    {256, "polyline", 4, 2 * 65536},
};

Error at(const std::string& src, const Value& v, const std::string& what) {
    return make_error(Code::Corrupt, src + ":" + std::to_string(v.line) + ": " + what);
}

bool sniff(const std::string&, std::string_view head) {
    // The export starts with {"shapes": (whitespace allowed).
    size_t i = 0;
    while (i < head.size() && std::isspace((unsigned char)head[i])) ++i;
    if (i >= head.size() || head[i] != '{') return false;
    ++i;
    while (i < head.size() && std::isspace((unsigned char)head[i])) ++i;
    return head.substr(i, 8) == "\"shapes\"";
}

Result<Document> load(const std::string& path, std::string text, const ImportOptions& opts) {
    auto root = json::parse(text, path);
    if (!root) return root.error();
    if (!root->is_object()) return at(path, *root, "expected an object with \"shapes\"");
    const Value* shapes = root->find("shapes");
    if (!shapes || !shapes->is_array()) return at(path, *root, "missing \"shapes\" array");
    if (shapes->items.size() > opts.limits.max_strokes_per_frame) return at(path, *shapes, "more shapes than the stroke limit");

    // Parse every shape first: the canvas may come from the first (background) rectangle.
    struct Shape { int type; std::vector<double> d; Rgba8 c; const Value* v; };
    std::vector<Shape> list;
    list.reserve(shapes->items.size());
    for (size_t i = 0; i < shapes->items.size(); ++i) {
        const Value& s = shapes->items[i];
        const std::string where = "shapes[" + std::to_string(i) + "]";
        if (!s.is_object()) return at(path, s, where + " must be an object");
        const Value* t = s.find("type");
        const Value* d = s.find("data");
        const Value* c = s.find("color");
        if (!t || !t->is_number()) return at(path, s, where + ": missing numeric \"type\"");
        if (!d || !d->is_array()) return at(path, s, where + ": missing \"data\" array");
        if (!c || !c->is_array() || c->items.size() != 4) return at(path, s, where + ": \"color\" must be [r, g, b, a]");
        const TypeInfo* ti = nullptr;
        for (const auto& k : kTypes)
            if (t->number == k.type) ti = &k;
        if (!ti) return at(path, *t, where + ": unknown shape type " + t->text);
        if (d->items.size() < ti->min_data || d->items.size() > ti->max_data || (ti->type == 256 && d->items.size() % 2))
            return at(path, *d, where + ": a " + ti->name + " needs " + std::to_string(ti->min_data) +
                                    (ti->max_data > ti->min_data ? "+ (even)" : "") + " data values, not " + std::to_string(d->items.size()));
        Shape sh{ti->type, {}, {}, &s};
        for (const auto& x : d->items) {
            if (!x.is_number() || std::fabs(x.number) > double(1 << 20)) return at(path, x, where + ": data values must be numbers within +-2^20");
            sh.d.push_back(x.number);
        }
        uint8_t rgba[4];
        for (int k = 0; k < 4; ++k) {
            const Value& x = c->items[size_t(k)];
            if (!x.is_number() || x.number < 0 || x.number > 255 || x.number != std::floor(x.number))
                return at(path, x, where + ": colour components must be integers 0..255");
            rgba[k] = uint8_t(x.number);
        }
        sh.c = {rgba[0], rgba[1], rgba[2], rgba[3]};
        list.push_back(std::move(sh));
    }

    Document doc;
    doc.info.templates = default_templates();
    doc.frames.resize(1);
    size_t first = 0;
    uint32_t W = 0, H = 0;
    Rgb8 bg{255, 255, 255};
    // geometrize's app writes the starting canvas as a first opaque rectangle at the origin.
    if (!list.empty() && list[0].type == 1 && list[0].c.a == 255 && std::min(list[0].d[0], list[0].d[2]) <= 0 &&
        std::min(list[0].d[1], list[0].d[3]) <= 0) {
        const auto& d = list[0].d;
        W = uint32_t(std::max(d[0], d[2])) + 1;
        H = uint32_t(std::max(d[1], d[3])) + 1;
        bg = {list[0].c.r, list[0].c.g, list[0].c.b};
        first = 1;
    } else {
        doc.report.background_stated = false;
    }
    if (opts.canvas_size) { W = opts.canvas_size->first; H = opts.canvas_size->second; }
    if (W == 0 || H == 0)
        return make_error(Code::InvalidArgument, path + ": geometrize JSON does not give the canvas size (no background rectangle): pass --size WxH or --reference IMAGE");
    if (W > opts.limits.max_width || H > opts.limits.max_height || uint64_t(W) * H > opts.limits.max_pixels)
        return make_error(Code::LimitExceeded, path + ": canvas " + std::to_string(W) + "x" + std::to_string(H) + " is above the limits");
    doc.info.header = default_header(W, H, opts.background.value_or(bg));
    if (opts.fps) doc.info.header.fps = *opts.fps;

    auto& out = doc.frames[0].added;
    StrokeSink sink(out, doc.report);
    auto renderer = Renderer::create(doc.info.header, doc.info.templates);
    if (!renderer) return renderer.error();
    uint64_t differing = 0;
    for (size_t i = first; i < list.size(); ++i) {
        const auto& s = list[i];
        const auto& d = s.d;
        const double o = kHalf;
        if (s.type <= 32) {  // areas: the affine stroke closest to geometrize's own pixels
            ++doc.report.shapes;
            geometrize::append_shape(**renderer, s.type, d, s.c, W, H, out, doc.report, differing);
            continue;
        }
        switch (s.type) {
            case 64:  // x1, y1, x2, y2: a one-pixel line
                sink.polyline({{d[0] + o, d[1] + o}, {d[2] + o, d[3] + o}}, 1.0, s.c);
                break;
            case 128: {  // cx, cy, x1, y1, x2, y2: flattened into 16 segments
                std::vector<Point> pts;
                for (int k = 0; k <= 16; ++k) {
                    const double t = k / 16.0, u = 1 - t;
                    pts.push_back({u * u * d[2] + 2 * u * t * d[0] + t * t * d[4] + o, u * u * d[3] + 2 * u * t * d[1] + t * t * d[5] + o});
                }
                ++doc.report.approximated;
                doc.report.note("quadratic Bezier curves flattened to 16 segments");
                sink.polyline(pts, 1.0, s.c);
                break;
            }
            case 256: {
                std::vector<Point> pts;
                for (size_t k = 0; k + 1 < d.size(); k += 2) pts.push_back({d[k] + o, d[k + 1] + o});
                sink.polyline(pts, 1.0, s.c);
                break;
            }
        }
        if (s.type >= 64) doc.report.note("lines drawn 1 px wide with round caps (geometrize draws aliased 1 px lines)");
    }
    if (differing)
        doc.report.note("geometrize's scanline rasterisation reproduced by fitted affine and polygon strokes; " + std::to_string(differing) +
                        " shape pixels differ from it");
    // geometrize never paints the last row and column: put the canvas colour back there.
    for (const Stroke& st : canvas_strip_strokes(W, H, doc.info.header.background, 1)) out.push_back(st);
    doc.canvas_strips = true;
    if (Status st = validate(doc, path, opts.limits); !st) return st.error();
    return doc;
}

}  // namespace

extern const Importer kGeometrizeJsonImporter = {"geometrize-json", "geometrize's JSON shape export ({\"shapes\": [...]})", sniff, load};

}  // namespace spt::import
