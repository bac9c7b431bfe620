// `spt paint` / `spt plan` colour and alpha flags (issue 17): --color-encoding, --alpha,
// --colorspace, --ocio, --layer. Bad values are usage errors (exit 2) that name the flag; the
// defaults leave the file bytes as they were; non-defaults reach painter.options and farm plans.
#include <gtest/gtest.h>

#include "cli_test_util.hpp"
#include "ocio_test_config.hpp"
#include "spt/reader.hpp"

using namespace spt_test;

namespace {

void require_tool() { ASSERT_TRUE(fs::exists(SPT_TOOL)) << "the spt tool was not built: " << SPT_TOOL; }

// A small opaque 8-bit picture: every flag here paints it the same way.
std::string write_ppm(const TempDir& d) {
    const std::string p = d.file("in.ppm");
    std::ofstream f(p, std::ios::binary);
    f << "P6\n32 24\n255\n";
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x) {
            const unsigned char px[3] = {uint8_t(x * 8), uint8_t(200 - y * 4), uint8_t(x < 16 ? 40 : 220)};
            f.write(reinterpret_cast<const char*>(px), 3);
        }
    return p;
}

std::string write_config(const TempDir& d) { return write_studio_ocio(d.file("studio.ocio")); }

std::string painter_options(const std::string& spt_path) {
    auto r = spt::Reader::open(spt_path);
    EXPECT_TRUE(r.ok()) << r.error().message;
    if (!r.ok()) return {};
    for (const auto& [k, v] : (*r)->info().metadata)
        if (k == "painter.options") return v;
    return {};
}

const std::vector<std::string> kQuick = {"--max-strokes", "200", "--seed", "5", "--progress", "none", "--threads", "1"};

std::vector<std::string> paint_cmd(const std::string& in, const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> a = {"paint", in, "-o", out};
    a.insert(a.end(), kQuick.begin(), kQuick.end());
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
}

}  // namespace

TEST(PaintColorFlags, BadValuesAreUsageErrorsNamingTheFlag) {
    require_tool();
    TempDir d;
    const std::string in = write_ppm(d), cfg = write_config(d), out = d.file("x.spt");
    struct Case { std::vector<std::string> args; std::vector<std::string> want; };
    const Case cases[] = {
        {{"--alpha", "maybe"}, {"--alpha", "'maybe'", "auto, on or off"}},
        {{"--color-encoding", "half"}, {"--color-encoding", "'half'", "srgb8"}},
        {{"--colorspace", "ACEScg"}, {"--colorspace", "'ACEScg'", "built-in", "sRGB", "--ocio"}},
        {{"--colorspace", "ACEScgg", "--ocio", cfg}, {"--colorspace", "'ACEScgg'", "ACEScg", "studio.ocio"}},
        {{"--ocio", d.file("none.ocio")}, {"--ocio", "none.ocio", "no such file"}},
        {{"--layer="}, {"--layer"}},
    };
    for (const Case& c : cases) EXPECT_TRUE(refused(d, paint_cmd(in, out, c.args), 2, c.want, out)) << c.args[0];
    // $OCIO is the config when --ocio is not given.
    const std::string cmd = "OCIO=" + shell_quote(cfg) + " " + shell_quote(SPT_TOOL) + " paint " + shell_quote(in) +
                            " -o " + shell_quote(out) + " --colorspace ACEScgg --progress none 2>" +
                            shell_quote(d.file("env.err"));
    const int st = std::system(cmd.c_str());
    EXPECT_EQ(WEXITSTATUS(st), 2);
    EXPECT_NE(slurp(d.file("env.err")).find("studio.ocio"), std::string::npos) << slurp(d.file("env.err"));
}

// Blender 5 sets $OCIO to its own config, newer than this OpenColorIO reads, for the spt it
// starts: a $OCIO that cannot be loaded falls back to the built-in config with a warning (an
// explicit --ocio stays an error), and the painting is what it is without $OCIO.
TEST(PaintColorFlags, UnloadableOcioEnvironmentFallsBackWithAWarning) {
    require_tool();
    TempDir d;
    const std::string in = write_ppm(d), bad = d.file("newer.ocio");
    std::ofstream(bad) << "ocio_profile_version: 99\n";
    auto paint = [&](const std::string& env, const std::string& out, const std::string& extra) {
        const std::string cmd = env + shell_quote(SPT_TOOL) + " paint " + shell_quote(in) + " -o " + shell_quote(d.file(out)) +
                                " --seed 3 --max-strokes 200 --alpha on --progress none " + extra + " 2>" +
                                shell_quote(d.file(out + ".err"));
        return WEXITSTATUS(std::system(cmd.c_str()));
    };
    ASSERT_EQ(paint("env -u OCIO ", "plain.spt", ""), 0) << slurp(d.file("plain.spt.err"));
    ASSERT_EQ(paint("OCIO=" + shell_quote(bad) + " ", "env.spt", ""), 0) << slurp(d.file("env.spt.err"));
    const std::string err = slurp(d.file("env.spt.err"));
    EXPECT_NE(err.find("newer.ocio"), std::string::npos) << err;
    EXPECT_NE(err.find("built-in config instead"), std::string::npos) << err;
    EXPECT_EQ(slurp(d.file("plain.spt")), slurp(d.file("env.spt")));
    EXPECT_EQ(paint("env -u OCIO ", "flag.spt", "--ocio " + shell_quote(bad)), 2);
}

// --colorspace and --layer act on 8-bit paintings too (they were ignored when the painting was
// plain sRGB without alpha), and a missing layer is an error, not a painting of something else.
TEST(PaintColorFlags, ColourSpaceAndLayerActOnEightBitPaintings) {
    require_tool();
    TempDir d;
    const std::string in = write_ppm(d);
    auto paint = [&](const std::string& out, std::vector<std::string> extra) {
        return run_spt(d, paint_cmd(in, d.file(out), std::move(extra)));
    };
    ASSERT_EQ(paint("default.spt", {}).code, 0);
    ASSERT_EQ(paint("srgb.spt", {"--colorspace", "sRGB"}).code, 0);
    auto r = paint("linear.spt", {"--colorspace", "linear"});
    ASSERT_EQ(r.code, 0) << r.err;
    // The file is 8-bit sRGB either way; taking the input as linear light makes it brighter.
    auto mean = [&](const std::string& f) {
        auto rd = spt::Reader::open(d.file(f));
        EXPECT_TRUE(rd.ok());
        EXPECT_TRUE((*rd)->info().header.plain_color()) << f;
        spt::Canvas c;
        EXPECT_TRUE((*rd)->render_frame(0, c).ok());
        double sum = 0;
        for (uint8_t v : c.rgb) sum += v;
        return sum / double(c.rgb.size());
    };
    EXPECT_NEAR(mean("srgb.spt"), mean("default.spt"), 1.0);
    EXPECT_GT(mean("linear.spt"), mean("default.spt") + 20);
    EXPECT_NE(painter_options(d.file("linear.spt")).find("colorspace=linear"), std::string::npos);
    // A layer the file does not have.
    const std::string exr = std::string(SPT_MEDIA_DIR) + "/exr/orbit/orbit.0001.exr";
    EXPECT_TRUE(refused(d, {"paint", exr, "-o", d.file("layer.spt"), "--layer", "Nope", "--max-strokes", "50"}, 1,
                        {"no layer 'Nope'"}, d.file("layer.spt")));
    // An 8-bit sequence painting cannot apply them yet: refused, not ignored.
    EXPECT_TRUE(refused(d, {"paint", std::string(SPT_MEDIA_DIR) + "/exr/earth/earth.####.exr", "--frames", "1-2",
                            "-o", d.file("seq.spt"), "--color-encoding", "srgb8", "--colorspace", "sRGB"},
                        kAnyFailure, {"--colorspace and --layer apply to sequences"}, d.file("seq.spt")));
}

TEST(PaintColorFlags, HelpDescribesThem) {
    require_tool();
    TempDir d;
    auto r = run_spt(d, {"paint", "--help"});
    ASSERT_EQ(r.code, 0);
    for (const char* w : {"--color-encoding MODE", "--alpha MODE", "--colorspace NAME", "--ocio FILE", "--layer NAME",
                          "srgb8", "ACEScg", "$OCIO", "ViewLayer.Combined"})
        EXPECT_NE(r.out.find(w), std::string::npos) << w;
}

TEST(PaintColorFlags, DefaultsKeepTheBytesAndOthersReachPainterOptions) {
    require_tool();
    TempDir d;
    const std::string in = write_ppm(d);
    auto plain = run_spt(d, paint_cmd(in, d.file("plain.spt"), {}));
    ASSERT_EQ(plain.code, 0) << plain.err;
    auto defaults = run_spt(d, paint_cmd(in, d.file("defaults.spt"), {"--color-encoding", "auto", "--alpha", "auto"}));
    ASSERT_EQ(defaults.code, 0) << defaults.err;
    EXPECT_EQ(slurp(d.file("plain.spt")), slurp(d.file("defaults.spt")));
    const std::string base = painter_options(d.file("plain.spt"));
    EXPECT_EQ(base.find("alpha"), std::string::npos) << base;
    EXPECT_EQ(base.find("color"), base.find("color-step")) << base;

    // An opaque 8-bit sRGB picture is painted the same with these; painter.options tells them.
    auto named = run_spt(d, paint_cmd(in, d.file("named.spt"), {"--color-encoding", "srgb8", "--alpha", "off",
                                                                 "--colorspace", "sRGB"}));
    ASSERT_EQ(named.code, 0) << named.err;
    const std::string opts = painter_options(d.file("named.spt"));
    for (const char* w : {" color-encoding=srgb8", " alpha=off", " colorspace=sRGB"})
        EXPECT_NE(opts.find(w), std::string::npos) << w << " in " << opts;
    EXPECT_EQ(opts.rfind(base, 0), 0u) << "the new options follow the old ones: " << opts;
}

TEST(PaintColorFlags, FarmPlansCarryThem) {
    require_tool();
    TempDir d;
    const std::string cfg = write_config(d);
    const std::string seq = std::string(SPT_MEDIA_DIR) + "/exr/orbit/orbit.####.exr";
    ASSERT_TRUE(fs::exists(std::string(SPT_MEDIA_DIR) + "/exr/orbit/orbit.0001.exr")) << "test media missing";
    auto r = run_spt(d, {"plan", seq, "-o", d.file("plan.json"), "--frames", "1-3", "--progress", "none",
                         "--color-encoding", "linear", "--alpha", "on", "--colorspace", "ACEScg", "--ocio", cfg,
                         "--layer", "ViewLayer.Combined"});
    ASSERT_EQ(r.code, 0) << r.err;
    std::string plan;  // without the layout's white space
    for (char c : slurp(d.file("plan.json")))
        if (c != ' ' && c != '\n') plan += c;
    for (const std::string& w : {std::string("\"color-encoding\":\"linear\""), std::string("\"alpha\":\"on\""),
                                 std::string("\"colorspace\":\"ACEScg\""), "\"ocio\":\"" + cfg + "\"",
                                 std::string("\"layer\":\"ViewLayer.Combined\"")})
        EXPECT_NE(plan.find(w), std::string::npos) << w << " in " << plan;
    auto plain = run_spt(d, {"plan", seq, "-o", d.file("plain.json"), "--frames", "1-3", "--progress", "none"});
    ASSERT_EQ(plain.code, 0) << plain.err;
    const std::string p2 = slurp(d.file("plain.json"));
    for (const char* w : {"\"color-encoding\"", "\"alpha\"", "\"colorspace\"", "\"ocio\"", "\"layer\""})
        EXPECT_EQ(p2.find(w), std::string::npos) << w;
}
