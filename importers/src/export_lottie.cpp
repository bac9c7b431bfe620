// A .spt document as a Lottie animation (bodymovin JSON) that Lottie players draw: every stroke
// is one shape layer shown over the frames it is alive (so an unchanged stroke is written once,
// not once a frame). Polygons are closed filled paths (nonzero, as Lottie fills); curves are
// round-capped, round-joined stroked paths (their mean width: Lottie strokes have one width);
// stamp and affine strokes of the analytic templates are their ellipse, rectangle or triangle
// mapped by the stroke's matrix (an ellipse as four cubic arcs, exact for a circle's affine
// image up to the quarter-arc approximation). Bitmap templates have no vector form and are left
// out, counted; --vector-only leaves out every stamp and affine stroke.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "spt_import/export.hpp"

namespace spt::import {

namespace {

struct Span {
    Stroke stroke;
    size_t first = 0, last = 0;  // frames it is alive, inclusive
    uint64_t seq = 0;            // creation order
};

void num(std::string& o, double v) {
    char b[32];
    // 12 digits: every Q4 value (a multiple of 1/16 below 2^20 px) is written exactly.
    std::snprintf(b, sizeof b, "%.12g", std::fabs(v) < 1e-9 ? 0.0 : v);
    o += b;
}

void pt(std::string& o, double x, double y) {
    o += '[';
    num(o, x);
    o += ',';
    num(o, y);
    o += ']';
}

// A Bezier path of vertices with tangents (relative), as Lottie's "sh" holds it.
void path(std::string& o, const std::vector<std::array<double, 6>>& v, bool closed) {
    o += R"({"ty":"sh","ks":{"a":0,"k":{"c":)";
    o += closed ? "true" : "false";
    for (int part = 0; part < 3; ++part) {
        o += part == 0 ? R"(,"v":[)" : part == 1 ? R"(],"i":[)" : R"(],"o":[)";
        for (size_t k = 0; k < v.size(); ++k) {
            if (k) o += ',';
            pt(o, v[k][part * 2], v[k][part * 2 + 1]);
        }
    }
    o += "]}}}";
}

void colour(std::string& o, const Rgba8& c) {
    o += R"("c":{"a":0,"k":[)";
    num(o, c.r / 255.0); o += ',';
    num(o, c.g / 255.0); o += ',';
    num(o, c.b / 255.0);
    o += R"(,1]},"o":{"a":0,"k":)";
    num(o, c.a * 100.0 / 255.0);
    o += '}';
}

// The template's outline mapped by the affine map (px, py) + u (ax, ay) + v (bx, by).
bool template_path(std::string& o, TemplateKind kind, double px, double py, double ax, double ay, double bx, double by) {
    auto map = [&](double u, double v) { return std::array<double, 2>{px + u * ax + v * bx, py + u * ay + v * by}; };
    std::vector<std::array<double, 6>> v;
    if (kind == TemplateKind::Ellipse) {
        constexpr double k = 0.5519150244935105707435627;
        const double uv[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
        for (auto& q : uv) {
            const auto p = map(q[0], q[1]);
            // Tangent along the circle, clockwise in template space: (-v, u) direction.
            const double tx = -q[1] * ax + q[0] * bx, ty = -q[1] * ay + q[0] * by;
            v.push_back({p[0], p[1], -k * tx, -k * ty, k * tx, k * ty});
        }
    } else if (kind == TemplateKind::Rectangle || kind == TemplateKind::Triangle) {
        const double rect[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}, tri[3][2] = {{-1, -1}, {1, -1}, {-1, 1}};
        const size_t n = kind == TemplateKind::Rectangle ? 4 : 3;
        for (size_t j = 0; j < n; ++j) {
            const auto p = kind == TemplateKind::Rectangle ? map(rect[j][0], rect[j][1]) : map(tri[j][0], tri[j][1]);
            v.push_back({p[0], p[1], 0, 0, 0, 0});
        }
    } else {
        return false;
    }
    path(o, v, true);
    return true;
}

// The shapes of one stroke (a group's items without its transform); false when it has none.
bool stroke_items(std::string& o, const StreamInfo& info, const Stroke& s, LottieExportStats& st) {
    const double q = 1.0 / 16;
    switch (s.kind) {
        case StrokeKind::Polygon: {
            std::vector<std::array<double, 6>> v;
            for (const auto& p : s.polygon.points) v.push_back({p.x * q, p.y * q, 0, 0, 0, 0});
            path(o, v, true);
            o += R"(,{"ty":"fl","r":1,)";
            colour(o, s.polygon.color);
            o += '}';
            return true;
        }
        case StrokeKind::Curve: {
            const auto& P = s.curve.points;
            double w = 0;
            for (const auto& p : P) w += p.width * q;
            w /= double(P.size());
            bool varies = false;
            for (const auto& p : P) varies = varies || p.width != P[0].width;
            if (varies) ++st.approximated;
            if (P.size() == 1) {  // a disc
                o += R"({"ty":"el","p":{"a":0,"k":)";
                pt(o, P[0].x * q, P[0].y * q);
                o += R"(},"s":{"a":0,"k":)";
                pt(o, w, w);
                o += R"(}},{"ty":"fl","r":1,)";
            } else {
                std::vector<std::array<double, 6>> v;
                for (const auto& p : P) v.push_back({p.x * q, p.y * q, 0, 0, 0, 0});
                path(o, v, false);
                o += R"(,{"ty":"st","lc":2,"lj":2,"ml":4,"w":{"a":0,"k":)";
                num(o, w);
                o += "},";
            }
            colour(o, s.curve.color);
            o += '}';
            return true;
        }
        case StrokeKind::Affine: {
            const AffineStroke& a = s.affine;
            if (a.tmpl >= info.templates.size() || !template_path(o, info.templates[a.tmpl].kind, a.tx * q, a.ty * q, a.a * q, a.c * q, a.b * q, a.d * q)) {
                ++st.left_out_bitmaps;
                return false;
            }
            o += R"(,{"ty":"fl","r":1,)";
            colour(o, a.color);
            o += '}';
            return true;
        }
        case StrokeKind::Stamp: {
            const StampStroke& m = s.stamp;
            const auto& h = info.header;
            if (m.tmpl >= info.templates.size() || m.set >= h.sets.size() || m.orient >= h.orientations.size()) return false;
            const double C = h.orientations[m.orient].cos_q14 / 16384.0, S = h.orientations[m.orient].sin_q14 / 16384.0;
            const double hw = h.sets[m.set].width / 2.0, hh = h.sets[m.set].height / 2.0;
            // Centred on the centre of the pixel holding (x, y) (SPEC.md 4).
            const double cx = (m.x >> 4) + 0.5, cy = (m.y >> 4) + 0.5;
            if (!template_path(o, info.templates[m.tmpl].kind, cx, cy, hw * C, hw * S, -hh * S, hh * C)) {
                ++st.left_out_bitmaps;
                return false;
            }
            o += R"(,{"ty":"fl","r":1,)";
            colour(o, m.color);
            o += '}';
            return true;
        }
    }
    return false;
}

const char* kIdentity = R"("ks":{"o":{"a":0,"k":100},"r":{"a":0,"k":0},"p":{"a":0,"k":[0,0]},"a":{"a":0,"k":[0,0]},"s":{"a":0,"k":[100,100]}})";

}  // namespace

Result<std::string> export_lottie(const Document& doc, bool vector_only, LottieExportStats& st) {
    const Header& h = doc.info.header;
    if (h.color != ColorEncoding::Srgb8)
        return make_error(Code::Unsupported, "Lottie holds 8-bit sRGB colours; this file's colours are scene-linear half floats");
    // Each stroke's span of frames: it lives until a key frame, a removal or a motion field
    // (which moves it) ends it.
    auto lists = live_lists(doc);
    if (!lists) return lists.error();
    std::vector<Span> done, live;
    uint64_t seq = 0;
    for (size_t f = 0; f < doc.frames.size(); ++f) {
        const Frame& fr = doc.frames[f];
        std::vector<Span> next;
        if (fr.type == FrameType::Inter && fr.motion.empty()) {
            size_t r = 0;
            for (size_t k = 0; k < live.size(); ++k) {
                if (r < fr.removed.size() && fr.removed[r] == k) { ++r; live[k].last = f - 1; done.push_back(std::move(live[k])); continue; }
                next.push_back(std::move(live[k]));
            }
        } else if (fr.type == FrameType::Inter) {
            // Moved strokes: the live list after this frame, all new spans.
            for (Span& s : live) { s.last = f - 1; done.push_back(std::move(s)); }
            for (const Stroke& s : (*lists)[f]) next.push_back({s, f, f, seq++});
            live = std::move(next);
            continue;
        } else {
            for (Span& s : live) { s.last = f - 1; done.push_back(std::move(s)); }
        }
        for (const Stroke& s : fr.added) next.push_back({s, f, f, seq++});
        live = std::move(next);
    }
    for (Span& s : live) { s.last = doc.frames.empty() ? 0 : doc.frames.size() - 1; done.push_back(std::move(s)); }
    std::sort(done.begin(), done.end(), [](const Span& a, const Span& b) { return a.seq < b.seq; });
    // Creation order is drawing order in every frame (survivors keep their order, additions go
    // on top), so the layers are the spans in reverse (Lottie's first layer is on top).
    std::string layers;
    size_t ind = 0;
    for (auto it = done.rbegin(); it != done.rend(); ++it) {
        if (vector_only && it->stroke.kind != StrokeKind::Polygon && it->stroke.kind != StrokeKind::Curve) { ++st.left_out_vector_only; continue; }
        std::string items;
        if (!stroke_items(items, doc.info, it->stroke, st)) continue;
        if (!layers.empty()) layers += ',';
        layers += R"({"ddd":0,"ty":4,"ind":)" + std::to_string(++ind) + R"(,"ip":)" + std::to_string(it->first) + R"(,"op":)" +
                  std::to_string(it->last + 1) + R"(,"st":0,"sr":1,)" + kIdentity + R"(,"shapes":[{"ty":"gr","it":[)" + items +
                  R"(,{"ty":"tr","o":{"a":0,"k":100},"r":{"a":0,"k":0},"p":{"a":0,"k":[0,0]},"a":{"a":0,"k":[0,0]},"s":{"a":0,"k":[100,100]}}]}]})";
        ++st.layers;
    }
    if (!h.alpha) {  // an opaque canvas: its colour as a solid layer at the bottom
        char sc[8];
        std::snprintf(sc, sizeof sc, "#%02x%02x%02x", h.background.r, h.background.g, h.background.b);
        if (!layers.empty()) layers += ',';
        layers += R"({"ddd":0,"ty":1,"ind":)" + std::to_string(++ind) + R"(,"ip":0,"op":)" + std::to_string(doc.frames.size()) +
                  R"(,"st":0,"sr":1,"sc":")" + sc + R"(","sw":)" + std::to_string(h.width) + R"(,"sh":)" + std::to_string(h.height) + "," +
                  kIdentity + "}";
    }
    std::string o = R"({"v":"5.7.0","fr":)";
    num(o, double(h.fps.num) / double(h.fps.den ? h.fps.den : 1));
    o += R"(,"ip":0,"op":)" + std::to_string(doc.frames.size()) + R"(,"w":)" + std::to_string(h.width) + R"(,"h":)" +
         std::to_string(h.height) + R"(,"nm":"spt export","ddd":0,"assets":[],"layers":[)" + layers + "]}\n";
    return o;
}

}  // namespace spt::import
