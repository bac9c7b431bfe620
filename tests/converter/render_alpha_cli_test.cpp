// spt render of format 1.3 files (alpha canvases, scene-linear half colours): EXR keeps the
// half codes and premultiplied alpha exactly, PNG/TIFF get straight alpha, --background and
// JPEG flatten, --view goes through an OCIO config.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>

#include "cli_test_util.hpp"
#include "fmt13_test_util.hpp"
#include "spt/spt.hpp"

using namespace spt;
using spt_test::run_spt;
using spt_test::TempDir;
using namespace fmt13;

namespace {

struct Img {
    int w = 0, h = 0, n = 0;
    std::vector<std::string> names;
    std::vector<uint16_t> px;  // half bits, or 8/16-bit values
    std::string format;
};

Img read(const std::string& path, OIIO::TypeDesc type) {
    Img im;
    OIIO::ImageSpec hint;
    hint.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &hint);
    if (!in) {
        ADD_FAILURE() << "cannot read " << path << ": " << OIIO::geterror();
        return im;
    }
    const auto& s = in->spec();
    im.w = s.width, im.h = s.height, im.n = s.nchannels, im.names = s.channelnames, im.format = s.format.c_str();
    im.px.resize(size_t(im.w) * im.h * im.n);
    if (type == OIIO::TypeDesc::UINT8) {
        std::vector<uint8_t> b(im.px.size());
        EXPECT_TRUE(in->read_image(0, 0, 0, im.n, type, b.data()));
        for (size_t i = 0; i < b.size(); ++i) im.px[i] = b[i];
    } else {
        EXPECT_TRUE(in->read_image(0, 0, 0, im.n, type, im.px.data()));
    }
    return im;
}

float h2f(uint16_t bits) {
    // Half bits to float (finite, non-negative codes of these files, and alpha).
    return half_to_float(bits);
}

}  // namespace

TEST(RenderAlpha, LinearExrIsTheHalfCodesWithPremultipliedAlpha) {
    TempDir d;
    const std::string in = d.file("lin.spt"), out = d.file("out.exr");
    const Canvas c = make_file(in, ColorEncoding::LinearHalf, true);
    auto r = run_spt(d, {"render", in, "-o", out});
    ASSERT_EQ(r.code, 0) << r.err;
    const Img im = read(out, OIIO::TypeDesc::HALF);
    ASSERT_EQ(im.n, 4);
    EXPECT_EQ(im.format, "half");
    EXPECT_EQ(im.names, (std::vector<std::string>{"R", "G", "B", "A"}));
    int above1 = 0, transparent = 0, partial = 0;
    for (size_t i = 0; i < size_t(W) * H; ++i) {
        for (int k = 0; k < 3; ++k) ASSERT_EQ(im.px[i * 4 + k], c.rgb16[i * 3 + k]) << "pixel " << i;  // exact
        EXPECT_NEAR(h2f(im.px[i * 4 + 3]), c.alpha[i] / 255.f, 5e-4) << i;
        above1 += h2f(im.px[i * 4]) > 20.f;
        if (c.alpha[i] == 0) {
            ++transparent;
            for (int k = 0; k < 4; ++k) EXPECT_EQ(im.px[i * 4 + k], 0);
        } else if (c.alpha[i] < 255) {
            ++partial;
        }
    }
    EXPECT_EQ(above1, 25);  // the square of 21.0 (5 x 5 pixel centres), kept
    EXPECT_GT(transparent, 20);
    EXPECT_GT(partial, 16);
    EXPECT_EQ(c.rgb16[(3 * W + 2) * 3], 0x4D40);
}

TEST(RenderAlpha, LinearWithoutAlphaExrIsRgbCodes) {
    TempDir d;
    const std::string in = d.file("lin.spt"), out = d.file("out.exr");
    const Canvas c = make_file(in, ColorEncoding::LinearHalf, false);
    ASSERT_EQ(run_spt(d, {"render", in, "-o", out}).code, 0);
    const Img im = read(out, OIIO::TypeDesc::HALF);
    ASSERT_EQ(im.n, 3);
    EXPECT_EQ(im.px, c.rgb16);
}

TEST(RenderAlpha, LinearPngIsStraightAlphaThroughTheSrgbCurve) {
    TempDir d;
    const std::string in = d.file("lin.spt");
    const Canvas c = make_file(in, ColorEncoding::LinearHalf, true);
    for (int depth : {8, 16}) {
        const std::string out = d.file("out" + std::to_string(depth) + ".png");
        auto r = run_spt(d, {"render", in, "-o", out, "--depth", std::to_string(depth)});
        ASSERT_EQ(r.code, 0) << r.err;
        const Img im = read(out, depth == 8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16);
        ASSERT_EQ(im.n, 4);
        const float scale = depth == 8 ? 255.f : 65535.f;
        for (size_t i = 0; i < size_t(W) * H; ++i) {
            const uint32_t a = c.alpha[i];
            EXPECT_EQ(im.px[i * 4 + 3], depth == 8 ? a : a * 257u);
            for (int k = 0; k < 3; ++k) {
                const float lin = a ? half_to_float(c.rgb16[i * 3 + k]) * 255.f / float(a) : 0.f;
                const float want = std::floor(srgb_encode(lin) * scale + 0.5f);
                EXPECT_EQ(im.px[i * 4 + k], uint16_t(want)) << "depth " << depth << " pixel " << i << " channel " << k;
            }
        }
        // The opaque square: 21.0 clips to white, 0.18 is sRGB 118 (of 255).
        const size_t p = 3 * W + 2;
        EXPECT_EQ(im.px[p * 4], depth == 8 ? 255 : 65535);
        if (depth == 8) EXPECT_EQ(im.px[p * 4 + 1], 118);
    }
    // The 8-bit PNG is the viewers' view (spt/display.hpp to_rgba8).
    std::vector<uint8_t> view;
    to_rgba8(c, test_info(ColorEncoding::LinearHalf, true).header, view);
    const Img im = read(d.file("out8.png"), OIIO::TypeDesc::UINT8);
    for (size_t i = 0; i < view.size(); ++i) ASSERT_EQ(im.px[i], view[i]) << i;
}

TEST(RenderAlpha, Srgb8AlphaPngRoundTripsAndExrIsPremultipliedLinear) {
    TempDir d;
    const std::string in = d.file("a.spt");
    const Canvas c = make_file(in, ColorEncoding::Srgb8, true);
    ASSERT_EQ(run_spt(d, {"render", in, "-o", d.file("a.png")}).code, 0);
    ASSERT_EQ(run_spt(d, {"render", in, "-o", d.file("a.tif")}).code, 0);
    ASSERT_EQ(run_spt(d, {"render", in, "-o", d.file("a.exr")}).code, 0);
    for (const char* name : {"a.png", "a.tif"}) {
        const Img im = read(d.file(name), OIIO::TypeDesc::UINT8);
        ASSERT_EQ(im.n, 4) << name;
        int partial = 0;
        for (size_t i = 0; i < size_t(W) * H; ++i) {
            const uint32_t a = c.alpha[i];
            ASSERT_EQ(im.px[i * 4 + 3], a);
            partial += a > 0 && a < 255;
            for (int k = 0; k < 3; ++k) {
                EXPECT_EQ(im.px[i * 4 + k], unpremultiply8(c.rgb[i * 3 + k], a)) << name << " " << i;
                // Premultiplied again as the renderer composites, the straight value is the canvas.
                EXPECT_EQ(blend8(0, uint8_t(im.px[i * 4 + k]), a), c.rgb[i * 3 + k]) << name << " " << i;
            }
        }
        EXPECT_GT(partial, 16);
    }
    const Img ex = read(d.file("a.exr"), OIIO::TypeDesc::HALF);
    ASSERT_EQ(ex.n, 4);
    for (size_t i = 0; i < size_t(W) * H; ++i) {
        const float a = c.alpha[i] / 255.f;
        EXPECT_NEAR(h2f(ex.px[i * 4 + 3]), a, 5e-4);
        for (int k = 0; k < 3; ++k) {
            const float straight = c.alpha[i] ? std::min(1.f, float(c.rgb[i * 3 + k]) / float(c.alpha[i])) : 0.f;
            EXPECT_NEAR(h2f(ex.px[i * 4 + k]), srgb_decode(straight) * a, 2e-3) << i;
        }
    }
}

TEST(RenderAlpha, BackgroundFlattensAndJpegFlattensOverTheHeaderBackground) {
    TempDir d;
    const std::string in = d.file("lin.spt");
    const Canvas c = make_file(in, ColorEncoding::LinearHalf, true);
    // --background in every accepted spelling gives the same flattened PNG.
    for (const char* bg : {"255,0,128", "ff0080", "#FF0080"}) {
        auto r = run_spt(d, {"render", in, "-o", d.file("f.png"), "--background", bg});
        ASSERT_EQ(r.code, 0) << r.err;
        const Img im = read(d.file("f.png"), OIIO::TypeDesc::UINT8);
        ASSERT_EQ(im.n, 3);
        const float bgl[3] = {1.f, 0.f, srgb_decode(128 / 255.f)};
        for (size_t i = 0; i < size_t(W) * H; ++i)
            for (int k = 0; k < 3; ++k) {
                const float lin = half_to_float(c.rgb16[i * 3 + k]) + bgl[k] * (1.f - c.alpha[i] / 255.f);
                ASSERT_EQ(im.px[i * 3 + k], unit_to_u8(srgb_encode(lin))) << bg << " " << i;
            }
        EXPECT_EQ(im.px[0], 255);  // a transparent corner is the background
        EXPECT_EQ(im.px[2], 128);
    }
    // A colour name is the same colour.
    ASSERT_EQ(run_spt(d, {"render", in, "-o", d.file("w1.png"), "--background", "white"}).code, 0);
    ASSERT_EQ(run_spt(d, {"render", in, "-o", d.file("w2.png"), "--background", "255,255,255"}).code, 0);
    EXPECT_EQ(spt_test::slurp(d.file("w1.png")), spt_test::slurp(d.file("w2.png")));
    EXPECT_EQ(run_spt(d, {"render", in, "-o", d.file("w3.png"), "--background", "1,2"}).code, 2);
    EXPECT_EQ(run_spt(d, {"render", in, "-o", d.file("w3.png"), "--background", "nocolour"}).code, 2);
    // The EXR flattened: three channels, transparent pixels are the linear background.
    ASSERT_EQ(run_spt(d, {"render", in, "-o", d.file("f.exr"), "--background", "255,0,128"}).code, 0);
    const Img ex = read(d.file("f.exr"), OIIO::TypeDesc::HALF);
    ASSERT_EQ(ex.n, 3);
    EXPECT_EQ(h2f(ex.px[0]), 1.f);
    EXPECT_NEAR(h2f(ex.px[2]), srgb_decode(128 / 255.f), 1e-3);
    // JPEG: no alpha; the header's background (0.5, 0, 1.0), and a note.
    auto r = run_spt(d, {"render", in, "-o", d.file("f.jpg")});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("flattened"), std::string::npos) << r.err;
    const Img jp = read(d.file("f.jpg"), OIIO::TypeDesc::UINT8);
    ASSERT_EQ(jp.n, 3);
    // The top right corner, away from the strokes (JPEG is lossy and rings near edges).
    for (size_t i = 12; i < 16; ++i) {
        ASSERT_EQ(c.alpha[i], 0);
        EXPECT_NEAR(jp.px[i * 3], 188, 6) << i;  // sRGB of 0.5
        EXPECT_NEAR(jp.px[i * 3 + 1], 0, 6) << i;
        EXPECT_NEAR(jp.px[i * 3 + 2], 255, 6) << i;
    }
    // An 8-bit sRGB alpha file flattens in its own values, as strokes composite.
    const std::string in0 = d.file("a.spt");
    const Canvas c0 = make_file(in0, ColorEncoding::Srgb8, true);
    ASSERT_EQ(run_spt(d, {"render", in0, "-o", d.file("g.png"), "--background", "0,0,0"}).code, 0);
    const Img g = read(d.file("g.png"), OIIO::TypeDesc::UINT8);
    ASSERT_EQ(g.n, 3);
    for (size_t i = 0; i < c0.rgb.size(); ++i) ASSERT_EQ(g.px[i], c0.rgb[i]) << i;  // over black: the premultiplied values
}

TEST(RenderAlpha, PlainFilesRenderAsBefore) {
    TempDir d;
    const std::string in = d.file("p.spt");
    const Canvas c = make_file(in, ColorEncoding::Srgb8, false);
    ASSERT_EQ(run_spt(d, {"render", in, "-o", d.file("p.png")}).code, 0);
    ASSERT_EQ(run_spt(d, {"render", in, "-o", d.file("q.png"), "--background", "0,0,0"}).code, 0);
    EXPECT_EQ(spt_test::slurp(d.file("p.png")), spt_test::slurp(d.file("q.png")));
    const Img im = read(d.file("p.png"), OIIO::TypeDesc::UINT8);
    ASSERT_EQ(im.n, 3);
    for (size_t i = 0; i < c.rgb.size(); ++i) ASSERT_EQ(im.px[i], c.rgb[i]);
    // 16-bit: each value times 257.
    ASSERT_EQ(run_spt(d, {"render", in, "-o", d.file("p16.png"), "--depth", "16"}).code, 0);
    const Img im16 = read(d.file("p16.png"), OIIO::TypeDesc::UINT16);
    for (size_t i = 0; i < c.rgb.size(); ++i) ASSERT_EQ(im16.px[i], c.rgb[i] * 257);
}

TEST(RenderAlpha, ViewGoesThroughTheOcioConfig) {
    TempDir d;
    const std::string in = d.file("lin.spt"), cfg = d.file("half.ocio");
    const Canvas c = make_file(in, ColorEncoding::LinearHalf, false);
    // A display whose one view halves linear light: nothing else changes the values.
    std::ofstream(cfg) << "ocio_profile_version: 1\n"
                          "roles:\n  default: linear\n  scene_linear: linear\n"
                          "displays:\n  test:\n    - !<View> {name: halved, colorspace: halved}\n"
                          "colorspaces:\n"
                          "  - !<ColorSpace>\n    name: linear\n    isdata: false\n"
                          "  - !<ColorSpace>\n    name: halved\n    isdata: false\n"
                          "    from_reference: !<MatrixTransform> {matrix: [0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 1]}\n";
    auto r = run_spt(d, {"render", in, "-o", d.file("v.png"), "--view", "halved", "--ocio", cfg});
    ASSERT_EQ(r.code, 0) << r.err;
    const Img im = read(d.file("v.png"), OIIO::TypeDesc::UINT8);
    ASSERT_EQ(im.n, 3);
    for (size_t i = 0; i < c.rgb16.size(); ++i)
        ASSERT_NEAR(im.px[i], unit_to_u8(0.5f * half_to_float(c.rgb16[i])), 1) << i;
    EXPECT_EQ(im.px[(3 * W + 2) * 3 + 2], 128);  // 1.0 halved
    // Errors name what is missing.
    r = run_spt(d, {"render", in, "-o", d.file("v.png"), "--view", "nope", "--ocio", cfg});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("halved"), std::string::npos) << r.err;  // the views it has
    r = run_spt(d, {"render", in, "-o", d.file("v.exr"), "--view", "halved", "--ocio", cfg});
    EXPECT_EQ(r.code, 2);
    r = run_spt(d, {"render", in, "-o", d.file("v.png"), "--view", "halved", "--ocio", d.file("missing.ocio")});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("missing.ocio"), std::string::npos) << r.err;
}
