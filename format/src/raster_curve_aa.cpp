// SPEC 8.5 for curves with a grid (format 1.4): a pixel's coverage counts the samples of its
// g x g grid that some segment covers. The exact per-sample test runs only where a pixel is
// near a segment's edge: a pixel whose centre lies well inside a segment (every sample inside
// by more than the test's rounding) is full, one well outside every segment is empty, so a
// line costs its edge pixels' samples, not all of its pixels' (a 3 px line at grid 4 has about
// as many edge pixels as inside ones).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "curve_segment.hpp"
#include "raster.hpp"

namespace spt::raster {
namespace {

// Margin (Q4) of the classification by the centre's distance: a sample is at most 8 Q4 from
// the centre per axis (< 11.32 diagonally), and the exact test's floors move the closest point
// by at most |dx| / 2^16 + 1/256 and the half width by 1/256 Q4 (2 Q4 for the longest
// segment of the format's range); 16 covers both with room.
constexpr double kMargin = 16.0;

struct SegBox {
    Segment seg;
    int64_t x0, x1, y0, y1;   // pixels whose samples the segment may cover
    double hw_min, hw_max;    // half widths at its ends, Q4
};

// Distance (Q4) from the point (X, Y) to the segment, in double.
double distance_to(const Segment& s, double X, double Y) {
    const double qx = X - double(s.x0), qy = Y - double(s.y0);
    double t = 0;
    if (s.len2 > 0) t = std::clamp((qx * double(s.dx) + qy * double(s.dy)) / double(s.len2), 0.0, 1.0);
    const double ex = qx - t * double(s.dx), ey = qy - t * double(s.dy);
    return std::sqrt(ex * ex + ey * ey);
}

}  // namespace

void rasterize_curve_aa(const CurveStroke& s, int64_t bx0, int64_t by0, int64_t bx1, int64_t by1,
                        uint8_t* out) {
    const int64_t bw = bx1 - bx0 + 1;
    std::memset(out, 0, size_t(bw * (by1 - by0 + 1)));
    const int g = s.supersample;
    int64_t off[16];
    for (int k = 0; k < g; ++k) off[k] = (2 * k + 1) * 128 / g;
    const int samples = g * g;

    // Segments with their pixel boxes, clipped to the caller's box; bucketed by first row.
    const size_t n = s.points.size();
    std::vector<SegBox> segs;
    segs.reserve(n);
    for (size_t k = 0; k < n; ++k) {
        if (k + 1 == n && n > 1) break;  // n - 1 segments; a one-point curve is one disc
        const CurvePoint& p = s.points[k];
        const CurvePoint& q = s.points[k + 1 < n ? k + 1 : k];
        SegBox b;
        b.seg = {p.x, p.y, int64_t(q.x) - p.x, int64_t(q.y) - p.y, 0, p.width, int64_t(q.width) - int64_t(p.width)};
        b.seg.len2 = b.seg.dx * b.seg.dx + b.seg.dy * b.seg.dy;
        const int64_t m = (std::max<int64_t>(p.width, q.width) + 1) / 2 + 1 + 8;
        b.x0 = std::max(bx0, -floor_div(-(std::min<int64_t>(p.x, q.x) - m - 8), 16));
        b.x1 = std::min(bx1, floor_div(std::max<int64_t>(p.x, q.x) + m - 8, 16));
        b.y0 = std::max(by0, -floor_div(-(std::min<int64_t>(p.y, q.y) - m - 8), 16));
        b.y1 = std::min(by1, floor_div(std::max<int64_t>(p.y, q.y) + m - 8, 16));
        if (b.x0 > b.x1 || b.y0 > b.y1) continue;
        b.hw_min = double(std::min(p.width, q.width)) / 2;
        b.hw_max = double(std::max(p.width, q.width)) / 2;
        segs.push_back(b);
    }
    std::sort(segs.begin(), segs.end(), [](const SegBox& a, const SegBox& b) { return a.y0 < b.y0; });

    std::vector<uint8_t> full(static_cast<size_t>(bw));
    std::vector<std::pair<int64_t, uint32_t>> partial;  // (column, segment) to test sample by sample
    std::vector<uint32_t> active;
    size_t next = 0;
    for (int64_t y = by0; y <= by1; ++y) {
        while (next < segs.size() && segs[next].y0 <= y) active.push_back(uint32_t(next++));
        std::erase_if(active, [&](uint32_t i) { return segs[i].y1 < y; });
        if (active.empty()) continue;
        std::fill(full.begin(), full.end(), 0);
        partial.clear();
        const double Y = double(16 * y + 8);
        for (uint32_t i : active) {
            const SegBox& b = segs[i];
            const Segment& sg = b.seg;
            // Columns whose centres may lie within reach of the segment's line (as the centre
            // rasterizer's bound, widened by the samples' half pixel).
            int64_t xa = b.x0, xb = b.x1;
            const double reach = (b.hw_max + kMargin + 12) * std::sqrt(double(sg.len2));
            if (!reachable_columns(sg, reach, 16 * y + 8, xa, xb)) continue;
            for (int64_t x = xa; x <= xb; ++x) {
                if (full[size_t(x - bx0)]) continue;
                const double d = distance_to(sg, double(16 * x + 8), Y);
                if (d + kMargin <= b.hw_min) full[size_t(x - bx0)] = 1;
                else if (d - kMargin <= b.hw_max) partial.emplace_back(x, i);
            }
        }
        uint8_t* row = out + (y - by0) * bw - bx0;
        for (int64_t x = bx0; x <= bx1; ++x)
            if (full[size_t(x - bx0)]) row[x] = 255;
        std::sort(partial.begin(), partial.end());
        for (size_t a = 0; a < partial.size();) {
            size_t e = a;
            const int64_t x = partial[a].first;
            while (e < partial.size() && partial[e].first == x) ++e;
            if (!full[size_t(x - bx0)]) {
                int inside = 0;
                for (int qy = 0; qy < g; ++qy)
                    for (int qx = 0; qx < g; ++qx) {
                        const int64_t xs = 256 * x + off[qx], ys = 256 * y + off[qy];
                        for (size_t j = a; j < e; ++j)
                            if (covers_sample(segs[partial[j].second].seg, xs, ys)) { ++inside; break; }
                    }
                row[x] = uint8_t((255 * inside + samples / 2) / samples);
            }
            a = e;
        }
    }
}

}  // namespace spt::raster
