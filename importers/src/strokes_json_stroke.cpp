// The strokes of an spt JSON stroke list (importers/README.md): stamps, affine strokes, shapes
// (as affine strokes), polygons (version 2 stores them; version 1 fills them with stamps) and
// curves.
#include "strokes_json_fields.hpp"

#include "spt_import/shapes.hpp"

namespace spt::import::strokes_json {

bool read_stroke(const Ctx& c, const Value& s, const std::string& where, const StreamInfo& info,
                 std::vector<Stroke>& out, ImportReport& rep, Error& e) {
    if (!c.need(s, Type::Object, where, e)) return false;
    const Value* type = field(c, s, "type", where, e);
    if (!type) return false;
    if (!c.need(*type, Type::String, where + ".type", e)) return false;
    const std::string& t = type->text;
    Rgba8 color;
    if (t == "stamp") {
        StampStroke st;
        int64_t v;
        const Value* f;
        if (!(f = field(c, s, "set", where, e)) || !c.integer(*f, where + ".set", 0, int64_t(info.header.sets.size()) - 1, v, e)) return false;
        st.set = uint8_t(v);
        if (!read_template_ref(c, s, where, info.templates, st.tmpl, e)) return false;
        if (!(f = field(c, s, "orient", where, e)) || !c.integer(*f, where + ".orient", 0, int64_t(info.header.orientations.size()) - 1, v, e)) return false;
        st.orient = uint8_t(v);
        if (!(f = field(c, s, "x", where, e)) || !c.q4(*f, where + ".x", kPosPx, st.x, e)) return false;
        if (!(f = field(c, s, "y", where, e)) || !c.q4(*f, where + ".y", kPosPx, st.y, e)) return false;
        if (!read_color(c, s, where, st.color, e)) return false;
        out.push_back(Stroke::make_stamp(st));
        ++rep.strokes;
    } else if (t == "affine") {
        AffineStroke a;
        if (!read_template_ref(c, s, where, info.templates, a.tmpl, e)) return false;
        const char* keys[6] = {"tx", "ty", "a", "b", "c", "d"};
        int32_t* dst[6] = {&a.tx, &a.ty, &a.a, &a.b, &a.c, &a.d};
        for (int i = 0; i < 6; ++i) {
            const Value* f = field(c, s, keys[i], where, e);
            if (!f || !c.q4(*f, where + "." + keys[i], i < 2 ? kPosPx : kAxisPx, *dst[i], e)) return false;
        }
        if (int64_t(a.a) * a.d - int64_t(a.b) * a.c == 0) { e = c.err(s, where + ": affine matrix is not invertible"); return false; }
        if (!read_color(c, s, where, a.color, e)) return false;
        out.push_back(Stroke::make_affine(a));
        ++rep.strokes;
    } else if (t == "shape") {
        uint8_t tmpl;
        if (!read_template_ref(c, s, where, info.templates, tmpl, e)) return false;
        double ctr[2], size[2], angle = 0;
        const Value* f;
        if (!(f = field(c, s, "center", where, e)) || !read_point(c, *f, where + ".center", 2, ctr, e)) return false;
        if (!(f = field(c, s, "size", where, e)) || !read_point(c, *f, where + ".size", 2, size, e)) return false;
        if ((f = s.find("angle")) && !c.num(*f, where + ".angle", -1e6, 1e6, angle, e)) return false;
        if (!read_color(c, s, where, color, e)) return false;
        ++rep.shapes;
        StrokeSink sink(out, rep);
        sink.affine(tmpl, Mat2x3::translate(ctr[0], ctr[1]) * Mat2x3::rotate_deg(angle) * Mat2x3::scale(size[0] / 2, size[1] / 2), color);
    } else if (t == "polygon" && c.version >= 2) {
        // Version 2: a polygon stroke, stored as given (SPEC.md 4, format 1.2).
        PolygonStroke pg;
        if (!read_color(c, s, where, pg.color, e)) return false;
        if (!read_supersample(c, s, where, pg.supersample, e)) return false;
        const Value* f = points_field(c, s, where, 3, c.lim().max_polygon_vertices, "vertices", e);
        if (!f) return false;
        for (size_t i = 0; i < f->items.size(); ++i) {
            const std::string pn = where + ".points[" + std::to_string(i) + "]";
            const Value& p = f->items[i];
            if (!tuple_of(c, p, pn, 2, "[x, y]", e)) return false;
            PolygonVertex q;
            if (!c.q4(p.items[0], pn + ".x", kPosPx, q.x, e) || !c.q4(p.items[1], pn + ".y", kPosPx, q.y, e)) return false;
            pg.points.push_back(q);
        }
        out.push_back(Stroke::make_polygon(std::move(pg)));
        ++rep.strokes;
    } else if (t == "polygon") {
        const Value* f = field(c, s, "points", where, e);
        if (!f || !c.need(*f, Type::Array, where + ".points", e)) return false;
        if (f->items.size() > 4096) { e = c.err(*f, where + ".points: more than 4096 vertices"); return false; }
        std::vector<Point> pts;
        for (size_t i = 0; i < f->items.size(); ++i) {
            double p[2];
            if (!read_point(c, f->items[i], where + ".points[" + std::to_string(i) + "]", 2, p, e)) return false;
            pts.push_back({p[0], p[1]});
        }
        if (!read_color(c, s, where, color, e)) return false;
        TemplateIds ids;
        // Polygons need the analytic templates; find them by kind.
        bool have[4] = {false, false, false, false};
        for (size_t i = 0; i < info.templates.size(); ++i) {
            auto k = size_t(info.templates[i].kind);
            if (have[k]) continue;
            have[k] = true;
            if (k == 2) ids.rectangle = uint8_t(i);
            if (k == 3) ids.triangle = uint8_t(i);
        }
        if (!have[2] || !have[3]) { e = c.err(s, where + ": polygons need rectangle and triangle templates"); return false; }
        StrokeSink sink(out, rep, ids);
        sink.set_polygon_supersample(info.templates[ids.triangle].supersample);
        sink.polygon(pts, color);
    } else if (t == "curve") {
        CurveStroke cv;
        if (!read_color(c, s, where, cv.color, e)) return false;
        if (const Value* n = s.find("supersample"); n && c.version < 2) {  // anti-aliased lines (format 1.4)
            e = c.err(*n, where + ".supersample needs version 2");
            return false;
        }
        if (!read_supersample(c, s, where, cv.supersample, e)) return false;
        const Value* f = points_field(c, s, where, 1, c.lim().max_curve_points, "points", e);
        if (!f) return false;
        for (size_t i = 0; i < f->items.size(); ++i) {
            const std::string pn = where + ".points[" + std::to_string(i) + "]";
            const Value& p = f->items[i];
            if (!tuple_of(c, p, pn, 3, "[x, y, width]", e)) return false;
            CurvePoint q;
            int32_t w;
            if (!c.q4(p.items[0], pn + ".x", kPosPx, q.x, e) || !c.q4(p.items[1], pn + ".y", kPosPx, q.y, e) ||
                !c.q4(p.items[2], pn + ".width", kAxisPx, w, e))
                return false;
            if (w < 0) { e = c.err(p, pn + ": width must not be negative"); return false; }
            q.width = uint32_t(w);
            cv.points.push_back(q);
        }
        out.push_back(Stroke::make_curve(std::move(cv)));
        ++rep.strokes;
    } else {
        e = c.err(*type, where + ": unknown stroke type \"" + t + "\" (stamp, affine, shape, polygon, curve)");
        return false;
    }
    // "shape" and version-1 "polygon" count their shape above; every other entry is one shape.
    if (t != "shape" && (t != "polygon" || c.version >= 2)) ++rep.shapes;
    return true;
}

}  // namespace spt::import::strokes_json
