// The incremental canvas update (BandRenderer): re-rendering only the bands where strokes moved
// gives the bytes of a full render, directly and through the encoder on a shot whose camera
// stands still while one object moves.
#include <gtest/gtest.h>
#include <unistd.h>

#include <random>

#include "paint/painter.hpp"
#include "quick_options.hpp"
#include "spt/reader.hpp"
#include "spt/render.hpp"
#include "synthetic.hpp"
#include "video/band_render.hpp"
#include "video/video_encoder.hpp"

using namespace spt;
using namespace spt::video;

namespace {

// A static textured background with a disc moving right by `t` pixels.
std::vector<uint8_t> still_shot_with_mover(double t, uint32_t w, uint32_t h) {
    auto rgb = spt_test::scene_frame(0, 0, w, h, 0, 0);
    const double cx = 20 + 1.5 * t, cy = 24;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x)
            if ((x - cx) * (x - cx) + (y - cy) * (y - cy) < 100) {
                uint8_t* p = &rgb[(size_t(y) * w + x) * 3];
                p[0] = 250, p[1] = 200, p[2] = 20;
            }
    return rgb;
}

}  // namespace

TEST(BandRender, MovingSomeStrokesEqualsAFullRender) {
    const uint32_t w = 150, h = 300;  // 5 bands, the last one short
    paint::PaintSetup setup = paint::make_setup(w, h, {250, 250, 250}, paint::default_sets(w, h, 4),
                                                paint::default_templates());
    auto full = Renderer::create(setup.header, setup.templates);
    ASSERT_TRUE(full.ok());
    auto band = BandRenderer::create(setup.header, setup.templates, **full);
    ASSERT_TRUE(band.ok()) << band.error().message;
    std::mt19937 rng(5);
    std::vector<Stroke> before;
    for (int i = 0; i < 3000; ++i) {
        StampStroke s;
        s.set = uint8_t(rng() % setup.header.sets.size());
        s.tmpl = uint8_t(rng() % setup.templates.size());
        s.orient = uint8_t(rng() % setup.header.orientations.size());
        s.x = int32_t(rng() % (16 * (w + 40))) - 16 * 20;
        s.y = int32_t(rng() % (16 * (h + 40))) - 16 * 20;
        s.color = {uint8_t(rng()), uint8_t(rng()), uint8_t(rng()), uint8_t(rng() % 3 ? 255 : 128)};
        before.push_back(Stroke::make_stamp(s));
    }
    for (int trial = 0; trial < 3; ++trial) {
        Frame f;
        f.index = 1;
        f.type = FrameType::Inter;
        f.motion.block_size = 16;
        f.motion.cols = uint16_t((w + 15) / 16);
        f.motion.rows = uint16_t((h + 15) / 16);
        f.motion.vectors.assign(size_t(f.motion.cols) * f.motion.rows, {0, 0});
        // One moving block (trial 0, 1: a few bands dirty) or all of them (trial 2: full).
        for (size_t k = 0; k < f.motion.vectors.size(); ++k)
            if (trial == 2 || k == size_t(f.motion.cols) * (trial == 0 ? 2 : 17) + 3)
                f.motion.vectors[k] = {int16_t(23 + trial), int16_t(-37)};
        Canvas canvas;
        ASSERT_TRUE((*full)->render(canvas, before).ok());
        std::vector<Stroke> after = before;
        ASSERT_TRUE(apply_frame(after, f, setup.header).ok());
        auto rows = (*band)->update(canvas, before, f, after, 2);
        ASSERT_TRUE(rows.ok()) << rows.error().message;
        if (trial < 2) EXPECT_LT(*rows, 0.7) << "trial " << trial << " should re-render only some bands";
        Canvas expect;
        ASSERT_TRUE((*full)->render(expect, after).ok());
        ASSERT_EQ(canvas.rgb, expect.rgb) << "trial " << trial;
        before = after;
    }
}

TEST(BandRender, EncoderOnAStillShotMatchesTheDecoder) {
    const auto dir = spt_test::temp_dir("band");
    const uint32_t w = 96, h = 200;
    VideoPaintOptions o = spt_test::quick_options((dir / "still.spt").string(), 11, 2, 600, 100);
    auto enc = VideoEncoder::create(o, w, h, Rational{24, 1});
    ASSERT_TRUE(enc.ok()) << enc.error().message;
    std::vector<std::vector<uint8_t>> canvases;
    int partial = 0;
    for (int i = 0; i < 12; ++i) {
        const auto rgb = still_shot_with_mover(i, w, h);
        auto r = (*enc)->add_frame(rgb.data(), i);
        ASSERT_TRUE(r.ok()) << r.error().message;
        if (r->type == FrameType::Inter && r->rendered_fraction < 1.0) ++partial;
        canvases.push_back((*enc)->canvas().rgb);
    }
    ASSERT_TRUE((*enc)->finish().ok());
    EXPECT_GT(partial, 0) << "no inter frame used the incremental update";
    auto reader = Reader::open(o.output);
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    auto renderer = Renderer::create((*reader)->info().header, (*reader)->info().templates);
    ASSERT_TRUE(renderer.ok());
    Canvas c;
    for (size_t i = 0; i < canvases.size(); ++i) {
        auto live = (*reader)->strokes_at(i);
        ASSERT_TRUE(live.ok()) << live.error().message;
        ASSERT_TRUE((*renderer)->render(c, **live).ok());
        ASSERT_EQ(c.rgb, canvases[i]) << "frame " << i;
    }
    std::filesystem::remove_all(dir);
}
