// Canvas predictions of coding 2 (SPEC.md 7.7.4). Integer arithmetic only: encoder and decoder
// must compute the same contexts on every platform.
#include "canvas_ctx.hpp"

#include <algorithm>
#include <cstdlib>

namespace spt::detail {
namespace {

int bits_of(uint64_t v) { int n = 0; while (v) { ++n; v >>= 1; } return n; }

}  // namespace

FootprintMean footprint_mean(const Canvas& canvas, const Mask& fp, int32_t px, int32_t py) {
    FootprintMean m;
    const int64_t ox = int64_t(px) + fp.x0, oy = int64_t(py) + fp.y0;
    const int64_t i0 = std::max<int64_t>(0, -ox), i1 = std::min<int64_t>(fp.w, int64_t(canvas.width) - ox);
    const int64_t j0 = std::max<int64_t>(0, -oy), j1 = std::min<int64_t>(fp.h, int64_t(canvas.height) - oy);
    int64_t sa = 0, s[3] = {0, 0, 0};
    for (int64_t j = j0; j < j1; ++j) {
        const uint8_t* a = fp.a.data() + size_t(j) * fp.w;
        const uint8_t* c = canvas.row(uint32_t(oy + j)) + size_t(ox) * 3;
        for (int64_t i = i0; i < i1; ++i) {
            if (!a[i]) continue;
            sa += a[i];
            for (int k = 0; k < 3; ++k) s[k] += int64_t(a[i]) * c[i * 3 + k];
        }
    }
    if (sa == 0) return m;
    m.covered = true;
    const uint8_t r = uint8_t((s[0] + sa / 2) / sa), g = uint8_t((s[1] + sa / 2) / sa), b = uint8_t((s[2] + sa / 2) / sa);
    m.mean = Rgb8{r, g, b};
    // Activity: coverage-weighted mean absolute deviation of G from its mean, in classes.
    int64_t dev = 0;
    for (int64_t j = j0; j < j1; ++j) {
        const uint8_t* a = fp.a.data() + size_t(j) * fp.w;
        const uint8_t* c = canvas.row(uint32_t(oy + j)) + size_t(ox) * 3;
        for (int64_t i = i0; i < i1; ++i) dev += int64_t(a[i]) * std::abs(int(c[i * 3 + 1]) - int(g));
    }
    m.activity = dev < 2 * sa ? 0 : dev < 6 * sa ? 1 : dev < 16 * sa ? 2 : 3;
    return m;
}

OrientGuess gradient_orientation(const Canvas& canvas, uint32_t px, uint32_t py, const std::vector<Orientation>& table) {
    OrientGuess g;
    const int64_t W = canvas.width, H = canvas.height;
    auto luma = [&](int64_t x, int64_t y) {
        x = std::clamp<int64_t>(x, 0, W - 1);
        y = std::clamp<int64_t>(y, 0, H - 1);
        const uint8_t* p = canvas.row(uint32_t(y)) + size_t(x) * 3;
        return int64_t(p[0]) + 2 * int64_t(p[1]) + int64_t(p[2]);
    };
    int64_t jxx = 0, jyy = 0, jxy = 0;
    for (int64_t y = int64_t(py) - 3; y <= int64_t(py) + 3; ++y)
        for (int64_t x = int64_t(px) - 3; x <= int64_t(px) + 3; ++x) {
            const int64_t gx = luma(x + 1, y - 1) + 2 * luma(x + 1, y) + luma(x + 1, y + 1) - luma(x - 1, y - 1) -
                               2 * luma(x - 1, y) - luma(x - 1, y + 1);
            const int64_t gy = luma(x - 1, y + 1) + 2 * luma(x, y + 1) + luma(x + 1, y + 1) - luma(x - 1, y - 1) -
                               2 * luma(x, y - 1) - luma(x + 1, y - 1);
            jxx += gx * gx;
            jyy += gy * gy;
            jxy += gx * gy;
        }
    const int64_t a = jxx - jyy, b = 2 * jxy;  // (cos 2phi, sin 2phi) of the gradient, scaled
    const uint64_t s = uint64_t(std::abs(a)) + uint64_t(std::abs(b));
    const int bl = bits_of(s);
    g.strength = s == 0 ? 0 : bl < 20 ? 1 : bl < 25 ? 2 : 3;
    if (s == 0) return g;
    // The stroke runs along the edge, perpendicular to the gradient: maximise the dot product
    // of the entry's double angle with the negated gradient double angle. First maximum wins.
    int64_t best = 0;
    for (size_t k = 0; k < table.size(); ++k) {
        const int64_t C = table[k].cos_q14, S = table[k].sin_q14;
        const int64_t score = -(a * (C * C - S * S) + b * (2 * C * S));
        if (k == 0 || score > best) { best = score; g.orient = uint8_t(k); }
    }
    return g;
}

}  // namespace spt::detail
