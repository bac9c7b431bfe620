// SPEC 8.6 compositing, the renderer's hot loop. Exact integer arithmetic in 16-bit lanes:
//   alpha = (c * A + 127) / 255,  dst' = (dst * (255 - alpha) + src * alpha + 127) / 255
// where x / 255 == (x + 1 + (x >> 8)) >> 8 for every x <= 65152 (checked exhaustively in
// tests/format/render_math_test.cpp). Every lane of every path computes exactly that, so the
// SSE2, AVX2 and scalar paths give identical bytes and the choice is only about speed.
//
// Spans never write outside [dst, dst + bytes): a span's tail is handled by one last vector
// that ends exactly at the span's end and overlaps the previous one. Both are computed from the
// original pixels, so the overlap is written twice with the same values. Spans shorter than one
// vector go through a small stack copy. This keeps concurrent drawing into disjoint regions of
// one canvas safe.
#include <cstring>

#include "raster.hpp"

#if defined(__x86_64__) || defined(_M_X64)
#include <immintrin.h>
#define SPT_RASTER_X86 1
#endif

namespace spt::raster {
namespace {

inline uint8_t blend_byte(uint8_t d, uint8_t c, uint8_t p, uint32_t a) {
    const uint32_t al = a == 255 ? c : div255(c * a + 127u);
    return uint8_t(div255(d * (255u - al) + p * al + 127u));
}

void span_scalar(uint8_t* dst, const uint8_t* cov, const uint8_t* pat, uint32_t bytes, uint32_t a) {
    for (uint32_t k = 0; k < bytes; ++k) dst[k] = blend_byte(dst[k], cov[k], pat[k], a);
}

#ifdef SPT_RASTER_X86

// Eight 16-bit lanes of the rule.
inline __m128i blend8x16(__m128i d, __m128i c, __m128i p, __m128i a, bool opaque) {
    const __m128i k1 = _mm_set1_epi16(1), k127 = _mm_set1_epi16(127), k255 = _mm_set1_epi16(255);
    __m128i al = c;
    if (!opaque) {
        const __m128i t = _mm_add_epi16(_mm_mullo_epi16(c, a), k127);
        al = _mm_srli_epi16(_mm_add_epi16(_mm_add_epi16(t, k1), _mm_srli_epi16(t, 8)), 8);
    }
    __m128i v = _mm_add_epi16(_mm_mullo_epi16(d, _mm_sub_epi16(k255, al)), _mm_mullo_epi16(p, al));
    v = _mm_add_epi16(v, k127);
    return _mm_srli_epi16(_mm_add_epi16(_mm_add_epi16(v, k1), _mm_srli_epi16(v, 8)), 8);
}

inline __m128i blend16(const uint8_t* dst, const uint8_t* cov, const uint8_t* pat, __m128i a, bool opaque) {
    const __m128i z = _mm_setzero_si128();
    const __m128i d = _mm_loadu_si128(reinterpret_cast<const __m128i*>(dst));
    const __m128i c = _mm_loadu_si128(reinterpret_cast<const __m128i*>(cov));
    const __m128i p = _mm_loadu_si128(reinterpret_cast<const __m128i*>(pat));
    const __m128i lo = blend8x16(_mm_unpacklo_epi8(d, z), _mm_unpacklo_epi8(c, z), _mm_unpacklo_epi8(p, z), a, opaque);
    const __m128i hi = blend8x16(_mm_unpackhi_epi8(d, z), _mm_unpackhi_epi8(c, z), _mm_unpackhi_epi8(p, z), a, opaque);
    return _mm_packus_epi16(lo, hi);
}

inline void span_sse2(uint8_t* dst, const uint8_t* cov, const uint8_t* pat, uint32_t bytes, uint32_t a8) {
    const bool opaque = a8 == 255;
    const __m128i a = _mm_set1_epi16(int16_t(a8));
    if (bytes < 16) {
        // Short spans (stamps under 6 px wide): a vector via a stack copy would stall on
        // store forwarding; bytes one at a time are faster here.
        for (uint32_t k = 0; k < bytes; ++k) dst[k] = blend_byte(dst[k], cov[k], pat[k], a8);
        return;
    }
    const uint32_t last = bytes - 16;
    const __m128i tail = blend16(dst + last, cov + last, pat + last, a, opaque);
    for (uint32_t k = 0; k + 16 <= bytes; k += 16)
        _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + k), blend16(dst + k, cov + k, pat + k, a, opaque));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + last), tail);
}

__attribute__((target("avx2"))) inline __m256i blend16x16(__m256i d, __m256i c, __m256i p, __m256i a, bool opaque) {
    const __m256i k1 = _mm256_set1_epi16(1), k127 = _mm256_set1_epi16(127), k255 = _mm256_set1_epi16(255);
    __m256i al = c;
    if (!opaque) {
        const __m256i t = _mm256_add_epi16(_mm256_mullo_epi16(c, a), k127);
        al = _mm256_srli_epi16(_mm256_add_epi16(_mm256_add_epi16(t, k1), _mm256_srli_epi16(t, 8)), 8);
    }
    __m256i v = _mm256_add_epi16(_mm256_mullo_epi16(d, _mm256_sub_epi16(k255, al)), _mm256_mullo_epi16(p, al));
    v = _mm256_add_epi16(v, k127);
    return _mm256_srli_epi16(_mm256_add_epi16(_mm256_add_epi16(v, k1), _mm256_srli_epi16(v, 8)), 8);
}

// 32 bytes; unpack/pack work per 128-bit half, so the lanes come back in order.
__attribute__((target("avx2"))) inline __m256i blend32(const uint8_t* dst, const uint8_t* cov, const uint8_t* pat,
                                                       __m256i a, bool opaque) {
    const __m256i z = _mm256_setzero_si256();
    const __m256i d = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(dst));
    const __m256i c = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(cov));
    const __m256i p = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(pat));
    const __m256i lo = blend16x16(_mm256_unpacklo_epi8(d, z), _mm256_unpacklo_epi8(c, z), _mm256_unpacklo_epi8(p, z), a, opaque);
    const __m256i hi = blend16x16(_mm256_unpackhi_epi8(d, z), _mm256_unpackhi_epi8(c, z), _mm256_unpackhi_epi8(p, z), a, opaque);
    return _mm256_packus_epi16(lo, hi);
}

__attribute__((target("avx2"))) inline void span_avx2(uint8_t* dst, const uint8_t* cov, const uint8_t* pat,
                                                      uint32_t bytes, uint32_t a8) {
    if (bytes < 32) return span_sse2(dst, cov, pat, bytes, a8);
    const bool opaque = a8 == 255;
    const __m256i a = _mm256_set1_epi16(int16_t(a8));
    const uint32_t last = bytes - 32;
    const __m256i tail = blend32(dst + last, cov + last, pat + last, a, opaque);
    for (uint32_t k = 0; k + 32 <= bytes; k += 32)
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(dst + k), blend32(dst + k, cov + k, pat + k, a, opaque));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(dst + last), tail);
}

#endif  // SPT_RASTER_X86

template <void (*Span)(uint8_t*, const uint8_t*, const uint8_t*, uint32_t, uint32_t)>
inline void rows_with(const RowBatch& b) {
    for (uint32_t j = 0; j < b.rows; ++j) {
        const int32_t lo = b.lo[j] > b.clip_lo ? b.lo[j] : b.clip_lo;
        const int32_t hi = b.hi[j] < b.clip_hi ? b.hi[j] : b.clip_hi;
        if (lo >= hi) continue;
        Span(b.dst + size_t(j) * b.dst_stride + 3 * size_t(b.x_offset + lo), b.cov3 + size_t(j) * b.cov_stride + 3 * size_t(lo),
             b.pattern3, uint32_t(3 * (hi - lo)), b.a);
    }
}

void rows_scalar(const RowBatch& b) { rows_with<span_scalar>(b); }
#ifdef SPT_RASTER_X86
void rows_sse2(const RowBatch& b) { rows_with<span_sse2>(b); }
__attribute__((target("avx2"))) void rows_avx2(const RowBatch& b) { rows_with<span_avx2>(b); }
#endif

using RowsFn = void (*)(const RowBatch&);

RowsFn pick(BlendIsa isa) {
#ifdef SPT_RASTER_X86
    switch (isa) {
        case BlendIsa::Scalar: return rows_scalar;
        case BlendIsa::Sse2: return rows_sse2;
        case BlendIsa::Avx2: return blend_isa_available(BlendIsa::Avx2) ? rows_avx2 : rows_sse2;
        case BlendIsa::Best: return blend_isa_available(BlendIsa::Avx2) ? rows_avx2 : rows_sse2;
    }
#endif
    (void)isa;
    return rows_scalar;
}

}  // namespace

bool blend_isa_available(BlendIsa isa) {
#ifdef SPT_RASTER_X86
    if (isa == BlendIsa::Avx2) return __builtin_cpu_supports("avx2");
    return true;
#else
    return isa == BlendIsa::Scalar || isa == BlendIsa::Best;
#endif
}

void blend_rows(const RowBatch& b, BlendIsa isa) {
    if (isa == BlendIsa::Best) {
        static const RowsFn best = pick(BlendIsa::Best);
        return best(b);
    }
    pick(isa)(b);
}

void blend_row3(uint8_t* dst, const uint8_t* cov3, const uint8_t* pattern3, uint32_t n, uint32_t a) {
    const uint16_t lo = 0, hi = uint16_t(n);
    RowBatch b;
    b.dst = dst;
    b.cov3 = cov3;
    b.pattern3 = pattern3;
    b.lo = &lo;
    b.hi = &hi;
    b.rows = 1;
    b.clip_lo = 0;
    b.clip_hi = int32_t(n);
    b.a = a;
    blend_rows(b, BlendIsa::Best);
}

}  // namespace spt::raster
