// SPEC 8.6 compositing of span masks (raster.hpp: SpanMask, blend_spans), the hot loop of
// whole-frame rendering and of single strokes, in 16-bit lanes:
//   alpha = (c * A + 127) / 255,  dst' = (dst * (255 - alpha) + src * alpha + 127) / 255
// with x / 255 computed as mulhi_epu16(x, 0x8081) >> 7, i.e. (x * 32897) >> 23, which equals
// x / 255 for every x <= 65152 (= 255 * 255 + 127, the largest value here; checked for every
// input in tests/format/render_math_test.cpp). Two instructions instead of four.
//
// Span lengths (bytes = 3 * pixels), AVX2:
//   <= 32     one 16- or 32-byte vector when the target has slack (it may run past the span:
//             the mask's zero padding leaves those pixels unchanged, or they are in the
//             slack); otherwise byte by byte under 16, and two 16-byte vectors at both ends
//             (both computed before either is stored) from 16 to 32.
//   > 32      32-byte vectors, the last one ending exactly at the span's end and computed
//             before the loop overwrites the overlap.
// The SSE2 kernel is the same with 16-byte vectors.
// The colour is a 96-byte r, g, b pattern: a vector at byte offset k of a span reads it from
// offset k % 3.
#include <algorithm>
#include <cstring>


#include "raster.hpp"
#include "raster_cull.hpp"

#if defined(__x86_64__) || defined(_M_X64)
#include <immintrin.h>
#define SPT_SPAN_X86 1
#define SPT_SPAN_SSE2 1
#elif defined(__wasm_simd128__) && defined(__SSE2__)
// WebAssembly SIMD: emscripten maps the SSE2 intrinsics onto it (web/: -msimd128 -msse2), and
// the SSE2 kernel blends 16 bytes a step where the scalar loop did one (the browser's frame time).
#include <emmintrin.h>
#define SPT_SPAN_SSE2 1
#endif

namespace spt::raster {
namespace {

BlendIsa g_forced = BlendIsa::Best;

inline uint8_t blend_byte(uint8_t d, uint8_t c, uint8_t p, uint32_t a) {
    const uint32_t al = a == 255 ? c : div255(c * a + 127u);
    return uint8_t(div255(d * (255u - al) + p * al + 127u));
}

void span_scalar(uint8_t* dst, const uint8_t* cov, const uint8_t* pat, uint32_t bytes, uint32_t a, bool) {
    for (uint32_t k = 0; k < bytes; ++k) dst[k] = blend_byte(dst[k], cov[k], pat[k % 3], a);
}

#ifdef SPT_SPAN_SSE2

template <bool Opaque>
inline __m128i lanes8(__m128i d, __m128i c, __m128i p, __m128i a) {
    const __m128i k127 = _mm_set1_epi16(127), k255 = _mm_set1_epi16(255), m = _mm_set1_epi16(int16_t(0x8081));
    __m128i al = c;
    if (!Opaque) al = _mm_srli_epi16(_mm_mulhi_epu16(_mm_add_epi16(_mm_mullo_epi16(c, a), k127), m), 7);
    const __m128i v = _mm_add_epi16(_mm_add_epi16(_mm_mullo_epi16(d, _mm_sub_epi16(k255, al)), _mm_mullo_epi16(p, al)), k127);
    return _mm_srli_epi16(_mm_mulhi_epu16(v, m), 7);
}

template <bool Opaque>
inline __m128i blend16(const uint8_t* dst, const uint8_t* cov, const uint8_t* pat, __m128i a) {
    const __m128i z = _mm_setzero_si128();
    const __m128i d = _mm_loadu_si128(reinterpret_cast<const __m128i*>(dst));
    const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(cov));
    const __m128i p = _mm_loadu_si128(reinterpret_cast<const __m128i*>(pat));
    return _mm_packus_epi16(lanes8<Opaque>(_mm_unpacklo_epi8(d, z), _mm_unpacklo_epi8(c, z), _mm_unpacklo_epi8(p, z), a),
                            lanes8<Opaque>(_mm_unpackhi_epi8(d, z), _mm_unpackhi_epi8(c, z), _mm_unpackhi_epi8(p, z), a));
}

template <bool Opaque>
inline void span_sse2_t(uint8_t* dst, const uint8_t* cov, const uint8_t* pat, uint32_t bytes, uint32_t a8, bool slack) {
    const __m128i a = _mm_set1_epi16(int16_t(a8));
    if (bytes < 16) {
        if (slack) {
            _mm_storeu_si128(reinterpret_cast<__m128i*>(dst), blend16<Opaque>(dst, cov, pat, a));
        } else {
            for (uint32_t k = 0; k < bytes; ++k) dst[k] = blend_byte(dst[k], cov[k], pat[k % 3], a8);
        }
        return;
    }
    const uint32_t last = bytes - 16;
    const __m128i tail = blend16<Opaque>(dst + last, cov + last, pat + last % 3, a);
    for (uint32_t k = 0; k < last; k += 16)
        _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + k), blend16<Opaque>(dst + k, cov + k, pat + k % 3, a));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + last), tail);
}

void span_sse2(uint8_t* dst, const uint8_t* cov, const uint8_t* pat, uint32_t bytes, uint32_t a, bool slack) {
    if (a == 255) span_sse2_t<true>(dst, cov, pat, bytes, a, slack);
    else span_sse2_t<false>(dst, cov, pat, bytes, a, slack);
}

#endif  // SPT_SPAN_SSE2

#ifdef SPT_SPAN_X86

template <bool Opaque>
__attribute__((target("avx2"))) inline __m256i lanes16(__m256i d, __m256i c, __m256i p, __m256i a) {
    const __m256i k127 = _mm256_set1_epi16(127), k255 = _mm256_set1_epi16(255), m = _mm256_set1_epi16(int16_t(0x8081));
    __m256i al = c;
    if (!Opaque) al = _mm256_srli_epi16(_mm256_mulhi_epu16(_mm256_add_epi16(_mm256_mullo_epi16(c, a), k127), m), 7);
    const __m256i v = _mm256_add_epi16(
        _mm256_add_epi16(_mm256_mullo_epi16(d, _mm256_sub_epi16(k255, al)), _mm256_mullo_epi16(p, al)), k127);
    return _mm256_srli_epi16(_mm256_mulhi_epu16(v, m), 7);
}

template <bool Opaque>
__attribute__((target("avx2"))) inline __m256i blend32(const uint8_t* dst, const uint8_t* cov, const uint8_t* pat, __m256i a) {
    const __m256i z = _mm256_setzero_si256();
    const __m256i d = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(dst));
    const __m256i c = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(cov));
    const __m256i p = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(pat));
    // unpack/pack work per 128-bit half, so the lanes come back in order.
    return _mm256_packus_epi16(
        lanes16<Opaque>(_mm256_unpacklo_epi8(d, z), _mm256_unpacklo_epi8(c, z), _mm256_unpacklo_epi8(p, z), a),
        lanes16<Opaque>(_mm256_unpackhi_epi8(d, z), _mm256_unpackhi_epi8(c, z), _mm256_unpackhi_epi8(p, z), a));
}

// 16 bytes as one chain of 16 lanes (zero-extended), half the work of two 8-lane chains.
template <bool Opaque>
__attribute__((target("avx2"))) inline __m128i blend16y(const uint8_t* dst, const uint8_t* cov, const uint8_t* pat, __m256i a) {
    const __m256i d = _mm256_cvtepu8_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(dst)));
    const __m256i c = _mm256_cvtepu8_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(cov)));
    const __m256i p = _mm256_cvtepu8_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(pat)));
    const __m256i v = lanes16<Opaque>(d, c, p, a);
    return _mm_packus_epi16(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
}

template <bool Opaque>
__attribute__((target("avx2"))) inline void span_avx2_t(uint8_t* dst, const uint8_t* cov, const uint8_t* pat,
                                                        uint32_t bytes, uint32_t a8, bool slack) {
    const __m256i a = _mm256_set1_epi16(int16_t(a8));
    if (bytes <= 32) {
        if (bytes <= 16) {
            if (slack || bytes == 16) {
                _mm_storeu_si128(reinterpret_cast<__m128i*>(dst), blend16y<Opaque>(dst, cov, pat, a));
            } else {
                for (uint32_t k = 0; k < bytes; ++k) dst[k] = blend_byte(dst[k], cov[k], pat[k % 3], a8);
            }
        } else if (slack) {
            // May run up to 15 bytes past the span: padding (coverage 0) or the target's slack.
            _mm256_storeu_si256(reinterpret_cast<__m256i*>(dst), blend32<Opaque>(dst, cov, pat, a));
        } else {
            const uint32_t last = bytes - 16;
            const __m128i head = blend16y<Opaque>(dst, cov, pat, a);
            const __m128i tail = blend16y<Opaque>(dst + last, cov + last, pat + last % 3, a);
            _mm_storeu_si128(reinterpret_cast<__m128i*>(dst), head);
            _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + last), tail);
        }
        return;
    }
    const uint32_t last = bytes - 32;
    const __m256i tail = blend32<Opaque>(dst + last, cov + last, pat + last % 3, a);
    uint32_t ph = 0;  // k % 3; k grows by 32, so the phase by 2 mod 3
    for (uint32_t k = 0; k < last; k += 32) {
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(dst + k), blend32<Opaque>(dst + k, cov + k, pat + ph, a));
        ph = ph == 0 ? 2 : ph - 1;
    }
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(dst + last), tail);
}


// AVX-512BW: 64 bytes a step, the span's end by a byte mask (masked loads and stores touch
// nothing outside the span, so short spans need no slack and no size classes: a span of up to
// 21 pixels is one step).
// floor(u / 255) = ((u + 1) * 257) >> 16 for 0 <= u <= 65534 (a multiply-high and no shift;
// render_math_test checks the kernels against blend8 on every input): each division by 255 below
// adds 128 where SPEC 8.6 adds 127 and takes the high half of a product with 257.
template <bool Opaque>
__attribute__((target("avx512f,avx512bw"))) inline __m512i lanes32(__m512i d, __m512i c, __m512i p, __m512i a) {
    const __m512i k128 = _mm512_set1_epi16(128), k255 = _mm512_set1_epi16(255), m = _mm512_set1_epi16(257);
    __m512i al = c;
    if (!Opaque) al = _mm512_mulhi_epu16(_mm512_add_epi16(_mm512_mullo_epi16(c, a), k128), m);
    const __m512i v = _mm512_add_epi16(
        _mm512_add_epi16(_mm512_mullo_epi16(d, _mm512_sub_epi16(k255, al)), _mm512_mullo_epi16(p, al)), k128);
    return _mm512_mulhi_epu16(v, m);
}

// The vpmaddubsw form of an opaque blend (A = 255, so alpha = coverage c), 64 bytes: with the
// (c, 255 - c) pairs in the unpacklo/unpackhi order and the pixels (sd) and colour (sp) moved
// to signed bytes (x - 128), c * (p - 128) + (255 - c) * (d - 128) = c * p + (255 - c) * d -
// 128 * 255, which lies in [-32640, 32385] (no saturation); adding 32640 + 127 gives the rounded
// numerator of SPEC 8.6 in [127, 65152], divided by 255 as in lanes32 (bias 32640 + 128, then
// the high half of a product with 257).
__attribute__((target("avx512f,avx512bw"))) inline __m512i opaque_pairs64(__m512i pairs_lo, __m512i pairs_hi, __m512i sp,
                                                                          __m512i sd) {
    const __m512i bias = _mm512_set1_epi16(int16_t(32640 + 128)), m = _mm512_set1_epi16(257);
    const __m512i lo = _mm512_maddubs_epi16(pairs_lo, _mm512_unpacklo_epi8(sp, sd));
    const __m512i hi = _mm512_maddubs_epi16(pairs_hi, _mm512_unpackhi_epi8(sp, sd));
    return _mm512_packus_epi16(_mm512_mulhi_epu16(_mm512_add_epi16(lo, bias), m),
                               _mm512_mulhi_epu16(_mm512_add_epi16(hi, bias), m));
}

// Opaque colours: opaque_pairs64, with the (c, 255 - c) pairs formed from the span's coverage.
template <bool Opaque>
__attribute__((target("avx512f,avx512bw"))) inline void span_avx512_t(uint8_t* dst, const uint8_t* cov, const __m512i* pat,
                                                                      uint32_t bytes, uint32_t a8) {
    const __m512i a = _mm512_set1_epi16(int16_t(a8)), z = _mm512_setzero_si512();
    const __m512i k80 = _mm512_set1_epi8(int8_t(0x80)), ones = _mm512_set1_epi8(-1);
    uint32_t ph = 0;  // k % 3; k grows by 64, so the phase by 1 mod 3
    for (uint32_t k = 0; k < bytes; k += 64) {
        const uint32_t n = bytes - k;
        const __mmask64 mask = n >= 64 ? ~__mmask64(0) : (__mmask64(1) << n) - 1;
        const __m512i d = _mm512_maskz_loadu_epi8(mask, dst + k);
        const __m512i c = _mm512_maskz_loadu_epi8(mask, cov + k);
        const __m512i p = pat[ph];
        // unpack/pack work per 128-bit lane, so the bytes come back in order.
        __m512i r;
        if (Opaque) {
            const __m512i nc = _mm512_xor_si512(c, ones);
            r = opaque_pairs64(_mm512_unpacklo_epi8(c, nc), _mm512_unpackhi_epi8(c, nc), _mm512_xor_si512(p, k80),
                               _mm512_xor_si512(d, k80));
        } else {
            r = _mm512_packus_epi16(
                lanes32<Opaque>(_mm512_unpacklo_epi8(d, z), _mm512_unpacklo_epi8(c, z), _mm512_unpacklo_epi8(p, z), a),
                lanes32<Opaque>(_mm512_unpackhi_epi8(d, z), _mm512_unpackhi_epi8(c, z), _mm512_unpackhi_epi8(p, z), a));
        }
        _mm512_mask_storeu_epi8(dst + k, mask, r);
        ph = ph == 2 ? 0 : ph + 1;
    }
}

// A dense box (raster.hpp: SpanMask::dense): Steps full 64-byte steps a row, no masks and no
// size classes, for the rows named by `rows` (bit j: row j from dst; the others are left
// alone). Rows start on a pixel, so the colour pattern has the same phase in every row and is
// prepared once per stroke. Opaque strokes use opaque_pairs64 on the stored pairs.
template <bool Opaque, int Steps>
__attribute__((target("avx512f,avx512bw"))) inline void dense_rows_avx512_t(uint8_t* dst, size_t stride, const uint8_t* pairs,
                                                                            uint64_t rows, const __m512i* pat, uint32_t a8) {
    if (Opaque) {
        const __m512i k80 = _mm512_set1_epi8(int8_t(0x80));
        __m512i ps[Steps];
        for (int s = 0; s < Steps; ++s) ps[s] = _mm512_xor_si512(pat[(64 * s) % 3], k80);
        for (uint64_t left = rows; left; left &= left - 1) {
            const size_t j = size_t(__builtin_ctzll(left));
            uint8_t* const row = dst + j * stride;
            const uint8_t* const pr = pairs + j * 128 * Steps;
            for (int s = 0; s < Steps; ++s) {
                const __m512i d = _mm512_xor_si512(_mm512_loadu_si512(row + 64 * s), k80);
                _mm512_storeu_si512(row + 64 * s, opaque_pairs64(_mm512_loadu_si512(pr + 128 * s),
                                                                 _mm512_loadu_si512(pr + 128 * s + 64), ps[s], d));
            }
        }
    } else {
        // Coverage is the low byte of every (c, 255 - c) pair.
        const __m512i a = _mm512_set1_epi16(int16_t(a8)), z = _mm512_setzero_si512(), low = _mm512_set1_epi16(0xFF);
        __m512i plo[Steps], phi[Steps];
        for (int s = 0; s < Steps; ++s) {
            const __m512i p = pat[(64 * s) % 3];
            plo[s] = _mm512_unpacklo_epi8(p, z);
            phi[s] = _mm512_unpackhi_epi8(p, z);
        }
        for (uint64_t left = rows; left; left &= left - 1) {
            const size_t j = size_t(__builtin_ctzll(left));
            uint8_t* const row = dst + j * stride;
            const uint8_t* const pr = pairs + j * 128 * Steps;
            for (int s = 0; s < Steps; ++s) {
                const __m512i d = _mm512_loadu_si512(row + 64 * s);
                const __m512i clo = _mm512_and_si512(_mm512_loadu_si512(pr + 128 * s), low);
                const __m512i chi = _mm512_and_si512(_mm512_loadu_si512(pr + 128 * s + 64), low);
                _mm512_storeu_si512(row + 64 * s, _mm512_packus_epi16(lanes32<false>(_mm512_unpacklo_epi8(d, z), clo, plo[s], a),
                                                                      lanes32<false>(_mm512_unpackhi_epi8(d, z), chi, phi[s], a)));
            }
        }
    }
}

#endif  // SPT_SPAN_X86

using SpanFn = void (*)(uint8_t*, const uint8_t*, const uint8_t*, uint32_t, uint32_t, bool);

// The colour pattern of the narrower kernels: 96 bytes, byte k channel k % 3; a kernel loads it
// at offset k % 3 to match byte k of a span.
struct Pat96 {
    alignas(32) uint8_t b[96];
    operator uint8_t*() { return b; }
    operator const uint8_t*() const { return b; }
};
void make_pattern(uint8_t* pat96, Rgba4 c) {
    for (int i = 0; i < 32; ++i) {
        pat96[3 * i] = c.r;
        pat96[3 * i + 1] = c.g;
        pat96[3 * i + 2] = c.b;
    }
}

#ifdef SPT_SPAN_X86
// The same with three byte shuffles of the broadcast colour.
__attribute__((target("avx2"))) inline void make_pattern_avx2(uint8_t* pat96, Rgba4 c) {
    uint32_t word;
    std::memcpy(&word, &c, 4);
    const __m256i v = _mm256_set1_epi32(int32_t(word));
    // Byte k of the pattern is channel k % 3; each 128-bit lane shuffles on its own.
    const __m256i i0 = _mm256_setr_epi8(0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0,
                                        1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1);
    const __m256i i1 = _mm256_setr_epi8(2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2,
                                        0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0);
    const __m256i i2 = _mm256_setr_epi8(1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1,
                                        2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2);
    _mm256_store_si256(reinterpret_cast<__m256i*>(pat96), _mm256_shuffle_epi8(v, i0));
    _mm256_store_si256(reinterpret_cast<__m256i*>(pat96 + 32), _mm256_shuffle_epi8(v, i1));
    _mm256_store_si256(reinterpret_cast<__m256i*>(pat96 + 64), _mm256_shuffle_epi8(v, i2));
}

// The colour pattern as three 64-byte vectors, byte k of vector ph being channel (k + ph) % 3,
// made in registers: a pattern stored and reloaded at once (as pat96 is) stalls every stroke
// on a failed store forward (two 32-byte stores, one 64-byte load).
struct Pat512 {
    __m512i p[3];
};
alignas(64) constexpr uint8_t kPhase[66] = {
    0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2,
    0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2};
__attribute__((target("avx512f,avx512bw"))) inline void make_pattern512(Pat512& pat, Rgba4 c) {
    uint32_t word;
    std::memcpy(&word, &c, 4);
    // vpshufb picks within each 128-bit lane; every lane holds the colour in its bytes 0..2.
    const __m512i v = _mm512_set1_epi32(int32_t(word));
    for (int ph = 0; ph < 3; ++ph) pat.p[ph] = _mm512_shuffle_epi8(v, _mm512_loadu_si512(kPhase + ph));
}
#endif

// The loop over a mask's rows, written once and expanded per ISA so that the span kernel
// inlines (a template would not inline an AVX2 kernel into a function without the target).
#define SPT_SPANS_LOOP(SPAN, PATTERN, PAT_T)                                                            \
    PAT_T pat;                                                                                        \
    PATTERN(pat, p.c);                                                                                \
    const int64_t j0 = std::max<int64_t>(0, t.y0 - p.oy), j1 = std::min<int64_t>(p.h, t.y1 - p.oy);   \
    uint8_t* row = t.px + (p.oy + j0 - t.y0) * int64_t(t.stride);                                     \
    for (int64_t j = j0; j < j1; ++j, row += t.stride) {                                              \
        const SpanRow& r = p.rows[j];                                                                 \
        const int64_t s = p.ox + r.lo;                                                                \
        const int64_t xs = std::max<int64_t>(s, t.x0), xe = std::min<int64_t>(s + r.n, t.x1);         \
        if (xs >= xe) continue;                                                                       \
        SPAN(row + 3 * (xs - t.x0), p.cov3 + r.off + 3 * (xs - s), pat, uint32_t(3 * (xe - xs)), p.c.a, t.slack); \
    }

// The same for the rows of `rows` only (bit i: the i-th row inside t), each clipped further to
// its visible columns (blend_spans_cols): a loop over the set bits, not over every row.
#define SPT_SPANS_COLS_LOOP(SPAN, PATTERN, PAT_T)                                                       \
    PAT_T pat;                                                                                        \
    PATTERN(pat, p.c);                                                                                \
    const int64_t j0 = std::max<int64_t>(0, t.y0 - p.oy);                                             \
    uint8_t* const first = t.px + (p.oy + j0 - t.y0) * int64_t(t.stride);                             \
    for (uint64_t left = rows; left; left &= left - 1) {                                              \
        const int64_t i = __builtin_ctzll(left), j = j0 + i;                                          \
        const uint8_t* c = cols + 2 * i;                                                              \
        const int64_t s = p.ox + p.rows[j].lo, xs = t.x0 + c[0];                                      \
        SPAN(first + i * int64_t(t.stride) + 3 * int64_t(c[0]), p.cov3 + p.rows[j].off + 3 * (xs - s), \
             pat, uint32_t(3 * (c[1] - c[0])), p.c.a, t.slack);                                       \
    }

void spans_scalar(const BlendTarget& t, const PlacedSpans& p) { SPT_SPANS_LOOP(span_scalar, make_pattern, Pat96) }
void spans_cols_scalar(const BlendTarget& t, const PlacedSpans& p, const uint8_t* cols, uint64_t rows) {
    SPT_SPANS_COLS_LOOP(span_scalar, make_pattern, Pat96)
}
#ifdef SPT_SPAN_SSE2
void spans_sse2(const BlendTarget& t, const PlacedSpans& p) { SPT_SPANS_LOOP(span_sse2, make_pattern, Pat96) }
void spans_cols_sse2(const BlendTarget& t, const PlacedSpans& p, const uint8_t* cols, uint64_t rows) {
    SPT_SPANS_COLS_LOOP(span_sse2, make_pattern, Pat96)
}
#endif
#ifdef SPT_SPAN_X86
__attribute__((target("avx2"))) inline void span_avx2_inl(uint8_t* dst, const uint8_t* cov, const uint8_t* pat,
                                                          uint32_t bytes, uint32_t a, bool slack) {
    if (a == 255) span_avx2_t<true>(dst, cov, pat, bytes, a, slack);
    else span_avx2_t<false>(dst, cov, pat, bytes, a, slack);
}
__attribute__((target("avx2"))) void span_avx2(uint8_t* dst, const uint8_t* cov, const uint8_t* pat, uint32_t bytes,
                                               uint32_t a, bool slack) {
    span_avx2_inl(dst, cov, pat, bytes, a, slack);
}
__attribute__((target("avx2"))) void spans_avx2(const BlendTarget& t, const PlacedSpans& p) {
    SPT_SPANS_LOOP(span_avx2_inl, make_pattern_avx2, Pat96)
}
__attribute__((target("avx2"))) void spans_cols_avx2(const BlendTarget& t, const PlacedSpans& p, const uint8_t* cols, uint64_t rows) {
    SPT_SPANS_COLS_LOOP(span_avx2_inl, make_pattern_avx2, Pat96)
}
__attribute__((target("avx512f,avx512bw"))) inline void span_avx512_inl(uint8_t* dst, const uint8_t* cov, const Pat512& pat,
                                                                        uint32_t bytes, uint32_t a, bool) {
    if (a == 255) span_avx512_t<true>(dst, cov, pat.p, bytes, a);
    else span_avx512_t<false>(dst, cov, pat.p, bytes, a);
}
__attribute__((target("avx512f,avx512bw"))) void span_avx512(uint8_t* dst, const uint8_t* cov, const uint8_t* pat,
                                                             uint32_t bytes, uint32_t a, bool slack) {
    Pat512 p;
    for (int ph = 0; ph < 3; ++ph) p.p[ph] = _mm512_loadu_si512(pat + ph);
    span_avx512_inl(dst, cov, p, bytes, a, slack);
}
__attribute__((target("avx512f,avx512bw"))) void spans_avx512(const BlendTarget& t, const PlacedSpans& p) {
    SPT_SPANS_LOOP(span_avx512_inl, make_pattern512, Pat512)
}
__attribute__((target("avx512f,avx512bw"))) void spans_cols_avx512(const BlendTarget& t, const PlacedSpans& p,
                                                                   const uint8_t* cols, uint64_t rows) {
    SPT_SPANS_COLS_LOOP(span_avx512_inl, make_pattern512, Pat512)
}
// The run of Dense ops that ends at ops[k - 1], drawn last to first (dense_ops_kernel()): one
// loop over the strokes, with the constants and the call of dense_avx512 out of it.
__attribute__((target("avx512f,avx512bw"))) size_t dense_ops_avx512(uint8_t* origin, size_t stride, const DrawOp* ops,
                                                                    size_t k) {
    while (k > 0 && ops[k - 1].kind == DrawOp::Dense) {
        const DrawOp& op = ops[--k];
        uint32_t word;
        std::memcpy(&word, &op.c, 4);
        const __m512i v = _mm512_set1_epi32(int32_t(word));
        __m512i pat[2];  // phases 0 and 1: a row's first and second step
        pat[0] = _mm512_shuffle_epi8(v, _mm512_loadu_si512(kPhase));
        uint8_t* dst = origin + op.dst;
        if (op.steps == 1) {
            if (op.c.a == 255) dense_rows_avx512_t<true, 1>(dst, stride, op.pairs, op.vis, pat, 255);
            else dense_rows_avx512_t<false, 1>(dst, stride, op.pairs, op.vis, pat, op.c.a);
        } else {
            pat[1] = _mm512_shuffle_epi8(v, _mm512_loadu_si512(kPhase + 1));
            if (op.c.a == 255) dense_rows_avx512_t<true, 2>(dst, stride, op.pairs, op.vis, pat, 255);
            else dense_rows_avx512_t<false, 2>(dst, stride, op.pairs, op.vis, pat, op.c.a);
        }
    }
    return k;
}

__attribute__((target("avx512f,avx512bw"))) void dense_avx512(uint8_t* dst, size_t stride, const uint8_t* cov, uint32_t h,
                                                              uint32_t steps, Rgba4 c) {
    Pat512 pat;
    make_pattern512(pat, c);
    for (uint32_t j = 0; j < h; j += 64, dst += 64 * stride, cov += size_t(64) * 128 * steps) {
        const uint32_t n = std::min<uint32_t>(64, h - j);
        const uint64_t rows = n == 64 ? ~uint64_t(0) : (uint64_t(1) << n) - 1;
        if (c.a == 255) {
            if (steps == 1) dense_rows_avx512_t<true, 1>(dst, stride, cov, rows, pat.p, c.a);
            else dense_rows_avx512_t<true, 2>(dst, stride, cov, rows, pat.p, c.a);
        } else {
            if (steps == 1) dense_rows_avx512_t<false, 1>(dst, stride, cov, rows, pat.p, c.a);
            else dense_rows_avx512_t<false, 2>(dst, stride, cov, rows, pat.p, c.a);
        }
    }
}
#endif
#undef SPT_SPANS_LOOP
#undef SPT_SPANS_COLS_LOOP

using SpansFn = void (*)(const BlendTarget&, const PlacedSpans&);
using DenseFn = void (*)(uint8_t*, size_t, const uint8_t*, uint32_t, uint32_t, Rgba4);

using SpansColsFn = void (*)(const BlendTarget&, const PlacedSpans&, const uint8_t*, uint64_t);

struct Kernels {
    SpansFn spans;
    SpansColsFn spans_cols;
    SpanFn span;
    DenseFn dense;  // nullptr: this ISA has no dense kernel
};

static_assert(kDenseStep == 64 && kDenseMaxSteps == 2, "dense_avx512 handles one or two 64-byte steps a row");

Kernels pick(BlendIsa isa) {
#ifdef SPT_SPAN_X86
    const bool avx2 = blend_isa_available(BlendIsa::Avx2), avx512 = blend_isa_available(BlendIsa::Avx512);
    if (isa == BlendIsa::Scalar) return {spans_scalar, spans_cols_scalar, span_scalar, nullptr};
    if (isa == BlendIsa::Sse2 || !avx2) return {spans_sse2, spans_cols_sse2, span_sse2, nullptr};
    if (isa == BlendIsa::Avx2 || !avx512) return {spans_avx2, spans_cols_avx2, span_avx2, nullptr};
    return {spans_avx512, spans_cols_avx512, span_avx512, dense_avx512};
#elif defined(SPT_SPAN_SSE2)
    if (isa == BlendIsa::Scalar) return {spans_scalar, spans_cols_scalar, span_scalar, nullptr};
    return {spans_sse2, spans_cols_sse2, span_sse2, nullptr};
#else
    (void)isa;
    return {spans_scalar, spans_cols_scalar, span_scalar, nullptr};
#endif
}

const Kernels& kernels() {
    static const Kernels best = pick(BlendIsa::Best);
    if (g_forced == BlendIsa::Best) return best;
    thread_local Kernels forced;
    forced = pick(g_forced);
    return forced;
}

}  // namespace

void force_span_isa(BlendIsa isa) { g_forced = isa; }
BlendIsa forced_span_isa() { return g_forced; }

bool blend_isa_available(BlendIsa isa) {
#ifdef SPT_SPAN_X86
    if (isa == BlendIsa::Avx2) return __builtin_cpu_supports("avx2");
    if (isa == BlendIsa::Avx512) return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("avx512bw");
    return true;
#elif defined(SPT_SPAN_SSE2)
    return isa == BlendIsa::Scalar || isa == BlendIsa::Sse2 || isa == BlendIsa::Best;
#else
    return isa == BlendIsa::Scalar || isa == BlendIsa::Best;
#endif
}

void span_mask_add_row(SpanMask& m, const uint8_t* cov, int64_t n, int64_t first) {
    int64_t lo = 0, hi = n;
    while (lo < hi && cov[lo] == 0) ++lo;
    while (hi > lo && cov[hi - 1] == 0) --hi;
    SpanRow r;
    r.lo = int32_t(first + lo);
    r.n = uint32_t(hi - lo);
    r.off = uint32_t(m.cov3.size());
    if (r.n == 0) r.lo = 0;
    m.cov3.resize(m.cov3.size() + 3 * size_t(r.n) + kSpanPad, 0);
    uint8_t* d = m.cov3.data() + r.off;
    for (int64_t i = lo; i < hi; ++i) d[0] = d[1] = d[2] = cov[i], d += 3;
    m.rows.push_back(r);
}

void span_mask_make_dense(SpanMask& m) {
    const uint32_t row_bytes = 3 * m.w;
    m.dense_steps = 0;
    m.dense.clear();
    if (m.w == 0 || row_bytes > kDenseMaxSteps * kDenseStep) return;
    m.dense_steps = (row_bytes + kDenseStep - 1) / kDenseStep;
    const size_t stride = size_t(m.dense_steps) * kDenseStep;
    std::vector<uint8_t> row(stride);
    m.dense.assign(m.rows.size() * 2 * stride, 0);
    uint8_t* out = m.dense.data();
    for (const SpanRow& r : m.rows) {
        std::fill(row.begin(), row.end(), uint8_t(0));
        if (r.n) std::memcpy(&row[3 * size_t(r.lo)], &m.cov3[r.off], 3 * size_t(r.n));
        // Per 64 bytes: bytes 0-7 of each 16-byte lane as (c, 255 - c) pairs, then bytes 8-15
        // (the order of x86 unpacklo/unpackhi_epi8 on 512-bit vectors).
        for (size_t step = 0; step < stride; step += kDenseStep, out += 2 * kDenseStep)
            for (size_t half = 0; half < 2; ++half)
                for (size_t lane = 0; lane < 4; ++lane)
                    for (size_t i = 0; i < 8; ++i) {
                        const uint8_t c = row[step + 16 * lane + 8 * half + i];
                        out[64 * half + 16 * lane + 2 * i] = c;
                        out[64 * half + 16 * lane + 2 * i + 1] = uint8_t(255 - c);
                    }
    }
}

void span_mask_make_core(SpanMask& m) {
    m.core.clear();
    m.extent.clear();
    m.foot.clear();
    m.core_words = 0;
    if (m.w >= 65536) return;
    if (m.w <= 64) m.foot.assign(m.rows.size(), 0);
    const size_t h = m.rows.size();
    m.core_words = (m.w + 63) / 64;
    m.core.assign(h * m.core_words, 0);
    m.extent.assign(h, 0);
    for (size_t j = 0; j < h; ++j) {
        const SpanRow& r = m.rows[j];
        if (r.n) m.extent[j] = uint32_t(r.lo) | (uint32_t(r.lo) + r.n) << 16;
        for (uint32_t i = 0; i < r.n; ++i) {
            const uint8_t cov = m.cov3[r.off + 3 * size_t(i)];
            const uint32_t col = uint32_t(r.lo) + i;
            if (cov == 255) m.core[(col / 64) * h + j] |= uint64_t(1) << (col % 64);
            if (cov && !m.foot.empty()) m.foot[j] |= uint64_t(1) << col;
        }
    }
}

bool dense_available() { return kernels().dense != nullptr; }
DenseOpsKernel dense_ops_kernel() {
#ifdef SPT_SPAN_X86
    if (kernels().dense == dense_avx512) return dense_ops_avx512;
#endif
    return nullptr;
}

void blend_spans_cols(const BlendTarget& t, const PlacedSpans& p, const uint8_t* cols, uint64_t rows) {
    if (p.c.a == 0) return;
    kernels().spans_cols(t, p, cols, rows);
}

bool blend_dense(uint8_t* origin, size_t stride, const PlacedSpans& p, uint32_t j0, uint32_t j1) {
    const DenseFn fn = kernels().dense;
    if (!fn || !p.dense) return false;
    if (p.c.a != 0 && j1 > j0)
        fn(origin, stride, p.dense + size_t(j0) * p.dense_steps * 2 * kDenseStep, j1 - j0, p.dense_steps, p.c);
    return true;
}

void blend_spans(const BlendTarget& t, const PlacedSpans& p) {
    if (p.c.a == 0) return;
    kernels().spans(t, p);
}

void blend_spans(const BlendTarget& t, const SpanMask& m, int64_t ox, int64_t oy, Rgba4 c) {
    PlacedSpans p;
    p.rows = m.rows.data();
    p.cov3 = m.cov3.data();
    p.ox = int32_t(ox);
    p.oy = int32_t(oy);
    p.h = uint32_t(m.rows.size());
    p.c = c;
    blend_spans(t, p);
}

void blend_cov_row(const BlendTarget& t, int64_t x, int64_t y, const uint8_t* cov, int64_t n, Rgba4 c) {
    if (c.a == 0 || y < t.y0 || y >= t.y1) return;
    int64_t lo = std::max<int64_t>(0, t.x0 - x), hi = std::min<int64_t>(n, t.x1 - x);
    while (lo < hi && cov[lo] == 0) ++lo;
    while (hi > lo && cov[hi - 1] == 0) --hi;
    if (lo >= hi) return;
    // Expanded to three bytes a pixel with the zero padding the kernels may read.
    thread_local std::vector<uint8_t> c3;
    const size_t need = 3 * size_t(hi - lo) + kSpanPad;
    if (c3.size() < need) c3.resize(need);
    uint8_t* d = c3.data();
    for (int64_t i = lo; i < hi; ++i) d[0] = d[1] = d[2] = cov[i], d += 3;
    std::memset(d, 0, kSpanPad);
    alignas(32) uint8_t pat[96];
    make_pattern(pat, c);
    kernels().span(t.px + size_t(y - t.y0) * t.stride + 3 * size_t(x + lo - t.x0), c3.data(), pat, uint32_t(3 * (hi - lo)),
                   c.a, t.slack);
}

}  // namespace spt::raster
