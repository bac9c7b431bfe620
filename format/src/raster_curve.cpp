// SPEC 8.5: curve strokes sampled at pixel centres (grid 0). A pixel centre is covered when its
// distance to some segment is at most the half width interpolated at the segment's closest
// point; the union of all segments is one coverage mask, composited once. Curves with a grid
// are raster_curve_aa.cpp's.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "curve_segment.hpp"
#include "raster.hpp"

namespace spt::raster {
namespace {

// Is the pixel centre (X, Y) (Q4) covered by the segment?
bool covers(const Segment& s, int64_t X, int64_t Y) {
    const int64_t qx = X - s.x0, qy = Y - s.y0;
    int64_t T = 0;
    if (s.len2 > 0) {
        const int64_t t = qx * s.dx + qy * s.dy;
        if (t <= 0) T = 0;
        else if (t >= s.len2) T = kT;
        else T = segment_param(t, s.len2);
    }
    // Offset from the closest point and the half width there, both in 1/256 of a Q4 unit.
    const int64_t ex = 256 * qx - floor_div(T * s.dx, int64_t(1) << 16);
    const int64_t ey = 256 * qy - floor_div(T * s.dy, int64_t(1) << 16);
    const int64_t r = (s.w0 * kT + T * s.dw) >> 17;
    if (ex > r || ex < -r || ey > r || ey < -r) return false;  // also keeps the squares in range
    return ex * ex + ey * ey <= r * r;
}

}  // namespace

void curve_box(const CurveStroke& s, int64_t& x0, int64_t& y0, int64_t& x1, int64_t& y1) {
    int64_t lo_x = INT64_MAX, lo_y = INT64_MAX, hi_x = INT64_MIN, hi_y = INT64_MIN;
    for (const CurvePoint& p : s.points) {
        // A covered centre is within half the larger width of its segment (plus the 1/256
        // rounding of the closest point), so half of every width plus one Q4 unit is enough.
        const int64_t m = (int64_t(p.width) + 1) / 2 + 1 + curve_sample_reach(s);
        lo_x = std::min<int64_t>(lo_x, p.x - m);
        hi_x = std::max<int64_t>(hi_x, p.x + m);
        lo_y = std::min<int64_t>(lo_y, p.y - m);
        hi_y = std::max<int64_t>(hi_y, p.y + m);
    }
    x0 = -floor_div(-(lo_x - 8), 16);
    y0 = -floor_div(-(lo_y - 8), 16);
    x1 = floor_div(hi_x - 8, 16);
    y1 = floor_div(hi_y - 8, 16);
}

void rasterize_curve(const CurveStroke& s, int64_t bx0, int64_t by0, int64_t bx1, int64_t by1,
                     uint8_t* out) {
    if (s.supersample >= 2) return rasterize_curve_aa(s, bx0, by0, bx1, by1, out);
    const int64_t bw = bx1 - bx0 + 1;
    std::memset(out, 0, size_t(bw * (by1 - by0 + 1)));
    const size_t n = s.points.size();
    for (size_t k = 0; k < n; ++k) {
        // A one-point curve is the segment (P0, P0): a disc.
        const CurvePoint& p = s.points[k];
        const CurvePoint& q = s.points[k + 1 < n ? k + 1 : k];
        if (k + 1 == n && n > 1) break;
        Segment seg{p.x, p.y, int64_t(q.x) - p.x, int64_t(q.y) - p.y, 0, p.width,
                    int64_t(q.width) - int64_t(p.width)};
        seg.len2 = seg.dx * seg.dx + seg.dy * seg.dy;
        // This segment's own box, clipped to the stroke's box.
        const int64_t m = (std::max<int64_t>(p.width, q.width) + 1) / 2 + 1;
        const int64_t lx = std::min<int64_t>(p.x, q.x) - m, hx = std::max<int64_t>(p.x, q.x) + m;
        const int64_t ly = std::min<int64_t>(p.y, q.y) - m, hy = std::max<int64_t>(p.y, q.y) + m;
        const int64_t x0 = std::max(bx0, -floor_div(-(lx - 8), 16));
        const int64_t x1 = std::min(bx1, floor_div(hx - 8, 16));
        const int64_t y0 = std::max(by0, -floor_div(-(ly - 8), 16));
        const int64_t y1 = std::min(by1, floor_div(hy - 8, 16));
        // A covered centre is within max(w0, w1) / 2 + 1/128 (Q4) of a point of the segment
        // (|Ex|, |Ey| are that offset times 256 up to the floor roundings, and R <= 128 max(w)),
        // hence at most that far from the segment's line: |qx dy - qy dx| <= D sqrt(len2). Each
        // row evaluates only the columns this allows, widened by a pixel on each side; the
        // bound is computed in double with that much margin, the test itself stays exact.
        const double D = double(std::max<int64_t>(p.width, q.width)) / 2 + 2;
        const double reach = D * std::sqrt(double(seg.len2));
        for (int64_t y = y0; y <= y1; ++y) {
            uint8_t* row = out + (y - by0) * bw - bx0;
            const int64_t Y = 16 * y + 8;
            int64_t xa = x0, xb = x1;
            if (!reachable_columns(seg, reach, Y, xa, xb)) continue;
            for (int64_t x = xa; x <= xb; ++x) {
                if (row[x] == 0 && covers(seg, 16 * x + 8, Y)) row[x] = 255;
            }
        }
    }
}

}  // namespace spt::raster
