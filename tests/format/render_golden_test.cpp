// Golden canvas: a fixed mix of strokes whose rendering is pinned by its FNV-1a-64 hash. Any
// change to SPEC section 8's arithmetic changes the hash; such a change is a format change
// (a new major version), never a silent one. Stroke values come from raw mt19937 output, which
// the C++ standard fixes bit for bit (distributions are not portable, so none is used).
#include <gtest/gtest.h>

#include <random>

#include "format/render_test_util.hpp"

namespace {

using namespace spt_test;

TEST(RenderGolden, FixedFrameHash) {
    std::mt19937 rng(42);
    auto R = [&](uint32_t n) { return rng() % n; };
    std::vector<spt::Template> templates = {analytic(spt::TemplateKind::Ellipse), analytic(spt::TemplateKind::Rectangle),
                                            analytic(spt::TemplateKind::Triangle)};
    std::vector<uint8_t> px(24 * 16);
    for (size_t i = 0; i < px.size(); ++i) px[i] = uint8_t((i * 37 + (i / 24) * 11) % 256);
    templates.push_back(bitmap(24, 16, px));
    auto hd = make_header(96, 64, {{48, 20}, {16, 8}, {5, 3}}, 8);
    hd.background = {240, 230, 200};
    auto r = make_renderer(hd, templates);
    std::vector<spt::Stroke> v;
    // Every draw is its own statement: argument evaluation order is unspecified in C++.
    auto next = [&](uint32_t n, int32_t offset = 0) { return int32_t(R(n)) + offset; };
    for (int i = 0; i < 400; ++i) {
        spt::Rgba8 c;
        c.r = uint8_t(next(256));
        c.g = uint8_t(next(256));
        c.b = uint8_t(next(256));
        c.a = next(2) ? 255 : uint8_t(next(256));
        if (i % 4 < 2) {
            spt::StampStroke s;
            s.set = uint8_t(next(3));
            s.tmpl = uint8_t(next(4));
            s.orient = uint8_t(next(8));
            s.x = next(96 * 16 + 200, -100);
            s.y = next(64 * 16 + 200, -100);
            s.color = c;
            v.push_back(spt::Stroke::make_stamp(s));
        } else if (i % 4 == 2) {
            spt::AffineStroke s;
            s.tmpl = uint8_t(next(4));
            s.tx = next(96 * 16);
            s.ty = next(64 * 16);
            s.a = next(300, -150);
            s.b = next(300, -150);
            s.c = next(300, -150);
            s.d = next(300, -150);
            s.color = c;
            v.push_back(spt::Stroke::make_affine(s));
        } else {
            std::vector<spt::CurvePoint> pts;
            const uint32_t n = 1 + R(4);
            for (uint32_t k = 0; k < n; ++k) {
                spt::CurvePoint p;
                p.x = next(96 * 16);
                p.y = next(64 * 16);
                p.width = uint32_t(next(80));
                pts.push_back(p);
            }
            v.push_back(curve(std::move(pts), c));
        }
    }
    spt::Canvas canvas;
    ASSERT_TRUE(r->render(canvas, v).ok());
    ASSERT_EQ(canvas.rgb.size(), 96u * 64u * 3u);
    EXPECT_EQ(fnv1a64(canvas.rgb), 0x7b1bccd6dd5ec864ull) << std::hex << fnv1a64(canvas.rgb);
}

}  // namespace
