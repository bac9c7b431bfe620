// Occlusion culling of whole-frame rendering (format/src/raster_cull.hpp): the bit kernels
// against a pixel-by-pixel model on every ISA, and tiled renders of painter-like frames (opaque
// strokes coarse to fine, most of the coarse ones hidden) against drawing stroke by stroke.
#include <gtest/gtest.h>

#include <random>

#include "../format/src/raster_cull.hpp"
#include "format/render_test_util.hpp"

namespace {

using namespace spt_test;
using spt::raster::BlendIsa;
using spt::raster::CullBits;

constexpr int64_t kCols = 64 * int64_t(CullBits::kWordCols);  // model columns: tile column + kBias

// The model: one bool a pixel of the span of the bits.
struct Model {
    bool px[CullBits::kRows][kCols] = {};
    bool at(int64_t r, int64_t tile_col) const { return px[r][tile_col + CullBits::kBias]; }
};

bool same(const CullBits& b, const Model& m) {
    for (uint32_t r = 0; r < CullBits::kRows; ++r)
        for (int64_t c = 0; c < kCols; ++c)
            if (((b.w[c / 64][r] >> (c % 64)) & 1) != uint64_t(m.px[r][c])) return false;
    return true;
}

struct RandomMask {
    uint32_t w = 0, rows = 0, words = 0;
    std::vector<uint64_t> core;    // word-column-major, like SpanMask::core
    std::vector<uint32_t> extent;  // lo | hi << 16
};

RandomMask random_mask(std::mt19937& rng) {
    RandomMask m;
    m.w = 1 + rng() % 200;
    m.rows = 1 + rng() % 70;
    m.words = (m.w + 63) / 64;
    m.core.assign(size_t(m.words) * m.rows, 0);
    m.extent.assign(m.rows, 0);
    for (uint32_t j = 0; j < m.rows; ++j) {
        if (rng() % 8 == 0) continue;  // empty row
        const uint32_t lo = rng() % m.w, hi = lo + 1 + rng() % (m.w - lo);
        m.extent[j] = lo | hi << 16;
        const uint32_t a = lo + rng() % (hi - lo), b = a + rng() % (hi - a + 1);
        for (uint32_t c = a; c < b; ++c)
            if (rng() % 16) m.core[size_t(c / 64) * m.rows + j] |= uint64_t(1) << (c % 64);
    }
    return m;
}

TEST(RenderCull, KernelsMatchAPixelModelOnEveryIsa) {
    for (BlendIsa isa : {BlendIsa::Scalar, BlendIsa::Avx512}) {
        if (!spt::raster::blend_isa_available(isa)) continue;
        spt::raster::force_span_isa(isa);
        std::mt19937 rng(1234);
        for (int round = 0; round < 300; ++round) {
            CullBits bits;
            bits.clear();
            Model model;
            for (int s = 0; s < 12; ++s) {
                const RandomMask m = random_mask(rng);
                const uint32_t j0 = rng() % m.rows, j1 = j0 + rng() % (m.rows - j0 + 1);
                if (j1 - j0 > CullBits::kRows) continue;
                const int64_t r0 = int64_t(rng() % (CullBits::kRows - (j1 - j0) + 1));
                const int64_t dx = int64_t(rng() % 500) - 250, width = 1 + int64_t(rng() % 128);
                // Visible columns first (against the strokes marked so far), then the mark.
                std::vector<uint8_t> cols(2 * (j1 - j0), 77);
                spt::raster::cull_visible(bits, m.extent.data(), j0, j1, dx, r0, width, cols.data());
                for (uint32_t j = j0; j < j1; ++j) {
                    const int64_t lo = int64_t(m.extent[j] & 0xFFFF) + dx, hi = int64_t(m.extent[j] >> 16) + dx;
                    int64_t first = -1, last = -1;
                    for (int64_t c = std::max<int64_t>(lo, 0); c < std::min(hi, width); ++c)
                        if (!model.at(r0 + (j - j0), c)) {
                            if (first < 0) first = c;
                            last = c;
                        }
                    const uint8_t* got = &cols[2 * (j - j0)];
                    if (first < 0) {
                        ASSERT_EQ(got[0], 0) << "row " << j;
                        ASSERT_EQ(got[1], 0) << "row " << j;
                    } else {
                        ASSERT_EQ(got[0], first) << "isa " << int(isa) << " round " << round << " row " << j;
                        ASSERT_EQ(got[1], last + 1) << "isa " << int(isa) << " round " << round << " row " << j;
                    }
                }
                spt::raster::cull_mark(bits, m.core.data(), m.words, m.rows, j0, j1, dx, r0);
                for (uint32_t j = j0; j < j1; ++j)
                    for (uint32_t c = 0; c < m.w; ++c) {
                        const int64_t mc = dx + c + CullBits::kBias;
                        if ((m.core[size_t(c / 64) * m.rows + j] >> (c % 64) & 1) && mc >= 0 && mc < kCols)
                            model.px[r0 + (j - j0)][mc] = true;
                    }
                ASSERT_TRUE(same(bits, model)) << "isa " << int(isa) << " round " << round << " stroke " << s;
            }
        }
    }
    spt::raster::force_span_isa(BlendIsa::Best);
}

// A painting's structure: strokes from coarse to fine, mostly opaque, so that nearly all of
// the coarse strokes' pixels are hidden, including strokes that cross tile edges.
std::vector<spt::Stroke> painting(std::mt19937& rng, const spt::Header& h, size_t ntemplates, int n) {
    std::vector<spt::Stroke> v;
    for (int i = 0; i < n; ++i) {
        const uint8_t set = uint8_t(size_t(i) * h.sets.size() / size_t(n));
        const uint8_t a = rng() % 10 == 0 ? uint8_t(rng() % 255) : uint8_t(255);
        v.push_back(stamp(set, uint8_t(rng() % ntemplates), uint8_t(rng() % h.orientations.size()),
                          int32_t(rng() % (16 * h.width + 800)) - 400, int32_t(rng() % (16 * h.height + 800)) - 400,
                          {uint8_t(rng()), uint8_t(rng()), uint8_t(rng()), a}));
    }
    return v;
}

TEST(RenderCull, PaintingRendersAsDrawnStrokeByStroke) {
    std::mt19937 rng(77);
    const std::vector<spt::Template> t = {analytic(spt::TemplateKind::Rectangle), analytic(spt::TemplateKind::Ellipse),
                                          bitmap(3, 3, {0, 255, 0, 255, 255, 255, 90, 255, 200})};
    for (auto [w, hh] : {std::pair<uint32_t, uint32_t>{300, 200}, {129, 65}}) {
        auto hd = make_header(w, hh, {{150, 70}, {72, 36}, {34, 17}, {17, 8}, {8, 4}}, 8);
        auto r = make_renderer(hd, t);
        const auto v = painting(rng, hd, t.size(), 3000);
        spt::Canvas expect(hd.width, hd.height, hd.background);
        for (const auto& s : v) ASSERT_TRUE(r->draw(expect, s).ok());
        for (BlendIsa isa : {BlendIsa::Scalar, BlendIsa::Sse2, BlendIsa::Avx2, BlendIsa::Avx512}) {
            if (!spt::raster::blend_isa_available(isa)) continue;
            spt::raster::force_span_isa(isa);
            for (unsigned threads : {1u, 2u}) {
                spt::Canvas got;
                ASSERT_TRUE(r->render(got, v, threads).ok());
                ASSERT_EQ(got.rgb, expect.rgb) << w << "x" << hh << " isa " << int(isa) << " threads " << threads;
            }
        }
        spt::raster::force_span_isa(BlendIsa::Best);
    }
}

}  // namespace
