// Format 1.3 (SPEC.md 3.1, 4, 6, 7.4, 8.6): half-float codes, the linear compositing rule, alpha
// canvases, and what files of these kinds do in writers, readers and joins.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "format/test_dir.hpp"
#include "spt/concat.hpp"
#include "spt/spt.hpp"

using namespace spt;

namespace {

// The code nearest to v (units of 2^-24), ties to even, by search over every code.
uint16_t nearest_code(uint64_t v) {
    uint16_t best = 0;
    for (uint32_t h = 1; h <= kMaxHalfCode; ++h) {
        const uint64_t a = half_to_q24(uint16_t(h)), b = half_to_q24(best);
        const uint64_t da = a > v ? a - v : v - a, db = b > v ? b - v : v - b;
        if (da < db || (da == db && !(h & 1))) best = uint16_t(h);
    }
    return best;
}

Header linear_header(bool alpha) {
    Header h;
    h.width = 20; h.height = 10; h.fps = {24, 1};
    h.color = ColorEncoding::LinearHalf;
    h.alpha = alpha;
    h.background = {0x3C, 0x3C, 0x3C};  // 1.0
    h.sets = {{8, 4}};
    h.orientations = default_orientations(4);
    return h;
}

Rgba8 code_color(uint16_t r, uint16_t g, uint16_t b, uint8_t a) {
    Rgba8 c; c.a = a;
    set_code16(c, 0, r); set_code16(c, 1, g); set_code16(c, 2, b);
    return c;
}

}  // namespace

TEST(HalfCodes, EveryCodeRoundTripsThroughItsLinearValue) {
    for (uint32_t h = 0; h <= kMaxHalfCode; ++h) {
        ASSERT_EQ(q24_to_half(half_to_q24(uint16_t(h))), h);
        ASSERT_EQ(float_to_half_code(half_to_float(uint16_t(h))), h);
    }
    EXPECT_EQ(half_to_q24(0x3C00), 1u << 24);  // 1.0
    EXPECT_EQ(half_to_float(0x7BFF), 65504.0f);
}

TEST(HalfCodes, RoundingIsToTheNearestCodeTiesToEven) {
    std::mt19937_64 rng(7);
    for (int i = 0; i < 3000; ++i) {
        const uint64_t v = rng() % (half_to_q24(kMaxHalfCode) >> (rng() % 40));
        ASSERT_EQ(q24_to_half(v), nearest_code(v)) << v;
    }
    // A tie between 2048 (code 0x0800) and 2050 (0x0801): the even code.
    EXPECT_EQ(q24_to_half(2049), 0x0800);
    EXPECT_EQ(q24_to_half(2051), 0x0802);
}

TEST(HalfCodes, FloatsMapToNearestCodeAndBadValuesToTheRange) {
    EXPECT_EQ(float_to_half_code(-1.0f), 0);
    EXPECT_EQ(float_to_half_code(std::nanf("")), 0);
    EXPECT_EQ(float_to_half_code(INFINITY), kMaxHalfCode);
    EXPECT_EQ(float_to_half_code(1e9f), kMaxHalfCode);
    EXPECT_EQ(float_to_half_code(0.18f), 0x31C3);
    EXPECT_EQ(float_to_half_code(21.0f), 0x4D40);
}

TEST(LinearBlend, MixesLinearLightNotCodes) {
    // Half-way between 0 and 4.0 in light is 2.0, not the code half-way.
    EXPECT_EQ(blend_half(0, float_to_half_code(4.0f), 128), float_to_half_code(4.0f * 128 / 255));
    EXPECT_EQ(blend_half(0x1234, 0x4D40, 255), 0x4D40);
    EXPECT_EQ(blend_half(0x1234, 0x4D40, 0), 0x1234);
}

TEST(AlphaCanvas, StartsTransparentAndStrokesCompositeOver) {
    Header h = linear_header(false);
    h.color = ColorEncoding::Srgb8;
    h.alpha = true;
    h.background = {255, 255, 255};
    Template rect; rect.kind = TemplateKind::Rectangle;
    auto r = Renderer::create(h, {rect});
    ASSERT_TRUE(r.ok());
    StampStroke st; st.x = 16 * 10 + 8; st.y = 16 * 5 + 8; st.color = {200, 100, 50, 128};
    Canvas c(h);
    ASSERT_EQ(c.alpha.size(), 200u);
    EXPECT_EQ(c.rgb[0], 0);  // transparent black, not the background
    ASSERT_TRUE((*r)->render(c, {Stroke::make_stamp(st)}).ok());
    const size_t p = 5 * 20 + 10;
    EXPECT_EQ(c.alpha[p], 128);
    EXPECT_EQ(c.rgb[3 * p], blend8(0, 200, 128));  // premultiplied: 200 * 128 / 255
    EXPECT_EQ(c.alpha[0], 0);
    // A second opaque stroke makes the pixel opaque with exactly its colour.
    st.color = {10, 20, 30, 255};
    ASSERT_TRUE((*r)->draw(c, Stroke::make_stamp(st)).ok());
    EXPECT_EQ(c.alpha[p], 255);
    EXPECT_EQ(c.rgb[3 * p], 10);
}

TEST(LinearFiles, RoundTripInEveryCodingAndRejectBadCodes) {
    spt::testing::TestDir dir;
    for (bool alpha : {false, true})
        for (Coding coding : {Coding::Stored, Coding::Range, Coding::Replay}) {
            StreamInfo info;
            info.header = linear_header(alpha);
            Template e; e.kind = TemplateKind::Ellipse;
            info.templates = {e};
            Frame f;
            std::mt19937 rng(3);
            for (int i = 0; i < 40; ++i) {
                StampStroke st;
                st.x = int32_t(rng() % 320); st.y = int32_t(rng() % 160);
                st.color = code_color(uint16_t(rng() % 0x7C00), uint16_t(rng() % 0x7C00), uint16_t(rng() % 0x7C00),
                                      uint8_t(rng() % 2 ? 255 : rng() % 256));
                f.added.push_back(Stroke::make_stamp(st));
            }
            const std::string path = (dir / "lin.spt");
            WriterOptions o; o.coding = coding;
            auto w = Writer::create(path, info, o);
            ASSERT_TRUE(w.ok()) << w.error().message;
            ASSERT_TRUE((*w)->append(f).ok());
            ASSERT_TRUE((*w)->finish().ok());
            auto rd = Reader::open(path);
            ASSERT_TRUE(rd.ok()) << rd.error().message;
            EXPECT_EQ((*rd)->info().header.version_minor, kAlphaLinearMinorVersion);
            EXPECT_EQ((*rd)->info().header.alpha, alpha);
            EXPECT_EQ((*rd)->info().header.color, ColorEncoding::LinearHalf);
            // Coding 2 is for plain canvases: the writer codes such frames with coding 1.
            EXPECT_EQ((*rd)->frames()[0].coding, coding == Coding::Replay ? Coding::Range : coding);
            auto s = (*rd)->strokes_at(0);
            ASSERT_TRUE(s.ok()) << s.error().message;
            EXPECT_EQ(**s, f.added);
            Canvas a, b(info.header);
            ASSERT_TRUE((*rd)->render_frame(0, a).ok());
            auto r = Renderer::create(info.header, info.templates);
            for (const auto& st : f.added) ASSERT_TRUE((*r)->draw(b, st).ok());
            EXPECT_EQ(a.rgb16, b.rgb16);
            EXPECT_EQ(a.alpha, b.alpha);
            EXPECT_TRUE(a.rgb.empty());
        }
    // A code above 0x7BFF (an infinity) cannot be written.
    StreamInfo info;
    info.header = linear_header(false);
    Template e; e.kind = TemplateKind::Ellipse;
    info.templates = {e};
    auto w = Writer::create((dir / "bad.spt"), info, {});
    ASSERT_TRUE(w.ok());
    Frame f;
    StampStroke st; st.color = code_color(0x7C00, 0, 0, 255);
    f.added.push_back(Stroke::make_stamp(st));
    EXPECT_FALSE((*w)->append(f).ok());
    // Low bytes in colour encoding 0 are refused too.
    info.header.color = ColorEncoding::Srgb8;
    info.header.background = {1, 2, 3};
    auto w0 = Writer::create((dir / "bad0.spt"), info, {});
    ASSERT_TRUE(w0.ok());
    st.color = Rgba8{1, 2, 3, 255};
    st.color.g_lo = 1;
    f.added = {Stroke::make_stamp(st)};
    EXPECT_FALSE((*w0)->append(f).ok());
}

TEST(LinearFiles, PartsOfDifferentAlphaDoNotJoin) {
    spt::testing::TestDir dir;
    auto make = [&](const std::string& name, bool alpha) {
        StreamInfo info;
        info.header = linear_header(alpha);
        Template e; e.kind = TemplateKind::Ellipse;
        info.templates = {e};
        auto w = Writer::create((dir / name), info, {});
        Frame f;
        (void)(*w)->append(f);
        (void)(*w)->finish();
        return (dir / name);
    };
    const std::string a = make("a.spt", false), b = make("b.spt", true);
    auto st = concatenate({a, b}, dir / "ab.spt");
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("alpha"), std::string::npos) << st.error().message;
}

// 1.3 canvases render in row bands on several threads: the same values as one thread, for every
// stroke kind, and the same error (naming the stroke, those before it drawn) on a bad stroke.
TEST(DeepRender, ThreadsGiveTheValuesOfOneThread) {
    for (bool linear : {false, true}) {
        Header h = linear_header(true);
        h.width = 97; h.height = 61;
        if (!linear) { h.color = ColorEncoding::Srgb8; h.background = {1, 2, 3}; }
        Template e; e.kind = TemplateKind::Ellipse;
        Template r; r.kind = TemplateKind::Rectangle; r.supersample = 3;
        auto rd = Renderer::create(h, {e, r});
        ASSERT_TRUE(rd.ok());
        std::mt19937 rng(11);
        auto colour = [&] {
            return linear ? code_color(uint16_t(rng() % 0x7C00), uint16_t(rng() % 0x7C00), uint16_t(rng() % 0x7C00),
                                       uint8_t(rng() % 2 ? 255 : rng() % 256))
                          : Rgba8{uint8_t(rng()), uint8_t(rng()), uint8_t(rng()), uint8_t(rng() % 2 ? 255 : rng() % 256)};
        };
        std::vector<Stroke> strokes;
        for (int i = 0; i < 300; ++i) {
            const int32_t x = int32_t(rng() % (16 * 110)) - 100, y = int32_t(rng() % (16 * 70)) - 80;
            switch (i % 4) {
                case 0: { StampStroke s; s.x = x; s.y = y; s.tmpl = uint8_t(rng() % 2); s.orient = uint8_t(rng() % 4); s.color = colour();
                          strokes.push_back(Stroke::make_stamp(s)); break; }
                case 1: { AffineStroke a; a.tmpl = uint8_t(rng() % 2); a.tx = x; a.ty = y; a.a = 16 * 9; a.b = 30; a.c = -40; a.d = 16 * 5;
                          a.color = colour(); strokes.push_back(Stroke::make_affine(a)); break; }
                case 2: { CurveStroke c; c.color = colour(); c.points = {{x, y, 40}, {x + 300, y + 200, 8}};
                          strokes.push_back(Stroke::make_curve(c)); break; }
                default: { PolygonStroke p; p.color = colour(); p.supersample = 4; p.points = {{x, y}, {x + 400, y + 30}, {x + 90, y + 500}};
                           strokes.push_back(Stroke::make_polygon(p)); break; }
            }
        }
        Canvas one(h);
        ASSERT_TRUE((*rd)->render(one, strokes, 1).ok());
        for (unsigned t : {2u, 3u, 7u}) {
            Canvas many(h);
            ASSERT_TRUE((*rd)->render(many, strokes, t).ok());
            EXPECT_EQ(many.rgb, one.rgb) << t;
            EXPECT_EQ(many.rgb16, one.rgb16) << t;
            EXPECT_EQ(many.alpha, one.alpha) << t;
        }
        std::vector<Stroke> bad(strokes.begin(), strokes.begin() + 50);
        bad.push_back(strokes[0]);
        bad.back().stamp.tmpl = 9;  // no such template
        bad.insert(bad.end(), strokes.begin() + 50, strokes.end());
        Canvas b1(h), b3(h);
        auto s1 = (*rd)->render(b1, bad, 1), s3 = (*rd)->render(b3, bad, 3);
        ASSERT_FALSE(s1.ok());
        ASSERT_FALSE(s3.ok());
        EXPECT_EQ(s1.error().message, s3.error().message);
        EXPECT_NE(s3.error().message.find("stroke 50"), std::string::npos) << s3.error().message;
        EXPECT_EQ(b1.rgb16, b3.rgb16);
        EXPECT_EQ(b1.rgb, b3.rgb);
        EXPECT_EQ(b1.alpha, b3.alpha);
    }
}
