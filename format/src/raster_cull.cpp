// Occlusion bits of a render tile (raster_cull.hpp): a scalar version and an AVX-512 one that
// handles eight rows a step (the bits are stored word-column-major for that). Both give the
// same bits and columns; tests/format/render_cull_test.cpp compares them on random masks.
#include "raster_cull.hpp"

#include <algorithm>
#include <cstring>

#if defined(__x86_64__) || defined(_M_X64)
#include <immintrin.h>
#define SPT_CULL_X86 1
#endif

namespace spt::raster {
namespace {

constexpr int64_t kBias = CullBits::kBias;
constexpr int64_t kSpanBits = 64 * int64_t(CullBits::kWordCols);

// Where word column k of a mask placed at tile column dx lands: bit position q of the rows.
// False when none of its bits falls inside the word columns.
inline bool landing(int64_t dx, uint32_t k, int64_t& q) {
    q = dx + kBias + 64 * int64_t(k);
    return q > -64 && q < kSpanBits;
}

// Bits of columns [a, b) (0 <= a, b <= 128) that fall in the 64 columns starting at base.
inline uint64_t range_word(int64_t a, int64_t b, int64_t base) {
    const int64_t lo = std::clamp<int64_t>(a - base, 0, 64), hi = std::clamp<int64_t>(b - base, 0, 64);
    return hi > lo ? (~uint64_t(0) >> (64 - (hi - lo))) << lo : 0;
}

void mark_scalar(CullBits& bits, const uint64_t* core, uint32_t words, uint32_t rows, uint32_t j0, uint32_t j1,
                 int64_t dx, int64_t r0) {
    const uint32_t n = j1 - j0;
    for (uint32_t k = 0; k < words; ++k) {
        int64_t q;
        if (!landing(dx, k, q)) continue;
        const uint64_t* c = core + size_t(k) * rows + j0;
        if (q < 0) {
            for (uint32_t j = 0; j < n; ++j) bits.w[0][r0 + j] |= c[j] >> -q;
            continue;
        }
        const int64_t wi = q >> 6, sh = q & 63;
        for (uint32_t j = 0; j < n; ++j) bits.w[wi][r0 + j] |= c[j] << sh;
        if (sh && wi + 1 < int64_t(CullBits::kWordCols))
            for (uint32_t j = 0; j < n; ++j) bits.w[wi + 1][r0 + j] |= c[j] >> (64 - sh);
    }
}

void visible_scalar(const CullBits& bits, const uint32_t* extent, uint32_t j0, uint32_t j1, int64_t dx, int64_t r0,
                    int64_t width, uint8_t* cols) {
    for (uint32_t j = j0; j < j1; ++j, ++r0, cols += 2) {
        const int64_t xs = std::max<int64_t>(0, int64_t(extent[j] & 0xFFFF) + dx);
        const int64_t xe = std::min<int64_t>(width, int64_t(extent[j] >> 16) + dx);
        const uint64_t v1 = range_word(xs, xe, 0) & ~bits.w[1][r0];
        const uint64_t v2 = range_word(xs, xe, 64) & ~bits.w[2][r0];
        if ((v1 | v2) == 0) {
            cols[0] = cols[1] = 0;
            continue;
        }
        cols[0] = uint8_t(v1 ? __builtin_ctzll(v1) : 64 + __builtin_ctzll(v2));
        cols[1] = uint8_t(v2 ? 128 - __builtin_clzll(v2) : 64 - __builtin_clzll(v1));
    }
}

// Bit i set when row j0 + i (j1 - j0 <= 64) has a pixel in tile columns [0, width) not yet hidden.
uint64_t rows_scalar(const CullBits& bits, const uint32_t* extent, uint32_t j0, uint32_t j1, int64_t dx, int64_t r0,
                     int64_t width) {
    uint64_t out = 0;
    for (uint32_t j = j0; j < j1; ++j, ++r0) {
        const int64_t xs = std::max<int64_t>(0, int64_t(extent[j] & 0xFFFF) + dx);
        const int64_t xe = std::min<int64_t>(width, int64_t(extent[j] >> 16) + dx);
        if ((range_word(xs, xe, 0) & ~bits.w[1][r0]) | (range_word(xs, xe, 64) & ~bits.w[2][r0]))
            out |= uint64_t(1) << (j - j0);
    }
    return out;
}

// A mask of one word a row (MaskRef::foot set) with its column 0 at bit q = dx + kBias of the
// word columns, 0 <= q < 256: the rows [j0, j1) that have a footprint pixel in a live column
// (live[k]: the bits of word column k that are tile columns) not yet hidden, as bits from
// j0; then, when `opaque`, the core is marked. One pass over the rows for both.
uint64_t narrow_scalar(CullBits& bits, const MaskRef& m, uint32_t j0, uint32_t j1, int64_t dx, int64_t r0,
                       const uint64_t* live, bool opaque) {
    const int64_t q = dx + kBias, wi = q >> 6, sh = q & 63;
    uint64_t out = 0;
    for (uint32_t j = j0; j < j1; ++j, ++r0) {
        const uint64_t f = m.foot[j], c = m.core[j];
        const uint64_t lo = f << sh, hi = sh ? f >> (64 - sh) : 0;
        if ((lo & live[wi] & ~bits.w[wi][r0]) | (hi & live[wi + 1] & ~bits.w[wi + 1][r0])) out |= uint64_t(1) << (j - j0);
        if (opaque) {
            bits.w[wi][r0] |= c << sh;
            if (sh) bits.w[wi + 1][r0] |= c >> (64 - sh);
        }
    }
    return out;
}

// A span-drawn entry (cull_tile): the visible columns of rows [j0, j1) into cols, the rows with
// any as bits from j0 (returned), then, when `opaque`, its core into bits.
uint64_t span_scalar(CullBits& bits, const MaskRef& m, uint32_t j0, uint32_t j1, int64_t dx, int64_t r0,
                     int64_t width, uint8_t* cols, bool opaque) {
    visible_scalar(bits, m.extent, j0, j1, dx, r0, width, cols);
    uint64_t out = 0;
    for (uint32_t i = 0; i < j1 - j0; ++i)
        if (cols[2 * i] < cols[2 * i + 1]) out |= uint64_t(1) << i;
    if (opaque) mark_scalar(bits, m.core, m.core_words, m.h, j0, j1, dx, r0);
    return out;
}

// The tile loop of cull_tile, expanded per ISA so that the kernels inline.
#define SPT_CULL_TILE_LOOP(MARK, SPAN, ROWS, NARROW)                                                            \
    bits.clear();                                                                                               \
    if (plan.ops.size() < n) plan.ops.resize(n);                                                                \
    size_t slots = 0, ops = 0;                                                                                  \
    const int64_t width = t.x1 - t.x0;                                                                          \
    uint64_t live[CullBits::kWordCols];                                                                         \
    for (uint32_t k = 0; k < CullBits::kWordCols; ++k) live[k] = range_word(0, width, 64 * int64_t(k) - kBias); \
    for (uint32_t i = n; i-- > 0;) {                                                                            \
        const TileItem& it = list[i];                                                                           \
        if (it.mask == TileItem::kNoMask || !masks[it.mask].extent) {                                           \
            DrawOp& op = plan.ops[ops++];                                                                       \
            op.kind = DrawOp::Whole;                                                                            \
            op.item = i;                                                                                        \
            continue;                                                                                           \
        }                                                                                                       \
        const MaskRef& p = masks[it.mask];                                                                      \
        const int64_t j0 = std::max<int64_t>(0, t.y0 - it.oy);                                                  \
        const int64_t j1 = std::max(j0, std::min<int64_t>(p.h, t.y1 - it.oy));                                  \
        const int64_t dx = int64_t(it.ox) - t.x0, r0 = it.oy + j0 - t.y0;                                       \
        if (cull_dense(it, p, t)) {                                                                             \
            const bool narrow = p.foot && dx >= -kBias && dx < 4 * 64 - kBias;                                  \
            const uint64_t vis = narrow ? NARROW(bits, p, uint32_t(j0), uint32_t(j1), dx, r0, live, it.c.a == 255) \
                                        : ROWS(bits, p.extent, uint32_t(j0), uint32_t(j1), dx, r0, width);      \
            if (vis) {                                                                                          \
                const int64_t a = __builtin_ctzll(vis);                                                         \
                DrawOp& op = plan.ops[ops++];                                                                   \
                op.kind = DrawOp::Dense;                                                                        \
                op.pairs = p.dense + size_t(j0 + a) * p.dense_steps * 2 * kDenseStep;                           \
                op.dst = int32_t((r0 + a) * t.stride + 3 * dx);                                                 \
                op.vis = vis >> a;                                                                              \
                op.steps = uint8_t(p.dense_steps);                                                              \
                op.c = it.c;                                                                                    \
            }                                                                                                   \
            if (!narrow && it.c.a == 255 && j1 > j0)                                                            \
                MARK(bits, p.core, p.core_words, p.h, uint32_t(j0), uint32_t(j1), dx, r0);                      \
            continue;                                                                                           \
        }                                                                                                       \
        /* Drawn span by span: the visible columns of its rows into a slot of plan.cols (kept only */           \
        /* when a row has any), its core into bits. */                                                          \
        if (plan.cols.size() < (slots + 1) * 2 * CullBits::kRows) plan.cols.resize((slots + 1) * 2 * CullBits::kRows); \
        const uint64_t vis = j1 > j0 ? SPAN(bits, p, uint32_t(j0), uint32_t(j1), dx, r0, width,                 \
                                            &plan.cols[slots * 2 * CullBits::kRows], it.c.a == 255)             \
                                     : 0;                                                                       \
        if (vis) {                                                                                              \
            ++slots;                                                                                            \
            DrawOp& op = plan.ops[ops++];                                                                       \
            op.kind = DrawOp::SpanCols;                                                                         \
            op.item = i;                                                                                        \
            op.vis = vis;                                                                                       \
        }                                                                                                       \
    }                                                                                                           \
    plan.n = ops;                                                                                               \
    plan.slots = slots;

void tile_scalar(CullBits& bits, const TileItem* list, uint32_t n, const MaskRef* masks, const CullTile& t,
                 CullPlan& plan) {
    SPT_CULL_TILE_LOOP(mark_scalar, span_scalar, rows_scalar, narrow_scalar)
}

#ifdef SPT_CULL_X86
// GCC 12 warns that the _mm512_undefined_epi32() inside several AVX-512 intrinsics "may be
// used uninitialized"; it is the intrinsics' own don't-care operand.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#define SPT_CULL_TARGET __attribute__((target("avx512f,avx512bw,avx512cd,avx512vl")))

SPT_CULL_TARGET inline __mmask8 rows_mask(uint32_t left) { return left >= 8 ? __mmask8(0xFF) : __mmask8((1u << left) - 1); }

// OR of src << sh (sh < 0: >> -sh; shifts of 64 or more give 0) into n rows of dst.
SPT_CULL_TARGET inline void or_shifted(uint64_t* dst, const uint64_t* src, uint32_t n, int64_t sh) {
    const __m128i left = _mm_cvtsi64_si128(sh > 0 ? sh : 0), right = _mm_cvtsi64_si128(sh < 0 ? -sh : 0);
    for (uint32_t j = 0; j < n; j += 8) {
        const __mmask8 m = rows_mask(n - j);
        const __m512i v = _mm512_srl_epi64(_mm512_sll_epi64(_mm512_maskz_loadu_epi64(m, src + j), left), right);
        _mm512_mask_storeu_epi64(dst + j, m, _mm512_or_si512(_mm512_maskz_loadu_epi64(m, dst + j), v));
    }
}

// The same for 0 <= sh < 64 into two adjacent word columns: src << sh into lo, the bits
// shifted out (src >> (64 - sh)) into hi; one load of src for both.
SPT_CULL_TARGET inline void or_shifted_pair(uint64_t* lo, uint64_t* hi, const uint64_t* src, uint32_t n, int64_t sh) {
    const __m128i left = _mm_cvtsi64_si128(sh), right = _mm_cvtsi64_si128(64 - sh);
    for (uint32_t j = 0; j < n; j += 8) {
        const __mmask8 m = rows_mask(n - j);
        const __m512i v = _mm512_maskz_loadu_epi64(m, src + j);
        _mm512_mask_storeu_epi64(lo + j, m, _mm512_or_si512(_mm512_maskz_loadu_epi64(m, lo + j), _mm512_sll_epi64(v, left)));
        _mm512_mask_storeu_epi64(hi + j, m, _mm512_or_si512(_mm512_maskz_loadu_epi64(m, hi + j), _mm512_srl_epi64(v, right)));
    }
}

SPT_CULL_TARGET inline void mark_avx512(CullBits& bits, const uint64_t* core, uint32_t words, uint32_t rows, uint32_t j0,
                                 uint32_t j1, int64_t dx, int64_t r0) {
    const uint32_t n = j1 - j0;
    for (uint32_t k = 0; k < words; ++k) {
        int64_t q;
        if (!landing(dx, k, q)) continue;
        const uint64_t* c = core + size_t(k) * rows + j0;
        if (q < 0) {
            or_shifted(&bits.w[0][r0], c, n, q);
            continue;
        }
        const int64_t wi = q >> 6, sh = q & 63;
        if (wi + 1 < int64_t(CullBits::kWordCols))
            or_shifted_pair(&bits.w[wi][r0], &bits.w[wi + 1][r0], c, n, sh);
        else
            or_shifted(&bits.w[wi][r0], c, n, sh);
    }
}

// mark_avx512 for the tile pass: only the two word columns of tile columns (1 and 2) are ever
// tested there (the apron's are for narrow strokes to land in), so wide cores write no others.
SPT_CULL_TARGET inline void mark_tile_avx512(CullBits& bits, const uint64_t* core, uint32_t words, uint32_t rows,
                                             uint32_t j0, uint32_t j1, int64_t dx, int64_t r0) {
    static_assert(kBias == 64 && CullBits::kTileCols == 128, "tile columns are word columns 1 and 2");
    const uint32_t n = j1 - j0;
    for (uint32_t k = 0; k < words; ++k) {
        const int64_t q = dx + kBias + 64 * int64_t(k);  // word k's bit 0 lands on bit q of the rows
        if (q <= 0 || q >= 192) continue;               // nothing in bits [64, 192)
        const uint64_t* c = core + size_t(k) * rows + j0;
        const int64_t wi = q >> 6, sh = q & 63;
        if (wi == 1 && sh)
            or_shifted_pair(&bits.w[1][r0], &bits.w[2][r0], c, n, sh);
        else if (wi == 0)
            or_shifted(&bits.w[1][r0], c, n, sh - 64);  // only the bits shifted out of word 0
        else
            or_shifted(&bits.w[wi][r0], c, n, sh);
    }
}

// The bits of columns [a, b) within one word, a and b already clamped to [0, 64] (an empty
// range shifts by 64, which gives 0).
SPT_CULL_TARGET inline __m512i word_mask(__m512i a, __m512i b) {
    const __m512i len = _mm512_max_epi64(_mm512_sub_epi64(b, a), _mm512_setzero_si512());
    return _mm512_sllv_epi64(_mm512_srlv_epi64(_mm512_set1_epi64(-1), _mm512_sub_epi64(_mm512_set1_epi64(64), len)), a);
}

// The bits of tile columns that rows j .. j + 7 of an extent cover (lanes outside m: none),
// in the two word columns of the tile.
struct RowMasks {
    __m512i m1, m2;
};
SPT_CULL_TARGET inline RowMasks row_masks(const uint32_t* extent, __mmask8 m, __m512i vdx, __m512i vw) {
    const __m512i zero = _mm512_setzero_si512(), k64 = _mm512_set1_epi64(64), low16 = _mm512_set1_epi64(0xFFFF);
    const __m512i e = _mm512_cvtepu32_epi64(_mm256_maskz_loadu_epi32(m, extent));
    const __m512i xs = _mm512_max_epi64(_mm512_add_epi64(_mm512_and_si512(e, low16), vdx), zero);
    const __m512i xe = _mm512_min_epi64(_mm512_add_epi64(_mm512_srli_epi64(e, 16), vdx), vw);
    return {word_mask(_mm512_min_epi64(xs, k64), _mm512_min_epi64(_mm512_max_epi64(xe, zero), k64)),
            word_mask(_mm512_min_epi64(_mm512_max_epi64(_mm512_sub_epi64(xs, k64), zero), k64),
                      _mm512_min_epi64(_mm512_max_epi64(_mm512_sub_epi64(xe, k64), zero), k64))};
}

// The visible columns of eight rows from their visible bits in the two word columns of the
// tile (v1, v2; k1, k2: the rows where each is non-zero): per row lo | hi << 8, [lo, hi) from
// the first to the last visible column, 0, 0 when none; stored for the rows of m.
SPT_CULL_TARGET inline void store_cols(__m512i v1, __m512i v2, __mmask8 k1, __mmask8 k2, __mmask8 m, uint8_t* cols) {
    const __m512i zero = _mm512_setzero_si512();
    // Lowest set bit: 63 - lzcnt(v & -v); highest: 63 - lzcnt(v).
    const __m512i lz1 = _mm512_lzcnt_epi64(_mm512_and_si512(v1, _mm512_sub_epi64(zero, v1)));
    const __m512i lz2 = _mm512_lzcnt_epi64(_mm512_and_si512(v2, _mm512_sub_epi64(zero, v2)));
    __m512i lo = _mm512_mask_mov_epi64(zero, k2, _mm512_sub_epi64(_mm512_set1_epi64(127), lz2));
    lo = _mm512_mask_mov_epi64(lo, k1, _mm512_sub_epi64(_mm512_set1_epi64(63), lz1));
    __m512i hi = _mm512_mask_mov_epi64(zero, k1, _mm512_sub_epi64(_mm512_set1_epi64(64), _mm512_lzcnt_epi64(v1)));
    hi = _mm512_mask_mov_epi64(hi, k2, _mm512_sub_epi64(_mm512_set1_epi64(128), _mm512_lzcnt_epi64(v2)));
    _mm512_mask_cvtepi64_storeu_epi16(cols, m, _mm512_or_si512(lo, _mm512_slli_epi64(hi, 8)));
}

SPT_CULL_TARGET inline void visible_avx512(const CullBits& bits, const uint32_t* extent, uint32_t j0, uint32_t j1, int64_t dx,
                                           int64_t r0, int64_t width, uint8_t* cols) {
    const __m512i vdx = _mm512_set1_epi64(dx), vw = _mm512_set1_epi64(width);
    const uint32_t n = j1 - j0;
    for (uint32_t j = 0; j < n; j += 8) {
        const __mmask8 m = rows_mask(n - j);
        const RowMasks rm = row_masks(extent + j0 + j, m, vdx, vw);
        const __m512i v1 = _mm512_andnot_si512(_mm512_maskz_loadu_epi64(m, &bits.w[1][r0 + j]), rm.m1);
        const __m512i v2 = _mm512_andnot_si512(_mm512_maskz_loadu_epi64(m, &bits.w[2][r0 + j]), rm.m2);
        store_cols(v1, v2, _mm512_test_epi64_mask(v1, v1), _mm512_test_epi64_mask(v2, v2), m, cols + 2 * j);
    }
}

SPT_CULL_TARGET inline uint64_t rows_avx512(const CullBits& bits, const uint32_t* extent, uint32_t j0, uint32_t j1,
                                            int64_t dx, int64_t r0, int64_t width) {
    const __m512i vdx = _mm512_set1_epi64(dx), vw = _mm512_set1_epi64(width);
    uint64_t out = 0;
    const uint32_t n = j1 - j0;
    for (uint32_t j = 0; j < n; j += 8) {
        const __mmask8 m = rows_mask(n - j);
        const RowMasks rm = row_masks(extent + j0 + j, m, vdx, vw);
        const __m512i v = _mm512_or_si512(_mm512_andnot_si512(_mm512_maskz_loadu_epi64(m, &bits.w[1][r0 + j]), rm.m1),
                                          _mm512_andnot_si512(_mm512_maskz_loadu_epi64(m, &bits.w[2][r0 + j]), rm.m2));
        out |= uint64_t(_mm512_mask_test_epi64_mask(m, v, v)) << j;
    }
    return out;
}

SPT_CULL_TARGET inline uint64_t narrow_avx512(CullBits& bits, const MaskRef& mr, uint32_t j0, uint32_t j1, int64_t dx,
                                              int64_t r0, const uint64_t* live, bool opaque) {
    const int64_t q = dx + kBias, wi = q >> 6, sh = q & 63;
    // Per-lane shift counts: one uop a shift (a count in an xmm register takes two); 64 gives 0.
    const __m512i left = _mm512_set1_epi64(sh), right = _mm512_set1_epi64(64 - sh);
    const __m512i live_lo = _mm512_set1_epi64(int64_t(live[wi])), live_hi = _mm512_set1_epi64(int64_t(live[wi + 1]));
    uint64_t* lo = &bits.w[wi][r0];
    uint64_t* hi = &bits.w[wi + 1][r0];
    uint64_t out = 0;
    const uint32_t n = j1 - j0;
    for (uint32_t j = 0; j < n; j += 8) {
        const __mmask8 m = rows_mask(n - j);
        const __m512i f = _mm512_maskz_loadu_epi64(m, mr.foot + j0 + j);
        const __m512i b0 = _mm512_maskz_loadu_epi64(m, lo + j), b1 = _mm512_maskz_loadu_epi64(m, hi + j);
        // (f << sh) & live_lo & ~b0 | (f >> (64 - sh)) & live_hi & ~b1
        const __m512i v0 = _mm512_ternarylogic_epi64(_mm512_sllv_epi64(f, left), live_lo, b0, 0x40);  // a & b & ~c
        const __m512i v1 = _mm512_ternarylogic_epi64(_mm512_srlv_epi64(f, right), live_hi, b1, 0x40);
        out |= uint64_t(_mm512_mask_test_epi64_mask(m, _mm512_or_si512(v0, v1), _mm512_or_si512(v0, v1))) << j;
        if (opaque) {
            const __m512i c = _mm512_maskz_loadu_epi64(m, mr.core + j0 + j);
            _mm512_mask_storeu_epi64(lo + j, m, _mm512_or_si512(b0, _mm512_sllv_epi64(c, left)));
            _mm512_mask_storeu_epi64(hi + j, m, _mm512_or_si512(b1, _mm512_srlv_epi64(c, right)));
        }
    }
    return out;
}

// src << s for s >= 0, src >> -s for s < 0; 0 when |s| >= 64 (per-lane shifts give 0 there).
SPT_CULL_TARGET inline __m512i shift_by(__m512i src, int64_t s) {
    return _mm512_srlv_epi64(_mm512_sllv_epi64(src, _mm512_set1_epi64(s > 0 ? s : 0)), _mm512_set1_epi64(s < 0 ? -s : 0));
}

// span_scalar, eight rows a step. A step whose rows are all hidden (most steps of the big
// strokes a painting starts with) stores no columns and marks nothing: the core lies inside
// the span, so its bits are set already. Only the two word columns of tile columns are marked.
SPT_CULL_TARGET inline uint64_t span_avx512(CullBits& bits, const MaskRef& mr, uint32_t j0, uint32_t j1, int64_t dx,
                                            int64_t r0, int64_t width, uint8_t* cols, bool opaque) {
    static_assert(kBias == 64 && CullBits::kTileCols == 128, "tile columns are word columns 1 and 2");
    const __m512i vdx = _mm512_set1_epi64(dx), vw = _mm512_set1_epi64(width);
    uint64_t out = 0;
    const uint32_t n = j1 - j0;
    for (uint32_t j = 0; j < n; j += 8) {
        const __mmask8 m = rows_mask(n - j);
        const RowMasks rm = row_masks(mr.extent + j0 + j, m, vdx, vw);
        uint64_t* w1 = &bits.w[1][r0 + j];
        uint64_t* w2 = &bits.w[2][r0 + j];
        const __m512i b1 = _mm512_maskz_loadu_epi64(m, w1), b2 = _mm512_maskz_loadu_epi64(m, w2);
        const __m512i v1 = _mm512_andnot_si512(b1, rm.m1), v2 = _mm512_andnot_si512(b2, rm.m2);
        const __mmask8 k1 = _mm512_test_epi64_mask(v1, v1), k2 = _mm512_test_epi64_mask(v2, v2);
        if (!(k1 | k2)) continue;
        out |= uint64_t(k1 | k2) << j;
        store_cols(v1, v2, k1, k2, m, cols + 2 * j);
        if (!opaque) continue;
        __m512i c1 = b1, c2 = b2;
        for (uint32_t k = 0; k < mr.core_words; ++k) {  // word k's bit 0 is tile column dx + 64k
            const __m512i c = _mm512_maskz_loadu_epi64(m, mr.core + size_t(k) * mr.h + j0 + j);
            c1 = _mm512_or_si512(c1, shift_by(c, dx + 64 * int64_t(k)));
            c2 = _mm512_or_si512(c2, shift_by(c, dx + 64 * int64_t(k) - 64));
        }
        _mm512_mask_storeu_epi64(w1, m, c1);
        _mm512_mask_storeu_epi64(w2, m, c2);
    }
    return out;
}

SPT_CULL_TARGET void tile_avx512(CullBits& bits, const TileItem* list, uint32_t n, const MaskRef* masks,
                                 const CullTile& t, CullPlan& plan) {
    SPT_CULL_TILE_LOOP(mark_tile_avx512, span_avx512, rows_avx512, narrow_avx512)
}
#undef SPT_CULL_TARGET
#pragma GCC diagnostic pop
#endif
#undef SPT_CULL_TILE_LOOP

using MarkFn = void (*)(CullBits&, const uint64_t*, uint32_t, uint32_t, uint32_t, uint32_t, int64_t, int64_t);
using VisibleFn = void (*)(const CullBits&, const uint32_t*, uint32_t, uint32_t, int64_t, int64_t, int64_t, uint8_t*);
using TileFn = void (*)(CullBits&, const TileItem*, uint32_t, const MaskRef*, const CullTile&, CullPlan&);

struct CullKernels {
    MarkFn mark;
    VisibleFn visible;
    TileFn tile;
};

CullKernels pick_cull() {
#ifdef SPT_CULL_X86
    const BlendIsa isa = forced_span_isa();
    if ((isa == BlendIsa::Best || isa == BlendIsa::Avx512) && blend_isa_available(BlendIsa::Avx512) &&
        __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512vl"))
        return {mark_avx512, visible_avx512, tile_avx512};
#endif
    return {mark_scalar, visible_scalar, tile_scalar};
}

const CullKernels& cull_kernels() {
    static const CullKernels best = pick_cull();
    if (forced_span_isa() == BlendIsa::Best) return best;
    thread_local CullKernels forced;
    forced = pick_cull();
    return forced;
}

}  // namespace

void CullBits::clear() { std::memset(w, 0, sizeof w); }

void cull_mark(CullBits& bits, const uint64_t* core, uint32_t words, uint32_t rows, uint32_t j0, uint32_t j1,
               int64_t dx, int64_t r0) {
    if (j1 > j0) cull_kernels().mark(bits, core, words, rows, j0, j1, dx, r0);
}

void cull_visible(const CullBits& bits, const uint32_t* extent, uint32_t j0, uint32_t j1, int64_t dx, int64_t r0,
                  int64_t width, uint8_t* cols) {
    if (j1 > j0) cull_kernels().visible(bits, extent, j0, j1, dx, r0, width, cols);
}

void cull_tile(CullBits& bits, const TileItem* list, uint32_t n, const MaskRef* masks, const CullTile& t,
               CullPlan& plan) {
    cull_kernels().tile(bits, list, n, masks, t, plan);
}

}  // namespace spt::raster
