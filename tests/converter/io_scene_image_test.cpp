// read_scene_image (issue 17): render output as a compositor has it. Real EXRs keep their
// premultiplied alpha and HDR values; straight alpha is premultiplied after linearizing; input
// colour spaces go through OCIO (a config using OCIO's own built-in ACES transform, so the
// expected numbers are not ours); NaN/inf/negatives are replaced with warnings; EXR layers and
// parts, data windows, limits and broken files.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "ocio_test_config.hpp"
#include "temp_dir.hpp"
#include "io/color_config.hpp"
#include "frames/exr_layers.hpp"
#include "frames/scene_image.hpp"

namespace fs = std::filesystem;
using spt::io::read_scene_image;
using spt::io::SceneImage;
using spt::io::SceneReadOptions;

namespace {

using spt_test::TempDir;

std::string media(const std::string& rel) { return std::string(SPT_MEDIA_DIR) + "/" + rel; }

// Writes float pixels (spec.width * spec.height * spec.nchannels) as the spec says.
void write_file(const std::string& path, const OIIO::ImageSpec& spec, const std::vector<float>& px) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << path;
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data())) << out->geterror();
    ASSERT_TRUE(out->close());
}

OIIO::ImageSpec exr_spec(int w, int h, std::vector<std::string> channels, OIIO::TypeDesc t = OIIO::TypeDesc::HALF) {
    OIIO::ImageSpec s(w, h, int(channels.size()), t);
    s.channelnames = std::move(channels);
    s.alpha_channel = -1;
    for (size_t i = 0; i < s.channelnames.size(); ++i)
        if (s.channelnames[i] == "A") s.alpha_channel = int(i);
    return s;
}

std::vector<float> raw_pixels(const std::string& path, int& w, int& h, int& n) {
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << path;
    if (!in) return {};
    const OIIO::ImageSpec& s = in->spec();
    w = s.width, h = s.height, n = s.nchannels;
    std::vector<float> px(size_t(w) * h * n);
    EXPECT_TRUE(in->read_image(0, 0, 0, n, OIIO::TypeDesc::FLOAT, px.data()));
    return px;
}

const float* px(const SceneImage& img, uint32_t x, uint32_t y) { return &img.rgba[(size_t(y) * img.width + x) * 4]; }

bool has_warning(const SceneImage& img, const std::string& a, const std::string& b = "") {
    for (const std::string& w : img.warnings)
        if (w.find(a) != std::string::npos && w.find(b) != std::string::npos) return true;
    return false;
}

std::string all_warnings(const SceneImage& img) {
    std::string t;
    for (const std::string& w : img.warnings) t += w + "\n";
    return t;
}

// A studio-style OCIO v2 config: lin_rec709 reference, ACEScg through OCIO's own built-in
// AP1 -> Rec.709 (Bradford) transform, sRGB texture space.
std::string write_aces_config(const TempDir& d) { return spt_test::write_studio_ocio(d.file("studio.ocio")); }

float srgb_to_linear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

}  // namespace

TEST(SceneImage, OrbitKeepsPremultipliedAlphaAndHdrExactly) {
    const std::string path = media("exr/orbit/orbit.0001.exr");
    ASSERT_TRUE(fs::exists(path)) << "test media missing: " << path;
    auto r = read_scene_image(path);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r->width, 480u);
    EXPECT_EQ(r->height, 270u);
    EXPECT_TRUE(r->has_alpha);
    EXPECT_TRUE(r->is_float);
    EXPECT_EQ(r->colorspace, "linear");  // the built-in config's name for linear Rec.709
    EXPECT_TRUE(r->warnings.empty()) << all_warnings(*r);
    int w, h, n;
    const std::vector<float> raw = raw_pixels(path, w, h, n);
    ASSERT_EQ(n, 4);
    ASSERT_EQ(raw.size(), r->rgba.size());
    // Linear Rec.709 in, linear Rec.709 out: the file's values, alpha included, bit for bit.
    size_t transparent = 0, opaque = 0, differ = 0;
    float max_color = 0.f;
    for (size_t i = 0; i < raw.size(); ++i) differ += raw[i] != r->rgba[i];
    for (size_t i = 0; i < raw.size(); i += 4) {
        transparent += r->rgba[i + 3] == 0.f;
        opaque += r->rgba[i + 3] == 1.f;
        for (int k = 0; k < 3; ++k) max_color = std::max(max_color, r->rgba[i + k]);
    }
    EXPECT_EQ(differ, 0u);
    EXPECT_GT(transparent, raw.size() / 4 / 4) << "orbit has a transparent background";
    EXPECT_GT(opaque, 1000u);
    EXPECT_GT(max_color, 10.f) << "the glowing sphere's HDR values must survive";
}

TEST(SceneImage, PngAndTiffStraightAlphaIsLinearizedThenPremultiplied) {
    TempDir d;
    for (const char* name : {"straight.png", "straight16.tif"}) {
        SCOPED_TRACE(name);
        const std::string path = d.file(name);
        OIIO::ImageSpec s(3, 1, 4, std::string(name).find(".tif") != std::string::npos ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
        s.alpha_channel = 3;
        s.attribute("oiio:UnassociatedAlpha", 1);  // the values are PNG's own: straight
        // (255,128,0) at alpha 128; a colour under alpha 0; an opaque mid grey.
        write_file(path, s, {1.f, 128 / 255.f, 0.f, 128 / 255.f, 1.f, 1.f, 1.f, 0.f, 0.5f, 0.5f, 0.5f, 1.f});
        auto r = read_scene_image(path);
        ASSERT_TRUE(r.ok()) << r.error().message;
        EXPECT_TRUE(r->has_alpha);
        EXPECT_FALSE(r->is_float);
        EXPECT_EQ(r->colorspace, "sRGB");
        const float a = 128 / 255.f;
        const float* p0 = px(*r, 0, 0);
        EXPECT_NEAR(p0[0], 1.f * a, 2e-3);
        EXPECT_NEAR(p0[1], srgb_to_linear(128 / 255.f) * a, 2e-3);  // 0.2159 * 0.502, not 0.502 * 0.502
        EXPECT_NEAR(p0[2], 0.f, 1e-6);
        EXPECT_NEAR(p0[3], a, 1e-6);
        const float* p1 = px(*r, 1, 0);
        for (int k = 0; k < 4; ++k) EXPECT_EQ(p1[k], 0.f) << k;
        const float* p2 = px(*r, 2, 0);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(p2[k], srgb_to_linear(0.5f), 2e-3);
        EXPECT_EQ(p2[3], 1.f);
    }
}

TEST(SceneImage, NoAlphaMeansOpaqueAndSixteenBitIsSrgb) {
    TempDir d;
    const std::string path = d.file("rgb16.png");
    write_file(path, OIIO::ImageSpec(2, 1, 3, OIIO::TypeDesc::UINT16), {0.f, 0.5f, 1.f, 0.25f, 0.25f, 0.25f});
    auto r = read_scene_image(path);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_FALSE(r->has_alpha);
    EXPECT_FALSE(r->is_float);
    EXPECT_NEAR(px(*r, 0, 0)[1], srgb_to_linear(0.5f), 2e-3);
    EXPECT_EQ(px(*r, 0, 0)[3], 1.f);
    EXPECT_EQ(px(*r, 1, 0)[3], 1.f);
    // Gray + alpha PNG: gray into all three channels, premultiplied.
    const std::string ga = d.file("ga.png");
    OIIO::ImageSpec s(1, 1, 2, OIIO::TypeDesc::UINT8);
    s.alpha_channel = 1;
    s.attribute("oiio:UnassociatedAlpha", 1);
    write_file(ga, s, {1.f, 0.5f});
    auto g = read_scene_image(ga);
    ASSERT_TRUE(g.ok()) << g.error().message;
    EXPECT_TRUE(g->has_alpha);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(px(*g, 0, 0)[k], 128 / 255.f, 3e-3);
}

TEST(SceneImage, AcesCgPrimaryConvertsAsOcioSaysAndNegativesAreClamped) {
    TempDir d;
    const std::string cfg = write_aces_config(d);
    const std::string path = d.file("acescg.exr");
    write_file(path, exr_spec(2, 1, {"R", "G", "B"}, OIIO::TypeDesc::FLOAT), {1.f, 0.f, 0.f, 0.5f, 0.5f, 0.5f});
    SceneReadOptions o;
    o.ocio_config = cfg;
    o.colorspace = "ACEScg";
    auto r = read_scene_image(path, o);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r->colorspace, "ACEScg");
    // ACEScg red is (1.705, -0.130, -0.024) in linear Rec.709: the negatives become 0.
    EXPECT_NEAR(px(*r, 0, 0)[0], 1.70505, 1e-3);
    EXPECT_EQ(px(*r, 0, 0)[1], 0.f);
    EXPECT_EQ(px(*r, 0, 0)[2], 0.f);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(px(*r, 1, 0)[k], 0.5f, 1e-3) << "grey stays grey";
    EXPECT_TRUE(has_warning(*r, path + ": 2 negative values set to 0", "ACEScg")) << all_warnings(*r);

    // Aliases resolve to the space; the default for a float file is lin_rec709, unchanged.
    o.colorspace = "ACES - ACEScg";
    auto alias = read_scene_image(path, o);
    ASSERT_TRUE(alias.ok()) << alias.error().message;
    EXPECT_EQ(alias->rgba, r->rgba);
    o.colorspace.clear();
    auto lin = read_scene_image(path, o);
    ASSERT_TRUE(lin.ok()) << lin.error().message;
    EXPECT_EQ(lin->colorspace, "lin_rec709");
    EXPECT_EQ(px(*lin, 0, 0)[0], 1.f);
    EXPECT_TRUE(lin->warnings.empty()) << all_warnings(*lin);

    // $OCIO picks the config when --ocio is not given.
    ::setenv("OCIO", cfg.c_str(), 1);
    SceneReadOptions env;
    env.colorspace = "ACEScg";
    auto e = read_scene_image(path, env);
    ::unsetenv("OCIO");
    ASSERT_TRUE(e.ok()) << e.error().message;
    EXPECT_EQ(e->rgba, r->rgba);
}

TEST(SceneImage, ConventionalNamesWorkWithEveryConfig) {
    TempDir d;
    auto builtin = spt::io::color_config("");
    ASSERT_TRUE(builtin.ok()) << builtin.error().message;
    EXPECT_TRUE(builtin->builtin);
    EXPECT_EQ(*spt::io::find_colorspace(*builtin, "lin_rec709"), "linear");
    EXPECT_EQ(*spt::io::find_colorspace(*builtin, "srgb"), "sRGB");
    auto studio = spt::io::color_config(write_aces_config(d));
    ASSERT_TRUE(studio.ok()) << studio.error().message;
    EXPECT_EQ(*spt::io::find_colorspace(*studio, "sRGB"), "srgb_tx");
    EXPECT_EQ(*spt::io::find_colorspace(*studio, "lin_ap1"), "ACEScg");
    EXPECT_EQ(*spt::io::find_colorspace(*studio, "scene_linear"), "ACEScg");  // a role
    EXPECT_EQ(*spt::io::linear_rec709_space(*studio), "lin_rec709");
    auto t = spt::io::color_transform(*studio, "srgb_tx", "lin_rec709");
    ASSERT_TRUE(t.ok()) << t.error().message;
    EXPECT_FALSE(t->linear);
    auto m = spt::io::color_transform(*studio, "ACEScg", "lin_rec709");
    ASSERT_TRUE(m.ok()) << m.error().message;
    EXPECT_TRUE(m->linear);
}

TEST(SceneImage, SrgbEncodedExrIsUnpremultipliedAroundTheCurve) {
    TempDir d;
    const std::string path = d.file("srgb.exr");
    // Premultiplied 0.25 at alpha 0.5: straight 0.5 sRGB -> 0.214 linear -> 0.107 premultiplied.
    write_file(path, exr_spec(1, 1, {"R", "G", "B", "A"}), {0.25f, 0.25f, 0.25f, 0.5f});
    SceneReadOptions o;
    o.colorspace = "sRGB";
    auto r = read_scene_image(path, o);
    ASSERT_TRUE(r.ok()) << r.error().message;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(px(*r, 0, 0)[k], srgb_to_linear(0.5f) * 0.5f, 2e-3);
    EXPECT_EQ(px(*r, 0, 0)[3], 0.5f);
}

TEST(SceneImage, UnknownColourSpaceAndBadConfigAreClearErrors) {
    TempDir d;
    const std::string path = d.file("a.exr");
    write_file(path, exr_spec(1, 1, {"R", "G", "B"}), {1.f, 1.f, 1.f});
    SceneReadOptions o;
    o.colorspace = "ACEScgg";
    auto r = read_scene_image(path, o);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, spt::Code::InvalidArgument);
    const std::string& m = r.error().message;
    EXPECT_EQ(m.rfind(path + ": ", 0), 0u) << m;
    EXPECT_NE(m.find("'ACEScgg'"), std::string::npos) << m;
    EXPECT_NE(m.find("sRGB"), std::string::npos) << m;
    EXPECT_NE(m.find("linear"), std::string::npos) << m;

    o.colorspace.clear();
    o.ocio_config = d.file("missing.ocio");
    auto missing = read_scene_image(path, o);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find(path), std::string::npos) << missing.error().message;
    EXPECT_NE(missing.error().message.find("missing.ocio"), std::string::npos) << missing.error().message;

    std::ofstream(d.file("broken.ocio")) << "ocio_profile_version: 2\ncolorspaces: [[[\n";
    o.ocio_config = d.file("broken.ocio");
    auto broken = read_scene_image(path, o);
    ASSERT_FALSE(broken.ok());
    EXPECT_NE(broken.error().message.find("broken.ocio"), std::string::npos) << broken.error().message;
}

TEST(SceneImage, NanInfAndNegativesAreReplacedWithWarnings) {
    TempDir d;
    const std::string path = d.file("bad.exr");
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    write_file(path, exr_spec(4, 1, {"R", "G", "B", "A"}, OIIO::TypeDesc::FLOAT),
               {nan, 0.5f, 3.f, 1.f,  inf, -0.5f, 0.25f, 1.f,  -inf, nan, 1.f, nan,  0.1f, 0.2f, 0.3f, 1.f});
    auto r = read_scene_image(path);
    ASSERT_TRUE(r.ok()) << r.error().message;
    const std::vector<float> want = {0.f, 0.5f, 3.f, 1.f,  3.f, 0.f, 0.25f, 1.f,  0.f, 0.f, 1.f, 0.f,  0.1f, 0.2f, 0.3f, 1.f};
    EXPECT_EQ(r->rgba, want);
    for (float v : r->rgba) EXPECT_TRUE(std::isfinite(v) && v >= 0.f);
    EXPECT_TRUE(has_warning(*r, path + ": 3 NaN values set to 0")) << all_warnings(*r);
    EXPECT_TRUE(has_warning(*r, path + ": 1 +infinite values set to 3")) << all_warnings(*r);
    EXPECT_TRUE(has_warning(*r, path + ": 1 -infinite values set to 0")) << all_warnings(*r);
    EXPECT_TRUE(has_warning(*r, path + ": 1 negative values set to 0")) << all_warnings(*r);

    // Only infinities: they take the half-float maximum.
    const std::string only = d.file("inf.exr");
    write_file(only, exr_spec(1, 1, {"R", "G", "B"}, OIIO::TypeDesc::FLOAT), {inf, 0.f, 0.f});
    auto i = read_scene_image(only);
    ASSERT_TRUE(i.ok()) << i.error().message;
    EXPECT_EQ(px(*i, 0, 0)[0], 65504.f);
}

TEST(SceneImage, LayersAreSelectedByNameAndAMissingLayerListsThem) {
    TempDir d;
    const std::string path = d.file("blender.exr");
    // Blender's multilayer layout: no unnamed channels.
    write_file(path, exr_spec(1, 1, {"ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B",
                                     "ViewLayer.Combined.A", "ViewLayer.Depth.Z", "ViewLayer.Emit.R",
                                     "ViewLayer.Emit.G", "ViewLayer.Emit.B"}, OIIO::TypeDesc::FLOAT),
               {0.1f, 0.2f, 0.3f, 0.5f, 100.f, 4.f, 5.f, 6.f});
    auto first = read_scene_image(path);
    ASSERT_TRUE(first.ok()) << first.error().message;
    EXPECT_TRUE(first->has_alpha);
    EXPECT_EQ(first->rgba, (std::vector<float>{0.1f, 0.2f, 0.3f, 0.5f}));
    SceneReadOptions o;
    o.layer = "ViewLayer.Emit";
    auto emit = read_scene_image(path, o);
    ASSERT_TRUE(emit.ok()) << emit.error().message;
    EXPECT_FALSE(emit->has_alpha);
    EXPECT_EQ(emit->rgba, (std::vector<float>{4.f, 5.f, 6.f, 1.f}));

    o.layer = "ViewLayer.Diffuse";
    auto missing = read_scene_image(path, o);
    ASSERT_FALSE(missing.ok());
    const std::string& m = missing.error().message;
    EXPECT_EQ(m.rfind(path + ": ", 0), 0u) << m;
    for (const char* want : {"'ViewLayer.Diffuse'", "ViewLayer.Combined", "ViewLayer.Depth", "ViewLayer.Emit"})
        EXPECT_NE(m.find(want), std::string::npos) << want << " in " << m;
    o.layer = "ViewLayer.Depth";
    auto depth = read_scene_image(path, o);
    ASSERT_FALSE(depth.ok());
    EXPECT_NE(depth.error().message.find("no R, G, B"), std::string::npos) << depth.error().message;

    // The unnamed layer wins over named ones.
    const std::string mixed = d.file("mixed.exr");
    write_file(mixed, exr_spec(1, 1, {"R", "G", "B", "A", "diffuse.R", "diffuse.G", "diffuse.B"}, OIIO::TypeDesc::FLOAT),
               {0.7f, 0.8f, 0.9f, 1.f, 0.1f, 0.1f, 0.1f});
    auto m2 = read_scene_image(mixed);
    ASSERT_TRUE(m2.ok()) << m2.error().message;
    EXPECT_EQ(m2->rgba, (std::vector<float>{0.7f, 0.8f, 0.9f, 1.f}));

    // Only data channels: an error that says to pick a layer.
    const std::string data = d.file("data.exr");
    write_file(data, exr_spec(1, 1, {"P.X", "P.Y", "P.Z"}, OIIO::TypeDesc::FLOAT), {1.f, 2.f, 3.f});
    auto none = read_scene_image(data);
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().message.find("--layer"), std::string::npos) << none.error().message;
}

TEST(SceneImage, MultiPartExrTakesThePartWithColour) {
    TempDir d;
    const std::string path = d.file("parts.exr");
    OIIO::ImageSpec specs[2] = {exr_spec(2, 1, {"Z"}, OIIO::TypeDesc::FLOAT),
                                exr_spec(2, 1, {"R", "G", "B", "A"}, OIIO::TypeDesc::FLOAT)};
    specs[0].attribute("oiio:subimagename", "depth");
    specs[1].attribute("oiio:subimagename", "beauty");
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->supports("multiimage"));
    ASSERT_TRUE(out->open(path, 2, specs)) << out->geterror();
    const std::vector<float> z = {7.f, 8.f}, rgba = {0.1f, 0.2f, 0.3f, 1.f, 0.4f, 0.5f, 0.6f, 0.5f};
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, z.data())) << out->geterror();
    ASSERT_TRUE(out->open(path, specs[1], OIIO::ImageOutput::AppendSubimage)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, rgba.data())) << out->geterror();
    ASSERT_TRUE(out->close());
    auto r = read_scene_image(path);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r->rgba, rgba);
    SceneReadOptions o;
    o.layer = "beauty";
    auto named = read_scene_image(path, o);
    ASSERT_TRUE(named.ok()) << named.error().message;
    EXPECT_EQ(named->rgba, rgba);
}

TEST(SceneImage, SmallDataWindowIsTransparentOutside) {
    TempDir d;
    for (bool tiled : {false, true}) {
        const std::string path = d.file(tiled ? "dw_tiled.exr" : "dw.exr");
        // Display 8x6; data 3x2 at (2,1), no alpha channel.
        OIIO::ImageSpec s = exr_spec(3, 2, {"R", "G", "B"}, OIIO::TypeDesc::FLOAT);
        s.x = 2, s.y = 1;
        s.full_x = 0, s.full_y = 0, s.full_width = 8, s.full_height = 6;
        if (tiled) s.tile_width = s.tile_height = 16;
        std::vector<float> v;
        for (int i = 0; i < 6; ++i) v.insert(v.end(), {float(i + 1), 0.5f, 0.25f});
        write_file(path, s, v);
        auto r = read_scene_image(path);
        ASSERT_TRUE(r.ok()) << r.error().message;
        EXPECT_EQ(r->width, 8u);
        EXPECT_EQ(r->height, 6u);
        EXPECT_TRUE(r->has_alpha) << "transparent pixels outside the data window";
        EXPECT_TRUE(has_warning(*r, path, "data window")) << all_warnings(*r);
        for (uint32_t y = 0; y < 6; ++y)
            for (uint32_t x = 0; x < 8; ++x) {
                const bool in = x >= 2 && x < 5 && y >= 1 && y < 3;
                const float* p = px(*r, x, y);
                if (in) {
                    EXPECT_EQ(p[0], float((y - 1) * 3 + (x - 2) + 1)) << x << "," << y;
                    EXPECT_EQ(p[3], 1.f);
                } else {
                    for (int k = 0; k < 4; ++k) EXPECT_EQ(p[k], 0.f) << x << "," << y;
                }
            }
    }
    // Overscan: a data window larger than the display window is cropped to it.
    const std::string over = d.file("overscan.exr");
    OIIO::ImageSpec s = exr_spec(4, 4, {"R", "G", "B"}, OIIO::TypeDesc::FLOAT);
    s.x = -1, s.y = -1;
    s.full_x = 0, s.full_y = 0, s.full_width = 2, s.full_height = 2;
    std::vector<float> v;
    for (int i = 0; i < 16; ++i) v.insert(v.end(), {float(i), 0.f, 0.f});
    write_file(over, s, v);
    auto r = read_scene_image(over);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r->width, 2u);
    EXPECT_FALSE(r->has_alpha);
    EXPECT_EQ(px(*r, 0, 0)[0], 5.f);
    EXPECT_EQ(px(*r, 1, 1)[0], 10.f);
}

TEST(SceneImage, TiledExrReadsExactly) {
    TempDir d;
    const std::string path = d.file("tiled.exr");
    OIIO::ImageSpec s = exr_spec(37, 23, {"R", "G", "B", "A"}, OIIO::TypeDesc::FLOAT);
    s.tile_width = s.tile_height = 16;
    std::vector<float> v;
    for (int i = 0; i < 37 * 23; ++i) v.insert(v.end(), {float(i % 37), float(i / 37), 0.5f, 1.f});
    write_file(path, s, v);
    SceneReadOptions o;
    auto r = read_scene_image(path, o);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r->rgba, v);
}

TEST(SceneImage, LimitsAndBrokenFilesAreErrorsNamingTheFile) {
    TempDir d;
    const std::string big = d.file("big.exr");
    write_file(big, exr_spec(64, 32, {"R", "G", "B"}), std::vector<float>(64 * 32 * 3, 0.5f));
    SceneReadOptions o;
    o.max_side = 48;
    auto side = read_scene_image(big, o);
    ASSERT_FALSE(side.ok());
    EXPECT_EQ(side.error().code, spt::Code::LimitExceeded);
    EXPECT_NE(side.error().message.find(big), std::string::npos);
    o.max_side = 1000;
    o.max_pixels = 1000;
    EXPECT_EQ(read_scene_image(big, o).error().code, spt::Code::LimitExceeded);

    auto missing = read_scene_image(d.file("none.exr"));
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("none.exr"), std::string::npos);
    auto folder = read_scene_image(d.path.string());
    ASSERT_FALSE(folder.ok());

    std::ofstream(d.file("junk.exr")) << "not an image at all";
    auto junk = read_scene_image(d.file("junk.exr"));
    ASSERT_FALSE(junk.ok());
    EXPECT_NE(junk.error().message.find("junk.exr"), std::string::npos);

    // A real render cut short.
    const std::string src = media("exr/orbit/orbit.0001.exr");
    ASSERT_TRUE(fs::exists(src)) << "test media missing: " << src;
    const std::string cut = d.file("cut.exr");
    fs::copy_file(src, cut);
    fs::resize_file(cut, fs::file_size(src) / 2);
    auto c = read_scene_image(cut);
    ASSERT_FALSE(c.ok());
    EXPECT_NE(c.error().message.find("cut.exr"), std::string::npos) << c.error().message;
}

TEST(SceneImage, ChannelPickRules) {
    using spt::io::ImagePart;
    using spt::io::pick_channels;
    // PNG-like: by name.
    auto rgba = pick_channels({ImagePart{"", {"R", "G", "B", "A"}, 3}}, "");
    ASSERT_TRUE(rgba.ok());
    EXPECT_EQ(rgba->alpha, 3);
    // Unnamed channels of unknown names: by position, as OIIO orders them.
    auto pos = pick_channels({ImagePart{"", {"channel0", "channel1", "channel2", "channel3"}, -1}}, "");
    ASSERT_TRUE(pos.ok());
    EXPECT_EQ(pos->color[2], 2);
    EXPECT_EQ(pos->alpha, 3);
    auto gray = pick_channels({ImagePart{"", {"Y"}, -1}}, "");
    ASSERT_TRUE(gray.ok());
    EXPECT_TRUE(gray->gray);
    EXPECT_FALSE(pick_channels({ImagePart{"", {}, -1}}, "").ok());
}
