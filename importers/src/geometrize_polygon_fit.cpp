// The polygon fit to geometrize's pixel sets: polygon strokes on geometrize's own integer
// vertices, moved out by half a pixel so that they cover the pixels its outlines take, then
// refined vertex by vertex against the pixel-difference objective.
#include "geometrize_internal.hpp"

#include <cmath>
#include <cstdlib>
#include <initializer_list>

#include "spt_import/shapes.hpp"

namespace spt::import::geometrize {

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

}  // namespace

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

}  // namespace spt::import::geometrize
