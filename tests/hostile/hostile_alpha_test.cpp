// Inputs the stamp painter cannot paint (issue 36 item 12): an image at uniform alpha 128
// painted 0 strokes, "converged", exit 0, 8 dB. Stamps composite over (SPEC.md 8.6): each one
// raises alpha where it lands and none can lower it, so inside an area that is partly
// transparent every stroke costs more alpha error than it gains in colour. Painting it needs a
// stroke that changes colour and keeps alpha (a Porter-Duff "atop" stroke, a format change);
// until then the command says so and names what paints it (--style cartoon: 32.8 dB).
#include <OpenImageIO/imageio.h>

#include "converter/cli_test_util.hpp"

using namespace spt_test;

namespace {

// A 96x64 RGBA PNG: a colour ramp at alpha `a` (a hard matte when `matte`: alpha 0 or 255).
std::string rgba_png(const TempDir& d, const std::string& name, int a, bool matte = false) {
    const int w = 96, h = 64;
    std::vector<uint8_t> px(size_t(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            uint8_t* p = &px[(size_t(y) * w + x) * 4];
            p[0] = uint8_t(x * 2), p[1] = uint8_t(y * 3), p[2] = uint8_t(200 - x);
            p[3] = uint8_t(matte ? (x < w / 2 ? 0 : 255) : a);
        }
    const std::string path = d.file(name);
    auto out = OIIO::ImageOutput::create(path);
    EXPECT_TRUE(out && out->open(path, OIIO::ImageSpec(w, h, 4, OIIO::TypeDesc::UINT8)));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
    out->close();
    return path;
}

}  // namespace

TEST(HostileAlpha, ATranslucentInputIsSaidNotReportedAsConverged) {
    TempDir d;
    for (int a : {128, 200}) {
        const std::string in = rgba_png(d, "a" + std::to_string(a) + ".png", a);
        const auto r = run_spt(d, {"paint", in, "-o", d.file("o.spt")});
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_NE(r.err.find("warning: " + in + ": 100% of its pixels are partly transparent"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("--style cartoon"), std::string::npos) << r.err;
    }
    // Opaque, and a hard matte: nothing to say.
    for (const std::string& in : {rgba_png(d, "a255.png", 255), rgba_png(d, "matte.png", 0, true)}) {
        const auto r = run_spt(d, {"paint", in, "-o", d.file("o.spt")});
        EXPECT_EQ(r.code, 0) << r.err;
        EXPECT_EQ(r.err.find("partly transparent"), std::string::npos) << r.err;
    }
}
