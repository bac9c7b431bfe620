// geometrize's scan conversion, re-derived from its documented behaviour and checked against its
// own PNGs (see spt_import/geometrize.hpp), and the fit of affine strokes to its pixel sets.
#include "spt_import/geometrize.hpp"

#include "spt_import/shapes.hpp"
#include "spt/render.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <cstdlib>
#include <map>

namespace spt::import::geometrize {

namespace {

using Pix = std::pair<int32_t, int32_t>;

// geometrize clips to [0, w-1) x [0, h-1): it passes the canvas size minus one as the bounds.
// A span is dropped when its row is outside or it starts right of the bound; then clamped.
std::vector<Span> trim(std::vector<Span> in, uint32_t w, uint32_t h) {
    const int32_t bw = int32_t(w) - 1, bh = int32_t(h) - 1;
    std::vector<Span> out;
    for (Span s : in) {
        if (s.y < 0 || s.y >= bh || s.x0 >= bw) continue;
        s.x0 = std::clamp(s.x0, 0, bw - 1);
        s.x1 = std::clamp(s.x1, 0, bw - 1);
        if (s.x0 > s.x1) continue;
        out.push_back(s);
    }
    return out;
}

// Integer line from (x0, y0) to (x1, y1), one pixel per step of the major axis; on an exact
// tie the minor coordinate advances only when moving in the positive major direction (the
// rule that reproduces geometrize's outlines).
void line(int32_t x0, int32_t y0, int32_t x1, int32_t y1, std::map<int32_t, std::pair<int32_t, int32_t>>& rows) {
    auto put = [&rows](int32_t x, int32_t y) {
        auto it = rows.find(y);
        if (it == rows.end()) rows.emplace(y, std::make_pair(x, x));
        else { it->second.first = std::min(it->second.first, x); it->second.second = std::max(it->second.second, x); }
    };
    const int32_t sx = (x1 > x0) - (x1 < x0), sy = (y1 > y0) - (y1 < y0);
    const int64_t dx = 2 * int64_t(std::abs(x1 - x0)), dy = 2 * int64_t(std::abs(y1 - y0));
    put(x0, y0);
    if (dx >= dy) {
        int64_t e = dy - dx / 2;
        while (x0 != x1) {
            if (e > 0 || (e == 0 && sx > 0)) { e -= dx; y0 += sy; }
            e += dy; x0 += sx; put(x0, y0);
        }
    } else {
        int64_t e = dx - dy / 2;
        while (y0 != y1) {
            if (e > 0 || (e == 0 && sy > 0)) { e -= dy; x0 += sx; }
            e += dx; y0 += sy; put(x0, y0);
        }
    }
}

std::vector<Span> polygon_spans(const std::vector<Pix>& p) {
    std::map<int32_t, std::pair<int32_t, int32_t>> rows;
    for (size_t i = 0; i < p.size(); ++i) {
        const Pix& a = p[i];
        const Pix& b = p[(i + 1) % p.size()];
        line(a.first, a.second, b.first, b.second, rows);
    }
    std::vector<Span> out;
    for (const auto& [y, r] : rows) out.push_back({y, r.first, r.second});
    return out;
}

// geometrize computes with float and its own value of pi; the vertices are then truncated
// toward zero, so the same float arithmetic is needed to land on the same pixels.
constexpr float kGeoPi = 3.141f;
int32_t trunc_px(float v) { return int32_t(v); }

}  // namespace

std::vector<Pix> explicit_polygon(const std::vector<double>& d) {
    std::vector<Pix> p;
    for (size_t k = 0; k + 1 < d.size(); k += 2) p.push_back({int32_t(float(d[k])), int32_t(float(d[k + 1]))});
    return p;
}

std::vector<Pix> polygon(int type, const std::vector<double>& d) {
    std::vector<Pix> p;
    if (type == 4 && d.size() >= 6) {
        for (int k = 0; k < 3; ++k) p.push_back({int32_t(d[2 * k]), int32_t(d[2 * k + 1])});
    } else if (type == 2 && d.size() >= 5) {
        const float x1 = std::fmin(float(d[0]), float(d[2])), x2 = std::fmax(float(d[0]), float(d[2]));
        const float y1 = std::fmin(float(d[1]), float(d[3])), y2 = std::fmax(float(d[1]), float(d[3]));
        const float cx = (x2 + x1) / 2.0f, cy = (y2 + y1) / 2.0f;
        const float ox1 = x1 - cx, ox2 = x2 - cx, oy1 = y1 - cy, oy2 = y2 - cy;
        const float rad = float(d[4]) * kGeoPi / 180.0f;
        const float c = std::cos(rad), s = std::sin(rad);
        const float px[4][2] = {{ox1, oy1}, {ox2, oy1}, {ox2, oy2}, {ox1, oy2}};
        for (const auto& q : px) {
            const float xa = q[0] * c, xb = q[1] * s, ya = q[0] * s, yb = q[1] * c;
            p.push_back({trunc_px(xa - xb + cx), trunc_px(ya + yb + cy)});
        }
    } else if (type == 16 && d.size() >= 5) {
        const float rad = float(d[4]) * (kGeoPi / 180.0f);
        const float co = std::cos(rad), si = std::sin(rad);
        const float rx = float(d[2]), ry = float(d[3]), x = float(d[0]), y = float(d[1]);
        for (uint32_t i = 0; i < 20; ++i) {
            const float ang = ((360.0f / 20.0f) * float(i)) * (kGeoPi / 180.0f);
            const float crx = rx * std::cos(ang), cry = ry * std::sin(ang);
            const float a = crx * co, b = cry * si, e = crx * si, f = cry * co;
            p.push_back({trunc_px(a - b + x), trunc_px(e + f + y)});
        }
    }
    return p;
}

std::vector<Span> spans(int type, const std::vector<double>& d, uint32_t w, uint32_t h) {
    std::vector<Span> out;
    const int32_t bw = int32_t(w) - 1;
    switch (type) {
        case 1: {  // rows y1 .. y2 - 1, columns x1 .. x2
            const int32_t x1 = int32_t(std::min(d[0], d[2])), x2 = int32_t(std::max(d[0], d[2]));
            const int32_t y1 = int32_t(std::min(d[1], d[3])), y2 = int32_t(std::max(d[1], d[3]));
            for (int32_t y = y1; y < y2; ++y) out.push_back({y, x1, x2});
            break;
        }
        case 32: {  // x^2 + y^2 <= r^2 around pixel (x, y)
            const int32_t x = int32_t(d[0]), y = int32_t(d[1]), r = int32_t(d[2]);
            for (int32_t j = -r; j <= r; ++j) {
                int32_t s = int32_t(std::sqrt(double(r) * r - double(j) * j));
                while (int64_t(s + 1) * (s + 1) + int64_t(j) * j <= int64_t(r) * r) ++s;
                while (s >= 0 && int64_t(s) * s + int64_t(j) * j > int64_t(r) * r) --s;
                if (s < 0) continue;
                out.push_back({y + j, std::clamp(x - s, 0, bw - 1), std::clamp(x + s, 0, bw - 1)});
            }
            break;
        }
        case 8: {  // rows |dy| < ry, half width trunc(sqrt(ry^2 - dy^2) * rx / ry)
            const float aspect = float(d[2]) / float(d[3]);
            const int32_t x = int32_t(d[0]), y = int32_t(d[1]);
            const float ry = float(d[3]);
            for (int32_t dy = 0; dy < ry; ++dy) {
                // int64 square: dy reaches 2^20. A denormal ry makes aspect infinite and fv NaN;
                // past 2^22 (|x| <= 2^20) every v gives the same clamped span.
                const float fv = std::sqrt(ry * ry - float(int64_t(dy) * dy)) * aspect;
                const int32_t v = std::isnan(fv) ? 0 : fv >= float(1 << 22) ? (1 << 22) : fv <= -float(1 << 22) ? -(1 << 22) : int32_t(fv);
                const int32_t x1 = std::max(x - v, 0), x2 = std::min(x + v, bw - 1);
                out.push_back({y - dy, x1, x2});
                if (dy > 0) out.push_back({y + dy, x1, x2});
            }
            break;
        }
        case 2: case 4: case 16: out = polygon_spans(polygon(type, d)); break;
        default: break;
    }
    return trim(std::move(out), w, h);
}

namespace {

// Pixels of the target and of a candidate stroke that differ, counted where geometrize paints.
class Objective {
public:
    Objective(const Renderer& r, const std::vector<Span>& t, uint32_t w, uint32_t h) : r_(r), w_(w), h_(h) {
        for (const Span& s : t) {
            x0_ = std::min(x0_, s.x0); x1_ = std::max(x1_, s.x1);
            y0_ = std::min(y0_, s.y); y1_ = std::max(y1_, s.y);
        }
        if (x1_ < x0_) { x0_ = x1_ = y0_ = y1_ = 0; }
        bw_ = uint32_t(x1_ - x0_ + 1);
        in_.assign(size_t(bw_) * uint32_t(y1_ - y0_ + 1), 0);
        for (const Span& s : t)
            for (int32_t x = s.x0; x <= s.x1; ++x) {
                uint8_t& v = in_[size_t(s.y - y0_) * bw_ + size_t(x - x0_)];
                if (!v) { v = 1; ++count_; }
            }
    }
    uint64_t operator()(const AffineStroke& s) const {
        Stroke st = Stroke::make_affine(s);
        st.affine.color = {0, 0, 0, 255};
        return (*this)(st);
    }
    // Any stroke kind, drawn opaque.
    uint64_t operator()(const Stroke& st) const {
        Mask m;
        if (!r_.stroke_mask(st, m)) return ~uint64_t(0);
        uint64_t hit = 0, extra = 0;
        const int32_t cw = int32_t(w_) - 1, ch = int32_t(h_) - 1;
        for (uint32_t j = 0; j < m.h; ++j) {
            const int32_t y = m.y0 + int32_t(j);
            if (y < 0 || y >= ch) continue;
            const uint8_t* row = &m.a[size_t(j) * m.w];
            for (uint32_t i = 0; i < m.w; ++i) {
                if (!row[i]) continue;
                const int32_t x = m.x0 + int32_t(i);
                if (x < 0 || x >= cw) continue;
                if (x >= x0_ && x <= x1_ && y >= y0_ && y <= y1_ && in_[size_t(y - y0_) * bw_ + size_t(x - x0_)]) ++hit;
                else ++extra;
            }
        }
        return (count_ - hit) + extra;
    }
private:
    const Renderer& r_;
    uint32_t w_, h_, bw_ = 0;
    int32_t x0_ = INT32_MAX, x1_ = INT32_MIN, y0_ = INT32_MAX, y1_ = INT32_MIN;
    std::vector<uint8_t> in_;
    uint64_t count_ = 0;
};

}  // namespace

uint64_t fit(const Renderer& r, const std::vector<Span>& target, uint32_t w, uint32_t h, AffineStroke& s) {
    const Objective f(r, target, w, h);
    uint64_t best = f(s);
    int32_t* p[6] = {&s.tx, &s.ty, &s.a, &s.b, &s.c, &s.d};
    // Coordinate descent: each parameter moves by +-step while that helps, coarse steps first.
    // Bounded so that a pathological shape cannot stall an import.
    for (int step : {4, 2, 1}) {
        for (int sweep = 0; sweep < 8 && best > 0; ++sweep) {
            bool improved = false;
            for (int k = 0; k < 6 && best > 0; ++k) {
                for (int dir : {1, -1}) {
                    for (int moves = 0; moves < 16; ++moves) {
                        const int32_t old = *p[k];
                        *p[k] = old + dir * step;
                        const int64_t det = int64_t(s.a) * s.d - int64_t(s.b) * s.c;
                        const uint64_t v = det != 0 ? f(s) : ~uint64_t(0);
                        if (v < best) { best = v; improved = true; continue; }
                        *p[k] = old;
                        break;
                    }
                }
            }
            if (!improved) break;
        }
    }
    return best;
}


namespace {

constexpr double kHalf = 0.5;  // pixel index -> pixel centre

// Convex polygon `v` (pixel centres) with every edge pushed out by k times the larger component
// of its unit normal: geometrize's outlines take every pixel within half a pixel of an edge
// along the edge's major axis, so k = 0.5 is the expected growth.
std::vector<Point> grow(const std::vector<Point>& v, double k) {
    const size_t n = v.size();
    double area = 0;
    for (size_t i = 0; i < n; ++i) area += v[i].x * v[(i + 1) % n].y - v[(i + 1) % n].x * v[i].y;
    const double sgn = area >= 0 ? 1 : -1;
    struct Line { double nx, ny, c; };
    std::vector<Line> lines;
    for (size_t i = 0; i < n; ++i) {
        const Point& p = v[i];
        const Point& q = v[(i + 1) % n];
        double nx = sgn * (q.y - p.y), ny = -sgn * (q.x - p.x);
        const double len = std::hypot(nx, ny);
        if (len == 0) { lines.push_back({0, 0, 0}); continue; }
        nx /= len; ny /= len;
        lines.push_back({nx, ny, nx * p.x + ny * p.y + k * std::max(std::fabs(nx), std::fabs(ny))});
    }
    std::vector<Point> out = v;
    for (size_t i = 0; i < n; ++i) {
        const Line& l0 = lines[(i + n - 1) % n];
        const Line& l1 = lines[i];
        const double det = l0.nx * l1.ny - l0.ny * l1.nx;
        if (std::fabs(det) < 1e-9) continue;  // parallel neighbours: keep the vertex
        out[i] = {(l0.c * l1.ny - l1.c * l0.ny) / det, (l0.nx * l1.c - l1.nx * l0.c) / det};
    }
    return out;
}

// Starting maps for the fit: the shape's geometry on pixel centres, grown by about half a pixel
// (geometrize's spans include every pixel an outline touches). The fit keeps the best result.
std::vector<AffineStroke> initial_guesses(int type, const std::vector<double>& d) {
    std::vector<AffineStroke> out;
    auto q = [](double v) { return to_q4(v); };
    switch (type) {
        case 1: {  // columns x1..x2, rows y1..y2-1: exact
            const double x1 = std::min(d[0], d[2]), x2 = std::max(d[0], d[2]) + 1;
            const double y1 = std::min(d[1], d[3]), y2 = std::max(d[1], d[3]);
            out.push_back({1, q((x1 + x2) / 2), q((y1 + y2) / 2), q((x2 - x1) / 2), 0, 0, q((y2 - y1) / 2), {}});
            break;
        }
        case 32: case 8: {  // exact up to the floor rounding of SPEC 8.2
            const double rx = d[2], ry = type == 32 ? d[2] : d[3];
            out.push_back({0, q(int32_t(d[0]) + kHalf), q(int32_t(d[1]) + kHalf), q(rx), 0, 0, q(ry), {}});
            break;
        }
        case 16: {  // a 20-gon of truncated vertices: on average centred on (x, y)
            for (double off : {0.0, kHalf})
                for (double grow_px : {0.3, 0.6}) {
                    const double inscribed = 0.994;  // mean radius of a 20-gon
                    const Mat2x3 m = Mat2x3::translate(d[0] + off, d[1] + off) * Mat2x3::rotate_deg(d[4] * 3.141 / 3.14159265358979) *
                                     Mat2x3::scale(d[2] * inscribed + grow_px, d[3] * inscribed + grow_px);
                    out.push_back({0, q(m.e), q(m.f), q(m.a), q(m.c), q(m.b), q(m.d), {}});
                }
            break;
        }
        case 2: case 4: case kExplicitPolygon: {
            auto p = type == kExplicitPolygon ? explicit_polygon(d) : polygon(type, d);
            std::vector<Point> c;
            for (auto& [x, y] : p) c.push_back({x + kHalf, y + kHalf});
            for (double k : {0.5, 0.35, 0.65}) {
                const auto v = grow(c, k);
                if (p.size() == 3) {  // template vertices (-1,-1) -> v0, (1,-1) -> v1, (-1,1) -> v2
                    out.push_back({2, q((v[1].x + v[2].x) / 2), q((v[1].y + v[2].y) / 2), q((v[1].x - v[0].x) / 2), q((v[2].x - v[0].x) / 2),
                                   q((v[1].y - v[0].y) / 2), q((v[2].y - v[0].y) / 2), {}});
                } else if (p.size() == 4) {  // ul, ur, br, bl -> the parallelogram through their averages
                    const double cx = (v[0].x + v[1].x + v[2].x + v[3].x) / 4, cy = (v[0].y + v[1].y + v[2].y + v[3].y) / 4;
                    out.push_back({1, q(cx), q(cy), q((v[1].x - v[0].x + v[2].x - v[3].x) / 4), q((v[3].x - v[0].x + v[2].x - v[1].x) / 4),
                                   q((v[1].y - v[0].y + v[2].y - v[3].y) / 4), q((v[3].y - v[0].y + v[2].y - v[1].y) / 4), {}});
                }
            }
            break;
        }
    }
    // A degenerate shape (collinear triangle, zero-width box) still paints an outline: start
    // from a thin, invertible map.
    for (auto& a : out) {
        if (int64_t(a.a) * a.d - int64_t(a.b) * a.c != 0) continue;
        if (a.a == 0 && a.b == 0) a.a = 4;
        if (int64_t(a.a) * a.d - int64_t(a.b) * a.c == 0) a.d += 4;
        if (int64_t(a.a) * a.d - int64_t(a.b) * a.c == 0) a.c += 4;
    }
    return out;
}

}  // namespace

namespace {

// The vertices without repeats (consecutive, and the last equal to the first).
std::vector<Pix> distinct_ring(const std::vector<Pix>& v) {
    std::vector<Pix> p;
    for (const Pix& q : v)
        if (p.empty() || q != p.back()) p.push_back(q);
    while (p.size() > 1 && p.front() == p.back()) p.pop_back();
    return p;
}

// Twice the signed area of the outline (positive: clockwise on screen, y down).
int64_t twice_area(const std::vector<Pix>& p) {
    int64_t area = 0;
    for (size_t i = 0; i < p.size(); ++i)
        area += int64_t(p[i].first) * p[(i + 1) % p.size()].second - int64_t(p[(i + 1) % p.size()].first) * p[i].second;
    return area;
}

// geometrize's outline of the edge from pixel a to pixel b takes, along the edge's major axis,
// every pixel whose centre lies within half a pixel of the line through the two centres (its
// span fill then closes the rows). A polygon through the pixel centres with each edge moved
// out by exactly half a pixel along its minor axis covers those centres: every vertex stays on
// the half-pixel lattice (Q4 multiples of 8), which codes compactly (SPEC.md 7.4 polygon
// shift). Where two edges move in different directions a short connector joins them; it
// encloses no pixel centre besides the vertex's own.
std::vector<PolygonVertex> lattice_polygon(const std::vector<Pix>& v) {
    const std::vector<Pix> p = distinct_ring(v);
    const size_t n = p.size();
    std::vector<PolygonVertex> out;
    if (n == 0) return out;
    const int64_t area = twice_area(p);
    const int sgn = area >= 0 ? 1 : -1;
    // Centre of pixel (x, y) in Q4 is (16x + 8, 16y + 8); half a pixel is 8.
    std::vector<std::pair<int32_t, int32_t>> shift(n);
    for (size_t i = 0; i < n; ++i) {
        const int64_t dx = p[(i + 1) % n].first - p[i].first, dy = p[(i + 1) % n].second - p[i].second;
        const int64_t nx = sgn * dy, ny = -sgn * dx;  // outward normal
        if (std::llabs(dx) >= std::llabs(dy)) shift[i] = {0, ny > 0 ? 8 : -8};
        else shift[i] = {nx > 0 ? 8 : -8, 0};
    }
    auto add = [&out](int32_t x, int32_t y) {
        const PolygonVertex q{x, y};
        if (out.empty() || !(out.back() == q)) out.push_back(q);
    };
    for (size_t i = 0; i < n; ++i) {
        const int32_t cx = 16 * p[i].first + 8, cy = 16 * p[i].second + 8;
        const auto& a = shift[(i + n - 1) % n];
        const auto& b = shift[i];
        add(cx + a.first, cy + a.second);
        add(cx + b.first, cy + b.second);
    }
    while (out.size() > 1 && out.front() == out.back()) out.pop_back();
    // Drop vertices in the middle of a straight run: the same edges, fewer bytes.
    for (bool again = true; again && out.size() > 3;) {
        again = false;
        for (size_t i = 0; i < out.size() && out.size() > 3; ++i) {
            const PolygonVertex& a = out[(i + out.size() - 1) % out.size()];
            const PolygonVertex& b = out[i];
            const PolygonVertex& c = out[(i + 1) % out.size()];
            const int64_t cr = int64_t(b.x - a.x) * (c.y - b.y) - int64_t(b.y - a.y) * (c.x - b.x);
            const int64_t dot = int64_t(b.x - a.x) * (c.x - b.x) + int64_t(b.y - a.y) * (c.y - b.y);
            if (cr == 0 && dot > 0) { out.erase(out.begin() + long(i)); again = true; }
        }
    }
    return out;
}

// One vertex per geometrize vertex, each moved out by half a pixel along both axes on the side
// of its two edges' outward normals: the same outline as lattice_polygon without connectors
// (close to it where the edges turn slowly, as on geometrize's ellipses), so that an n-gon
// stays an n-gon and codes by the conic prediction (SPEC.md 7.4 step 5). refine() then fixes
// single vertices.
std::vector<PolygonVertex> offset_polygon(const std::vector<Pix>& v) {
    const std::vector<Pix> p = distinct_ring(v);
    const size_t n = p.size();
    std::vector<PolygonVertex> out;
    if (n < 3) return out;
    const int64_t area = twice_area(p);
    const int64_t sgn = area >= 0 ? 1 : -1;
    for (size_t i = 0; i < n; ++i) {
        const Pix& a = p[(i + n - 1) % n];
        const Pix& b = p[i];
        const Pix& c = p[(i + 1) % n];
        // Sum of the outward normals of the edges a->b and b->c.
        const int64_t nx = sgn * ((b.second - a.second) + (c.second - b.second));
        const int64_t ny = -sgn * ((b.first - a.first) + (c.first - b.first));
        const int32_t ox = nx > 0 ? 8 : nx < 0 ? -8 : 0, oy = ny > 0 ? 8 : ny < 0 ? -8 : 0;
        out.push_back({16 * b.first + 8 + ox, 16 * b.second + 8 + oy});
    }
    return out;
}

// Moves single vertices by `steps` Q4 units while that lowers the count of differing pixels
// (ties between the half-open edge rule and geometrize's line rule). Bounded.
uint64_t refine(const Objective& f, PolygonStroke& pg, uint64_t best, std::initializer_list<int> steps = {1, -1, 2, -2, 4, -4}) {
    for (int sweep = 0; sweep < 2 && best > 0; ++sweep) {
        bool improved = false;
        for (size_t i = 0; i < pg.points.size() && best > 0; ++i)
            for (int axis = 0; axis < 2; ++axis)
                for (int d : steps) {
                    int32_t& c = axis ? pg.points[i].y : pg.points[i].x;
                    const int32_t old = c;
                    c = old + d;
                    const uint64_t v = f(Stroke::make_polygon(pg));
                    if (v < best) { best = v; improved = true; break; }
                    c = old;
                }
        if (!improved) break;
    }
    return best;
}

// The pixels of a polygon's bounding box (its points are Q4).
uint64_t polygon_box_pixels(const PolygonStroke& pg) {
    if (pg.points.empty()) return 0;
    int64_t x0 = pg.points[0].x, x1 = x0, y0 = pg.points[0].y, y1 = y0;
    for (const auto& p : pg.points) {
        x0 = std::min<int64_t>(x0, p.x), x1 = std::max<int64_t>(x1, p.x);
        y0 = std::min<int64_t>(y0, p.y), y1 = std::max<int64_t>(y1, p.y);
    }
    return uint64_t((x1 - x0) / 16 + 1) * uint64_t((y1 - y0) / 16 + 1);
}

bool append_polygon(const Renderer& r, const std::vector<Pix>& vertices, const std::vector<Span>& target, Rgba8 colour,
                    uint32_t w, uint32_t h, std::vector<Stroke>& out, ImportReport& rep, uint64_t& differing) {
    PolygonStroke pg;
    const Objective f(r, target, w, h);
    pg.color = {0, 0, 0, 255};
    uint64_t miss = ~uint64_t(0);
    // Compact first: one vertex per geometrize vertex, moved only along the half-pixel lattice
    // (the conic prediction codes such an n-gon in ~15 bytes). The connector outline matches
    // a few more pixels (rotated ellipses: 113 instead of 290 differing pixels, 48.3 instead of
    // 46.2 dB) at nearly twice the bytes; it is the fallback when the compact one degenerates.
    pg.points = offset_polygon(vertices);
    // Fitting renders the polygon many times: only shapes of geometrize's own size are
    // refined, and one that a reader would refuse to render (Limits::max_polygon_work) is
    // not rendered at all.
    if (polygon_render_work(pg, h) > Limits{}.max_polygon_work) {
        ++rep.dropped;
        rep.note("polygons needing more rendering work than spt::Limits allows dropped");
        return true;
    }
    // Refining renders the polygon's whole box some 300 times: a box far larger than the canvas
    // (geometrize's own shapes lie on it; a 357-byte file with a radius of 3430 px took 2 s)
    // is rendered once, unrefined.
    const bool refinable = pg.points.size() <= 64 && polygon_box_pixels(pg) <= 4 * uint64_t(w) * h + 4096;
    if (pg.points.size() >= 3)
        miss = refinable ? refine(f, pg, f(Stroke::make_polygon(pg)), {8, -8, 16, -16}) : f(Stroke::make_polygon(pg));
    if (miss == ~uint64_t(0)) {
        pg.points = lattice_polygon(vertices);
        if (pg.points.size() >= 3) miss = refinable ? refine(f, pg, f(Stroke::make_polygon(pg))) : f(Stroke::make_polygon(pg));
    }
    if (miss == ~uint64_t(0)) return false;
    pg.color = colour;
    out.push_back(Stroke::make_polygon(std::move(pg)));
    ++rep.strokes;
    if (miss) { ++rep.approximated; differing += miss; }
    return true;
}

}  // namespace

void append_shape(const Renderer& r, int type, const std::vector<double>& d, Rgba8 colour, uint32_t w, uint32_t h,
                  std::vector<Stroke>& out, ImportReport& rep, uint64_t& differing) {
    if (colour.a == 0) { ++rep.dropped; return; }
    const auto target = type == kExplicitPolygon ? trim(polygon_spans(explicit_polygon(d)), w, h) : spans(type, d, w, h);
    if (target.empty()) { ++rep.dropped; rep.note("shapes geometrize paints no pixel of dropped"); return; }
    // Rotated ellipses (20-gons) and polygons of more than four vertices: a polygon stroke on
    // geometrize's own integer vertices (format 1.2). Triangles and quadrilaterals stay affine
    // strokes of the analytic templates, which match its pixels as closely and cost fewer bytes.
    if (type == 16 || (type == kExplicitPolygon && d.size() > 8)) {
        const auto v = type == kExplicitPolygon ? explicit_polygon(d) : polygon(type, d);
        if (append_polygon(r, v, target, colour, w, h, out, rep, differing)) return;
    }
    AffineStroke a;
    uint64_t miss = ~uint64_t(0);
    for (AffineStroke g : initial_guesses(type, d)) {
        const uint64_t m = fit(r, target, w, h, g);
        if (m < miss) { miss = m; a = g; }
        if (m == 0) break;
    }
    if (miss == ~uint64_t(0)) { ++rep.dropped; return; }
    a.color = colour;
    out.push_back(Stroke::make_affine(a));
    ++rep.strokes;
    if (miss) { ++rep.approximated; differing += miss; }
}

}  // namespace spt::import::geometrize
