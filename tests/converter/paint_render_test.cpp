// Whole-painting properties: the painter's canvas is what a decoder renders (bit for bit, also
// through a written and re-read file), the output does not depend on the thread count, more
// strokes give a higher PSNR, a PSNR target stops near it, and regions of interest are painted
// finer than the rest.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "paint/painter.hpp"
#include "paint_test_util.hpp"
#include "spt/reader.hpp"
#include "spt/render.hpp"
#include "spt/writer.hpp"

using namespace spt;
using namespace spt::paint;
using spt::paint_test::Model;
using spt::paint_test::Painting;

namespace {

Painting run(const Model& m, PaintOptions opts, std::vector<StrokeSet> sets = {}) {
    if (sets.empty()) sets = default_sets(m.width, m.height, 5);
    return paint_test::paint_model(m.view(), make_setup(m.width, m.height, Rgb8{255, 255, 255}, sets, default_templates()),
                                   opts);
}

PaintOptions base_opts() {
    PaintOptions o;
    o.seed = 42;
    o.threads = 2;
    o.max_strokes = 3000;
    // Small canvases need small strokes; the default lambda suits photos of a megapixel.
    o.lambda = 2;
    return o;
}

}  // namespace

TEST(PaintRender, CanvasEqualsTheRendererBitForBit) {
    const Model m = paint_test::model_or_synthetic(96, 64);
    Painting p = run(m, base_opts());
    ASSERT_GT(p.strokes.size(), 50u);
    Canvas rendered(m.width, m.height);
    ASSERT_TRUE(p.renderer->render(rendered, p.strokes).ok());
    EXPECT_EQ(rendered.rgb, p.canvas.rgb);
    EXPECT_NEAR(psnr(m.view(), p.canvas.rgb.data()), p.stats.psnr, 1e-9);
    for (const Stroke& s : p.strokes) {  // stamps at pixel centres, opaque
        ASSERT_EQ(s.kind, StrokeKind::Stamp);
        EXPECT_EQ(s.stamp.x & 15, 8);
        EXPECT_EQ(s.stamp.y & 15, 8);
        EXPECT_EQ(s.stamp.color.a, 255);
    }
}

TEST(PaintRender, WrittenFileDecodesToTheCanvas) {
    const Model m = paint_test::model_or_synthetic(96, 64);
    Painting p = run(m, base_opts());
    const std::string path = std::string(SPT_BINARY_DIR) + "/paint_render_test_roundtrip." + std::to_string(::getpid()) + ".spt";
    StreamInfo info;
    info.header = p.setup.header;
    info.templates = p.setup.templates;
    auto w = Writer::create(path, info);
    ASSERT_TRUE(w.ok()) << w.error().message;
    Frame f;
    f.added = p.strokes;
    ASSERT_TRUE((*w)->append(f).ok());
    ASSERT_TRUE((*w)->finish().ok());
    auto rd = Reader::open(path);
    ASSERT_TRUE(rd.ok()) << rd.error().message;
    auto live = (*rd)->strokes_at(0);
    ASSERT_TRUE(live.ok()) << live.error().message;
    auto r2 = Renderer::create((*rd)->info().header, (*rd)->info().templates);
    ASSERT_TRUE(r2.ok());
    Canvas c((*rd)->info().header.width, (*rd)->info().header.height);
    ASSERT_TRUE((*r2)->render(c, **live).ok());
    EXPECT_EQ(c.rgb, p.canvas.rgb);
    std::filesystem::remove(path);
}

TEST(PaintRender, ThreadCountDoesNotChangeTheStrokes) {
    const Model m = paint_test::model_or_synthetic(96, 64);
    PaintOptions o = base_opts();
    o.threads = 1;
    Painting a = run(m, o);
    o.threads = 2;
    Painting b = run(m, o);
    o.threads = 3;
    Painting c = run(m, o);
    ASSERT_GT(a.strokes.size(), 50u);
    EXPECT_TRUE(a.strokes == b.strokes);
    EXPECT_TRUE(a.strokes == c.strokes);
    o.seed = 43;
    Painting d = run(m, o);
    EXPECT_FALSE(a.strokes == d.strokes);  // the seed matters
}

TEST(PaintRender, PsnrRisesWithMaxStrokes) {
    const Model m = paint_test::model_or_synthetic(96, 64);
    PaintOptions o = base_opts();
    o.threshold = 0.001;
    double last = 0;
    for (uint64_t n : {30, 150, 600, 1500}) {
        o.max_strokes = n;
        Painting p = run(m, o);
        EXPECT_EQ(p.strokes.size(), n);
        EXPECT_GT(p.stats.psnr, last + 0.3) << n;
        last = p.stats.psnr;
    }
}

TEST(PaintRender, TargetPsnrStopsNearTheTarget) {
    const Model m = paint_test::model_or_synthetic(96, 64);
    for (double target : {20.0, 24.0}) {
        PaintOptions o = base_opts();
        o.max_strokes = 100000;
        o.target_psnr = target;
        Painting p = run(m, o);
        EXPECT_EQ(p.stats.stop, StopReason::TargetPsnr) << target;
        EXPECT_GE(p.stats.psnr, target);
        EXPECT_LT(p.stats.psnr, target + 0.5);
    }
}

TEST(PaintRender, RoiIsPaintedFinerThanTheRest) {
    const Model m = paint_test::model_or_synthetic(96, 64);
    PaintOptions o = base_opts();
    o.max_strokes = 100000;
    o.threshold = 0.005;
    const Rect roi{30, 16, 36, 32};
    o.rois = {roi};
    // Coarse sets, then a much finer last one, so that where it paints shows.
    const std::vector<StrokeSet> sets = {{24, 12}, {12, 6}, {8, 4}, {2, 2}};
    Painting p = run(m, o, sets);
    // The finest set painted only inside the region.
    ASSERT_GT(p.stats.strokes_per_set.back(), 0u);
    for (const Stroke& s : p.strokes) {
        if (s.stamp.set + 1u != p.setup.header.sets.size()) continue;
        const int x = s.stamp.x >> 4, y = s.stamp.y >> 4;
        EXPECT_TRUE(x >= roi.x && x < roi.x + roi.w && y >= roi.y && y < roi.y + roi.h);
    }
    // The region ends up closer to the model than when another region is the ROI, and closer
    // than the rest of the canvas.
    const Rect other{0, 0, 28, 64};
    PaintOptions o2 = o;
    o2.rois = {other};
    Painting q = run(m, o2, sets);
    const double roi_with = psnr_rect(m.view(), p.canvas.rgb.data(), roi);
    const double roi_without = psnr_rect(m.view(), q.canvas.rgb.data(), roi);
    EXPECT_GT(roi_with, roi_without + 1.0) << roi_with << " vs " << roi_without;
    const double other_with = psnr_rect(m.view(), q.canvas.rgb.data(), other);
    const double other_without = psnr_rect(m.view(), p.canvas.rgb.data(), other);
    EXPECT_GT(other_with, other_without + 1.0) << other_with << " vs " << other_without;
}
