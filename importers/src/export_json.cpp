// The JSON stroke list writer. Output is deterministic and exact: Q4 values are written as
// pixels with at most four decimals (k/16 has a finite decimal expansion, and nlohmann-json
// prints a double with the fewest digits that give it back), so importing the output gives back
// the same values, and the same .spt bytes. The document is built as a JSON value and printed
// with one stroke a line (json::dump_layout), the layout this file has always had.
#include <cstdint>
#include <string_view>

#include "spt_import/export.hpp"
#include "spt_import/codec.hpp"
#include "spt_json/write.hpp"

namespace spt::import {

namespace {

using json::Doc;

// A Q4 fixed-point value (1/16 pixel) in pixels: a whole number as an integer ("3", not "3.0").
Doc q4(int64_t v) {
    if (v % 16 == 0) return v / 16;
    return double(v) / 16.0;
}

// Colour encoding 1 (`linear`) writes the 16-bit half codes (exact); encoding 0 the 8-bit values.
Doc color(Rgba8 c, bool linear) {
    if (linear) return Doc::array({code16(c, 0), code16(c, 1), code16(c, 2), c.a});
    return Doc::array({c.r, c.g, c.b, c.a});
}

Doc stroke(const Stroke& s, bool linear) {
    Doc o = Doc::object();
    switch (s.kind) {
        case StrokeKind::Stamp: {
            const auto& t = s.stamp;
            o["type"] = "stamp";
            o["set"] = t.set;
            o["template"] = t.tmpl;
            o["orient"] = t.orient;
            o["x"] = q4(t.x);
            o["y"] = q4(t.y);
            o["color"] = color(t.color, linear);
            break;
        }
        case StrokeKind::Affine: {
            const auto& a = s.affine;
            o["type"] = "affine";
            o["template"] = a.tmpl;
            o["tx"] = q4(a.tx);
            o["ty"] = q4(a.ty);
            o["a"] = q4(a.a);
            o["b"] = q4(a.b);
            o["c"] = q4(a.c);
            o["d"] = q4(a.d);
            o["color"] = color(a.color, linear);
            break;
        }
        case StrokeKind::Curve: {
            o["type"] = "curve";
            o["color"] = color(s.curve.color, linear);
            if (s.curve.supersample) o["supersample"] = s.curve.supersample;
            Doc& pts = o["points"] = Doc::array();
            for (const auto& p : s.curve.points) pts.push_back(Doc::array({q4(p.x), q4(p.y), q4(p.width)}));
            break;
        }
        case StrokeKind::Polygon: {
            const auto& pg = s.polygon;
            o["type"] = "polygon";
            o["color"] = color(pg.color, linear);
            if (pg.supersample) o["supersample"] = pg.supersample;
            Doc& pts = o["points"] = Doc::array();
            for (const auto& p : pg.points) pts.push_back(Doc::array({q4(p.x), q4(p.y)}));
            break;
        }
    }
    return o;
}

// One line per template, frame and stroke; everything else of them on that line.
bool broken(const Doc& node, std::string_view key, int depth) {
    if (depth == 0) return true;
    if (depth == 1) return key == "templates" || key == "frames";
    return depth == 3 && key == "strokes" && !node.empty();
}

}  // namespace

std::string export_json(const Document& doc) {
    const Header& h = doc.info.header;
    // Version 2 only when a polygon stroke or anti-aliased curves (format 1.4) need it: other
    // documents export as before.
    bool polygons = h.curve_grid;
    for (const Frame& f : doc.frames)
        for (const Stroke& s : f.added) polygons = polygons || s.kind == StrokeKind::Polygon;
    // Version 3 only for format 1.3 canvases (alpha, colour encoding 1).
    const bool v3 = !h.plain_color();
    const bool linear = h.color == ColorEncoding::LinearHalf;
    Doc o = Doc::object();
    o["format"] = "spt-strokes";
    o["version"] = v3 ? 3 : polygons ? 2 : 1;
    const unsigned bg[3] = {linear ? unsigned(h.background.r << 8 | h.background_lo.r) : h.background.r,
                            linear ? unsigned(h.background.g << 8 | h.background_lo.g) : h.background.g,
                            linear ? unsigned(h.background.b << 8 | h.background_lo.b) : h.background.b};
    Doc& canvas = o["canvas"] = Doc::object();
    canvas["width"] = h.width;
    canvas["height"] = h.height;
    if (v3) {
        canvas["color_encoding"] = color_encoding_name(h.color);
        canvas["alpha"] = h.alpha;
    }
    if (h.curve_grid) canvas["curve_grid"] = true;
    canvas["background"] = Doc::array({bg[0], bg[1], bg[2]});
    canvas["fps"] = Doc::array({h.fps.num, h.fps.den});
    Doc& sets = o["sets"] = Doc::array();
    for (const auto& s : h.sets) sets.push_back(Doc::array({s.width, s.height}));
    Doc& orients = o["orientations"] = Doc::array();
    for (const auto& r : h.orientations) orients.push_back(Doc::array({r.cos_q14, r.sin_q14}));
    Doc& templates = o["templates"] = Doc::array();
    for (const Template& t : doc.info.templates) {
        Doc e = Doc::object();
        e["kind"] = template_kind_name(t.kind);
        if (!t.name.empty()) e["name"] = t.name;
        if (t.supersample) e["supersample"] = t.supersample;
        if (t.kind == TemplateKind::Bitmap) {
            e["width"] = t.width;
            e["height"] = t.height;
            e["base64"] = base64_encode(t.pixels.data(), t.pixels.size());
        }
        templates.push_back(std::move(e));
    }
    if (!doc.info.metadata.empty()) {
        // Appended as pairs, not assigned by key: a key the file repeats is written as often as
        // the file has it, as it always was.
        Doc& meta = o["metadata"] = Doc::object();
        for (const auto& [k, v] : doc.info.metadata) meta.get_ref<Doc::object_t&>().push_back({k, v});
    }
    if (!doc.info.rois.empty()) {
        Doc& rois = o["rois"] = Doc::array();
        for (const Roi& r : doc.info.rois) rois.push_back(Doc::array({r.first_frame, r.last_frame, r.x, r.y, r.w, r.h}));
    }
    Doc& frames = o["frames"] = Doc::array();
    for (const Frame& fr : doc.frames) {
        Doc f = Doc::object();
        f["type"] = fr.type == FrameType::Key ? "key" : "inter";
        if (fr.type == FrameType::Inter) {
            f["removed"] = fr.removed;
            if (!fr.motion.empty()) {
                Doc& m = f["motion"] = Doc::object();
                m["block_size"] = fr.motion.block_size;
                Doc& vec = m["vectors"] = Doc::array();
                for (const auto& v : fr.motion.vectors) vec.push_back(Doc::array({q4(v.first), q4(v.second)}));
            }
        }
        Doc& strokes = f["strokes"] = Doc::array();
        for (const Stroke& s : fr.added) strokes.push_back(stroke(s, linear));
        frames.push_back(std::move(f));
    }
    return json::dump_layout(o, broken) + "\n";
}

}  // namespace spt::import
