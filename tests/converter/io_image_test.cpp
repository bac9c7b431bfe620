// read_image / write_image: every input flavour (bit depth, channel count, alpha, float),
// errors that name the file, and write/read round trips.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/image_io.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using spt::io::read_image;
using spt::io::write_image;

namespace {

using spt_test::TempDir;

// Writes `px` (w*h*nch values of `type`) with OpenImageIO directly.
template <class T>
void write_raw(const std::string& path, int w, int h, int nch, OIIO::TypeDesc type,
               const std::vector<T>& px, OIIO::TypeDesc file_type) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << path;
    OIIO::ImageSpec spec(w, h, nch, file_type);
    if (nch == 2) spec.alpha_channel = 1;
    if (nch == 4) spec.alpha_channel = 3;
    // The values are as PNG stores them: do not let OIIO un-premultiply them.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(type, px.data())) << out->geterror();
    ASSERT_TRUE(out->close());
}

std::string media(const std::string& rel) { return std::string(SPT_MEDIA_DIR) + "/" + rel; }

}  // namespace

TEST(IoImage, ReadsMediaStills) {
    for (const char* name : {"stills/astronaut.png", "stills/coffee.png", "stills/kodim02.tif"}) {
        if (!fs::exists(media(name))) GTEST_FAIL() << "media absent: " << media(name);
        auto r = read_image(media(name));
        ASSERT_TRUE(r.ok()) << r.error().message;
        EXPECT_GT(r->width, 0u);
        EXPECT_EQ(r->rgb.size(), size_t(r->width) * r->height * 3);
    }
    auto a = read_image(media("stills/astronaut.png"));
    EXPECT_EQ(a->width, 512u);
    EXPECT_EQ(a->height, 512u);
}

TEST(IoImage, ReadsMediaExr) {
    const std::string p = media("exr/earth/earth.0001.exr");
    if (!fs::exists(p)) GTEST_FAIL() << "media absent: " << p;
    auto r = read_image(p);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r->width, 480u);
    EXPECT_EQ(r->height, 270u);
}

TEST(IoImage, Exr8BitKnownValues) {
    TempDir d;
    // Linear values and their sRGB 8-bit codes: 0.214041 is sRGB 0.5 -> 128 (rounded 127.5..).
    std::vector<float> px = {0.f, 0.f, 0.f,  1.f, 1.f, 1.f,  0.0031308f, 0.0031308f, 0.0031308f,
                             4.f, -1.f, 0.2140411f};
    write_raw(d.file("k.exr"), 4, 1, 3, OIIO::TypeDesc::FLOAT, px, OIIO::TypeDesc::FLOAT);
    auto r = read_image(d.file("k.exr"));
    ASSERT_TRUE(r.ok()) << r.error().message;
    const auto& v = r->rgb;
    EXPECT_EQ(v[0], 0);
    EXPECT_EQ(v[3], 255);
    // 0.0031308 linear is 0.04045 sRGB: 10.3 -> 10.
    EXPECT_EQ(v[6], 10);
    EXPECT_EQ(v[9], 255);   // above 1 clips
    EXPECT_EQ(v[10], 0);    // negative clips
    EXPECT_NEAR(v[11], 128, 1);
}

TEST(IoImage, Png16BitAndGray) {
    TempDir d;
    std::vector<uint16_t> rgb16 = {0, 65535, 32896, 257 * 200, 257 * 10, 257 * 77};
    write_raw(d.file("a16.png"), 2, 1, 3, OIIO::TypeDesc::UINT16, rgb16, OIIO::TypeDesc::UINT16);
    auto r = read_image(d.file("a16.png"));
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r->rgb, (std::vector<uint8_t>{0, 255, 128, 200, 10, 77}));

    std::vector<uint8_t> gray = {0, 50, 200};
    write_raw(d.file("g.png"), 3, 1, 1, OIIO::TypeDesc::UINT8, gray, OIIO::TypeDesc::UINT8);
    auto g = read_image(d.file("g.png"));
    ASSERT_TRUE(g.ok()) << g.error().message;
    EXPECT_EQ(g->rgb, (std::vector<uint8_t>{0, 0, 0, 50, 50, 50, 200, 200, 200}));
}

TEST(IoImage, AlphaOverBackground) {
    TempDir d;
    // Gray + alpha: opaque 100, transparent, half-covered 200.
    std::vector<uint8_t> ga = {100, 255, 7, 0, 200, 128};
    write_raw(d.file("ga.png"), 3, 1, 2, OIIO::TypeDesc::UINT8, ga, OIIO::TypeDesc::UINT8);
    spt::io::ReadOptions o;
    o.background = {10, 20, 30};
    auto r = read_image(d.file("ga.png"), o);
    ASSERT_TRUE(r.ok()) << r.error().message;
    const auto& v = r->rgb;
    EXPECT_EQ(v[0], 100);
    EXPECT_EQ(v[3], 10);
    EXPECT_EQ(v[4], 20);
    EXPECT_EQ(v[5], 30);
    // 200 * 128/255 + bg * 127/255
    EXPECT_NEAR(v[6], 200 * 128 / 255.0 + 10 * 127 / 255.0, 1.0);

    // RGBA over white (the default).
    std::vector<uint8_t> rgba = {255, 0, 0, 255, 0, 0, 255, 0, 0, 255, 0, 64};
    write_raw(d.file("c.png"), 3, 1, 4, OIIO::TypeDesc::UINT8, rgba, OIIO::TypeDesc::UINT8);
    auto c = read_image(d.file("c.png"));
    ASSERT_TRUE(c.ok()) << c.error().message;
    EXPECT_EQ(c->rgb[0], 255);
    EXPECT_EQ(c->rgb[1], 0);
    EXPECT_EQ(c->rgb[3], 255);  // transparent blue -> white
    EXPECT_EQ(c->rgb[5], 255);
    EXPECT_NEAR(c->rgb[6], 255 * 191 / 255.0, 1.0);  // 25% green over white
    EXPECT_EQ(c->rgb[7], 255);
}

TEST(IoImage, ErrorsNameTheFile) {
    TempDir d;
    auto missing = read_image(d.file("nope.png"));
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("nope.png"), std::string::npos);

    const std::string bad = d.file("corrupt.png");
    {
        std::ofstream f(bad, std::ios::binary);
        f << "\x89PNG\r\n\x1a\n" << std::string(40, '\x11');
    }
    auto c = read_image(bad);
    ASSERT_FALSE(c.ok());
    EXPECT_NE(c.error().message.find("corrupt.png"), std::string::npos) << c.error().message;

    // A truncated real image.
    std::vector<uint8_t> px(64 * 64 * 3, 90);
    ASSERT_TRUE(write_image(d.file("t.png"), 64, 64, px.data()).ok());
    fs::resize_file(d.file("t.png"), fs::file_size(d.file("t.png")) / 2);
    auto t = read_image(d.file("t.png"));
    ASSERT_FALSE(t.ok());
    EXPECT_NE(t.error().message.find("t.png"), std::string::npos) << t.error().message;

    spt::io::ReadOptions small;
    small.max_pixels = 100;
    ASSERT_TRUE(write_image(d.file("big.png"), 64, 64, px.data()).ok());
    auto lim = read_image(d.file("big.png"), small);
    ASSERT_FALSE(lim.ok());
    EXPECT_EQ(lim.error().code, spt::Code::LimitExceeded);
}

TEST(IoImage, RoundTripPngTifExactExrClose) {
    TempDir d;
    const uint32_t w = 37, h = 23;
    std::vector<uint8_t> px(size_t(w) * h * 3);
    for (size_t i = 0; i < px.size(); ++i) px[i] = uint8_t((i * 7919u) >> 3);
    for (const char* name : {"r.png", "r.tif"}) {
        ASSERT_TRUE(write_image(d.file(name), w, h, px.data()).ok());
        auto r = read_image(d.file(name));
        ASSERT_TRUE(r.ok()) << r.error().message;
        EXPECT_EQ(r->rgb, px) << name;
    }
    ASSERT_TRUE(write_image(d.file("r.exr"), w, h, px.data()).ok());
    auto in = OIIO::ImageInput::open(d.file("r.exr"));
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().format, OIIO::TypeDesc::HALF);
    auto e = read_image(d.file("r.exr"));
    ASSERT_TRUE(e.ok()) << e.error().message;
    int maxdiff = 0;
    for (size_t i = 0; i < px.size(); ++i) maxdiff = std::max(maxdiff, std::abs(int(e->rgb[i]) - int(px[i])));
    EXPECT_LE(maxdiff, 1);
    // No temporary file is left beside the outputs.
    for (auto& f : fs::directory_iterator(d.path))
        EXPECT_EQ(f.path().string().find(".partial"), std::string::npos) << f.path();
}

TEST(IoImage, FailedWriteLeavesNothing) {
    TempDir d;
    std::vector<uint8_t> px(12, 1);
    auto s = write_image(d.file("no/such/dir/x.png"), 2, 2, px.data());
    EXPECT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("x.png"), std::string::npos);
    auto u = write_image(d.file("x.unknownext"), 2, 2, px.data());
    EXPECT_FALSE(u.ok());
    EXPECT_TRUE(fs::is_empty(d.path));
}

// spt plan reads half-float files through io::half_to_srgb8 instead of read_image's float
// path; the table must give read_image's bytes for every one of the 65536 half bit patterns
// (NaN, infinities, negatives, denormals included), in every channel position, and for gray.
TEST(IoImage, HalfTableGivesReadImageBytesForEveryHalf) {
    const std::array<uint8_t, 65536>* table = spt::io::half_to_srgb8();
    ASSERT_NE(table, nullptr) << "no table: spt plan would read half files the long way";
    TempDir d;
    std::vector<uint16_t> rgb(65536 * 3), gray(65536);
    for (uint32_t i = 0; i < 65536; ++i) {
        rgb[i * 3] = uint16_t(i);
        rgb[i * 3 + 1] = uint16_t(i * 40503u + 12345u);  // an odd multiplier: every value once
        rgb[i * 3 + 2] = uint16_t(65535u - i);
        gray[i] = uint16_t(i * 2654435761u);
    }
    write_raw(d.file("rgb.exr"), 256, 256, 3, OIIO::TypeDesc::HALF, rgb, OIIO::TypeDesc::HALF);
    write_raw(d.file("gray.exr"), 256, 256, 1, OIIO::TypeDesc::HALF, gray, OIIO::TypeDesc::HALF);
    auto a = read_image(d.file("rgb.exr"));
    ASSERT_TRUE(a.ok()) << a.error().message;
    size_t wrong = 0;
    for (size_t k = 0; k < rgb.size(); ++k) wrong += a->rgb[k] != (*table)[rgb[k]];
    EXPECT_EQ(wrong, 0u) << "of " << rgb.size() << " RGB samples";
    auto g = read_image(d.file("gray.exr"));
    ASSERT_TRUE(g.ok()) << g.error().message;
    wrong = 0;
    for (size_t p = 0; p < gray.size(); ++p)
        for (int k = 0; k < 3; ++k) wrong += g->rgb[p * 3 + size_t(k)] != (*table)[gray[p]];
    EXPECT_EQ(wrong, 0u) << "of " << gray.size() << " gray samples";
    EXPECT_EQ((*table)[0x3C00], 255);  // 1.0
    EXPECT_EQ((*table)[0x7E00], 0);    // NaN
    EXPECT_EQ((*table)[0x7C00], 255);  // +inf
    EXPECT_EQ((*table)[0xBC00], 0);    // -1.0
}
