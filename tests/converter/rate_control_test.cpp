// Rate control and frame coding 2 on painter output: the file decodes to exactly the painter's
// strokes and canvas; --target-bytes lands near its target; --target-psnr reaches its target.
#include <gtest/gtest.h>

#include <filesystem>

#include "converter/cli_test_util.hpp"
#include "converter/paint_test_util.hpp"
#include "paint/painter.hpp"
#include "spt/spt.hpp"

using namespace spt;
namespace fs = std::filesystem;

namespace {

struct Painted {
    paint::PaintSetup setup;
    std::vector<Stroke> strokes;
    Canvas canvas;
};

Painted paint_model(const paint_test::Model& m, const paint::PaintOptions& po) {
    Painted p;
    p.setup = paint::make_setup(m.width, m.height, {255, 255, 255}, paint::default_sets(m.width, m.height, 4),
                                paint::default_templates());
    auto r = Renderer::create(p.setup.header, p.setup.templates);
    p.canvas = Canvas(m.width, m.height, {255, 255, 255});
    paint::paint(m.view(), p.canvas, **r, p.setup, po, p.strokes);
    return p;
}

// Writes with coding 2 and checks the frame used it and decodes to the painter's canvas.
void expect_replay_round_trip(const Painted& p, const paint::PaintOptions& po, const std::string& path) {
    StreamInfo info;
    info.header = p.setup.header;
    info.templates = p.setup.templates;
    WriterOptions wo;
    wo.coding = Coding::Replay;
    auto w = Writer::create(path, info, wo);
    ASSERT_TRUE(w);
    Frame f;
    f.added = p.strokes;
    f.replay = paint::replay_info(p.setup, po, p.canvas.width, p.canvas.height);
    ASSERT_TRUE((*w)->append(f));
    ASSERT_TRUE((*w)->finish());
    auto r = Reader::open(path);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ((*r)->frames()[0].coding, Coding::Replay);
    auto live = (*r)->strokes_at(0);
    ASSERT_TRUE(live) << live.error().message;
    EXPECT_EQ(**live, p.strokes);
    auto rd = Renderer::create((*r)->info().header, (*r)->info().templates);
    Canvas out(p.canvas.width, p.canvas.height);
    ASSERT_TRUE((*rd)->render(out, **live));
    EXPECT_TRUE(out.rgb == p.canvas.rgb) << "decoded canvas differs from the painter's";
}

paint_test::Model model() {
    auto m = paint_test::load_small("stills/kodim07.tif", 96, 64);
    return m.width ? m : paint_test::synthetic(96, 64);
}

TEST(RateCoding2, PainterOutputDecodesBitIdentically) {
    spt_test::TempDir dir;
    const auto m = model();
    for (int variant = 0; variant < 3; ++variant) {
        paint::PaintOptions po;
        po.seed = 11 + variant;
        po.threads = 2;
        po.lambda = 16;
        po.color_step = variant == 0 ? 1 : 4;
        if (variant == 1) po.orient = paint::OrientMode::Random;
        if (variant == 2) po.rois = {{10, 8, 30, 20}, {50, 30, 100, 100}};
        const Painted p = paint_model(m, po);
        ASSERT_GT(p.strokes.size(), 50u);
        SCOPED_TRACE("variant " + std::to_string(variant));
        expect_replay_round_trip(p, po, dir.file("p" + std::to_string(variant) + ".spt"));
    }
}

TEST(RateCoding2, RepaintRegionDecodesBitIdentically) {
    // An inter-frame style repaint: a pixel region becomes the 8x8 blocks it touches.
    spt_test::TempDir dir;
    const auto m = model();
    paint::PaintOptions po;
    po.lambda = 16;
    po.color_step = 4;
    std::vector<uint8_t> region(size_t(m.width) * m.height, 0);
    for (uint32_t y = 20; y < 45; ++y)
        for (uint32_t x = 30; x < 70; ++x) region[size_t(y) * m.width + x] = 1;
    Painted p;
    p.setup = paint::make_setup(m.width, m.height, {255, 255, 255}, paint::default_sets(m.width, m.height, 4),
                                paint::default_templates());
    auto r = Renderer::create(p.setup.header, p.setup.templates);
    p.canvas = Canvas(m.width, m.height, {255, 255, 255});
    paint::paint(m.view(), p.canvas, **r, p.setup, po, p.strokes, &region);
    ASSERT_GT(p.strokes.size(), 10u);
    for (const Stroke& s : p.strokes) {
        const uint32_t x = uint32_t(s.stamp.x >> 4), y = uint32_t(s.stamp.y >> 4);
        EXPECT_TRUE(x >= 24 && x < 72 && y >= 16 && y < 48) << x << "," << y;  // the touched blocks
    }
    StreamInfo info;
    info.header = p.setup.header;
    info.templates = p.setup.templates;
    WriterOptions wo;
    wo.coding = Coding::Replay;
    const std::string path = dir.file("region.spt");
    auto w = Writer::create(path, info, wo);
    Frame f;
    f.added = p.strokes;
    f.replay = paint::replay_info(p.setup, po, m.width, m.height, &region);
    ASSERT_TRUE((*w)->append(f));
    ASSERT_TRUE((*w)->finish());
    auto rd = Reader::open(path);
    ASSERT_TRUE(rd);
    EXPECT_EQ((*rd)->frames()[0].coding, Coding::Replay);
    auto live = (*rd)->strokes_at(0);
    ASSERT_TRUE(live);
    EXPECT_EQ(**live, p.strokes);
}

TEST(RateCli, TargetBytesLandsWithinFivePercent) {
    REQUIRE_TOOL();
    const std::string in = paint_test::media("foreign/coffee-256.png");
    if (!std::filesystem::exists(in)) GTEST_FAIL() << "media missing";
    spt_test::TempDir dir;
    const uint64_t target = 7000;
    const auto r = spt_test::run_spt(dir, {"paint", in, "-o", dir.file("t.spt"), "--progress", "none", "--target-bytes",
                                           std::to_string(target), "--threads", "2"});
    ASSERT_EQ(r.code, 0) << r.err;
    const auto size = std::filesystem::file_size(dir.file("t.spt"));
    EXPECT_LE(size, target);
    EXPECT_GE(double(size), 0.95 * double(target));
    EXPECT_NE(r.err.find("--target-bytes"), std::string::npos) << r.err;
}

TEST(RateCli, TargetPsnrIsReached) {
    REQUIRE_TOOL();
    const std::string in = paint_test::media("foreign/coffee-256.png");
    if (!std::filesystem::exists(in)) GTEST_FAIL() << "media missing";
    spt_test::TempDir dir;
    const auto r = spt_test::run_spt(dir, {"paint", in, "-o", dir.file("p.spt"), "--progress", "none", "--target-psnr",
                                           "27", "--threads", "2", "--preview", dir.file("p.png")});
    ASSERT_EQ(r.code, 0) << r.err;
    auto src = io::read_image(in);
    auto got = io::read_image(dir.file("p.png"));
    ASSERT_TRUE(src && got);
    EXPECT_GE(paint::psnr({src->width, src->height, src->rgb.data()}, got->rgb.data()), 27.0);
    auto rd = Reader::open(dir.file("p.spt"));
    ASSERT_TRUE(rd);
    EXPECT_EQ((*rd)->frames()[0].coding, Coding::Replay);
}

}  // namespace
