// Whole-frame (tiled, optionally threaded) rendering against the simplest correct composition:
// fill the background, then draw() every stroke onto the whole canvas. Random frames of every
// stroke kind, size and alpha, many strokes partly or wholly off the canvas, canvas sizes that
// are and are not multiples of the tile size, every span kernel.
#include <gtest/gtest.h>

#include <random>

#include "../format/src/raster.hpp"
#include "../format/src/render_impl.hpp"
#include "format/render_test_util.hpp"

namespace {

using namespace spt_test;
using i64 = int64_t;

std::vector<spt::Template> templates(std::mt19937& rng) {
    std::vector<spt::Template> t = {analytic(spt::TemplateKind::Ellipse), analytic(spt::TemplateKind::Rectangle),
                                    analytic(spt::TemplateKind::Triangle)};
    for (auto [w, h] : {std::pair{1, 1}, {5, 9}, {32, 32}}) {
        std::vector<uint8_t> px(size_t(w * h));
        for (auto& p : px) p = uint8_t(rng() % 3 == 0 ? 0 : rng() % 256);
        t.push_back(bitmap(uint16_t(w), uint16_t(h), std::move(px)));
    }
    return t;
}

std::vector<spt::Stroke> frame(std::mt19937& rng, const spt::Header& h, size_t ntemplates, int n) {
    auto U = [&](i64 lo, i64 hi) { return std::uniform_int_distribution<i64>(lo, hi)(rng); };
    const i64 W = i64(h.width) * 16, H = i64(h.height) * 16;
    std::vector<spt::Stroke> v;
    for (int i = 0; i < n; ++i) {
        const int al = int(U(0, 9));
        const spt::Rgba8 c{uint8_t(U(0, 255)), uint8_t(U(0, 255)), uint8_t(U(0, 255)),
                           uint8_t(al < 5 ? 255 : al == 5 ? 0 : U(1, 254))};
        const int kind = int(U(0, 9));
        if (kind < 6) {
            v.push_back(stamp(uint8_t(U(0, i64(h.sets.size()) - 1)), uint8_t(U(0, i64(ntemplates) - 1)),
                              uint8_t(U(0, i64(h.orientations.size()) - 1)), int32_t(U(-3000, W + 3000)),
                              int32_t(U(-3000, H + 3000)), c));
        } else if (kind < 8) {
            const i64 sc = U(0, 4) == 0 ? 2500 : 300;
            int32_t m[4];
            for (int32_t& e : m) e = int32_t(U(-sc, sc));
            v.push_back(affine(uint8_t(U(0, i64(ntemplates) - 1)), int32_t(U(-2000, W + 2000)),
                               int32_t(U(-2000, H + 2000)), m[0], m[1], m[2], m[3], c));
        } else {
            std::vector<spt::CurvePoint> pts;
            i64 x = U(-500, W + 500), y = U(-500, H + 500);
            for (int k = int(U(1, 6)); k > 0; --k) {
                pts.push_back({int32_t(x), int32_t(y), uint32_t(U(0, 400))});
                x += U(-1500, 1500);
                y += U(-1500, 1500);
            }
            v.push_back(curve(std::move(pts), c));
        }
    }
    return v;
}

spt::Canvas draw_loop(const spt::Renderer& r, const spt::Header& h, const std::vector<spt::Stroke>& v) {
    spt::Canvas c(h.width, h.height, h.background);
    for (const auto& s : v) EXPECT_TRUE(r.draw(c, s).ok());
    return c;
}

TEST(RenderTiles, TiledRenderEqualsDrawLoopOnRandomFrames) {
    std::mt19937 rng(99);
    const auto t = templates(rng);
    // Sizes around the 128 x 64 tile: smaller, exact multiples, one past, odd.
    const std::pair<uint32_t, uint32_t> sizes[] = {{1, 1}, {37, 5}, {128, 64}, {129, 65}, {300, 170}, {256, 200}, {700, 33}};
    for (auto [w, hh] : sizes) {
        auto hd = make_header(w, hh, {{300, 120}, {64, 20}, {12, 6}, {4, 4}, {1, 1}}, 8);
        hd.background = {uint8_t(w), 90, uint8_t(hh)};
        hd.orientations.push_back({-16385, -7});  // legal but longer than unit
        auto r = make_renderer(hd, t);
        const auto v = frame(rng, hd, t.size(), 400);
        const spt::Canvas expect = draw_loop(*r, hd, v);
        for (unsigned threads : {1u, 2u, 3u, 0u}) {
            spt::Canvas got;
            ASSERT_TRUE(r->render(got, v, threads).ok());
            ASSERT_EQ(got.width, w);
            ASSERT_EQ(got.height, hh);
            ASSERT_EQ(got.rgb, expect.rgb) << w << "x" << hh << " threads " << threads;
        }
        spt::Canvas got(5, 5, {1, 2, 3});  // wrong size on entry: render() resizes
        ASSERT_TRUE(r->render(got, v).ok());
        ASSERT_EQ(got.rgb, expect.rgb);
    }
}

TEST(RenderTiles, EverySpanKernelGivesTheSameBytes) {
    using spt::raster::BlendIsa;
    std::mt19937 rng(5);
    const auto t = templates(rng);
    auto hd = make_header(260, 140, {{90, 40}, {24, 10}, {6, 3}, {2, 2}}, 16);
    auto r = make_renderer(hd, t);
    const auto v = frame(rng, hd, t.size(), 800);
    spt::raster::force_span_isa(BlendIsa::Scalar);
    const spt::Canvas expect = draw_loop(*r, hd, v);
    spt::Canvas scalar_tiles;
    ASSERT_TRUE(r->render(scalar_tiles, v).ok());
    ASSERT_EQ(scalar_tiles.rgb, expect.rgb);
    for (BlendIsa isa : {BlendIsa::Sse2, BlendIsa::Avx2, BlendIsa::Avx512, BlendIsa::Best}) {
        if (!spt::raster::blend_isa_available(isa)) continue;
        spt::raster::force_span_isa(isa);
        spt::Canvas tiles;
        ASSERT_TRUE(r->render(tiles, v).ok());
        EXPECT_EQ(tiles.rgb, expect.rgb) << int(isa);
        EXPECT_EQ(draw_loop(*r, hd, v).rgb, expect.rgb) << int(isa);
    }
    spt::raster::force_span_isa(BlendIsa::Best);
}

TEST(RenderTiles, BadStrokeStopsAfterDrawingTheOnesBefore) {
    std::mt19937 rng(8);
    const auto t = templates(rng);
    auto hd = make_header(200, 100, {{30, 12}}, 8);
    auto r = make_renderer(hd, t);
    auto v = frame(rng, hd, t.size(), 50);
    const std::vector<spt::Stroke> before(v.begin(), v.begin() + 20);
    v.insert(v.begin() + 20, stamp(3, 0, 0, 100, 100, {0, 0, 0, 255}));  // set 3 does not exist
    spt::Canvas got;
    const spt::Status st = r->render(got, v, 2);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("stroke 20"), std::string::npos) << st.error().message;
    EXPECT_EQ(got.rgb, draw_loop(*r, hd, before).rgb);
}

TEST(RenderTiles, HugeFootprintIsDrawnUncachedWithinBudget) {
    // 4096 x 4096 at 45 degrees: ~100 MB at 3 bytes a pixel, over the per-footprint limit.
    auto hd = make_header(150, 90, {{4096, 4096}, {4000, 90}, {20, 10}}, 8);
    auto r = make_renderer(hd, {analytic(spt::TemplateKind::Ellipse), analytic(spt::TemplateKind::Triangle)});
    std::vector<spt::Stroke> v;
    for (uint8_t o = 0; o < 8; ++o)
        for (uint8_t set = 0; set < 3; ++set)
            v.push_back(stamp(set, uint8_t(o % 2), o, 16 * (o * 40 - 100) + 3, 16 * (o * 30 - 60) + 11,
                              {uint8_t(30 * o), uint8_t(80 * set), 200, uint8_t(o % 3 ? 255 : 120)}));
    spt::Canvas got;
    ASSERT_TRUE(r->render(got, v).ok());
    EXPECT_LT(r->footprint_cache_bytes(), spt::RendererImpl::kFootprintCacheBytes);
    EXPECT_LT(r->footprint_cache_bytes(), size_t(64) << 20);
    // Uncached stamps take the inverse-map path in both; render_reference_test checks the
    // pixels against the spec's formulas.
    EXPECT_EQ(got.rgb, draw_loop(*r, hd, v).rgb);
}

}  // namespace

// Binning sorts a stroke into up to 2 x 2 tiles without a branch on how many: thousands of small
// stamps on a 3 x 3-tile canvas, placed across tile edges and corners in every direction and in
// every order (so that some reach a tile whose list is already complete), must draw as the
// draw loop does.
TEST(RenderTiles, SmallStrokesAcrossTileEdgesAndCorners) {
    std::mt19937 rng(7);
    auto U = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
    const auto t = templates(rng);
    auto hd = make_header(384, 192, {{12, 6}, {4, 4}, {30, 14}}, 8);
    auto r = make_renderer(hd, t);
    // Dense frames, and sparse ones where a tile's first strokes stay visible.
    for (int round = 0; round < 64; ++round) {
        std::vector<spt::Stroke> v;
        const int n = round < 4 ? 3000 : int(U(5, 60));
        for (int i = 0; i < n; ++i) {
            // Near a tile edge (x a multiple of 128, y of 64) most of the time.
            const int64_t x = U(0, 2) ? 128 * U(0, 3) + U(-12, 12) : U(0, 383);
            const int64_t y = U(0, 2) ? 64 * U(0, 3) + U(-8, 8) : U(0, 191);
            const spt::Rgba8 c{uint8_t(U(0, 255)), uint8_t(U(0, 255)), uint8_t(U(0, 255)), uint8_t(U(0, 3) ? 255 : U(1, 254))};
            v.push_back(stamp(uint8_t(U(0, 2)), uint8_t(U(0, i64(t.size()) - 1)), uint8_t(U(0, 7)), int32_t(16 * x + 8),
                              int32_t(16 * y + 8), c));
        }
        const spt::Canvas expect = draw_loop(*r, hd, v);
        spt::Canvas got;
        ASSERT_TRUE(r->render(got, v).ok());
        ASSERT_EQ(got.rgb, expect.rgb) << "round " << round;
    }
}
