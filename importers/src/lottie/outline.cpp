// Filled and stroked outlines as spt strokes. A fill is one polygon stroke (nonzero rule) of all
// its contours, joined by bridges that run out and back so they cancel in the winding number;
// a stroke with round caps and joins is a curve stroke (exactly that geometry); other caps and
// joins are one polygon of the segments' quads, the joins (miter, bevel, round) and the caps,
// every piece wound the same way, so that the nonzero fill is their union, blended once.
// A polygon whose rendering work (SPEC.md 10: edges x rows x samples) would be large is cut
// into bands at whole pixel rows: no pixel has samples in two bands, so the bands draw exactly
// the pixels the whole would.
#include <algorithm>
#include <cmath>

#include "model.hpp"

namespace spt::import::lottie {

namespace {

using Ring = std::vector<Point>;

double area2(const Ring& r) {
    double a = 0;
    for (size_t j = 0; j < r.size(); ++j) {
        const Point& p = r[j];
        const Point& q = r[(j + 1) % r.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return a;
}

void positive(Ring& r) {
    if (area2(r) < 0) std::reverse(r.begin(), r.end());
}

// Contours as one closed outline: a0 .. ak a0  b0 .. bm b0 a0  c0 .. (closing to a0).
Ring bridge(const std::vector<Ring>& rings) {
    Ring out;
    for (size_t k = 0; k < rings.size(); ++k) {
        const Ring& r = rings[k];
        if (r.size() < 3) continue;
        const bool first = out.empty();
        out.insert(out.end(), r.begin(), r.end());
        out.push_back(r[0]);
        if (!first) out.push_back(out.front());
    }
    return out;
}

// Vertices of the Q4 outline clipped to rows [y0, y1) (Q4 values; y0, y1 multiples of 16).
std::vector<PolygonVertex> clip_rows(const std::vector<PolygonVertex>& in, int32_t y0, int32_t y1) {
    auto clip = [](const std::vector<PolygonVertex>& v, int32_t yc, bool keep_below) {
        std::vector<PolygonVertex> o;
        const size_t n = v.size();
        auto inside = [&](const PolygonVertex& p) { return keep_below ? p.y >= yc : p.y <= yc; };
        for (size_t j = 0; j < n; ++j) {
            const PolygonVertex& a = v[j];
            const PolygonVertex& b = v[(j + 1) % n];
            const bool ia = inside(a), ib = inside(b);
            if (ia) o.push_back(a);
            if (ia != ib) {
                const double f = double(yc - a.y) / double(b.y - a.y);
                o.push_back({int32_t(std::lround(a.x + f * (b.x - a.x))), yc});
            }
        }
        // Runs along the clip row are horizontal edges, which never count (SPEC.md 8.8).
        std::vector<PolygonVertex> r;
        for (size_t j = 0; j < o.size(); ++j) {
            const bool on = o[j].y == yc;
            const bool prev_on = o[(j + o.size() - 1) % o.size()].y == yc, next_on = o[(j + 1) % o.size()].y == yc;
            if (on && prev_on && next_on) continue;
            r.push_back(o[j]);
        }
        return r;
    };
    auto a = clip(in, y0, true);
    if (a.size() < 3) return {};
    return clip(a, y1, false);
}

void emit_polygon(Ctx& c, std::vector<PolygonVertex> v, Rgba8 col, std::vector<Stroke>& out) {
    if (v.size() < 3 || col.a == 0) { c.report->dropped++; return; }
    int32_t ymin = v[0].y, ymax = v[0].y;
    for (const auto& p : v) { ymin = std::min(ymin, p.y); ymax = std::max(ymax, p.y); }
    const uint64_t rows = uint64_t((ymax >> 4) - (ymin >> 4) + 1);
    const uint64_t work = uint64_t(v.size()) * rows * c.grid * c.grid;
    constexpr uint64_t kBandWork = 1ull << 21;
    std::vector<std::vector<PolygonVertex>> parts;
    if (work <= kBandWork || rows < 2) {
        parts.push_back(std::move(v));
    } else {
        const uint64_t band = std::max<uint64_t>(1, kBandWork / (uint64_t(v.size()) * c.grid * c.grid));
        for (int64_t r = ymin >> 4; r <= (ymax >> 4); r += int64_t(band)) {
            auto p = clip_rows(v, int32_t(r * 16), int32_t((r + int64_t(band)) * 16));
            if (p.size() >= 3) parts.push_back(std::move(p));
        }
    }
    for (auto& p : parts) {
        if (p.size() > c.bounds.max_path_vertices) { c.fail("an outline clipped to a band has too many vertices"); return; }
        PolygonStroke s;
        s.color = col;
        s.supersample = c.grid;
        s.points = std::move(p);
        out.push_back(Stroke::make_polygon(std::move(s)));
        c.report->strokes++;
    }
}

void emit_ring(Ctx& c, const Ring& r, Rgba8 col, std::vector<Stroke>& out) {
    std::vector<PolygonVertex> v;
    v.reserve(r.size());
    for (const Point& p : r) {
        const PolygonVertex q{to_q4(p.x), to_q4(p.y)};
        c.report->max_q4_error_px = std::max(c.report->max_q4_error_px, std::hypot(q.x / 16.0 - p.x, q.y / 16.0 - p.y));
        if (v.empty() || !(v.back() == q)) v.push_back(q);
    }
    while (v.size() > 1 && v.back() == v.front()) v.pop_back();
    emit_polygon(c, std::move(v), col, out);
}

// Rings bridged into outlines of at most one polygon stroke's vertices each.
void emit_rings(Ctx& c, const std::vector<Ring>& rings, Rgba8 col, std::vector<Stroke>& out) {
    std::vector<Ring> group;
    size_t n = 0, groups = 0;
    auto flush = [&] {
        if (group.empty()) return;
        emit_ring(c, group.size() == 1 ? group[0] : bridge(group), col, out);
        group.clear();
        n = 0;
        ++groups;
    };
    for (const Ring& r : rings) {
        if (r.size() < 3) continue;
        if (n + r.size() + 2 > c.bounds.max_path_vertices) flush();
        group.push_back(r);
        n += r.size() + 2;
    }
    flush();
    if (groups > 1 && col.a < 255)
        c.warn("an outline has more vertices than one polygon stroke holds: it is split (translucent overlaps blend twice)");
}

Ring disc(Ctx& c, Point p, double r) {
    const double tol = std::min(c.tolerance, r / 2);
    const int n = std::clamp(int(std::ceil(M_PI / std::acos(std::max(-1.0, 1 - tol / std::max(r, 1e-9))))), 8, 256);
    Ring d;
    for (int k = 0; k < n; ++k) d.push_back({p.x + r * std::cos(2 * M_PI * k / n), p.y + r * std::sin(2 * M_PI * k / n)});
    return d;
}

}  // namespace

void fill_polys(Ctx& c, const std::vector<Poly>& polys, Rgba8 col, std::vector<Stroke>& out) {
    std::vector<Ring> rings;
    for (const Poly& p : polys)
        if (p.pts.size() >= 3) rings.push_back(p.pts);
    c.report->shapes++;
    if (rings.empty()) { c.report->dropped++; return; }
    emit_rings(c, rings, col, out);
}

void stroke_polys(Ctx& c, const std::vector<Poly>& polys, const StrokeStyle& st, Rgba8 col, std::vector<Stroke>& out) {
    c.report->shapes++;
    const double hw = st.width / 2;
    if (hw <= 0 || col.a == 0) { c.report->dropped++; return; }
    if (st.cap == 2 && st.join == 2) {  // round caps and joins: curve strokes, the same geometry
        for (const Poly& p : polys) {
            if (p.pts.empty()) continue;
            CurveStroke s;
            s.color = col;
            s.supersample = c.grid;
            const uint32_t w = uint32_t(std::clamp<int64_t>(to_q4(st.width), 0, 1 << 16));
            for (const Point& q : p.pts) s.points.push_back({to_q4(q.x), to_q4(q.y), w});
            if (p.closed) s.points.push_back(s.points.front());
            if (s.points.size() > c.bounds.max_path_vertices) { c.fail("a stroke has more points than one curve holds"); return; }
            out.push_back(Stroke::make_curve(std::move(s)));
            c.report->strokes++;
        }
        return;
    }
    std::vector<Ring> pieces;
    for (const Poly& p0 : polys) {
        Ring pts;
        for (const Point& q : p0.pts)
            if (pts.empty() || std::hypot(q.x - pts.back().x, q.y - pts.back().y) > 1e-9) pts.push_back(q);
        const bool closed = p0.closed && pts.size() > 2;
        if (closed && std::hypot(pts.front().x - pts.back().x, pts.front().y - pts.back().y) <= 1e-9) pts.pop_back();
        if (pts.empty()) continue;
        if (pts.size() == 1) {  // a dot: only round and square caps draw it
            if (st.cap == 2) pieces.push_back(disc(c, pts[0], hw));
            else if (st.cap == 3) pieces.push_back({{pts[0].x - hw, pts[0].y - hw}, {pts[0].x + hw, pts[0].y - hw}, {pts[0].x + hw, pts[0].y + hw}, {pts[0].x - hw, pts[0].y + hw}});
            continue;
        }
        const size_t n = pts.size(), segs = closed ? n : n - 1;
        auto dir = [&](size_t j) {
            const Point& a = pts[j % n];
            const Point& b = pts[(j + 1) % n];
            const double l = std::hypot(b.x - a.x, b.y - a.y);
            return Point{(b.x - a.x) / l, (b.y - a.y) / l};
        };
        for (size_t j = 0; j < segs; ++j) {
            const Point a = pts[j], b = pts[(j + 1) % n], d = dir(j), nn{-d.y * hw, d.x * hw};
            pieces.push_back({{a.x + nn.x, a.y + nn.y}, {b.x + nn.x, b.y + nn.y}, {b.x - nn.x, b.y - nn.y}, {a.x - nn.x, a.y - nn.y}});
        }
        // Joins at every vertex between two segments.
        for (size_t j = closed ? 0 : 1; j < (closed ? n : n - 1); ++j) {
            const Point P = pts[j], d0 = dir((j + n - 1) % n), d1 = dir(j);
            const double cross = d0.x * d1.y - d0.y * d1.x;
            if (std::fabs(cross) < 1e-12 && d0.x * d1.x + d0.y * d1.y > 0) continue;
            if (st.join == 2) { pieces.push_back(disc(c, P, hw)); continue; }
            const double s = cross > 0 ? -1 : 1;
            const Point n0{-d0.y, d0.x}, n1{-d1.y, d1.x};
            const Point A{P.x + s * hw * n0.x, P.y + s * hw * n0.y}, B{P.x + s * hw * n1.x, P.y + s * hw * n1.y};
            const double sx = n0.x + n1.x, sy = n0.y + n1.y, l2 = sx * sx + sy * sy;
            if (st.join == 1 && l2 > 1e-12 && 2 / std::sqrt(l2) <= st.miter) {
                const Point M{P.x + s * hw * sx * 2 / l2, P.y + s * hw * sy * 2 / l2};
                pieces.push_back({P, A, M, B});
            } else {
                pieces.push_back({P, A, B});
            }
        }
        if (!closed) {
            const Point d0 = dir(0), d1 = dir(n - 2);
            const Point a = pts[0], b = pts[n - 1];
            if (st.cap == 2) {
                pieces.push_back(disc(c, a, hw));
                pieces.push_back(disc(c, b, hw));
            } else if (st.cap == 3) {
                const Point n0{-d0.y * hw, d0.x * hw}, n1{-d1.y * hw, d1.x * hw};
                pieces.push_back({{a.x + n0.x, a.y + n0.y}, {a.x - n0.x, a.y - n0.y}, {a.x - n0.x - d0.x * hw, a.y - n0.y - d0.y * hw}, {a.x + n0.x - d0.x * hw, a.y + n0.y - d0.y * hw}});
                pieces.push_back({{b.x + n1.x, b.y + n1.y}, {b.x - n1.x, b.y - n1.y}, {b.x - n1.x + d1.x * hw, b.y - n1.y + d1.y * hw}, {b.x + n1.x + d1.x * hw, b.y + n1.y + d1.y * hw}});
            }
        }
    }
    for (Ring& r : pieces) positive(r);
    if (pieces.empty()) { c.report->dropped++; return; }
    emit_rings(c, pieces, col, out);
}

}  // namespace spt::import::lottie
