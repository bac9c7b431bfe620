// Small cases of SPEC section 8 whose answers are known by hand or by a simple argument.
#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "format/render_test_util.hpp"

namespace {

using namespace spt_test;
using spt::Rgba8;

int count_nonzero(const spt::Mask& m) {
    int n = 0;
    for (uint8_t a : m.a) n += a != 0;
    return n;
}

uint8_t mask_at(const spt::Mask& m, int32_t x, int32_t y) {
    if (x < m.x0 || y < m.y0 || x >= m.x0 + int32_t(m.w) || y >= m.y0 + int32_t(m.h)) return 0;
    return m.a[size_t(y - m.y0) * m.w + size_t(x - m.x0)];
}

const std::vector<spt::StrokeSet> kSets = {{1, 1}, {2, 2}, {4, 3}, {7, 10}, {16, 9}, {60, 33}, {255, 128}};

TEST(RenderRules, StampAtOrientation0CoversExactlyItsSetSize) {
    auto r = make_renderer(make_header(64, 64, kSets), {bitmap(60, 60, std::vector<uint8_t>(3600, 255))});
    for (uint8_t s = 0; s < kSets.size(); ++s) {
        const spt::Mask& m = r->stamp_footprint(s, 0, 0);
        EXPECT_EQ(m.w, kSets[s].width) << int(s);
        EXPECT_EQ(m.h, kSets[s].height) << int(s);
        EXPECT_EQ(count_nonzero(m), kSets[s].width * kSets[s].height) << int(s);
        for (uint8_t a : m.a) ASSERT_EQ(a, 255);
        // Centred on the centre pixel: an even size has one more pixel on the negative side.
        EXPECT_EQ(m.x0, -int32_t(kSets[s].width / 2));
        EXPECT_EQ(m.y0, -int32_t(kSets[s].height / 2));
    }
}

TEST(RenderRules, QuarterTurnSwapsWidthAndHeight) {
    auto r = make_renderer(make_header(64, 64, kSets), {bitmap(60, 60, std::vector<uint8_t>(3600, 255)),
                                                        analytic(spt::TemplateKind::Ellipse)});
    for (uint8_t t = 0; t < 2; ++t)
        for (uint8_t s = 0; s < kSets.size(); ++s) {
            const spt::Mask& m0 = r->stamp_footprint(s, t, 0);
            const spt::Mask& m4 = r->stamp_footprint(s, t, 4);  // entry 4 of 8: (0, 16384)
            EXPECT_EQ(m4.w, m0.h);
            EXPECT_EQ(m4.h, m0.w);
            EXPECT_EQ(count_nonzero(m4), count_nonzero(m0));
        }
}

TEST(RenderRules, StampAtOrientation0IsMirrorSymmetricForOddSizes) {
    auto r = make_renderer(make_header(64, 64, {{31, 17}}), {analytic(spt::TemplateKind::Ellipse)});
    const spt::Mask& m = r->stamp_footprint(0, 0, 0);
    for (int32_t y = -20; y <= 20; ++y)
        for (int32_t x = -20; x <= 20; ++x) {
            ASSERT_EQ(mask_at(m, x, y), mask_at(m, -x, y));
            ASSERT_EQ(mask_at(m, x, y), mask_at(m, x, -y));
        }
}

// An ellipse against a double-precision evaluation, skipping centres within a hair of the
// boundary where rounding legitimately decides.
TEST(RenderRules, AnalyticEllipseMatchesFloatingPointAwayFromBoundary) {
    auto r = make_renderer(make_header(200, 200, {{40, 20}}), {analytic(spt::TemplateKind::Ellipse)});
    const int32_t tx = 16 * 100 + 3, ty = 16 * 97 + 11;
    const int32_t mats[][4] = {{400, 0, 0, 250}, {300, -200, 150, 120}, {-640, 40, 33, 500}, {17, 900, -800, 5}};
    for (const auto& M : mats) {
        spt::Mask m;
        ASSERT_TRUE(r->stroke_mask(affine(0, tx, ty, M[0], M[1], M[2], M[3], {0, 0, 0, 255}), m).ok());
        const double det = double(M[0]) * M[3] - double(M[1]) * M[2];
        int inside = 0, checked = 0;
        for (int32_t y = 0; y < 200; ++y)
            for (int32_t x = 0; x < 200; ++x) {
                const double dx = 16.0 * x + 8 - tx, dy = 16.0 * y + 8 - ty;
                const double u = (M[3] * dx - M[1] * dy) / det, v = (-M[2] * dx + M[0] * dy) / det;
                const double f = u * u + v * v;
                if (std::fabs(f - 1.0) < 1e-3) continue;
                ++checked;
                inside += f < 1.0;
                ASSERT_EQ(mask_at(m, x, y), f < 1.0 ? 255 : 0) << x << "," << y;
            }
        EXPECT_GT(inside, 100);
        EXPECT_GT(checked, 30000);
    }
}

TEST(RenderRules, StampEllipseMatchesFloatingPoint) {
    auto hd = make_header(64, 64, {{41, 23}});
    auto r = make_renderer(hd, {analytic(spt::TemplateKind::Ellipse)});
    for (uint8_t o = 0; o < 8; ++o) {
        const spt::Mask& m = r->stamp_footprint(0, 0, o);
        const double c = hd.orientations[o].cos_q14 / 16384.0, s = hd.orientations[o].sin_q14 / 16384.0;
        for (int32_t j = -30; j <= 30; ++j)
            for (int32_t i = -30; i <= 30; ++i) {
                const double u = (i * c + j * s) / 20.5, v = (-i * s + j * c) / 11.5;
                const double f = u * u + v * v;
                if (std::fabs(f - 1.0) < 1e-3) continue;
                ASSERT_EQ(mask_at(m, i, j), f < 1.0 ? 255 : 0) << int(o) << " " << i << "," << j;
            }
    }
}

TEST(RenderRules, AffineRectangleAndTriangleByHand) {
    auto r = make_renderer(make_header(16, 16, {{1, 1}}), {analytic(spt::TemplateKind::Rectangle),
                                                           analytic(spt::TemplateKind::Triangle)});
    spt::Mask m;
    // Centre of pixel (5, 5), half sizes 2 x 1 px: columns 3..7, rows 4..6 (edges inclusive).
    ASSERT_TRUE(r->stroke_mask(affine(0, centre(5), centre(5), 32, 0, 0, 16, {0, 0, 0, 255}), m).ok());
    EXPECT_EQ(count_nonzero(m), 15);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) EXPECT_EQ(mask_at(m, x, y), (x >= 3 && x <= 7 && y >= 4 && y <= 6) ? 255 : 0);
    // Triangle, half size 2 px: offsets (i, j) with i, j >= -2 and i + j <= 0.
    ASSERT_TRUE(r->stroke_mask(affine(1, centre(5), centre(5), 32, 0, 0, 32, {0, 0, 0, 255}), m).ok());
    EXPECT_EQ(count_nonzero(m), 15);
    for (int j = -3; j <= 3; ++j)
        for (int i = -3; i <= 3; ++i)
            EXPECT_EQ(mask_at(m, 5 + i, 5 + j), (i >= -2 && j >= -2 && i + j <= 0) ? 255 : 0) << i << "," << j;
    // Alpha 128 scales coverage: (255 * 128 + 127) / 255 = 128.
    ASSERT_TRUE(r->stroke_mask(affine(0, centre(5), centre(5), 32, 0, 0, 16, {0, 0, 0, 128}), m).ok());
    EXPECT_EQ(mask_at(m, 5, 5), 128);
}

TEST(RenderRules, AffineBitmapBilinearByHand) {
    // A 4x1 ramp 0, 85, 170, 255 spanning 4 pixels: centres sample texel positions 0, 1, 2, 3
    // (x 1/256: 0, 256, 512, 768); bilinear between texel centres gives 0, 42.5, 127.5, 212.5,
    // rounded half up by the + 32768.
    auto r = make_renderer(make_header(16, 16, {{1, 1}}), {bitmap(4, 1, {0, 85, 170, 255})});
    spt::Mask m;
    ASSERT_TRUE(r->stroke_mask(affine(0, centre(8), centre(8), 32, 0, 0, 16, {0, 0, 0, 255}), m).ok());
    EXPECT_EQ(mask_at(m, 6, 8), 0);
    EXPECT_EQ(mask_at(m, 7, 8), 43);
    EXPECT_EQ(mask_at(m, 8, 8), 128);
    EXPECT_EQ(mask_at(m, 9, 8), 213);
    EXPECT_EQ(mask_at(m, 10, 8), 0);  // u = +1 is outside: texels cover [i, i+1)
    // Half height 1 px: row 7 is v = -1 (inside, the top edge), row 9 is v = +1 (outside).
    EXPECT_EQ(mask_at(m, 8, 7), 128);
    EXPECT_EQ(mask_at(m, 8, 9), 0);
}

TEST(RenderRules, OnePointCurveIsADisc) {
    auto r = make_renderer(make_header(64, 64, {{1, 1}}), {});
    for (uint32_t radius = 0; radius <= 12; ++radius) {
        spt::Mask m;
        ASSERT_TRUE(r->stroke_mask(curve({{centre(30), centre(30), 32 * radius}}, {0, 0, 0, 255}), m).ok());
        int expect = 0;
        for (int j = -20; j <= 20; ++j)
            for (int i = -20; i <= 20; ++i) {
                const bool in = i * i + j * j <= int(radius * radius);
                expect += in;
                ASSERT_EQ(mask_at(m, 30 + i, 30 + j), in ? 255 : 0) << radius << " " << i << "," << j;
            }
        EXPECT_EQ(count_nonzero(m), expect);
    }
}

TEST(RenderRules, TwoPointCurveHasRoundCaps) {
    auto r = make_renderer(make_header(16, 16, {{1, 1}}), {});
    spt::Mask m;
    // Pixels (2,5) -> (10,5), full width 2 px: row 5 spans 1..11, rows 4 and 6 span 2..10.
    ASSERT_TRUE(r->stroke_mask(curve({{centre(2), centre(5), 32}, {centre(10), centre(5), 32}}, {0, 0, 0, 255}), m).ok());
    EXPECT_EQ(count_nonzero(m), 29);
    EXPECT_EQ(mask_at(m, 1, 5), 255);
    EXPECT_EQ(mask_at(m, 1, 4), 0);
    EXPECT_EQ(mask_at(m, 2, 4), 255);
    EXPECT_EQ(mask_at(m, 11, 5), 255);
    EXPECT_EQ(mask_at(m, 12, 5), 0);
    // Width grows linearly: 0 at the left end, 8 px at the right end.
    ASSERT_TRUE(r->stroke_mask(curve({{centre(2), centre(8), 0}, {centre(12), centre(8), 128}}, {0, 0, 0, 255}), m).ok());
    EXPECT_EQ(mask_at(m, 2, 8), 255);
    EXPECT_EQ(mask_at(m, 2, 9), 0);
    EXPECT_EQ(mask_at(m, 12, 12), 255);
    EXPECT_EQ(mask_at(m, 7, 10), 255);  // radius 2 px at x = 7
    EXPECT_EQ(mask_at(m, 7, 11), 0);
}

// Drawing a stroke equals compositing its stroke_mask with blend8, clipped to the canvas, for
// strokes across each edge, each corner and fully outside.
TEST(RenderRules, ClippingAtEveryEdgeMatchesMaskComposite) {
    const uint32_t W = 40, H = 30;
    auto r = make_renderer(make_header(W, H, {{25, 15}, {9, 9}}), {bitmap(3, 3, {10, 200, 30, 255, 255, 255, 0, 128, 90}),
                                                                   analytic(spt::TemplateKind::Ellipse)});
    std::vector<spt::Stroke> strokes;
    const int32_t xs[] = {-1000, -13, -3, 0, 20, 39, 42, 52, 5000};
    const int32_t ys[] = {-1000, -8, -2, 0, 15, 29, 31, 38, 5000};
    for (int32_t x : xs)
        for (int32_t y : ys) {
            strokes.push_back(stamp(0, 0, 3, 16 * x + 5, 16 * y + 9, {200, 40, 90, 255}));
            strokes.push_back(stamp(1, 1, 1, 16 * x, 16 * y, {10, 240, 90, 140}));
            strokes.push_back(affine(0, 16 * x, 16 * y, 300, 50, -40, 200, {0, 0, 250, 200}));
            strokes.push_back(curve({{16 * x, 16 * y, 64}, {16 * x + 100, 16 * y - 70, 20}}, {90, 0, 0, 255}));
        }
    // Extreme coordinates far outside: nothing drawn, no crash, no huge allocation.
    for (const auto& s : {stamp(0, 0, 0, 1 << 24, -(1 << 24), {0, 0, 0, 255}),
                          affine(1, 1 << 24, 1 << 24, 1 << 16, 1 << 16, -(1 << 16), 1 << 16, {0, 0, 0, 255}),
                          curve({{-(1 << 24), -(1 << 24), 1 << 16}, {1 << 24, -(1 << 24), 1 << 16}}, {0, 0, 0, 255})}) {
        spt::Canvas a(W, H, {30, 60, 90});
        const auto before = a.rgb;
        ASSERT_TRUE(r->draw(a, s).ok());
        EXPECT_EQ(a.rgb, before);
    }
    for (const auto& s : strokes) {
        spt::Canvas a(W, H, {30, 60, 90}), b = a;
        ASSERT_TRUE(r->draw(a, s).ok());
        spt::Mask m;
        ASSERT_TRUE(r->stroke_mask(s, m).ok());
        const Rgba8 c = s.kind == spt::StrokeKind::Stamp ? s.stamp.color : s.kind == spt::StrokeKind::Affine ? s.affine.color : s.curve.color;
        for (uint32_t y = 0; y < H; ++y)
            for (uint32_t x = 0; x < W; ++x) {
                const uint8_t al = mask_at(m, int32_t(x), int32_t(y));
                uint8_t* p = b.row(y) + 3 * x;
                p[0] = spt::blend8(p[0], c.r, al);
                p[1] = spt::blend8(p[1], c.g, al);
                p[2] = spt::blend8(p[2], c.b, al);
            }
        ASSERT_EQ(a.rgb, b.rgb) << "stroke kind " << int(s.kind);
    }
}

TEST(RenderRules, DegenerateAndInvalidStrokes) {
    auto r = make_renderer(make_header(20, 20, {{5, 5}}), {analytic(spt::TemplateKind::Ellipse)});
    spt::Canvas c(20, 20, {1, 2, 3});
    const auto before = c.rgb;
    // Singular matrix: nothing drawn, not an error.
    EXPECT_TRUE(r->draw(c, affine(0, 160, 160, 32, 64, 16, 32, {0, 0, 0, 255})).ok());
    // Transparent colour: nothing drawn.
    EXPECT_TRUE(r->draw(c, stamp(0, 0, 0, 160, 160, {0, 0, 0, 0})).ok());
    EXPECT_EQ(c.rgb, before);
    // Invalid references and ranges are errors that leave the canvas alone.
    EXPECT_FALSE(r->draw(c, stamp(1, 0, 0, 160, 160, {0, 0, 0, 255})).ok());
    EXPECT_FALSE(r->draw(c, stamp(0, 1, 0, 160, 160, {0, 0, 0, 255})).ok());
    EXPECT_FALSE(r->draw(c, stamp(0, 0, 8, 160, 160, {0, 0, 0, 255})).ok());
    EXPECT_FALSE(r->draw(c, stamp(0, 0, 0, (1 << 24) + 1, 160, {0, 0, 0, 255})).ok());
    EXPECT_FALSE(r->draw(c, affine(0, 160, 160, (1 << 16) + 1, 0, 0, 16, {0, 0, 0, 255})).ok());
    EXPECT_FALSE(r->draw(c, curve({}, {0, 0, 0, 255})).ok());
    EXPECT_FALSE(r->draw(c, curve({{0, 0, (1u << 16) + 1}}, {0, 0, 0, 255})).ok());
    EXPECT_EQ(c.rgb, before);
    // Bad headers and templates are refused by create().
    EXPECT_FALSE(spt::Renderer::create(make_header(0, 20, {{5, 5}}), {}).ok());
    EXPECT_FALSE(spt::Renderer::create(make_header(20, 20, {}), {}).ok());
    EXPECT_FALSE(spt::Renderer::create(make_header(20, 20, {{0, 5}}), {}).ok());
    EXPECT_FALSE(spt::Renderer::create(make_header(20, 20, {{5, 5}}), {bitmap(3, 3, {1, 2})}).ok());
    auto hd = make_header(20, 20, {{5, 5}});
    hd.orientations[0] = {16384, 16384};
    EXPECT_FALSE(spt::Renderer::create(hd, {}).ok());
}

TEST(RenderRules, FootprintCacheIsStableAcrossThreads) {
    auto r = make_renderer(make_header(64, 64, kSets, 16), {analytic(spt::TemplateKind::Ellipse),
                                                            bitmap(2, 2, {0, 255, 255, 0})});
    std::vector<const spt::Mask*> seen[2];
    auto work = [&](int k) {
        for (uint8_t s = 0; s < kSets.size(); ++s)
            for (uint8_t t = 0; t < 2; ++t)
                for (uint8_t o = 0; o < 16; ++o) seen[k].push_back(&r->stamp_footprint(s, t, o));
    };
    std::thread a(work, 0), b(work, 1);
    a.join();
    b.join();
    EXPECT_EQ(seen[0], seen[1]);
}

}  // namespace
