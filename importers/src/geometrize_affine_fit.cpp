// The affine fit to geometrize's pixel sets: starting maps from the shape's geometry, then a
// coordinate descent over the Q4 map (fit()); and append_shape, which picks the polygon fit
// (geometrize_polygon_fit.cpp) or this one for each shape.
#include "geometrize_internal.hpp"

#include <cmath>
#include <cstdlib>

#include "spt_import/shapes.hpp"

namespace spt::import::geometrize {

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
