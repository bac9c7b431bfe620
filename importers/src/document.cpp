// Documents: defaults, frame building from stroke lists, validation with readable messages,
// and reading/writing through libspt.
#include "spt_import/document.hpp"

#include <memory>

#include "spt/reader.hpp"
#include "spt/render.hpp"
#include "spt/utf8.hpp"

namespace spt::import {

std::vector<Template> default_templates() {
    std::vector<Template> t(3);
    t[0].kind = TemplateKind::Ellipse; t[0].name = "ellipse";
    t[1].kind = TemplateKind::Rectangle; t[1].name = "rectangle";
    t[2].kind = TemplateKind::Triangle; t[2].name = "triangle";
    return t;
}

Header default_header(uint32_t width, uint32_t height, Rgb8 background) {
    Header h;
    h.width = width;
    h.height = height;
    h.background = background;
    h.fps = {24, 1};
    // Shape painters use affine strokes only; one nominal stamp set keeps the header valid.
    h.sets = {StrokeSet{16, 16}};
    h.orientations = default_orientations(8);
    return h;
}

void drop_unused_tables(Document& doc) {
    std::vector<int> remap(doc.info.templates.size(), -1);
    bool stamps = false;
    for (const Frame& f : doc.frames)
        for (const Stroke& s : f.added) {
            if (s.kind == StrokeKind::Stamp) stamps = true, remap.at(s.stamp.tmpl) = 0;
            if (s.kind == StrokeKind::Affine) remap.at(s.affine.tmpl) = 0;
        }
    std::vector<Template> kept;
    for (size_t t = 0; t < remap.size(); ++t)
        if (remap[t] == 0) {
            remap[t] = int(kept.size());
            kept.push_back(doc.info.templates[t]);
        }
    for (Frame& f : doc.frames)
        for (Stroke& s : f.added) {
            if (s.kind == StrokeKind::Stamp) s.stamp.tmpl = uint8_t(remap[s.stamp.tmpl]);
            if (s.kind == StrokeKind::Affine) s.affine.tmpl = uint8_t(remap[s.affine.tmpl]);
        }
    doc.info.templates = std::move(kept);
    if (!stamps && doc.info.header.orientations.size() > 1) doc.info.header.orientations.resize(1);
}

std::vector<Frame> frames_from_lists(const std::vector<std::vector<Stroke>>& lists) {
    std::vector<Frame> frames;
    for (size_t i = 0; i < lists.size(); ++i) {
        Frame f;
        f.index = uint32_t(i);
        const auto& cur = lists[i];
        size_t k = 0;
        if (i > 0) {
            const auto& prev = lists[i - 1];
            while (k < prev.size() && k < cur.size() && prev[k] == cur[k]) ++k;
            if (k > 0) {
                f.type = FrameType::Inter;
                for (size_t r = k; r < prev.size(); ++r) f.removed.push_back(uint32_t(r));
            }
        }
        f.added.assign(cur.begin() + long(k), cur.end());
        frames.push_back(std::move(f));
    }
    return frames;
}

namespace {

Error bad(const std::string& source, const std::string& what) {
    return make_error(Code::InvalidArgument, source + ": " + what);
}

Status check_stroke(const Stroke& s, const Header& h, size_t templates, const Limits& lim,
                    const std::string& where) {
    constexpr int64_t kPos = int64_t(1) << 24, kAxis = int64_t(1) << 16;
    auto pos_ok = [&](int64_t v) { return v >= -kPos && v <= kPos; };
    auto axis_ok = [&](int64_t v) { return v >= -kAxis && v <= kAxis; };
    switch (s.kind) {
        case StrokeKind::Stamp:
            if (s.stamp.set >= h.sets.size()) return Error(bad(where, "stamp set " + std::to_string(s.stamp.set) + " does not exist"));
            if (s.stamp.tmpl >= templates) return Error(bad(where, "template " + std::to_string(s.stamp.tmpl) + " does not exist"));
            if (s.stamp.orient >= h.orientations.size()) return Error(bad(where, "orientation " + std::to_string(s.stamp.orient) + " does not exist"));
            if (!pos_ok(s.stamp.x) || !pos_ok(s.stamp.y)) return Error(bad(where, "stamp position out of range"));
            break;
        case StrokeKind::Affine: {
            const auto& a = s.affine;
            if (a.tmpl >= templates) return Error(bad(where, "template " + std::to_string(a.tmpl) + " does not exist"));
            if (!pos_ok(a.tx) || !pos_ok(a.ty)) return Error(bad(where, "affine position out of range"));
            if (!axis_ok(a.a) || !axis_ok(a.b) || !axis_ok(a.c) || !axis_ok(a.d)) return Error(bad(where, "affine matrix entry out of range (|a..d| <= 4096 px)"));
            if (int64_t(a.a) * a.d - int64_t(a.b) * a.c == 0) return Error(bad(where, "affine matrix is not invertible"));
            break;
        }
        case StrokeKind::Curve:
            if (s.curve.points.empty()) return Error(bad(where, "curve without points"));
            if (s.curve.points.size() > lim.max_curve_points) return Error(bad(where, "curve has more points than the limit"));
            for (const auto& p : s.curve.points)
                if (!pos_ok(p.x) || !pos_ok(p.y) || p.width > uint32_t(kAxis)) return Error(bad(where, "curve point out of range"));
            if (curve_render_work(s.curve, h.width, h.height) > lim.max_curve_work)
                return Error(make_error(Code::LimitExceeded, where + ": curve needs more rendering work (pixels of its segments' boxes) than the limit " +
                                                                 std::to_string(lim.max_curve_work)));
            break;
        case StrokeKind::Polygon:
            if (s.polygon.points.size() < 3) return Error(bad(where, "polygon with fewer than 3 vertices"));
            if (s.polygon.points.size() > lim.max_polygon_vertices) return Error(bad(where, "polygon has more vertices than the limit"));
            if (s.polygon.supersample == 1 || s.polygon.supersample > 16) return Error(bad(where, "polygon supersampling is not 0 or 2..16"));
            for (const auto& p : s.polygon.points)
                if (!pos_ok(p.x) || !pos_ok(p.y)) return Error(bad(where, "polygon vertex out of range"));
            if (polygon_render_work(s.polygon, h.height) > lim.max_polygon_work)
                return Error(make_error(Code::LimitExceeded, where + ": polygon needs more rendering work (edges x rows x samples) than the limit " +
                                                                 std::to_string(lim.max_polygon_work)));
            break;
    }
    return {};
}

}  // namespace

std::vector<Stroke> canvas_strip_strokes(uint32_t w, uint32_t h, Rgb8 c, uint8_t rect) {
    // Pixel column w-1 spans Q4 [16(w-1), 16w) horizontally and [0, 16h) vertically.
    AffineStroke col{rect, int32_t(16 * w - 8), int32_t(8 * h), 8, 0, 0, int32_t(8 * h), {c.r, c.g, c.b, 255}};
    AffineStroke row{rect, int32_t(8 * (w - 1)), int32_t(16 * h - 8), int32_t(8 * (w - 1)), 0, 0, 8, {c.r, c.g, c.b, 255}};
    std::vector<Stroke> out{Stroke::make_affine(col)};
    if (w > 1) out.push_back(Stroke::make_affine(row));
    return out;
}

void set_background(Document& doc, Rgb8 c) {
    const Rgb8 old = doc.info.header.background;
    doc.info.header.background = c;
    if (!doc.canvas_strips) return;
    const Header& h = doc.info.header;
    for (auto& f : doc.frames)
        for (auto& s : f.added) {
            if (s.kind != StrokeKind::Affine) continue;
            for (const Stroke& strip : canvas_strip_strokes(h.width, h.height, old, s.affine.tmpl))
                if (s.affine == strip.affine) s.affine.color = {c.r, c.g, c.b, 255};
        }
}

Status validate(const Document& doc, const std::string& source, const Limits& lim) {
    const Header& h = doc.info.header;
    if (h.width < 1 || h.height < 1 || h.width > lim.max_width || h.height > lim.max_height ||
        uint64_t(h.width) * h.height > lim.max_pixels)
        return Error(bad(source, "canvas " + std::to_string(h.width) + "x" + std::to_string(h.height) + " is empty or above the limits"));
    if (h.fps.num == 0 || h.fps.den == 0) return Error(bad(source, "frame rate must be positive"));
    if (h.sets.empty() || h.sets.size() > 16) return Error(bad(source, "1..16 stroke sets required"));
    for (const auto& s : h.sets)
        if (s.width < 1 || s.height < 1 || s.width > 4096 || s.height > 4096) return Error(bad(source, "stroke set size must be 1..4096"));
    if (h.orientations.empty() || h.orientations.size() > 64) return Error(bad(source, "1..64 orientations required"));
    for (const auto& o : h.orientations)
        if (int64_t(o.cos_q14) * o.cos_q14 + int64_t(o.sin_q14) * o.sin_q14 > (int64_t(1) << 28) + (1 << 16))
            return Error(bad(source, "orientation longer than unit length"));
    const auto& T = doc.info.templates;
    if (T.size() > lim.max_templates || T.size() > 255) return Error(bad(source, "too many templates"));
    for (size_t i = 0; i < T.size(); ++i) {
        if (T[i].kind != TemplateKind::Bitmap) continue;
        if (T[i].width < 1 || T[i].height < 1 || T[i].width > lim.max_template_side || T[i].height > lim.max_template_side ||
            T[i].pixels.size() != size_t(T[i].width) * T[i].height)
            return Error(bad(source, "template " + std::to_string(i) + ": bitmap size or sample count is wrong"));
    }
    for (size_t i = 0; i < T.size(); ++i)
        if (!is_valid_utf8(T[i].name)) return Error(bad(source, "template " + std::to_string(i) + ": the name is not valid UTF-8"));
    for (const auto& [k, v] : doc.info.metadata) {
        if (!is_valid_utf8(k)) return Error(bad(source, "metadata key \"" + printable_text(k) + "\" is not valid UTF-8"));
        if (!is_valid_utf8(v)) return Error(bad(source, "metadata key \"" + k + "\": the value is not valid UTF-8"));
    }
    if (doc.frames.empty()) return Error(bad(source, "no frames"));
    size_t live = 0;
    for (size_t f = 0; f < doc.frames.size(); ++f) {
        const Frame& fr = doc.frames[f];
        const std::string where = source + ": frame " + std::to_string(f);
        if (fr.index != f) return Error(bad(where, "frame index " + std::to_string(fr.index) + " out of order"));
        if (f == 0 && fr.type != FrameType::Key) return Error(bad(where, "the first frame must be a key frame"));
        if (fr.added.size() > lim.max_strokes_per_frame) return Error(bad(where, "more strokes than the limit"));
        if (fr.type == FrameType::Inter) {
            for (size_t r = 0; r < fr.removed.size(); ++r)
                if (fr.removed[r] >= live || (r > 0 && fr.removed[r] <= fr.removed[r - 1]))
                    return Error(bad(where, "removed index " + std::to_string(fr.removed[r]) + " is not increasing or beyond the live list"));
            live -= fr.removed.size();
            if (!fr.motion.empty() && fr.motion.vectors.size() != size_t(fr.motion.cols) * fr.motion.rows)
                return Error(bad(where, "motion field has the wrong number of vectors"));
        } else {
            live = 0;
        }
        for (size_t s = 0; s < fr.added.size(); ++s) {
            Status st = check_stroke(fr.added[s], h, T.size(), lim, where + ", stroke " + std::to_string(s));
            if (!st) return st;
        }
        live += fr.added.size();
        if (live > lim.max_live_strokes) return Error(bad(where, "more live strokes than the limit"));
    }
    return {};
}

Result<WriteStats> write_document(const Document& doc, const std::string& path, const WriterOptions& opts) {
    if (Status v = validate(doc, path); !v) return v.error();
    StreamInfo info = doc.info;
    info.header.frame_count = uint32_t(doc.frames.size());
    // Polygon strokes are format 1.2 (SPEC.md 11): say so from the start, so that frames coded
    // before the first polygon use the same kind coding; documents without them stay 1.0.
    for (const Frame& f : doc.frames)
        for (const Stroke& s : f.added)
            if (s.kind == StrokeKind::Polygon && info.header.version_minor < 2) info.header.version_minor = 2;
    auto w = Writer::create(path, info, opts);
    if (!w) return w.error();
    for (const Frame& f : doc.frames) {
        if (Status s = (*w)->append(f); !s) { (*w)->abort(); return s.error(); }
    }
    if (Status s = (*w)->finish(); !s) { (*w)->abort(); return s.error(); }
    return (*w)->stats();
}

Result<Document> read_document(const std::string& path, const Limits& limits) {
    ReaderOptions ro;
    ro.limits = limits;
    auto r = Reader::open(path, ro);
    if (!r) return r.error();
    Document doc;
    doc.info = (*r)->info();
    const size_t n = (*r)->frames().size();
    for (size_t i = 0; i < n; ++i) {
        auto f = (*r)->read_frame(i);
        if (!f) return f.error();
        doc.frames.push_back(std::move(*f));
    }
    if (doc.frames.empty()) return make_error(Code::Corrupt, path + ": no complete frame");
    return doc;
}

Result<std::vector<std::vector<Stroke>>> live_lists(const Document& doc) {
    std::vector<std::vector<Stroke>> out;
    std::vector<Stroke> live;
    for (const Frame& f : doc.frames) {
        if (Status s = apply_frame(live, f, doc.info.header, {}, &doc.info.templates); !s) return s.error();
        out.push_back(live);
    }
    return out;
}

}  // namespace spt::import
