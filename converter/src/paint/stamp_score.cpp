#include "paint/stamp_score.hpp"

#include <algorithm>

namespace spt::paint {

Clip clip_footprint(const Mask& fp, int32_t px, int32_t py, uint32_t width, uint32_t height) {
    Clip c;
    const int64_t ox = int64_t(px) + fp.x0, oy = int64_t(py) + fp.y0;
    c.i0 = int32_t(std::max<int64_t>(0, -ox));
    c.i1 = int32_t(std::min<int64_t>(fp.w, int64_t(width) - ox));
    c.j0 = int32_t(std::max<int64_t>(0, -oy));
    c.j1 = int32_t(std::min<int64_t>(fp.h, int64_t(height) - oy));
    return c;
}

Spans footprint_spans(const Mask& fp) {
    Spans s;
    s.lo.assign(fp.h, 0);
    s.hi.assign(fp.h, 0);
    for (uint32_t j = 0; j < fp.h; ++j) {
        const uint8_t* r = fp.a.data() + size_t(j) * fp.w;
        int32_t lo = 0, hi = int32_t(fp.w);
        while (lo < hi && r[lo] == 0) ++lo;
        while (hi > lo && r[hi - 1] == 0) --hi;
        s.lo[j] = lo;
        s.hi[j] = hi;
    }
    return s;
}

namespace {

// The plain and the alpha kernels are one template: the plain instantiation is the loop it
// always was (no test per pixel), the alpha one adds the fourth channel.
template <bool Alpha>
ColourSums colour_sums_impl(const Plane& p, const Mask& fp, const Spans& sp, int32_t px, int32_t py,
                            int32_t j0, int32_t j1) {
    // Integer sums are exact: a^2 <= 65025 and the numerators stay far below 2^63 for any
    // footprint the format allows.
    ColourSums s;
    const Clip c = clip_footprint(fp, px, py, p.width, p.height);
    j0 = std::max(j0, c.j0);
    j1 = std::min(j1, c.j1);
    const int32_t ox = px + fp.x0, oy = py + fp.y0;
    for (int32_t j = j0; j < j1; ++j) {
        const int32_t i0 = std::max(c.i0, sp.lo[j]), i1 = std::min(c.i1, sp.hi[j]);
        if (i0 >= i1) continue;
        const uint8_t* a_row = fp.a.data() + size_t(j) * fp.w;
        const size_t base = (size_t(oy + j) * p.width + size_t(ox)) * 3;
        const uint8_t* m = p.model + base;
        const uint8_t* k = p.canvas + base;
        const size_t abase = size_t(oy + j) * p.width + size_t(ox);
        int64_t r_saa = 0, r0 = 0, r1 = 0, r2 = 0, r_old = 0, r_sa = 0, c0 = 0, c1 = 0, c2 = 0;
        for (int32_t i = i0; i < i1; ++i) {
            const int32_t a = a_row[i];
            const uint8_t* mi = m + size_t(i) * 3;
            const uint8_t* ki = k + size_t(i) * 3;
            const int32_t na = 255 - a;
            r_saa += a * a;
            r_sa += a;
            c0 += a * ki[0]; c1 += a * ki[1]; c2 += a * ki[2];
            r0 += int64_t(a) * (255 * mi[0] - na * ki[0]);
            r1 += int64_t(a) * (255 * mi[1] - na * ki[1]);
            r2 += int64_t(a) * (255 * mi[2] - na * ki[2]);
            const int32_t d0 = ki[0] - mi[0], d1 = ki[1] - mi[1], d2 = ki[2] - mi[2];
            r_old += d0 * d0 + d1 * d1 + d2 * d2;
            if constexpr (Alpha) {
                const int32_t da = int32_t(p.canvas_a[abase + size_t(i)]) - p.model_a[abase + size_t(i)];
                r_old += (da > 0 ? p.alpha_weight : 1) * da * da;
            }
        }
        s.saa += r_saa; s.num[0] += r0; s.num[1] += r1; s.num[2] += r2; s.old_err += r_old;
        s.sa += r_sa; s.sac[0] += c0; s.sac[1] += c1; s.sac[2] += c2;
    }
    return s;
}

// The lattice point pred + step*k in 0..255 nearest the real optimum num / saa.
int lattice(int64_t num, int64_t saa, int pred, int step) {
    const int64_t t = num - int64_t(pred) * saa;          // (x* - pred) * saa
    const int64_t d = int64_t(step) * saa;
    int64_t k = t >= 0 ? (2 * t + d) / (2 * d) : -((-2 * t + d) / (2 * d));
    while (pred + step * k > 255) --k;
    while (pred + step * k < 0) ++k;
    return int(pred + step * k);
}

}  // namespace

bool best_colour(const ColourSums& s, Rgb8& out, int step) {
    if (s.saa == 0) return false;
    if (step > 1 && s.sa > 0) {
        // The canvas prediction of coding 2: coverage-weighted mean, rounded.
        int p[3];
        for (int c = 0; c < 3; ++c) p[c] = int((s.sac[c] + s.sa / 2) / s.sa);
        const int g = lattice(s.num[1], s.saa, p[1], step);
        const int r = lattice(s.num[0], s.saa, std::clamp(g + p[0] - p[1], 0, 255), step);
        const int b = lattice(s.num[2], s.saa, std::clamp(g + p[2] - p[1], 0, 255), step);
        out = Rgb8{uint8_t(r), uint8_t(g), uint8_t(b)};
        return true;
    }
    uint8_t col[3];
    for (int ch = 0; ch < 3; ++ch) {
        // Round half away from zero, then clamp: the optimum of a clamped quadratic is the
        // clamped optimum.
        const int64_t n = s.num[ch];
        const int64_t q = n >= 0 ? (2 * n + s.saa) / (2 * s.saa) : -((-2 * n + s.saa) / (2 * s.saa));
        col[ch] = uint8_t(std::clamp<int64_t>(q, 0, 255));
    }
    out = Rgb8{col[0], col[1], col[2]};
    return true;
}

namespace {

template <bool Alpha>
int64_t new_error_impl(const Plane& p, const Mask& fp, const Spans& sp, int32_t px, int32_t py,
                       int32_t j0, int32_t j1, Rgb8 col) {
    const Clip c = clip_footprint(fp, px, py, p.width, p.height);
    j0 = std::max(j0, c.j0);
    j1 = std::min(j1, c.j1);
    const int32_t ox = px + fp.x0, oy = py + fp.y0;
    int64_t e = 0;
    for (int32_t j = j0; j < j1; ++j) {
        const int32_t i0 = std::max(c.i0, sp.lo[j]), i1 = std::min(c.i1, sp.hi[j]);
        if (i0 >= i1) continue;
        const uint8_t* a_row = fp.a.data() + size_t(j) * fp.w;
        const size_t base = (size_t(oy + j) * p.width + size_t(ox)) * 3;
        const uint8_t* m = p.model + base;
        const uint8_t* k = p.canvas + base;
        const size_t abase = size_t(oy + j) * p.width + size_t(ox);
        int64_t r_new = 0;
        for (int32_t i = i0; i < i1; ++i) {
            // Zero coverage leaves the pixel as it is: blend8(d, s, 0) == d, so including the
            // few zeros inside a span changes nothing but keeps the loop branch-free.
            const uint32_t a = a_row[i];
            const uint8_t* mi = m + size_t(i) * 3;
            const uint8_t* ki = k + size_t(i) * 3;
            const int32_t d0 = int32_t(blend8(ki[0], col.r, a)) - mi[0];
            const int32_t d1 = int32_t(blend8(ki[1], col.g, a)) - mi[1];
            const int32_t d2 = int32_t(blend8(ki[2], col.b, a)) - mi[2];
            r_new += d0 * d0 + d1 * d1 + d2 * d2;
            if constexpr (Alpha) {
                const int32_t da = int32_t(blend8(p.canvas_a[abase + size_t(i)], 255, a)) - p.model_a[abase + size_t(i)];
                r_new += (da > 0 ? p.alpha_weight : 1) * da * da;
            }
        }
        e += r_new;
    }
    return e;
}

}  // namespace

ColourSums colour_sums(const Plane& p, const Mask& fp, const Spans& sp, int32_t px, int32_t py,
                       int32_t j0, int32_t j1) {
    return p.has_alpha() ? colour_sums_impl<true>(p, fp, sp, px, py, j0, j1)
                         : colour_sums_impl<false>(p, fp, sp, px, py, j0, j1);
}

int64_t new_error(const Plane& p, const Mask& fp, const Spans& sp, int32_t px, int32_t py,
                  int32_t j0, int32_t j1, Rgb8 col) {
    return p.has_alpha() ? new_error_impl<true>(p, fp, sp, px, py, j0, j1, col)
                         : new_error_impl<false>(p, fp, sp, px, py, j0, j1, col);
}

StampScore score_stamp(const Plane& p, const Mask& fp, const Spans& sp, int32_t px, int32_t py, int step) {
    StampScore s;
    const ColourSums cs = colour_sums(p, fp, sp, px, py, 0, int32_t(fp.h));
    if (!best_colour(cs, s.color, step)) return s;
    s.valid = true;
    s.delta = new_error(p, fp, sp, px, py, 0, int32_t(fp.h), s.color) - cs.old_err;
    return s;
}

StampScore score_stamp(const Plane& p, const Mask& fp, int32_t px, int32_t py, int step) {
    return score_stamp(p, fp, footprint_spans(fp), px, py, step);
}

void commit_stamp(const Plane& p, const Mask& fp, int32_t px, int32_t py, Rgb8 color) {
    const Clip c = clip_footprint(fp, px, py, p.width, p.height);
    if (c.empty()) return;
    const int32_t ox = px + fp.x0, oy = py + fp.y0;
    for (int32_t j = c.j0; j < c.j1; ++j) {
        const uint8_t* a_row = fp.a.data() + size_t(j) * fp.w;
        uint8_t* k = p.canvas + (size_t(oy + j) * p.width + size_t(ox)) * 3;
        for (int32_t i = c.i0; i < c.i1; ++i) {
            const uint32_t a = a_row[i];
            if (a == 0) continue;
            uint8_t* ki = k + size_t(i) * 3;
            ki[0] = blend8(ki[0], color.r, a);
            ki[1] = blend8(ki[1], color.g, a);
            ki[2] = blend8(ki[2], color.b, a);
        }
        if (p.has_alpha()) {
            uint8_t* ka = p.canvas_a + size_t(oy + j) * p.width + size_t(ox);
            for (int32_t i = c.i0; i < c.i1; ++i) ka[i] = blend8(ka[i], 255, a_row[i]);
        }
    }
}

}  // namespace spt::paint
