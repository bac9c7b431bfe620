// Polygon strokes (SPEC.md 8.8): nonzero winding at sample points, with a half-open edge rule
// so that two polygons sharing an edge cover each sample once. All in exact integers.
#include "raster_polygon.hpp"

#include <algorithm>

#include "raster.hpp"

namespace spt::raster {

namespace {

// ceil(n / d) for d > 0.
int64_t ceil_div(int64_t n, int64_t d) { return -floor_div(-n, d); }

}  // namespace

void polygon_box(const PolygonStroke& s, int64_t& x0, int64_t& y0, int64_t& x1, int64_t& y1) {
    x0 = y0 = 0;
    x1 = y1 = -1;
    if (s.points.empty()) return;
    int64_t lx = s.points[0].x, hx = lx, ly = s.points[0].y, hy = ly;
    for (const auto& p : s.points) {
        lx = std::min<int64_t>(lx, p.x); hx = std::max<int64_t>(hx, p.x);
        ly = std::min<int64_t>(ly, p.y); hy = std::max<int64_t>(hy, p.y);
    }
    // A sample of pixel x lies in [256x, 256x + 256) (1/256 px); an inside sample lies in the
    // vertices' box [16 lx, 16 hx] (SPEC 8.8), so x is in [floor(lx / 16), floor(hx / 16)].
    x0 = floor_div(lx, 16); x1 = floor_div(hx, 16);
    y0 = floor_div(ly, 16); y1 = floor_div(hy, 16);
}

PolygonRaster::PolygonRaster(const PolygonStroke& s) {
    // Sample offsets (SPEC 8.2): N = 0 is one sample at the pixel centre, 128/256.
    n_ = s.supersample >= 2 ? s.supersample : 1;
    for (uint32_t k = 0; k < n_; ++k) o_[k] = n_ == 1 ? 128 : int64_t((2 * k + 1) * 128 / n_);
    const size_t n = s.points.size();
    edges_.reserve(n);
    for (size_t k = 0; k < n; ++k) {
        const PolygonVertex& p = s.points[k];
        const PolygonVertex& q = s.points[(k + 1) % n];
        if (p.y == q.y) continue;  // horizontal edges never count
        Edge e;
        if (p.y < q.y) { e = {16 * int64_t(p.x), 16 * int64_t(p.y), 16 * int64_t(q.x), 16 * int64_t(q.y), +1}; }
        else { e = {16 * int64_t(q.x), 16 * int64_t(q.y), 16 * int64_t(p.x), 16 * int64_t(p.y), -1}; }
        edges_.push_back(e);
    }
    std::sort(edges_.begin(), edges_.end(), [](const Edge& a, const Edge& b) { return a.ya < b.ya; });
}

void PolygonRaster::sample_row(int64_t Y, int64_t x0, int64_t w) {
    // Activate edges starting at or above Y, retire those ending at or above it.
    while (next_ < edges_.size() && edges_[next_].ya <= Y) active_.push_back(edges_[next_++]);
    active_.erase(std::remove_if(active_.begin(), active_.end(), [Y](const Edge& e) { return e.yb <= Y; }), active_.end());
    if (active_.empty()) return;
    cross_.clear();
    for (const Edge& e : active_) {
        // The edge counts for samples X with (X - xa)(yb - ya) >= (xb - xa)(Y - ya): X >= xa + ceil(...).
        // |xb - xa|, Y - ya < 2^30 (vertices within 2^28, canvas rows within 2^28): fits.
        cross_.push_back({e.xa + ceil_div((e.xb - e.xa) * (Y - e.ya), e.yb - e.ya), e.dir});
    }
    std::sort(cross_.begin(), cross_.end(), [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
    for (uint32_t p = 0; p < n_; ++p) {
        // Pixel x's sample p is at 256x + o_p: the edge counts from column ceil((X_e - o_p) / 256).
        int wind = 0;
        int64_t from = 0;  // box column where the current winding starts
        for (const Crossing& c : cross_) {
            const int64_t col = std::clamp<int64_t>(ceil_div(c.x - o_[p], 256) - x0, 0, w);
            if (wind != 0)
                for (int64_t x = from; x < col; ++x) ++count_[size_t(x)];
            wind += c.dir;
            from = col;
        }
        if (wind != 0)  // cannot happen for a closed polygon; kept for safety
            for (int64_t x = from; x < w; ++x) ++count_[size_t(x)];
    }
}

void PolygonRaster::row(int64_t y, int64_t x0, int64_t x1, uint8_t* out) {
    const int64_t w = x1 - x0 + 1;
    if (w <= 0) return;
    count_.assign(size_t(w), 0);
    for (uint32_t q = 0; q < n_; ++q) {
        const int64_t Y = 256 * y + o_[q];
        if (Y < last_Y_) {  // rows out of order: start the edge list again
            active_.clear();
            next_ = 0;
        }
        last_Y_ = Y;
        sample_row(Y, x0, w);
    }
    const uint32_t nn = n_ * n_;
    for (int64_t x = 0; x < w; ++x) out[x] = uint8_t((255u * count_[size_t(x)] + nn / 2) / nn);
}

void rasterize_polygon(const PolygonStroke& s, int64_t x0, int64_t y0, int64_t x1, int64_t y1, uint8_t* out) {
    PolygonRaster r(s);
    const int64_t w = x1 - x0 + 1;
    for (int64_t y = y0; y <= y1; ++y) r.row(y, x0, x1, out + size_t((y - y0) * w));
}

}  // namespace spt::raster
