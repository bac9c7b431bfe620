// spt/display.hpp: the straight sRGB view of every canvas kind that viewers and spt render's
// 8-bit outputs use (SPEC.md B.5a).
#include <gtest/gtest.h>

#include <cmath>

#include "spt/spt.hpp"

using namespace spt;

TEST(Display, SrgbCurveIsTheStandardOneAndClips) {
    EXPECT_FLOAT_EQ(srgb_encode(0.f), 0.f);
    EXPECT_FLOAT_EQ(srgb_encode(1.f), 1.f);
    EXPECT_FLOAT_EQ(srgb_encode(21.f), 1.f);  // no tone mapping
    EXPECT_FLOAT_EQ(srgb_encode(-1.f), 0.f);
    EXPECT_FLOAT_EQ(srgb_encode(std::nanf("")), 0.f);
    EXPECT_NEAR(srgb_encode(0.18f), 0.46135, 1e-4);
    EXPECT_NEAR(srgb_encode(0.002f), 0.002f * 12.92f, 1e-7);  // the linear toe
    for (int v = 0; v <= 255; ++v) EXPECT_EQ(unit_to_u8(srgb_encode(srgb_decode(v / 255.f))), v);
}

TEST(Display, UnpremultipliedValuesPremultiplyBackExactly) {
    // Every premultiplied value the renderer can make (p <= a): straight with
    // (255p + a/2) / a, premultiplied again by blend8, is p.
    for (uint32_t a = 1; a <= 255; ++a)
        for (uint32_t p = 0; p <= a; ++p) {
            const uint8_t s = unpremultiply8(p, a);
            ASSERT_EQ(blend8(0, s, a), p) << p << " / " << a;
        }
    EXPECT_EQ(unpremultiply8(100, 128), 199);
    EXPECT_EQ(unpremultiply8(9, 0), 0);
    EXPECT_EQ(unpremultiply8(200, 100), 255);  // not a renderer's value: clamped
}

TEST(Display, ToRgba8OfEveryCanvasKind) {
    Header h;
    h.width = 3, h.height = 1;
    // Plain: the values, alpha 255.
    Canvas c(h);
    c.rgb = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    std::vector<uint8_t> out;
    to_rgba8(c, h, out);
    EXPECT_EQ(out, (std::vector<uint8_t>{1, 2, 3, 255, 4, 5, 6, 255, 7, 8, 9, 255}));
    // Alpha, encoding 0: unpremultiplied; transparent is 0, 0, 0, 0.
    h.alpha = true;
    c.reset(h);
    c.rgb = {100, 50, 0, 10, 20, 30, 7, 7, 7};
    c.alpha = {128, 255, 0};
    to_rgba8(c, h, out);
    EXPECT_EQ(out, (std::vector<uint8_t>{199, 100, 0, 128, 10, 20, 30, 255, 0, 0, 0, 0}));
    // Linear, with alpha: the value divided by alpha, through the sRGB curve.
    h.color = ColorEncoding::LinearHalf;
    c.reset(h);
    c.rgb16 = {0x4D40, 0x31C3, 0x3C00, float_to_half_code(0.09f), 0, 0, 0x3C00, 0x3C00, 0x3C00};
    c.alpha = {255, 128, 0};
    to_rgba8(c, h, out);
    EXPECT_EQ(out[0], 255);  // 21.0 clips
    EXPECT_EQ(out[1], 118);  // 0.18
    EXPECT_EQ(out[2], 255);
    EXPECT_EQ(out[3], 255);
    EXPECT_EQ(out[4], unit_to_u8(srgb_encode(half_to_float(float_to_half_code(0.09f)) * 255.f / 128.f)));
    EXPECT_NEAR(out[4], 118, 1);  // 0.09 at half coverage is 0.18 straight
    EXPECT_EQ(out[7], 128);
    EXPECT_EQ(std::vector<uint8_t>(out.begin() + 8, out.end()), (std::vector<uint8_t>{0, 0, 0, 0}));
    // Without alpha: every code of the table against the curve.
    h.alpha = false;
    h.width = 1;
    c.reset(h);
    for (uint32_t code = 0; code <= kMaxHalfCode; code += 7) {
        c.rgb16 = {uint16_t(code), uint16_t(code), uint16_t(code)};
        to_rgba8(c, h, out);
        ASSERT_EQ(out[0], unit_to_u8(srgb_encode(half_to_float(uint16_t(code))))) << code;
        ASSERT_EQ(out[3], 255);
    }
}

TEST(Display, BackgroundLinear) {
    Header h;
    h.background = {255, 0, 188};
    EXPECT_FLOAT_EQ(background_linear(h, 0), 1.f);
    EXPECT_FLOAT_EQ(background_linear(h, 1), 0.f);
    EXPECT_NEAR(background_linear(h, 2), 0.5029, 1e-3);
    h.color = ColorEncoding::LinearHalf;
    h.background = {0x4D, 0x38, 0};
    h.background_lo = {0x40, 0, 0};
    EXPECT_FLOAT_EQ(background_linear(h, 0), 21.f);
    EXPECT_FLOAT_EQ(background_linear(h, 1), 0.5f);
    EXPECT_FLOAT_EQ(background_linear(h, 2), 0.f);
}
