// The renderer's arithmetic shortcuts against the spec's integer formulas, for every input.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "../format/src/raster.hpp"
#include "spt/render.hpp"

namespace {

// The span kernels divide by 255 as mulhi_epu16(x, 0x8081) >> 7 (raster_span.cpp).
TEST(RenderMath, MulhiDiv255EqualsIntegerDivisionOnWholeRange) {
    for (uint32_t x = 0; x <= 255u * 255u + 127u; ++x) ASSERT_EQ(((x * 0x8081u) >> 16) >> 7, x / 255u) << x;
}

TEST(RenderMath, Div255EqualsIntegerDivisionOnWholeRange) {
    // 255 * 255 + 127 is the largest numerator blend8 and the alpha rule produce.
    for (uint32_t x = 0; x <= 255u * 255u + 127u; ++x) ASSERT_EQ(spt::raster::div255(x), x / 255u) << x;
}

TEST(RenderMath, StrokeAlphaEqualsSpecFormula) {
    for (uint32_t c = 0; c < 256; ++c)
        for (uint32_t a = 0; a < 256; ++a) ASSERT_EQ(spt::raster::stroke_alpha(c, a), (c * a + 127u) / 255u);
}

// blend_row3 (the vectorised hot loop) equals blend8 for every (dst, src, alpha) with an
// opaque colour, where alpha is the coverage itself.
TEST(RenderMath, BlendRowOpaqueEqualsBlend8Exhaustively) {
    std::vector<uint8_t> dst(256 * 3), cov3(256 * 3), pat(256 * 3);
    for (uint32_t src = 0; src < 256; ++src) {
        for (uint32_t k = 0; k < pat.size(); ++k) pat[k] = uint8_t(src);
        for (uint32_t alpha = 0; alpha < 256; ++alpha) {
            for (uint32_t i = 0; i < 256; ++i) {
                dst[3 * i] = dst[3 * i + 1] = dst[3 * i + 2] = uint8_t(i);
                cov3[3 * i] = cov3[3 * i + 1] = cov3[3 * i + 2] = uint8_t(alpha);
            }
            spt::raster::blend_row3(dst.data(), cov3.data(), pat.data(), 256, 255);
            for (uint32_t i = 0; i < 256; ++i)
                ASSERT_EQ(dst[3 * i], spt::blend8(uint8_t(i), uint8_t(src), alpha)) << i << " " << src << " " << alpha;
        }
    }
}

// With a translucent colour the row kernel first forms alpha = (c*A + 127) / 255: every
// (coverage, A) pair, against a sweep of dst/src values.
TEST(RenderMath, BlendRowTranslucentEqualsSpec) {
    std::vector<uint8_t> dst(256 * 3), cov3(256 * 3), pat(256 * 3);
    for (uint32_t a = 0; a < 255; ++a) {
        for (uint32_t src = 0; src < 256; src += 15) {
            for (uint32_t k = 0; k < pat.size(); ++k) pat[k] = uint8_t(src + k);
            for (uint32_t i = 0; i < 256 * 3; ++i) {
                dst[i] = uint8_t(i * 7 + a);
                cov3[i] = uint8_t(i / 3);
            }
            const std::vector<uint8_t> before = dst;
            spt::raster::blend_row3(dst.data(), cov3.data(), pat.data(), 256, a);
            for (uint32_t i = 0; i < 256 * 3; ++i) {
                const uint32_t alpha = (cov3[i] * a + 127u) / 255u;
                ASSERT_EQ(dst[i], (before[i] * (255u - alpha) + pat[i] * alpha + 127u) / 255u);
            }
        }
    }
}

// Every vector path (scalar, SSE2, AVX2 when the CPU has it) on every span length up to 120
// pixels, with clipping on both sides: identical to blend8, and nothing outside the span moves.
TEST(RenderMath, EveryBlendPathEqualsBlend8OnEverySpanLength) {
    using spt::raster::BlendIsa;
    uint32_t seed = 1;
    auto rnd = [&]() { seed = seed * 1103515245u + 12345u; return uint8_t(seed >> 16); };
    for (BlendIsa isa : {BlendIsa::Scalar, BlendIsa::Sse2, BlendIsa::Avx2, BlendIsa::Best}) {
        if (!spt::raster::blend_isa_available(isa)) continue;
        for (uint16_t n = 1; n <= 120; ++n)
            for (uint32_t a : {255u, 200u, 1u}) {
                std::vector<uint8_t> dst(3 * 140), cov3(3 * 140), pat(3 * 140);
                for (auto& v : dst) v = rnd();
                for (size_t i = 0; i < 140; ++i) cov3[3 * i] = cov3[3 * i + 1] = cov3[3 * i + 2] = rnd();
                for (size_t i = 0; i < pat.size(); ++i) pat[i] = uint8_t(i % 3 == 0 ? 17 : i % 3 == 1 ? 200 : 99);
                const uint16_t lo = 3, hi = uint16_t(3 + n);
                spt::raster::RowBatch b;
                b.dst = dst.data();
                b.x_offset = 5;
                b.cov3 = cov3.data();
                b.pattern3 = pat.data();
                b.lo = &lo;
                b.hi = &hi;
                b.rows = 1;
                b.clip_lo = n > 8 ? 4 : 0;            // clip the first pixel of longer spans
                b.clip_hi = n > 16 ? hi - 2 : 1000;    // and the last two
                b.a = a;
                std::vector<uint8_t> expect = dst;
                const int32_t from = std::max<int32_t>(lo, b.clip_lo), to = std::min<int32_t>(hi, b.clip_hi);
                for (int32_t c = from; c < to; ++c)
                    for (int k = 0; k < 3; ++k) {
                        const uint32_t al = (cov3[3 * size_t(c) + size_t(k)] * a + 127u) / 255u;
                        uint8_t& d = expect[3 * size_t(5 + c) + size_t(k)];
                        d = spt::blend8(d, pat[3 * size_t(c - from) + size_t(k)], al);
                    }
                spt::raster::blend_rows(b, isa);
                ASSERT_EQ(dst, expect) << "isa " << int(isa) << " n " << n << " a " << a;
            }
    }
}

}  // namespace
