// spt info, export and import of format 1.3 files: the colour encoding and alpha are shown,
// SVG carries opacity and no background on alpha canvases, and JSON (version 3) round-trips
// half codes and alpha exactly.
#include <gtest/gtest.h>

#include <fstream>

#include "cli_test_util.hpp"
#include "fmt13_test_util.hpp"
#include "io_json_check.hpp"

using namespace fmt13;
using spt_test::run_spt;
using spt_test::slurp;
using spt_test::TempDir;

TEST(InfoFmt13, ShowsEncodingAlphaAndLinearBackground) {
    TempDir d;
    const std::string lin = d.file("lin.spt"), plain = d.file("p.spt");
    make_file(lin, ColorEncoding::LinearHalf, true);
    make_file(plain, ColorEncoding::Srgb8, false);
    auto r = run_spt(d, {"info", lin});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find(".spt 1.3"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("scene-linear half float"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(", alpha,"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("background 0.5, 0, 1 linear (codes 3800 0000 3c00)"), std::string::npos) << r.out;
    r = run_spt(d, {"info", plain});
    ASSERT_EQ(r.code, 0);
    EXPECT_NE(r.out.find("colour srgb8, background #0ac81e\n"), std::string::npos) << r.out;  // as before 1.3

    r = run_spt(d, {"info", lin, "--json"});
    ASSERT_EQ(r.code, 0) << r.err;
    spt_test::Json j;
    ASSERT_TRUE(spt_test::JsonParser::parse(r.out, j)) << r.out;
    EXPECT_EQ(j["color"].str, "linear-half");
    EXPECT_EQ(j["color_encoding"]["id"].num, 1);
    EXPECT_EQ(j["color_encoding"]["name"].str, "scene-linear half float");
    EXPECT_TRUE(j["alpha"].b);
    ASSERT_EQ(j["background_codes"].arr.size(), 3u);
    EXPECT_EQ(j["background_codes"][0].num, 0x3800);
    EXPECT_EQ(j["background_linear"][0].num, 0.5);
    EXPECT_EQ(j["background_linear"][2].num, 1.0);
    EXPECT_EQ(j["background"][0].num, 0x38);  // the existing key keeps its meaning: the high bytes
    r = run_spt(d, {"info", plain, "--json"});
    ASSERT_TRUE(spt_test::JsonParser::parse(r.out, j));
    EXPECT_EQ(j["color"].str, "srgb8");
    EXPECT_EQ(j["color_encoding"]["name"].str, "8-bit sRGB");
    EXPECT_EQ(j["alpha"].type, spt_test::Json::Bool);
    EXPECT_FALSE(j["alpha"].b);
    EXPECT_FALSE(j.has("background_codes"));
}

TEST(ExportFmt13, SvgHasOpacityAndNoBackgroundOnAlphaCanvases) {
    TempDir d;
    const std::string lin = d.file("lin.spt"), opaque = d.file("o.spt");
    make_file(lin, ColorEncoding::LinearHalf, true);
    make_file(opaque, ColorEncoding::LinearHalf, false);
    ASSERT_EQ(run_spt(d, {"export", lin, "-o", d.file("a.svg")}).code, 0);
    ASSERT_EQ(run_spt(d, {"export", opaque, "-o", d.file("o.svg")}).code, 0);
    const std::string a = slurp(d.file("a.svg")), o = slurp(d.file("o.svg"));
    EXPECT_EQ(a.find("<rect width="), std::string::npos) << a;  // transparent: no background
    // The opaque square of (21.0, 0.18, 1.0) through the sRGB curve: #ff76ff.
    EXPECT_NE(a.find("fill=\"#ffffff\""), std::string::npos) << a;  // 2.0 clips to white
    EXPECT_NE(a.find("fill=\"#ff76ff\""), std::string::npos) << a;
    EXPECT_NE(a.find("fill-opacity=\"0.501961\""), std::string::npos) << a;  // alpha 128
    EXPECT_NE(a.find("fill-opacity=\"0.784314\""), std::string::npos) << a;  // alpha 200
    // Without alpha the background is drawn, through the same view: 0.5, 0, 1.0 is #bc00ff.
    EXPECT_NE(o.find("<rect width=\"16\" height=\"8\" fill=\"#bc00ff\"/>"), std::string::npos) << o;
}

TEST(ExportFmt13, JsonRoundTripsCodesAndAlphaExactly) {
    TempDir d;
    for (ColorEncoding enc : {ColorEncoding::LinearHalf, ColorEncoding::Srgb8})
        for (bool alpha : {true, false}) {
            if (enc == ColorEncoding::Srgb8 && !alpha) continue;  // plain files: the existing tests
            const std::string in = d.file("in.spt"), js = d.file("x.json"), back = d.file("back.spt");
            const Canvas want = make_file(in, enc, alpha);
            auto r = run_spt(d, {"export", in, "-o", js});
            ASSERT_EQ(r.code, 0) << r.err;
            const std::string text = slurp(js);
            spt_test::Json j;
            ASSERT_TRUE(spt_test::JsonParser::parse(text, j)) << text;
            EXPECT_EQ(j["version"].num, 3);
            EXPECT_EQ(j["canvas"]["color_encoding"].str, enc == ColorEncoding::LinearHalf ? "linear-half" : "srgb8");
            EXPECT_EQ(j["canvas"]["alpha"].b, alpha);
            if (enc == ColorEncoding::LinearHalf) {
                EXPECT_NE(text.find("\"color\": [19776, 12739, 15360, 255]"), std::string::npos) << text;  // 21.0, 0.18, 1.0
                EXPECT_NE(text.find("\"background\": [14336, 0, 15360]"), std::string::npos) << text;
            }
            r = run_spt(d, {"import", js, "-o", back});
            ASSERT_EQ(r.code, 0) << r.err;
            auto a = Reader::open(in), b = Reader::open(back);
            ASSERT_TRUE(a.ok() && b.ok());
            Header ha = (*a)->info().header, hb = (*b)->info().header;
            EXPECT_EQ(hb.color, enc);
            EXPECT_EQ(hb.alpha, alpha);
            EXPECT_EQ(hb.background, ha.background);
            EXPECT_EQ(hb.background_lo, ha.background_lo);
            auto sa = (*a)->strokes_at(0), sb = (*b)->strokes_at(0);
            ASSERT_TRUE(sa.ok() && sb.ok());
            EXPECT_EQ(**sa, **sb);
            Canvas got;
            ASSERT_TRUE((*b)->render_frame(0, got).ok());
            EXPECT_EQ(got.rgb16, want.rgb16);
            EXPECT_EQ(got.rgb, want.rgb);
            EXPECT_EQ(got.alpha, want.alpha);
        }
}

TEST(ImportFmt13, LinearValuesAndErrors) {
    TempDir d;
    auto doc = [](const std::string& canvas, const std::string& stroke, int version = 3) {
        return "{\"format\": \"spt-strokes\", \"version\": " + std::to_string(version) + ", \"canvas\": {\"width\": 8, \"height\": 8" +
               canvas + "}, \"sets\": [[4, 4]], \"strokes\": [{\"type\": \"stamp\", \"set\": 0, \"template\": 1, \"orient\": 0, "
               "\"x\": 4, \"y\": 4, " + stroke + "}]}";
    };
    auto import = [&](const std::string& text) {
        std::ofstream(d.file("i.json")) << text;
        return run_spt(d, {"import", d.file("i.json"), "-o", d.file("i.spt")});
    };
    // Linear values become their nearest codes; the background defaults to 1.0.
    auto r = import(doc(", \"color_encoding\": \"linear-half\", \"alpha\": true", "\"linear\": [21, 0.18, 100000, 77]"));
    ASSERT_EQ(r.code, 1) << r.err;  // 100000 is above the largest half
    EXPECT_NE(r.err.find("65504"), std::string::npos) << r.err;
    r = import(doc(", \"color_encoding\": \"linear-half\", \"alpha\": true", "\"linear\": [21, 0.18, 65504, 77]"));
    ASSERT_EQ(r.code, 0) << r.err;
    auto rd = Reader::open(d.file("i.spt"));
    ASSERT_TRUE(rd.ok());
    EXPECT_EQ((*rd)->info().header.background, (Rgb8{0x3C, 0x3C, 0x3C}));
    auto s = (*rd)->strokes_at(0);
    ASSERT_TRUE(s.ok());
    const Rgba8 c = (**s)[0].color();
    EXPECT_EQ(code16(c, 0), 0x4D40);
    EXPECT_EQ(code16(c, 1), 0x31C3);
    EXPECT_EQ(code16(c, 2), kMaxHalfCode);
    EXPECT_EQ(c.a, 77);
    // Codes above 0x7BFF, 1.3 fields in older versions, unknown encodings: errors naming the field.
    r = import(doc(", \"color_encoding\": \"linear-half\"", "\"color\": [31744, 0, 0]"));
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("color[0]"), std::string::npos) << r.err;
    r = import(doc(", \"alpha\": true", "\"color\": [1, 2, 3]", 2));
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("version 3"), std::string::npos) << r.err;
    r = import(doc(", \"color_encoding\": \"log\"", "\"color\": [1, 2, 3]"));
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("color_encoding"), std::string::npos) << r.err;
    r = import(doc(", \"color_encoding\": \"linear-half\"", "\"color\": [1, 2, 3], \"linear\": [1, 2, 3]"));
    EXPECT_EQ(r.code, 1);
    // An 8-bit document in version 3 reads as before.
    r = import(doc(", \"alpha\": false", "\"color\": [1, 2, 3]"));
    EXPECT_EQ(r.code, 0) << r.err;
}
