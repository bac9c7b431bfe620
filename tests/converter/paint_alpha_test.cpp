// The RGBA painter (alpha canvases, format 1.3): its canvas is what a decoder renders, bit for
// bit, alpha included; transparent parts of the model stay transparent; the strokes do not
// depend on the thread count.
#include <gtest/gtest.h>

#include <cmath>

#include "paint/painter.hpp"
#include "paint_test_util.hpp"
#include "spt/render.hpp"

using namespace spt;
using namespace spt::paint;

namespace {

// A premultiplied RGBA8 model: a textured opaque disc with a soft rim, transparent around it.
struct RgbaModel {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgb, alpha;
    ImageView view() const { return ImageView{width, height, rgb.data(), alpha.data()}; }
};

RgbaModel disc_model(uint32_t w, uint32_t h) {
    RgbaModel m;
    m.width = w;
    m.height = h;
    m.rgb.assign(size_t(w) * h * 3, 0);
    m.alpha.assign(size_t(w) * h, 0);
    const double cx = w * 0.45, cy = h * 0.5, r = h * 0.35;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
            const double a = std::clamp(r + 1.5 - d, 0.0, 3.0) / 3.0;  // 3-pixel soft rim
            const size_t i = size_t(y) * w + x;
            m.alpha[i] = uint8_t(std::lround(255 * a));
            const double straight[3] = {200.0 - 100.0 * x / w, 60.0 + 150.0 * y / h, ((x / 6 + y / 6) % 2) ? 220.0 : 90.0};
            for (int c = 0; c < 3; ++c) m.rgb[3 * i + c] = uint8_t(std::lround(straight[c] * m.alpha[i] / 255.0));
        }
    return m;
}

using paint_test::Painting;

Painting run(const RgbaModel& m, int threads) {
    PaintSetup setup =
        make_setup(m.width, m.height, Rgb8{255, 255, 255}, default_sets(m.width, m.height, 5), default_templates());
    setup.header.alpha = true;
    PaintOptions o;
    o.seed = 7;
    o.threads = threads;
    o.max_strokes = 3000;
    o.lambda = 2;
    return paint_test::paint_model(m.view(), std::move(setup), o);
}

}  // namespace

TEST(PaintAlpha, CanvasEqualsTheRendererBitForBitAlphaIncluded) {
    const RgbaModel m = disc_model(96, 64);
    Painting p = run(m, 2);
    ASSERT_GT(p.strokes.size(), 50u);
    ASSERT_EQ(p.canvas.alpha.size(), size_t(96) * 64);
    Canvas rendered(p.setup.header);
    ASSERT_TRUE(p.renderer->render(rendered, p.strokes).ok());
    EXPECT_EQ(rendered.rgb, p.canvas.rgb);
    EXPECT_EQ(rendered.alpha, p.canvas.alpha);
    EXPECT_GT(p.stats.psnr, 18.0);  // R, G, B and A; the 6-pixel checker is hard at this size
}

TEST(PaintAlpha, TransparentStaysTransparentAndOpaqueGetsCovered) {
    const RgbaModel m = disc_model(96, 64);
    Painting p = run(m, 2);
    size_t out_n = 0, out_clear = 0, in_n = 0, in_opaque = 0;
    for (size_t i = 0; i < m.alpha.size(); ++i) {
        if (m.alpha[i] == 0) { ++out_n; out_clear += p.canvas.alpha[i] < 32; }
        if (m.alpha[i] == 255) { ++in_n; in_opaque += p.canvas.alpha[i] > 224; }
    }
    ASSERT_GT(out_n, 1000u);
    ASSERT_GT(in_n, 1000u);
    EXPECT_GT(double(out_clear) / double(out_n), 0.9);
    EXPECT_GT(double(in_opaque) / double(in_n), 0.9);
}

TEST(PaintAlpha, SameStrokesForAnyThreadCount) {
    const RgbaModel m = disc_model(96, 64);
    Painting a = run(m, 1), b = run(m, 3);
    ASSERT_FALSE(a.strokes.empty());
    EXPECT_EQ(a.strokes, b.strokes);
    EXPECT_EQ(a.canvas.alpha, b.canvas.alpha);
}

TEST(PaintAlpha, RefusesAnAlphaHeaderWithoutModelAlpha) {
    const RgbaModel m = disc_model(32, 32);
    PaintSetup setup = make_setup(32, 32, Rgb8{255, 255, 255}, default_sets(32, 32, 3), default_templates());
    setup.header.alpha = true;
    auto r = Renderer::create(setup.header, setup.templates);
    ASSERT_TRUE(r.ok());
    Canvas c(setup.header);
    std::vector<Stroke> out;
    const ImageView no_alpha{32, 32, m.rgb.data(), nullptr};
    paint::paint(no_alpha, c, **r, setup, PaintOptions{}, out);
    EXPECT_TRUE(out.empty());
}
