// The exact arithmetic of one curve segment (SPEC 8.5), shared by the centre-sampled and the
// supersampled curve rasterizers.
#pragma once
#include <cmath>
#include <cstdint>
#include <utility>

#include "raster.hpp"

namespace spt::raster {

constexpr int64_t kT = int64_t(1) << 24;  // segment parameter t in Q24

// floor(t * 2^24 / len2) for 0 < t < len2 <= 2^56 without overflowing int64.
inline int64_t segment_param(int64_t t, int64_t len2) {
    if (t < (int64_t(1) << 39)) return (t << 24) / len2;
    int64_t q = 0, r = t;  // binary long division, one quotient bit per step; r < len2
    for (int k = 0; k < 24; ++k) {
        r <<= 1;
        q <<= 1;
        if (r >= len2) { r -= len2; q |= 1; }
    }
    return q;
}

// Segment (x0, y0) -> (x0 + dx, y0 + dy) in Q4, full width w0 growing by dw along it.
struct Segment {
    int64_t x0, y0, dx, dy, len2, w0, dw;
};

// Narrows the columns [xa, xb] of the row whose pixel centres have Y (Q4) to those whose
// centres may lie within `reach` / sqrt(len2) (Q4) of the segment's line, plus a pixel each
// side: the bound is computed in double with that margin, the per-pixel test stays exact.
// False when no column of the row can be within reach.
inline bool reachable_columns(const Segment& s, double reach, int64_t Y, int64_t& xa, int64_t& xb) {
    if (s.len2 == 0) return true;
    const double qdx = double(Y - s.y0) * double(s.dx);
    if (s.dy == 0) return std::fabs(qdx) <= reach + 1;
    double lo = (qdx - reach) / double(s.dy), hi = (qdx + reach) / double(s.dy);
    if (lo > hi) std::swap(lo, hi);
    // qx = 16 x + 8 - x0 in [lo, hi]
    const double fa = std::floor((lo + double(s.x0) - 8) / 16) - 1;
    const double fb = std::ceil((hi + double(s.x0) - 8) / 16) + 1;
    if (fa > double(xa)) xa = fa > double(xb) ? xb + 1 : int64_t(fa);
    if (fb < double(xb)) xb = fb < double(xa) ? xa - 1 : int64_t(fb);
    return true;
}

// How far (Q4, per axis) a pixel's samples lie from its centre: 0 at the centre (grid 0), up
// to half a pixel on a grid.
inline int64_t curve_sample_reach(const CurveStroke& s) { return s.supersample >= 2 ? 8 : 0; }

// Does the segment cover the sample (xs, ys), in 1/256 pixel (SPEC 8.5)?
inline bool covers_sample(const Segment& s, int64_t xs, int64_t ys) {
    const int64_t qx = xs - 16 * s.x0, qy = ys - 16 * s.y0;
    int64_t T = 0;
    if (s.len2 > 0) {
        const int64_t t = qx * s.dx + qy * s.dy;
        if (t <= 0) T = 0;
        else if (t >= 16 * s.len2) T = kT;
        else T = segment_param(t, 16 * s.len2);  // floor(t 2^20 / len2)
    }
    const int64_t ex = 16 * qx - floor_div(T * s.dx, int64_t(1) << 16);
    const int64_t ey = 16 * qy - floor_div(T * s.dy, int64_t(1) << 16);
    const int64_t r = (s.w0 * kT + T * s.dw) >> 17;
    if (ex > r || ex < -r || ey > r || ey < -r) return false;  // also keeps the squares in range
    return ex * ex + ey * ey <= r * r;
}

}  // namespace spt::raster
