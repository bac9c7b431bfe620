// Scene-linear painting (colour encoding 1): the proxy transform, the colour refit (never worse
// in linear light than the proxy colours converted, smooth darks without 8-bit steps), and the
// whole paint_scene() path (alpha + linear, exact rendering, any thread count).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "paint/scene_paint.hpp"
#include "spt/color.hpp"
#include "spt/render.hpp"

using namespace spt;
using namespace spt::paint;

namespace {

struct LinearImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;
    LinearView view() const { return LinearView{width, height, rgba.data()}; }
};

// A premultiplied linear RGBA image: a dark-to-mid background ramp, a glowing disc up to 20 and
// a transparent band on the right when `alpha`.
LinearImage hdr_image(uint32_t w, uint32_t h, bool alpha) {
    LinearImage m{w, h, std::vector<float>(size_t(w) * h * 4)};
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            float* p = &m.rgba[(size_t(y) * w + x) * 4];
            const double d = std::hypot(x + 0.5 - w * 0.35, y + 0.5 - h * 0.5) / (h * 0.3);
            const double glow = d < 1 ? 20.0 * (1 - d) + 0.5 : 0.0;
            const double a = alpha ? std::clamp((w * 0.8 - x) / 3.0, 0.0, 1.0) : 1.0;
            p[0] = float(a * (0.02 + 0.3 * x / w + glow));
            p[1] = float(a * (0.01 + 0.2 * y / h + 0.6 * glow));
            p[2] = float(a * (0.05 + 0.1 * glow));
            p[3] = float(a);
        }
    return m;
}

PaintSetup setup_for(uint32_t w, uint32_t h) {
    return make_setup(w, h, Rgb8{255, 255, 255}, default_sets(w, h, 5), default_templates());
}

PaintOptions opts(int threads) {
    PaintOptions o;
    o.seed = 11;
    o.threads = threads;
    o.max_strokes = 3000;
    o.lambda = 2;
    return o;
}

}  // namespace

TEST(LinearProxy, SrgbBelowOneLogAboveAndThePeakAt255) {
    ProxyTransform t;
    t.peak = 20;
    EXPECT_DOUBLE_EQ(t.encode(20), 1.0);
    EXPECT_DOUBLE_EQ(t.encode(100), 1.0);  // clamped at the peak
    EXPECT_DOUBLE_EQ(t.encode(0), 0.0);
    for (double x : {0.001, 0.01, 0.18, 0.5, 1.0, 1.5, 4.0, 19.0}) EXPECT_NEAR(t.decode(t.encode(x)), x, 1e-9 * (1 + x));
    // C1 at 1: equal slopes from both sides.
    const double e = 1e-6;
    const double left = (t.encode(1) - t.encode(1 - e)) / e, right = (t.encode(1 + e) - t.encode(1)) / e;
    EXPECT_NEAR(left, right, 1e-4 * left);
    // The bent segment of a peak of 21: 1.0 at 0.7 of the range, still C1 at 1, monotone.
    const ProxyTransform b = ProxyTransform::with_peak(21.0);
    EXPECT_GT(b.bend, 1.0);
    EXPECT_NEAR(b.encode(1.0), 0.7, 1e-9);
    EXPECT_DOUBLE_EQ(b.encode(21.0), 1.0);
    const double bl = (b.encode(1) - b.encode(1 - e)) / e, br = (b.encode(1 + e) - b.encode(1)) / e;
    EXPECT_NEAR(bl, br, 1e-4 * bl);
    for (double x = 1.0; x < 21; x *= 1.5) {
        EXPECT_LT(b.encode(x), b.encode(x * 1.5));
        EXPECT_NEAR(b.decode(b.encode(x)), x, 1e-9 * x);
    }
    // Peak 1: the plain sRGB curve.
    ProxyTransform s;
    EXPECT_NEAR(s.encode(0.18), srgb_encode(0.18), 1e-12);
}

TEST(LinearRefit, NeverWorseThanTheProxyColoursConverted) {
    for (int run = 0; run < 4; ++run) {
        // With and without alpha; the refit's own weighted error and plain linear least squares.
        const bool alpha = run & 1, weighted = run & 2;
        const LinearImage img = hdr_image(96, 64, alpha);
        PaintSetup setup = setup_for(96, 64);
        SceneTarget target;
        target.alpha = alpha;
        target.linear = true;
        target.refit.highlight_weight = weighted;
        auto sp = paint_scene(img.view(), setup, opts(2), target);
        ASSERT_TRUE(sp.ok()) << sp.error().message;
        ASSERT_GT(sp->strokes.size(), 50u);
        // The same geometry with the proxy colours converted to linear (what a painter without
        // the refit would store).
        const ProxyTransform t = sp->transform;
        ASSERT_GT(t.peak, 15.0);
        std::vector<uint8_t> rgb, a8;
        make_proxy(img.view(), t, rgb, alpha ? &a8 : nullptr);
        PaintSetup proxy = setup;
        proxy.header.alpha = alpha;
        proxy.header.background = proxy_background(setup.header.background, t);
        auto pr = Renderer::create(proxy.header, proxy.templates);
        ASSERT_TRUE(pr.ok());
        Canvas pc(proxy.header);
        std::vector<Stroke> proxy_strokes;
        paint::paint(ImageView{96, 64, rgb.data(), alpha ? a8.data() : nullptr}, pc, **pr, proxy, opts(2), proxy_strokes);
        ASSERT_EQ(proxy_strokes.size(), sp->strokes.size());
        std::vector<Stroke> converted = proxy_strokes;
        for (Stroke& s : converted) s.stamp.color = proxy_to_linear(s.stamp.color, t);
        auto lr = Renderer::create(sp->header, setup.templates);
        ASSERT_TRUE(lr.ok());
        Canvas conv(sp->header), refit(sp->header);
        ASSERT_TRUE((*lr)->render(conv, converted).ok());
        ASSERT_TRUE((*lr)->render(refit, sp->strokes).ok());
        EXPECT_EQ(refit.rgb16, sp->canvas.rgb16);  // the refit's canvas is the decoder's
        EXPECT_EQ(refit.alpha, sp->canvas.alpha);
        const double e_refit = refit_error(img.view(), refit, weighted), e_conv = refit_error(img.view(), conv, weighted);
        EXPECT_LT(e_refit, e_conv) << "alpha " << alpha << " weighted " << weighted;
        if (!weighted) EXPECT_LT(linear_sse(img.view(), refit), linear_sse(img.view(), conv));
        // Highlights survive: the painted glow peaks far above 1.
        float peak = 0;
        for (uint16_t c : refit.rgb16) peak = std::max(peak, half_to_float(c));
        EXPECT_GT(peak, 5.0f);
    }
}

TEST(LinearRefit, DarkGradientPaintsWithoutEightBitSteps) {
    // Linear 0.001 .. 0.02 left to right: about 30 sRGB 8-bit codes over the whole width.
    const uint32_t W = 160, H = 24;
    LinearImage img{W, H, std::vector<float>(size_t(W) * H * 4)};
    for (uint32_t y = 0; y < H; ++y)
        for (uint32_t x = 0; x < W; ++x) {
            float* p = &img.rgba[(size_t(y) * W + x) * 4];
            p[0] = p[1] = p[2] = float(0.001 + 0.019 * x / (W - 1));
            p[3] = 1;
        }
    SceneTarget target;
    target.linear = true;
    PaintOptions o = opts(2);
    o.color_step = 1;
    auto sp = paint_scene(img.view(), setup_for(W, H), o, target);
    ASSERT_TRUE(sp.ok()) << sp.error().message;
    std::set<int> proxy_levels, linear_levels;
    for (uint32_t x = 0; x < W; ++x) proxy_levels.insert(int(std::lround(255 * srgb_encode(img.rgba[4 * x]))));
    const uint32_t y = H / 2;
    for (uint32_t x = 0; x < W; ++x) linear_levels.insert(sp->canvas.rgb16[(size_t(y) * W + x) * 3 + 1]);
    EXPECT_GT(linear_levels.size(), 2 * proxy_levels.size())
        << linear_levels.size() << " linear codes against " << proxy_levels.size() << " 8-bit levels";
    // And it follows the ramp: mean absolute error well below one 8-bit step in the darks.
    double err = 0;
    for (uint32_t x = 0; x < W; ++x)
        err += std::abs(half_to_float(sp->canvas.rgb16[(size_t(y) * W + x) * 3 + 1]) - img.rgba[(size_t(y) * W + x) * 4 + 1]);
    EXPECT_LT(err / W, 0.0012);
}

TEST(LinearRefit, CoarserMantissaStaysOnItsLattice) {
    for (int bits : {10, 7, 4})
        for (double v : {0.0, 1e-6, 0.003, 0.18, 1.0, 7.5, 21.0, 70000.0}) {
            const uint16_t c = linear_code(v, bits);
            EXPECT_LE(c, kMaxHalfCode);
            EXPECT_EQ(c & ((1u << (10 - bits)) - 1), 0u) << v << " " << bits;
            if (v > 1e-3 && v < 60000) EXPECT_NEAR(half_to_float(c), v, v * std::ldexp(1.0, -bits));
        }
}

TEST(ScenePaint, SameBytesForAnyThreadCount) {
    const LinearImage img = hdr_image(96, 64, true);
    SceneTarget target;
    target.alpha = true;
    target.linear = true;
    auto a = paint_scene(img.view(), setup_for(96, 64), opts(1), target);
    auto b = paint_scene(img.view(), setup_for(96, 64), opts(3), target);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_EQ(a->strokes, b->strokes);
    EXPECT_EQ(a->canvas.rgb16, b->canvas.rgb16);
}
