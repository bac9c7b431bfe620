// Importer for the documented spt JSON stroke list (schema: importers/README.md), which is also
// what `spt export -o X.json` writes.
// The fields are read by strokes_json_fields.hpp, the strokes by strokes_json_stroke.cpp; this
// file reads the templates, the header and the frames, and registers the importer.
#include <algorithm>

#include "strokes_json_fields.hpp"

#include "spt/color.hpp"
#include "spt/display.hpp"

namespace spt::import {

namespace {

using namespace strokes_json;

bool read_templates(const Ctx& c, const Value* tv, std::vector<Template>& T, Error& e) {
    if (!tv) { T = default_templates(); return true; }
    if (!c.need(*tv, Type::Array, "templates", e)) return false;
    if (tv->items.size() > c.lim().max_templates) { e = c.err(*tv, "more than " + std::to_string(c.lim().max_templates) + " templates"); return false; }
    for (size_t i = 0; i < tv->items.size(); ++i) {
        const Value& t = tv->items[i];
        const std::string where = "templates[" + std::to_string(i) + "]";
        if (!c.need(t, Type::Object, where, e)) return false;
        Template out;
        const Value* kind = field(c, t, "kind", where, e);
        if (!kind || !c.need(*kind, Type::String, where + ".kind", e)) return false;
        if (kind->text == "ellipse") out.kind = TemplateKind::Ellipse;
        else if (kind->text == "rectangle") out.kind = TemplateKind::Rectangle;
        else if (kind->text == "triangle") out.kind = TemplateKind::Triangle;
        else if (kind->text == "bitmap") out.kind = TemplateKind::Bitmap;
        else { e = c.err(*kind, where + ": unknown template kind \"" + kind->text + "\""); return false; }
        if (const Value* n = t.find("name")) {
            if (!c.need(*n, Type::String, where + ".name", e)) return false;
            if (n->text.size() > 255) { e = c.err(*n, where + ".name longer than 255 bytes"); return false; }
            if (!c.utf8(*n, where + ".name", e)) return false;
            out.name = n->text;
        }
        if (const Value* ss = t.find("supersample")) {  // analytic kinds: 0 or 2..16 (SPEC.md 3.2)
            int64_t n;
            if (!c.integer(*ss, where + ".supersample", 0, 16, n, e)) return false;
            if (n == 1 || (n && out.kind == TemplateKind::Bitmap)) {
                e = c.err(*ss, where + ".supersample must be 0 or 2..16, and 0 for bitmaps");
                return false;
            }
            out.supersample = uint8_t(n);
        }
        if (out.kind == TemplateKind::Bitmap) {
            int64_t w, h;
            const Value* f;
            const int64_t side = c.lim().max_template_side;
            if (!(f = field(c, t, "width", where, e)) || !c.integer(*f, where + ".width", 1, side, w, e)) return false;
            if (!(f = field(c, t, "height", where, e)) || !c.integer(*f, where + ".height", 1, side, h, e)) return false;
            out.width = uint16_t(w);
            out.height = uint16_t(h);
            if (const Value* b = t.find("base64")) {
                if (!c.need(*b, Type::String, where + ".base64", e)) return false;
                auto d = base64_decode(b->text);
                if (!d) { e = c.err(*b, where + ".base64 is not valid base64"); return false; }
                out.pixels = std::move(*d);
            } else if (const Value* sv = t.find("samples")) {
                if (!c.need(*sv, Type::Array, where + ".samples", e)) return false;
                if (sv->items.size() != size_t(w * h)) { e = c.err(*sv, where + ".samples must hold width*height values"); return false; }
                for (size_t k = 0; k < sv->items.size(); ++k) {
                    int64_t v;
                    if (!c.integer(sv->items[k], where + ".samples[" + std::to_string(k) + "]", 0, 255, v, e)) return false;
                    out.pixels.push_back(uint8_t(v));
                }
            } else { e = c.err(t, where + ": a bitmap template needs \"base64\" or \"samples\""); return false; }
            if (out.pixels.size() != size_t(w * h)) {
                e = c.err(t, where + ": " + std::to_string(out.pixels.size()) + " samples for a " + std::to_string(w) + "x" + std::to_string(h) + " bitmap");
                return false;
            }
        }
        T.push_back(std::move(out));
    }
    return true;
}

bool read_header(Ctx& c, const Value& root, Header& h, Error& e) {
    const Value* canvas = field(c, root, "canvas", "document", e);
    if (!canvas || !c.need(*canvas, Type::Object, "canvas", e)) return false;
    // Version 3 (format 1.3): the colour encoding and the alpha canvas.
    ColorEncoding enc = ColorEncoding::Srgb8;
    bool alpha = false;
    for (const char* k : {"color_encoding", "alpha"}) {
        const Value* f = canvas->find(k);
        if (!f) continue;
        if (c.version < 3) { e = c.err(*f, std::string("canvas.") + k + " needs version 3"); return false; }
        if (k[0] == 'a') {
            if (f->type != Type::Bool) { e = c.err(*f, "canvas.alpha must be true or false"); return false; }
            alpha = f->boolean;
        } else if (f->is_string() && (f->text == "srgb8" || f->text == "linear-half")) {
            enc = f->text == "srgb8" ? ColorEncoding::Srgb8 : ColorEncoding::LinearHalf;
        } else {
            e = c.err(*f, "canvas.color_encoding must be \"srgb8\" or \"linear-half\"");
            return false;
        }
    }
    c.linear = enc == ColorEncoding::LinearHalf;
    // Version 2: canvas.curve_grid (format 1.4) keeps a file's flag when none of its curves has a
    // grid; a curve's "supersample" sets it too.
    bool curve_grid = false;
    if (const Value* g = canvas->find("curve_grid")) {
        if (c.version < 2) { e = c.err(*g, "canvas.curve_grid needs version 2"); return false; }
        if (g->type != Type::Bool) { e = c.err(*g, "canvas.curve_grid must be true or false"); return false; }
        curve_grid = g->boolean;
    }
    int64_t w, hh;
    const Value* f;
    if (!(f = field(c, *canvas, "width", "canvas", e)) || !c.integer(*f, "canvas.width", 1, c.lim().max_width, w, e)) return false;
    if (!(f = field(c, *canvas, "height", "canvas", e)) || !c.integer(*f, "canvas.height", 1, c.lim().max_height, hh, e)) return false;
    if (uint64_t(w) * uint64_t(hh) > c.lim().max_pixels) { e = c.err(*canvas, "canvas has more pixels than the limit"); return false; }
    Rgb8 bg{255, 255, 255}, bg_lo{0, 0, 0};
    if ((f = canvas->find("background"))) {
        Value tmp;
        tmp.type = Type::Object;
        tmp.line = f->line;
        tmp.members.emplace_back("color", *f);
        Rgba8 c4;
        if (!read_color(c, tmp, "canvas.background", c4, e)) return false;
        if (c4.a != 255) { e = c.err(*f, "canvas.background has no alpha"); return false; }
        bg = {c4.r, c4.g, c4.b};
        bg_lo = {c4.r_lo, c4.g_lo, c4.b_lo};
    } else if (c.linear) {
        bg = {0x3C, 0x3C, 0x3C};  // 1.0: white, as in encoding 0
    }
    h = default_header(uint32_t(w), uint32_t(hh), bg);
    h.color = enc;
    h.alpha = alpha;
    h.curve_grid = curve_grid;
    h.background_lo = bg_lo;
    if ((f = canvas->find("fps"))) {
        if (f->is_array()) {
            int64_t n, d;
            if (f->items.size() != 2) { e = c.err(*f, "canvas.fps must be a number or [num, den]"); return false; }
            if (!c.integer(f->items[0], "canvas.fps[0]", 1, 0xFFFFFFFF, n, e) || !c.integer(f->items[1], "canvas.fps[1]", 1, 0xFFFFFFFF, d, e)) return false;
            h.fps = {uint32_t(n), uint32_t(d)};
        } else {
            int64_t n;
            if (!c.integer(*f, "canvas.fps", 1, 0xFFFFFFFF, n, e)) return false;
            h.fps = {uint32_t(n), 1};
        }
    }
    if ((f = root.find("sets"))) {
        if (!list_of(c, *f, "sets", 16, e)) return false;
        h.sets.clear();
        for (size_t i = 0; i < f->items.size(); ++i) {
            const Value& s = f->items[i];
            const std::string n = "sets[" + std::to_string(i) + "]";
            if (!tuple_of(c, s, n, 2, "[width, height]", e)) return false;
            int64_t sw, sh;
            if (!c.integer(s.items[0], n + "[0]", 1, 4096, sw, e) || !c.integer(s.items[1], n + "[1]", 1, 4096, sh, e)) return false;
            h.sets.push_back({uint16_t(sw), uint16_t(sh)});
        }
    }
    if ((f = root.find("orientations"))) {
        if (f->is_number()) {
            int64_t n;
            if (!c.integer(*f, "orientations", 1, 64, n, e)) return false;
            h.orientations = default_orientations(int(n));
        } else {
            if (!list_of(c, *f, "orientations", 64, e)) return false;
            h.orientations.clear();
            for (size_t i = 0; i < f->items.size(); ++i) {
                const Value& o = f->items[i];
                const std::string n = "orientations[" + std::to_string(i) + "]";
                if (!tuple_of(c, o, n, 2, "[cos_q14, sin_q14]", e)) return false;
                int64_t co, si;
                if (!c.integer(o.items[0], n + "[0]", -16384, 16384, co, e) || !c.integer(o.items[1], n + "[1]", -16384, 16384, si, e)) return false;
                if (co * co + si * si > (int64_t(1) << 28) + (1 << 16)) { e = c.err(o, n + " is longer than unit length"); return false; }
                h.orientations.push_back({int16_t(co), int16_t(si)});
            }
        }
    }
    return true;
}

bool read_frame(const Ctx& c, const Value& fv, size_t index, const StreamInfo& info, Frame& fr, ImportReport& rep, Error& e) {
    const std::string where = "frames[" + std::to_string(index) + "]";
    if (!c.need(fv, Type::Object, where, e)) return false;
    fr.index = uint32_t(index);
    if (const Value* t = fv.find("type")) {
        if (!c.need(*t, Type::String, where + ".type", e)) return false;
        if (t->text == "key") fr.type = FrameType::Key;
        else if (t->text == "inter") fr.type = FrameType::Inter;
        else { e = c.err(*t, where + ".type must be \"key\" or \"inter\""); return false; }
    }
    if (fr.type == FrameType::Inter && index == 0) { e = c.err(fv, where + ": the first frame must be a key frame"); return false; }
    if (const Value* r = fv.find("removed")) {
        if (fr.type != FrameType::Inter) { e = c.err(*r, where + ".removed is only allowed in inter frames"); return false; }
        if (!c.need(*r, Type::Array, where + ".removed", e)) return false;
        for (size_t i = 0; i < r->items.size(); ++i) {
            int64_t v;
            if (!c.integer(r->items[i], where + ".removed[" + std::to_string(i) + "]", 0, 0xFFFFFFFE, v, e)) return false;
            if (!fr.removed.empty() && uint32_t(v) <= fr.removed.back()) { e = c.err(r->items[i], where + ".removed must be strictly increasing"); return false; }
            fr.removed.push_back(uint32_t(v));
        }
    }
    if (const Value* m = fv.find("motion")) {
        if (fr.type != FrameType::Inter) { e = c.err(*m, where + ".motion is only allowed in inter frames"); return false; }
        if (!c.need(*m, Type::Object, where + ".motion", e)) return false;
        int64_t bs;
        const Value* f;
        if (!(f = field(c, *m, "block_size", where + ".motion", e)) || !c.integer(*f, where + ".motion.block_size", 8, 256, bs, e)) return false;
        fr.motion.block_size = uint16_t(bs);
        fr.motion.cols = uint16_t((info.header.width + bs - 1) / bs);
        fr.motion.rows = uint16_t((info.header.height + bs - 1) / bs);
        if (!(f = field(c, *m, "vectors", where + ".motion", e)) || !c.need(*f, Type::Array, where + ".motion.vectors", e)) return false;
        if (f->items.size() != size_t(fr.motion.cols) * fr.motion.rows) {
            e = c.err(*f, where + ".motion.vectors must hold cols*rows = " + std::to_string(size_t(fr.motion.cols) * fr.motion.rows) + " [dx, dy] pairs");
            return false;
        }
        for (size_t i = 0; i < f->items.size(); ++i) {
            const Value& v = f->items[i];
            const std::string n = where + ".motion.vectors[" + std::to_string(i) + "]";
            if (!tuple_of(c, v, n, 2, "[dx, dy]", e)) return false;
            int32_t dx, dy;
            if (!c.q4(v.items[0], n + "[0]", 2047.9375, dx, e) || !c.q4(v.items[1], n + "[1]", 2047.9375, dy, e)) return false;
            fr.motion.vectors.emplace_back(int16_t(dx), int16_t(dy));
        }
    }
    const Value* strokes = fv.find("strokes");
    if (strokes) {
        if (!c.need(*strokes, Type::Array, where + ".strokes", e)) return false;
        if (strokes->items.size() > c.lim().max_strokes_per_frame) { e = c.err(*strokes, where + ": more strokes than the limit"); return false; }
        for (size_t i = 0; i < strokes->items.size(); ++i)
            if (!read_stroke(c, strokes->items[i], where + ".strokes[" + std::to_string(i) + "]", info, fr.added, rep, e)) return false;
    }
    return true;
}

bool sniff(const std::string& path, std::string_view head) {
    auto p = head.find("\"spt-strokes\"");
    (void)path;
    return p != std::string_view::npos;
}

// The reader's counts, checked by the parser as it goes: a list over them is refused before
// the parse tree holds it (10 million vertices took 3.7 GB to be found over the limit).
json::ParseLimits parse_limits(const Limits& lim) {
    json::ParseLimits p;
    const uint64_t side = lim.max_template_side;
    p.max_items_by_key = {{"points", std::max<size_t>({lim.max_polygon_vertices, lim.max_curve_points, 4096})},
                          {"strokes", lim.max_strokes_per_frame},
                          {"templates", lim.max_templates},
                          {"samples", size_t(side * side)}};
    p.max_tuple_items = 16;  // [x, y], [x, y, width], [dx, dy], an ROI's six numbers
    return p;
}

Result<Document> load(const std::string& path, std::string text, const ImportOptions& opts) {
    auto root = json::parse(text, path, parse_limits(opts.limits));
    if (!root) return root.error();
    Ctx c(path, opts.limits);
    Error e;
    const Value& r = *root;
    if (!c.need(r, Type::Object, "the document", e)) return e;
    const Value* fmt = r.find("format");
    if (!fmt || !fmt->is_string() || fmt->text != "spt-strokes")
        return c.err(fmt ? *fmt : r, "not an spt stroke list (\"format\": \"spt-strokes\" expected)");
    int64_t version = 0;
    const Value* ver = field(c, r, "version", "document", e);
    if (!ver || !c.integer(*ver, "version", 0, 1 << 30, version, e)) return e;
    if (version < 1 || version > 3)
        return c.err(*ver, "stroke list version " + std::to_string(version) + " is not supported (this reader knows 1, 2 and 3)");
    c.version = version;
    Document doc;
    if (!read_header(c, r, doc.info.header, e)) return e;
    if (!read_templates(c, r.find("templates"), doc.info.templates, e)) return e;
    if (const Value* m = r.find("metadata")) {
        if (!c.need(*m, Type::Object, "metadata", e)) return e;
        for (const auto& [k, v] : m->members) {
            if (!c.need(v, Type::String, "metadata." + k, e)) return e;
            if (!is_valid_utf8(k)) return c.err(v, "metadata key \"" + printable_text(k) + "\" is not valid UTF-8");
            if (!c.utf8(v, "metadata key \"" + k + "\": the value", e)) return e;
            doc.info.metadata.emplace_back(k, v.text);
        }
    }
    if (const Value* rois = r.find("rois")) {
        if (!c.need(*rois, Type::Array, "rois", e)) return e;
        for (size_t i = 0; i < rois->items.size(); ++i) {
            const Value& v = rois->items[i];
            const std::string n = "rois[" + std::to_string(i) + "]";
            if (!tuple_of(c, v, n, 6, "[first_frame, last_frame, x, y, w, h]", e)) return e;
            int64_t x[6];
            for (int k = 0; k < 6; ++k)
                if (!c.integer(v.items[size_t(k)], n + "[" + std::to_string(k) + "]", 0, 0xFFFFFFFF, x[k], e)) return e;
            doc.info.rois.push_back({uint32_t(x[0]), uint32_t(x[1]), uint32_t(x[2]), uint32_t(x[3]), uint32_t(x[4]), uint32_t(x[5])});
        }
    }
    const Value* frames = r.find("frames");
    const Value* strokes = r.find("strokes");
    if (frames && strokes) return c.err(*strokes, "give either \"frames\" or a top-level \"strokes\", not both");
    if (strokes) {
        Frame fr;
        Value wrapper;
        wrapper.type = Type::Object;
        wrapper.line = strokes->line;
        wrapper.members.emplace_back("strokes", *strokes);
        if (!read_frame(c, wrapper, 0, doc.info, fr, doc.report, e)) return e;
        doc.frames.push_back(std::move(fr));
    } else {
        if (!frames) return c.err(r, "missing \"frames\"");
        if (!c.need(*frames, Type::Array, "frames", e)) return e;
        if (frames->items.empty()) return c.err(*frames, "frames is empty");
        for (size_t i = 0; i < frames->items.size(); ++i) {
            Frame fr;
            if (!read_frame(c, frames->items[i], i, doc.info, fr, doc.report, e)) return e;
            doc.frames.push_back(std::move(fr));
        }
    }
    for (const Frame& fr : doc.frames)
        for (const Stroke& s : fr.added)
            if (s.kind == StrokeKind::Curve && s.curve.supersample) doc.info.header.curve_grid = true;
    if (opts.background && doc.info.header.color == ColorEncoding::LinearHalf) {
        // The sRGB colour given, as linear codes.
        Rgba8 c;
        const uint8_t ch[3] = {opts.background->r, opts.background->g, opts.background->b};
        for (int k = 0; k < 3; ++k) set_code16(c, k, float_to_half_code(srgb_decode(ch[k] / 255.f)));
        doc.info.header.background = {c.r, c.g, c.b};
        doc.info.header.background_lo = {c.r_lo, c.g_lo, c.b_lo};
    } else if (opts.background) {
        doc.info.header.background = *opts.background;
    }
    if (opts.fps) doc.info.header.fps = *opts.fps;
    if (Status s = validate(doc, path, opts.limits); !s) return s.error();
    return doc;
}

}  // namespace

extern const Importer kStrokesJsonImporter = {"spt-json", "the documented spt JSON stroke list (importers/README.md)", sniff, load};

}  // namespace spt::import
