// SPEC 8.2-8.4: stamps and affine strokes map each pixel centre back to template space
// (U, V in Q16) with one exact rule, then read the template's coverage there.
#include <algorithm>
#include <cstdlib>

#include "raster.hpp"

namespace spt::raster {
namespace {

int64_t abs64(int64_t v) { return v < 0 ? -v : v; }

// Pixel columns whose Q4 centre 16x+8 lies in [lo, hi].
int64_t first_centre_at_or_after(int64_t lo) { return -floor_div(-(lo - 8), 16); }
int64_t last_centre_at_or_before(int64_t hi) { return floor_div(hi - 8, 16); }

inline uint8_t bitmap_coverage(const Template& t, int64_t U, int64_t V) {
    // Texel position in 1/256 texel: template pixel i covers [i, i+1), u = -1 is the left
    // edge and u = +1 the right edge, so s = (u + 1) / 2 * width.
    const int64_t tw = t.width, th = t.height;
    const int64_t sx = floor_div((U + kOne) * tw, 512);
    const int64_t sy = floor_div((V + kOne) * th, 512);
    if (sx < 0 || sy < 0 || sx >= tw * 256 || sy >= th * 256) return 0;
    // Bilinear between texel centres (i + 0.5); clamped to the edge texels near the border.
    const int64_t qx = sx - 128, qy = sy - 128;
    const int64_t fx = qx & 255, fy = qy & 255;
    const int64_t i0 = std::clamp<int64_t>(qx >> 8, 0, tw - 1);
    const int64_t i1 = std::clamp<int64_t>((qx >> 8) + 1, 0, tw - 1);
    const int64_t j0 = std::clamp<int64_t>(qy >> 8, 0, th - 1);
    const int64_t j1 = std::clamp<int64_t>((qy >> 8) + 1, 0, th - 1);
    const uint8_t* p = t.pixels.data();
    const int64_t top = p[j0 * tw + i0] * (256 - fx) + p[j0 * tw + i1] * fx;
    const int64_t bot = p[j1 * tw + i0] * (256 - fx) + p[j1 * tw + i1] * fx;
    return uint8_t((top * (256 - fy) + bot * fy + 32768) >> 16);
}

}  // namespace

uint8_t template_coverage(const Template& t, int64_t U, int64_t V) {
    // Everything any template covers lies in [-1, 1]^2; the guard also bounds the squares below.
    if (U < -2 * kOne || U > 2 * kOne || V < -2 * kOne || V > 2 * kOne) return 0;
    switch (t.kind) {
        case TemplateKind::Bitmap: return bitmap_coverage(t, U, V);
        case TemplateKind::Ellipse: return U * U + V * V <= kOne * kOne ? 255 : 0;
        case TemplateKind::Rectangle:
            return (U >= -kOne && U <= kOne && V >= -kOne && V <= kOne) ? 255 : 0;
        case TemplateKind::Triangle: return (U >= -kOne && V >= -kOne && U + V <= 0) ? 255 : 0;
    }
    return 0;
}

InverseMap stamp_inverse(uint32_t w, uint32_t h, Orientation o, uint8_t supersample) {
    // Pixel offset (i, j) from the centre pixel, rotated back by the table entry and divided
    // by the half size: U = 65536 * (i*cos + j*sin) / 16384 / (w / 2) = 8 (i cos + j sin) / w.
    const int64_t C = o.cos_q14, S = o.sin_q14;
    InverseMap m;
    m.u = {8 * C, 8 * S, 0, int64_t(w)};
    m.v = {-8 * S, 8 * C, 0, int64_t(h)};
    const int64_t rx = (int64_t(w) * abs64(C) + int64_t(h) * abs64(S)) / 32768 + 1;
    const int64_t ry = (int64_t(w) * abs64(S) + int64_t(h) * abs64(C)) / 32768 + 1;
    m.x0 = -rx; m.x1 = rx; m.y0 = -ry; m.y1 = ry;
    // The box already reaches a pixel past the stamp, so supersampling needs no wider box.
    m.aa = supersample > 1 ? supersample : 1;
    return m;
}

bool affine_inverse(const AffineStroke& s, InverseMap& m, uint8_t supersample) {
    int64_t a = s.a, b = s.b, c = s.c, d = s.d;
    const int64_t tx = s.tx, ty = s.ty;
    int64_t det = a * d - b * c;
    if (det == 0) return false;
    // (U, V) = 65536 * inverse(M) * (16x + 8 - tx, 16y + 8 - ty); the sign goes to the
    // numerators so that every denominator is positive and floor_div is the one rounding.
    int64_t sgn = 1;
    if (det < 0) { det = -det; sgn = -1; }
    m.u = {sgn * (d << 20), sgn * (-b << 20), sgn * ((d * (8 - tx) - b * (8 - ty)) << 16), det};
    m.v = {sgn * (-c << 20), sgn * (a << 20), sgn * ((a * (8 - ty) - c * (8 - tx)) << 16), det};
    // Supersampled: a pixel whose centre is within half a pixel (8 Q4) of the box may hold
    // samples inside it (SPEC 8.2).
    m.aa = supersample > 1 ? supersample : 1;
    const int64_t grow = m.aa > 1 ? 8 : 0;
    const int64_t ex = abs64(a) + abs64(b) + grow, ey = abs64(c) + abs64(d) + grow;
    m.x0 = first_centre_at_or_after(tx - ex);
    m.x1 = last_centre_at_or_before(tx + ex);
    m.y0 = first_centre_at_or_after(ty - ey);
    m.y1 = last_centre_at_or_before(ty + ey);
    return true;
}

InverseMap stamp_inverse_at(uint32_t w, uint32_t h, Orientation o, int64_t cx, int64_t cy, uint8_t supersample) {
    // value(i, j) with i = x - cx, j = y - cy: the constant absorbs the shift.
    InverseMap m = stamp_inverse(w, h, o, supersample);
    m.u.c = -(m.u.ax * cx + m.u.ay * cy);
    m.v.c = -(m.v.ax * cx + m.v.ay * cy);
    m.x0 += cx; m.x1 += cx; m.y0 += cy; m.y1 += cy;
    return m;
}

namespace {

// Narrows [x0, x1] to the x with lo <= floor((ax x + k) / den) <= hi (den > 0). Since
// floor(n / den) >= lo  <=>  n >= lo den  and  floor(n / den) <= hi  <=>  n <= (hi + 1) den - 1,
// this is A <= ax x <= B, solved exactly with floor divisions.
void narrow(const LinearMap& f, int64_t y, int64_t lo, int64_t hi, int64_t& x0, int64_t& x1) {
    const int64_t k = f.ay * y + f.c;
    const int64_t A = lo * f.den - k, B = (hi + 1) * f.den - 1 - k;
    if (f.ax == 0) {
        if (A > 0 || B < 0) x1 = x0 - 1;
        return;
    }
    auto ceil_div = [](int64_t n, int64_t d) { return -floor_div(-n, d); };
    int64_t a, b;
    if (f.ax > 0) { a = ceil_div(A, f.ax); b = floor_div(B, f.ax); }
    else { a = ceil_div(B, f.ax); b = floor_div(A, f.ax); }
    x0 = std::max(x0, a);
    x1 = std::min(x1, b);
}

template <class Cov>
void walk_row(const InverseMap& m, int64_t y, int64_t x0, int64_t x1, uint8_t* out, Cov cov) {
    LinearWalker U(m.u, x0, y), V(m.v, x0, y);
    for (int64_t x = x0; x <= x1; ++x) {
        *out++ = cov(U.value(), V.value());
        U.next();
        V.next();
    }
}

// SPEC 8.2 supersampling. Sample positions are in 1/256 pixel: P = 256 x + o_i with
// o_i = floor((2 i + 1) 128 / N), so N = 1 would be the pixel centre (o = 128). A map
// value(x) = floor((ax x + ay y + c) / den) taken at the centre becomes, at P,
// floor((ax (P - 128) + ay (Q - 128) + 256 c) / (256 den)); affine maps have ax, ay divisible
// by 256 and are reduced by it, which keeps every product below 2^60 (stamps stay far below).
struct SampleMap {
    int64_t ax, ay, c, den;
    int64_t at(int64_t P, int64_t Q) const { return floor_div(ax * P + ay * Q + c, den); }
};
SampleMap sample_map(const LinearMap& f) {
    if (f.ax % 256 == 0 && f.ay % 256 == 0) return {f.ax / 256, f.ay / 256, f.c - (f.ax + f.ay) / 2, f.den};
    return {f.ax, f.ay, 256 * f.c - 128 * (f.ax + f.ay), 256 * f.den};
}

bool inside(TemplateKind k, int64_t U, int64_t V) {
    switch (k) {
        case TemplateKind::Ellipse: return U >= -kOne && U <= kOne && V >= -kOne && V <= kOne && U * U + V * V <= kOne * kOne;
        case TemplateKind::Rectangle: return U >= -kOne && U <= kOne && V >= -kOne && V <= kOne;
        case TemplateKind::Triangle: return U >= -kOne && V >= -kOne && U + V <= 0;
        default: return false;
    }
}

// Whether every sample with U in [ul, uh] and V in [vl, vh] is inside (1), outside (0), or
// either (-1). Bounds only: exact answers, a quick path for pixels away from the edge.
int classify(TemplateKind k, int64_t ul, int64_t uh, int64_t vl, int64_t vh) {
    if (uh < -kOne || ul > kOne || vh < -kOne || vl > kOne) return 0;
    switch (k) {
        case TemplateKind::Rectangle:
            return (ul >= -kOne && uh <= kOne && vl >= -kOne && vh <= kOne) ? 1 : -1;
        case TemplateKind::Triangle:
            if (ul + vl > 0) return 0;
            return (ul >= -kOne && vl >= -kOne && uh + vh <= 0) ? 1 : -1;
        case TemplateKind::Ellipse: {
            const int64_t au = std::max(abs64(ul), abs64(uh)), av = std::max(abs64(vl), abs64(vh));
            if (au <= kOne && av <= kOne && au * au + av * av <= kOne * kOne) return 1;
            const int64_t nu = (ul <= 0 && uh >= 0) ? 0 : std::min(abs64(ul), abs64(uh));
            const int64_t nv = (vl <= 0 && vh >= 0) ? 0 : std::min(abs64(vl), abs64(vh));
            return nu * nu + nv * nv > kOne * kOne ? 0 : -1;
        }
        default: return -1;
    }
}

void supersample_row(const InverseMap& m, TemplateKind k, int64_t y, int64_t x0, int64_t x1, uint8_t* out) {
    const int64_t n = m.aa, n2 = n * n;
    const SampleMap su = sample_map(m.u), sv = sample_map(m.v);
    int64_t off[16];
    for (int64_t i = 0; i < n; ++i) off[i] = (2 * i + 1) * 128 / n;
    for (int64_t x = x0; x <= x1; ++x, ++out) {
        const int64_t P0 = 256 * x + off[0], P1 = 256 * x + off[n - 1];
        const int64_t Q0 = 256 * y + off[0], Q1 = 256 * y + off[n - 1];
        // A linear map takes its extremes over the sample grid at the grid's corners.
        const int64_t u00 = su.at(P0, Q0), u01 = su.at(P0, Q1), u10 = su.at(P1, Q0), u11 = su.at(P1, Q1);
        const int64_t v00 = sv.at(P0, Q0), v01 = sv.at(P0, Q1), v10 = sv.at(P1, Q0), v11 = sv.at(P1, Q1);
        const int c = classify(k, std::min({u00, u01, u10, u11}), std::max({u00, u01, u10, u11}),
                               std::min({v00, v01, v10, v11}), std::max({v00, v01, v10, v11}));
        if (c >= 0) { *out = c ? 255 : 0; continue; }
        int64_t count = 0;
        for (int64_t j = 0; j < n; ++j)
            for (int64_t i = 0; i < n; ++i) {
                const int64_t P = 256 * x + off[i], Q = 256 * y + off[j];
                count += inside(k, su.at(P, Q), sv.at(P, Q));
            }
        *out = uint8_t((255 * count + n2 / 2) / n2);
    }
}

}  // namespace

bool map_row_range(const InverseMap& m, int64_t y, int64_t& x0, int64_t& x1) {
    if (m.aa > 1) {
        // A sample lies less than half a pixel from the centre in each axis, so its value
        // differs from the centre's by less than (|ax| + |ay|) / (2 den) + 1 (two floors).
        const int64_t mu = (abs64(m.u.ax) + abs64(m.u.ay)) / (2 * m.u.den) + 2;
        const int64_t mv = (abs64(m.v.ax) + abs64(m.v.ay)) / (2 * m.v.den) + 2;
        narrow(m.u, y, -kOne - mu, kOne + mu, x0, x1);
        if (x0 <= x1) narrow(m.v, y, -kOne - mv, kOne + mv, x0, x1);
        return x0 <= x1;
    }
    narrow(m.u, y, -kOne, kOne, x0, x1);
    if (x0 <= x1) narrow(m.v, y, -kOne, kOne, x0, x1);
    return x0 <= x1;
}

void rasterize_map_row(const InverseMap& m, const Template& t, int64_t y, int64_t x0, int64_t x1, uint8_t* out) {
    if (m.aa > 1 && t.kind != TemplateKind::Bitmap) return supersample_row(m, t.kind, y, x0, x1, out);
    // Inside map_row_range |U|, |V| <= 65536, so the +-2 guard of template_coverage holds and
    // each kind's test reduces to what remains of it (SPEC 8.4).
    switch (t.kind) {
        case TemplateKind::Rectangle: std::fill(out, out + (x1 - x0 + 1), uint8_t(255)); return;
        case TemplateKind::Ellipse:
            return walk_row(m, y, x0, x1, out, [](int64_t U, int64_t V) { return U * U + V * V <= kOne * kOne ? 255 : 0; });
        case TemplateKind::Triangle:
            return walk_row(m, y, x0, x1, out, [](int64_t U, int64_t V) { return U + V <= 0 ? 255 : 0; });
        case TemplateKind::Bitmap:
            return walk_row(m, y, x0, x1, out, [&t](int64_t U, int64_t V) { return bitmap_coverage(t, U, V); });
    }
    std::fill(out, out + (x1 - x0 + 1), uint8_t(0));
}

void rasterize_map(const InverseMap& m, const Template& t, int64_t x0, int64_t y0, int64_t x1,
                   int64_t y1, uint8_t* out) {
    const int64_t w = x1 - x0 + 1;
    std::fill(out, out + w * (y1 - y0 + 1), uint8_t(0));
    for (int64_t y = y0; y <= y1; ++y) {
        int64_t a = x0, b = x1;
        if (map_row_range(m, y, a, b)) rasterize_map_row(m, t, y, a, b, out + (y - y0) * w + (a - x0));
    }
}

}  // namespace spt::raster
