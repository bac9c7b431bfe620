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

// A one-row target over `px` (n pixels, plus the kernels' padding when `slack`).
spt::raster::BlendTarget row_target(std::vector<uint8_t>& px, int64_t x0, int64_t x1, bool slack) {
    spt::raster::BlendTarget t;
    t.px = px.data() + 3 * size_t(x0);
    t.stride = px.size();
    t.x0 = x0;
    t.x1 = x1;
    t.y0 = 0;
    t.y1 = 1;
    t.slack = slack;
    return t;
}

// The span kernels (the hot loop of render() and draw()) equal blend8 for every
// (dst, src, coverage) with an opaque colour, on every ISA the CPU has.
TEST(RenderMath, SpanKernelsOpaqueEqualBlend8Exhaustively) {
    using spt::raster::BlendIsa;
    for (BlendIsa isa : {BlendIsa::Scalar, BlendIsa::Sse2, BlendIsa::Avx2, BlendIsa::Avx512}) {
        if (!spt::raster::blend_isa_available(isa)) continue;
        spt::raster::force_span_isa(isa);
        std::vector<uint8_t> dst(256 * 3 + spt::raster::kSpanPad), cov(256);
        for (uint32_t src = 0; src < 256; ++src)
            for (uint32_t alpha = 1; alpha < 256; ++alpha) {
                for (uint32_t i = 0; i < 256; ++i) {
                    dst[3 * i] = dst[3 * i + 1] = dst[3 * i + 2] = uint8_t(i);
                    cov[i] = uint8_t(alpha);
                }
                const auto t = row_target(dst, 0, 256, (src + alpha) % 2 == 0);
                spt::raster::blend_cov_row(t, 0, 0, cov.data(), 256, spt::Rgba8{uint8_t(src), uint8_t(src), uint8_t(src), 255});
                for (uint32_t i = 0; i < 256; ++i)
                    ASSERT_EQ(dst[3 * i], spt::blend8(uint8_t(i), uint8_t(src), alpha))
                        << "isa " << int(isa) << " dst " << i << " src " << src << " alpha " << alpha;
            }
    }
    spt::raster::force_span_isa(BlendIsa::Best);
}

// With a translucent colour the kernels first form alpha = (c*A + 127) / 255: every
// (coverage, A) pair, against a sweep of dst/src values.
TEST(RenderMath, SpanKernelsTranslucentEqualSpec) {
    std::vector<uint8_t> dst(256 * 3 + spt::raster::kSpanPad), cov(256);
    for (uint32_t i = 0; i < 256; ++i) cov[i] = uint8_t(i);
    for (uint32_t a = 1; a < 255; ++a)
        for (uint32_t src = 0; src < 256; src += 15) {
            const spt::Rgba8 c{uint8_t(src), uint8_t(src + 1), uint8_t(src + 2), uint8_t(a)};
            for (uint32_t i = 0; i < 256 * 3; ++i) dst[i] = uint8_t(i * 7 + a);
            const std::vector<uint8_t> before = dst;
            spt::raster::blend_cov_row(row_target(dst, 0, 256, false), 0, 0, cov.data(), 256, c);
            const uint8_t rgb[3] = {c.r, c.g, c.b};
            for (uint32_t i = 0; i < 256 * 3; ++i) {
                const uint32_t alpha = (cov[i / 3] * a + 127u) / 255u;
                ASSERT_EQ(dst[i], spt::blend8(before[i], rgb[i % 3], alpha)) << "a " << a << " i " << i;
            }
        }
}

// Every vector path (scalar, SSE2, AVX2 when the CPU has it) on every span length up to 120
// pixels, clipped on both sides, with and without slack: identical to blend8, and nothing
// outside the written pixels moves.
TEST(RenderMath, EverySpanPathEqualsBlend8OnEverySpanLength) {
    using spt::raster::BlendIsa;
    uint32_t seed = 1;
    auto rnd = [&]() { seed = seed * 1103515245u + 12345u; return uint8_t(seed >> 16); };
    for (BlendIsa isa : {BlendIsa::Scalar, BlendIsa::Sse2, BlendIsa::Avx2, BlendIsa::Avx512, BlendIsa::Best}) {
        if (!spt::raster::blend_isa_available(isa)) continue;
        spt::raster::force_span_isa(isa);
        for (int64_t n = 1; n <= 120; ++n)
            for (uint8_t a : {uint8_t(255), uint8_t(200), uint8_t(1)})
                for (bool slack : {false, true}) {
                    std::vector<uint8_t> dst(3 * 140 + spt::raster::kSpanPad);
                    std::vector<uint8_t> cov{};
                    cov.resize(size_t(n));
                    for (auto& v : dst) v = rnd();
                    for (auto& v : cov) v = uint8_t(rnd() | 1);  // no zero ends: the span is all of it
                    const spt::Rgba8 c{17, 200, 99, a};
                    const int64_t x = 5, x0 = n > 8 ? 6 : 0, x1 = n > 16 ? x + n - 2 : 140;
                    std::vector<uint8_t> expect = dst;
                    for (int64_t p = std::max(x, x0); p < std::min(x + n, x1); ++p) {
                        const uint32_t al = (cov[size_t(p - x)] * uint32_t(a) + 127u) / 255u;
                        const uint8_t rgb[3] = {c.r, c.g, c.b};
                        for (int k = 0; k < 3; ++k) {
                            uint8_t& d = expect[3 * size_t(p) + size_t(k)];
                            d = spt::blend8(d, rgb[k], al);
                        }
                    }
                    spt::raster::blend_cov_row(row_target(dst, x0, x1, slack), x, 0, cov.data(), n, c);
                    // With slack the kernels may rewrite the padding past x1 (nobody reads it).
                    const size_t checked = slack ? 3 * size_t(x1) : dst.size();
                    ASSERT_TRUE(std::equal(dst.begin(), dst.begin() + long(checked), expect.begin()))
                        << "isa " << int(isa) << " n " << n << " a " << int(a) << " slack " << slack;
                }
    }
    spt::raster::force_span_isa(BlendIsa::Best);
}

}  // namespace

// The dense-box kernel (blend_dense, used by render() for narrow stamps): every (dst, colour,
// coverage) triple for an opaque colour (its vpmaddubsw form), and a sweep of translucent
// alphas, on one- and two-step rows; bytes outside a row's span keep their value.
TEST(RenderMath, DenseKernelEqualsBlend8Exhaustively) {
    for (uint32_t width : {21u, 42u}) {
        spt::raster::SpanMask m;
        std::vector<uint8_t> cov(width);
        for (uint32_t j = 0; j < 256; ++j) {
            std::fill(cov.begin(), cov.end(), uint8_t(j));
            cov[0] = 1;  // keeps the span the whole row
            spt::raster::span_mask_add_row(m, cov.data(), width, 0);
        }
        m.w = width;
        spt::raster::span_mask_make_dense(m);
        ASSERT_EQ(m.dense_steps, width == 21 ? 1u : 2u);
        const size_t stride = 64 * m.dense_steps;
        std::vector<uint8_t> px(256 * stride);
        for (uint32_t a : {255u, 254u, 128u, 1u})
            for (uint32_t src = 0; src < 256; src += a == 255 ? 1 : 5)
                for (uint32_t offset : {0u, 126u, 252u}) {
                    for (size_t j = 0; j < 256; ++j)
                        for (size_t b = 0; b < stride; ++b) px[j * stride + b] = uint8_t(offset + b + (b >= 3 * width ? j : 0));
                    const std::vector<uint8_t> before = px;
                    spt::raster::PlacedSpans p;
                    p.dense = m.dense.data();
                    p.dense_steps = m.dense_steps;
                    p.h = 256;
                    p.c = spt::Rgba8{uint8_t(src), uint8_t(src ^ 0x55), uint8_t(255 - src), uint8_t(a)};
                    if (!spt::raster::blend_dense(px.data(), stride, p, 0, 256)) GTEST_SKIP() << "no AVX-512 dense kernel here";
                    const uint8_t rgb[3] = {p.c.r, p.c.g, p.c.b};
                    for (size_t j = 0; j < 256; ++j)
                        for (size_t b = 0; b < stride; ++b) {
                            const uint32_t c = b < 3 * width ? (b < 3 ? 1u : uint32_t(j)) : 0u;
                            const uint32_t al = (c * a + 127u) / 255u;
                            ASSERT_EQ(px[j * stride + b], spt::blend8(before[j * stride + b], rgb[b % 3], al))
                                << "width " << width << " a " << a << " src " << src << " row " << j << " byte " << b;
                        }
                }
    }
}

// blend_dense on a row range (render() clips a dense box to the tile's rows): only rows
// [j0, j1) of the box are drawn, row j0 at the origin given.
TEST(RenderMath, DenseKernelDrawsOnlyTheRowsAsked) {
    spt::raster::SpanMask m;
    std::vector<uint8_t> cov(30);
    for (uint32_t j = 0; j < 40; ++j) {
        for (uint32_t i = 0; i < 30; ++i) cov[i] = uint8_t(1 + (i * 37 + j * 11) % 255);
        spt::raster::span_mask_add_row(m, cov.data(), 30, 0);
    }
    m.w = 30;
    spt::raster::span_mask_make_dense(m);
    const size_t stride = 64 * m.dense_steps;
    std::vector<uint8_t> px(40 * stride);
    for (size_t i = 0; i < px.size(); ++i) px[i] = uint8_t(i * 13);
    const std::vector<uint8_t> before = px;
    spt::raster::PlacedSpans p;
    p.dense = m.dense.data();
    p.dense_steps = m.dense_steps;
    p.h = 40;
    p.c = spt::Rgba8{200, 10, 90, 255};
    if (!spt::raster::blend_dense(px.data() + 17 * stride, stride, p, 17, 23)) GTEST_SKIP() << "no AVX-512 dense kernel here";
    const uint8_t rgb[3] = {p.c.r, p.c.g, p.c.b};
    for (size_t j = 0; j < 40; ++j)
        for (size_t b = 0; b < stride; ++b) {
            const bool drawn = j >= 17 && j < 23 && b < 90;
            const uint32_t c = drawn ? 1 + (uint32_t(b / 3) * 37 + uint32_t(j) * 11) % 255 : 0;
            ASSERT_EQ(px[j * stride + b], spt::blend8(before[j * stride + b], rgb[b % 3], c)) << "row " << j << " byte " << b;
        }
}
