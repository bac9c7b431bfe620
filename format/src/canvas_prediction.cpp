// Canvas predictions of coding 2 (SPEC.md 7.7.4). Integer arithmetic only: encoder and decoder
// must compute the same contexts on every platform.
#include "canvas_prediction.hpp"

#include <algorithm>
#include <cstdlib>

#if defined(__x86_64__) || defined(_M_X64)
#include <immintrin.h>
#endif

namespace spt::detail {
namespace {

int bits_of(uint64_t v) { int n = 0; while (v) { ++n; v >>= 1; } return n; }

// One clipped footprint row: nb bytes (a multiple of 3) of an RGB canvas row x under the
// three-byte-a-pixel coverage a. `vb` >= nb bytes may be read: past nb the coverage is the
// row's zero padding (and the canvas bytes exist), so vector blocks may run over the end.
struct Seg {
    const uint8_t* a;
    const uint8_t* x;
    uint32_t nb, vb;
};

// Over all segments: sa3 += sum a, s[k % 3] += a[k] * x[k]; and dev = sum over the G bytes of
// a * |x - g|. Products a * x fit 16 bits (<= 255 * 255). Scalar, and AVX2 on 48-byte blocks
// (16 pixels), chosen at run time; both give the same integers.
void sums_tail(const uint8_t* a, const uint8_t* x, uint32_t nb, uint64_t& sa3, uint64_t* s) {
    for (uint32_t k = 0; k < nb; k += 3) {
        s[0] += uint32_t(a[k]) * x[k];
        s[1] += uint32_t(a[k + 1]) * x[k + 1];
        s[2] += uint32_t(a[k + 2]) * x[k + 2];
        sa3 += uint32_t(a[k]) + a[k + 1] + a[k + 2];
    }
}

uint64_t dev_tail(const uint8_t* a, const uint8_t* x, uint32_t nb, int g) {
    uint64_t dev = 0;
    for (uint32_t k = 1; k < nb; k += 3) dev += uint64_t(a[k]) * uint64_t(std::abs(int(x[k]) - g));
    return dev;
}

void sums_scalar(const Seg* seg, size_t n, uint64_t& sa3, uint64_t* s) {
    for (size_t i = 0; i < n; ++i) sums_tail(seg[i].a, seg[i].x, seg[i].nb, sa3, s);
}

uint64_t dev_scalar(const Seg* seg, size_t n, int g) {
    uint64_t dev = 0;
    for (size_t i = 0; i < n; ++i) dev += dev_tail(seg[i].a, seg[i].x, seg[i].nb, g);
    return dev;
}

#if defined(__x86_64__) || defined(_M_X64)
#define SPT_CTX_X86 1
// Channel (k % 3) of the byte behind 32-bit lane i of the unpacklo (u = 0) or unpackhi (u = 1)
// of the 16-lane products of the 16 bytes at block offset 16 * c: unpack works per 128-bit half.
constexpr int lane_channel(int c, int u, int i) {
    const int byte = (i < 4 ? i : i + 4) + 4 * u;
    return (16 * c + byte) % 3;
}

// Blocks a segment may run as vectors, and the bytes left for the scalar tail.
inline uint32_t vector_bytes(const Seg& g) { return g.vb >= ((g.nb + 47) / 48) * 48 ? (g.nb + 47) / 48 * 48 : g.nb / 48 * 48; }

__attribute__((target("avx2"))) void sums_flush(__m256i (&acc)[3][2], uint64_t* s) {
    alignas(32) uint32_t lanes[8];
    for (int c = 0; c < 3; ++c)
        for (int u = 0; u < 2; ++u) {
            _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), acc[c][u]);
            for (int i = 0; i < 8; ++i) s[lane_channel(c, u, i)] += lanes[i];
            acc[c][u] = _mm256_setzero_si256();
        }
}

__attribute__((target("avx2"))) uint64_t dev_flush(__m256i& acc) {
    alignas(32) uint32_t lanes[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), acc);
    acc = _mm256_setzero_si256();
    uint64_t d = 0;
    for (uint32_t v : lanes) d += v;
    return d;
}

__attribute__((target("avx2"))) void sums_avx2(const Seg* seg, size_t n, uint64_t& sa3, uint64_t* s) {
    const __m256i z = _mm256_setzero_si256();
    __m256i acc[3][2] = {{z, z}, {z, z}, {z, z}};
    __m128i asum = _mm_setzero_si128();
    // Lane sums stay in 32 bits: one product of at most 255 * 255 per lane and block, and a
    // footprint has far fewer than 2^16 blocks (flushed below every 2^15 blocks anyway).
    uint32_t blocks = 0;
    for (size_t i = 0; i < n; ++i) {
        const uint8_t* a = seg[i].a;
        const uint8_t* x = seg[i].x;
        const uint32_t vb = vector_bytes(seg[i]);
        for (uint32_t k = 0; k < vb; k += 48) {
            for (int c = 0; c < 3; ++c) {
                const __m128i a8 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(a + k + 16 * c));
                const __m128i x8 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(x + k + 16 * c));
                const __m256i p = _mm256_mullo_epi16(_mm256_cvtepu8_epi16(a8), _mm256_cvtepu8_epi16(x8));
                acc[c][0] = _mm256_add_epi32(acc[c][0], _mm256_unpacklo_epi16(p, z));
                acc[c][1] = _mm256_add_epi32(acc[c][1], _mm256_unpackhi_epi16(p, z));
                asum = _mm_add_epi64(asum, _mm_sad_epu8(a8, _mm_setzero_si128()));
            }
            if (++blocks == (1u << 15)) { sums_flush(acc, s); blocks = 0; }
        }
        if (vb < seg[i].nb) sums_tail(a + vb, x + vb, seg[i].nb - vb, sa3, s);
    }
    sums_flush(acc, s);
    sa3 += uint64_t(_mm_cvtsi128_si64(asum)) + uint64_t(_mm_extract_epi64(asum, 1));
}

__attribute__((target("avx2"))) uint64_t dev_avx2(const Seg* seg, size_t n, int g) {
    const __m256i z = _mm256_setzero_si256();
    const __m128i gv = _mm_set1_epi8(char(g));
    // Keeps the G bytes (k % 3 == 1) of each 16-byte piece of a 48-byte block.
    const __m128i keep[3] = {_mm_setr_epi8(0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0),
                             _mm_setr_epi8(-1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1),
                             _mm_setr_epi8(0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0)};
    __m256i acc = z;
    uint64_t dev = 0;
    uint32_t blocks = 0;
    for (size_t i = 0; i < n; ++i) {
        const uint8_t* a = seg[i].a;
        const uint8_t* x = seg[i].x;
        const uint32_t vb = vector_bytes(seg[i]);
        for (uint32_t k = 0; k < vb; k += 48) {
            for (int c = 0; c < 3; ++c) {
                const __m128i a8 = _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(a + k + 16 * c)), keep[c]);
                const __m128i x8 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(x + k + 16 * c));
                const __m128i d8 = _mm_or_si128(_mm_subs_epu8(x8, gv), _mm_subs_epu8(gv, x8));
                const __m256i p = _mm256_mullo_epi16(_mm256_cvtepu8_epi16(a8), _mm256_cvtepu8_epi16(d8));
                acc = _mm256_add_epi32(acc, _mm256_add_epi32(_mm256_unpacklo_epi16(p, z), _mm256_unpackhi_epi16(p, z)));
            }
            if (++blocks == (1u << 14)) { dev += dev_flush(acc); blocks = 0; }
        }
        if (vb < seg[i].nb) dev += dev_tail(a + vb, x + vb, seg[i].nb - vb, g);
    }
    return dev + dev_flush(acc);
}
#endif

using SumsFn = void (*)(const Seg*, size_t, uint64_t&, uint64_t*);
using DevFn = uint64_t (*)(const Seg*, size_t, int);

struct CtxKernels {
    SumsFn sums = sums_scalar;
    DevFn dev = dev_scalar;
};

const CtxKernels& ctx_kernels() {
    static const CtxKernels k = [] {
        CtxKernels r;
#ifdef SPT_CTX_X86
        if (__builtin_cpu_supports("avx2")) { r.sums = sums_avx2; r.dev = dev_avx2; }
#endif
        return r;
    }();
    return k;
}

}  // namespace

FootprintRows::FootprintRows(const Mask& m) : x0(m.x0), y0(m.y0) {
    rows.resize(m.h);
    for (uint32_t j = 0; j < m.h; ++j) {
        const uint8_t* a = m.a.data() + size_t(j) * m.w;
        uint32_t lo = 0, hi = m.w;
        while (lo < hi && a[lo] == 0) ++lo;
        while (hi > lo && a[hi - 1] == 0) --hi;
        Row& r = rows[j];
        r.lo = int32_t(lo);
        r.n = hi - lo;
        r.off = uint32_t(cov3.size());
        for (uint32_t i = lo; i < hi; ++i) cov3.insert(cov3.end(), 3, a[i]);
        cov3.insert(cov3.end(), kRowPad, 0);
    }
}

const FootprintRows& FootprintTable::get(uint8_t set, uint8_t tmpl, uint8_t orient) {
    auto& slot = map_[(uint32_t(set) << 16) | (uint32_t(tmpl) << 8) | orient];
    if (!slot) slot = std::make_unique<FootprintRows>(renderer_.stamp_footprint(set, tmpl, orient));
    return *slot;
}

FootprintMean footprint_mean(const Canvas& canvas, const FootprintRows& fp, int32_t px, int32_t py) {
    FootprintMean m;
    const int64_t W = canvas.width, H = canvas.height;
    const int64_t ox = int64_t(px) + fp.x0, oy = int64_t(py) + fp.y0;
    const int64_t j0 = std::max<int64_t>(0, -oy), j1 = std::min<int64_t>(int64_t(fp.rows.size()), H - oy);
    const uint8_t* canvas_end = canvas.rgb.data() + canvas.rgb.size();
    // The clipped row spans; a span that is not cut on the right may be read on into its
    // coverage's zero padding, as far as the canvas has bytes.
    thread_local std::vector<Seg> segs;
    segs.clear();
    for (int64_t j = j0; j < j1; ++j) {
        const FootprintRows::Row& r = fp.rows[size_t(j)];
        const int64_t xs = ox + r.lo, xe = xs + r.n;
        const int64_t cs = std::max<int64_t>(xs, 0), ce = std::min<int64_t>(xe, W);
        if (cs >= ce) continue;
        Seg g;
        g.a = fp.cov3.data() + r.off + 3 * (cs - xs);
        g.x = canvas.row(uint32_t(oy + j)) + 3 * cs;
        g.nb = uint32_t(3 * (ce - cs));
        g.vb = g.nb;
        if (ce == xe) g.vb = uint32_t(std::min<int64_t>(g.nb + FootprintRows::kRowPad, canvas_end - g.x));
        segs.push_back(g);
    }
    const CtxKernels& kern = ctx_kernels();
    uint64_t sa3 = 0, s[3] = {0, 0, 0};
    kern.sums(segs.data(), segs.size(), sa3, s);
    const int64_t sa = int64_t(sa3 / 3);
    if (sa == 0) return m;
    m.covered = true;
    const uint8_t r = uint8_t((int64_t(s[0]) + sa / 2) / sa), g = uint8_t((int64_t(s[1]) + sa / 2) / sa),
                  b = uint8_t((int64_t(s[2]) + sa / 2) / sa);
    m.mean = Rgb8{r, g, b};
    const int64_t d = int64_t(kern.dev(segs.data(), segs.size(), g));
    m.activity = d < 2 * sa ? 0 : d < 6 * sa ? 1 : d < 16 * sa ? 2 : 3;
    return m;
}

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
    // The luma of the 9x9 window the 7x7 Sobel gradients read, clamped at the canvas edges as
    // the definition's L(x, y) is; then the Sobel filters as their separable halves:
    //   gx(x, y) = V(x + 1, y) - V(x - 1, y),  V(x, y) = L(x, y - 1) + 2 L(x, y) + L(x, y + 1)
    //   gy(x, y) = Hs(x, y + 1) - Hs(x, y - 1), Hs(x, y) = L(x - 1, y) + 2 L(x, y) + L(x + 1, y)
    // (the same sums as the definition, regrouped: integers, so the same values).
    int32_t L[9][9];
    size_t xo[9];
    for (int c = 0; c < 9; ++c) xo[c] = size_t(std::clamp<int64_t>(int64_t(px) - 4 + c, 0, W - 1)) * 3;
    for (int r = 0; r < 9; ++r) {
        const uint8_t* row = canvas.row(uint32_t(std::clamp<int64_t>(int64_t(py) - 4 + r, 0, H - 1)));
        for (int c = 0; c < 9; ++c) {
            const uint8_t* p = row + xo[c];
            L[r][c] = int32_t(p[0]) + 2 * int32_t(p[1]) + int32_t(p[2]);
        }
    }
    int32_t V[9][9], Hs[9][9];
    for (int r = 1; r < 8; ++r)
        for (int c = 0; c < 9; ++c) V[r][c] = L[r - 1][c] + 2 * L[r][c] + L[r + 1][c];
    for (int r = 0; r < 9; ++r)
        for (int c = 1; c < 8; ++c) Hs[r][c] = L[r][c - 1] + 2 * L[r][c] + L[r][c + 1];
    int64_t jxx = 0, jyy = 0, jxy = 0;
    for (int r = 1; r < 8; ++r)
        for (int c = 1; c < 8; ++c) {
            const int64_t gx = V[r][c + 1] - V[r][c - 1];
            const int64_t gy = Hs[r + 1][c] - Hs[r - 1][c];
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
