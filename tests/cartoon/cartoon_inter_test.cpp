// Cartoon inter frames cost bytes only where the picture really changed (issue 21): the
// noise of compressed video does not make still shapes and their stamps be drawn again
// (stamp_keep.hpp, inter_frame.hpp), a polygon retraced low in the drawing order does not make
// every polygon above it be added again (frame_diff.hpp, draw_order.hpp), and every frame
// still renders at the target.
#include <gtest/gtest.h>

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "cartoon/cartoon_sequence.hpp"
#include "cartoon/cartoon_test_util.hpp"
#include "cartoon/stamp_keep.hpp"
#include "converter/cli_test_util.hpp"
#include "spt/spt.hpp"

namespace {

using spt_test::TempDir;

// Flat shapes on white, anti-aliased (drawn at 8x, box-filtered down); `bump` grows a notch
// on the green ground's top edge, far from the shapes standing on it.
cv::Mat scene(int bump) {
    const int k = 8, w = 192, h = 128;
    cv::Mat big(h * k, w * k, CV_8UC3, cv::Scalar(255, 255, 255));
    cv::rectangle(big, cv::Rect(0, 80 * k, w * k, 48 * k), cv::Scalar(40, 170, 60), cv::FILLED);  // the ground
    if (bump > 0) cv::rectangle(big, cv::Rect(170 * k, (80 - bump) * k, 6 * k, bump * k), cv::Scalar(40, 170, 60), cv::FILLED);
    for (int i = 0; i < 6; ++i) {  // flowers standing on the ground, drawn over it
        const cv::Point c((16 + 24 * i) * k, 96 * k);
        cv::circle(big, c, 7 * k, cv::Scalar(30 + 30 * i, 40, 220 - 20 * i), cv::FILLED);
        cv::circle(big, c, 7 * k, cv::Scalar(0, 0, 0), k);
        cv::circle(big, c, 2 * k, cv::Scalar(20, 220, 250), cv::FILLED);
    }
    cv::circle(big, cv::Point(60 * k, 55 * k), 18 * k, cv::Scalar(220, 30, 40), cv::FILLED);
    cv::circle(big, cv::Point(60 * k, 55 * k), 18 * k, cv::Scalar(0, 0, 0), 2 * k);
    cv::Mat small;
    cv::resize(big, small, cv::Size(w, h), 0, 0, cv::INTER_AREA);
    return small;
}

// The same picture under grain that is new every frame, as a camera or a lossy codec leaves
// a still shot: every pixel changes, the picture does not.
cv::Mat noisy(int i) {
    cv::Mat clean = scene(0), grain(clean.size(), CV_16SC3), out;
    cv::RNG rng(uint64_t(1000 + i));
    rng.fill(grain, cv::RNG::NORMAL, 0, 2.5);
    clean.convertTo(out, CV_16SC3);
    out += grain;
    out.convertTo(out, CV_8UC3);
    return out;
}

// The ground's edge changes a little every other frame; nothing else moves.
cv::Mat bumpy(int i) { return scene(i % 2 ? 3 : 0); }

spt::cartoon::SequenceReport paint(const TempDir& dir, const std::string& out, double target) {
    spt::cartoon::SequenceOptions o;
    o.input = dir.file("f.####.png");
    o.output = dir.file(out);
    o.paint.target_psnr = target;
    o.paint.threads = 2;
    o.fill.trace.upsample = 4;  // as the CLI paints sequences
    // The key frame keeps its small regions and its palette (no trials): these tests count the
    // stamps and polygons the inter frames keep and add against a key frame that needs stamps.
    o.fill.search_min_region = false;
    o.fill.search_palette = false;
    spt::cartoon::SequenceReport r;
    const spt::Status s = spt::cartoon::paint_sequence(o, r);
    EXPECT_TRUE(s) << (s ? "" : s.error().message);
    return r;
}

struct Counts {
    size_t polygons = 0, stamps = 0, removed = 0;
};

Counts counts(const spt::Frame& f) {
    Counts c;
    for (const spt::Stroke& s : f.added) (s.kind == spt::StrokeKind::Polygon ? c.polygons : c.stamps) += 1;
    c.removed = f.removed.size();
    return c;
}

// Every frame as a decoder renders it reaches the target against its own source.
template <class Art>
void expect_at_target(const std::string& file, int n, double target, Art art) {
    auto rd = spt::Reader::open(file);
    ASSERT_TRUE(rd) << rd.error().message;
    ASSERT_EQ((*rd)->frames().size(), size_t(n));
    for (int i = 0; i < n; ++i) {
        spt::Canvas c;
        ASSERT_TRUE((*rd)->render_frame(size_t(i), c));
        EXPECT_GE(spt_test::psnr_of(c.rgb, art(i).data), target) << "frame " << i;
    }
}

TEST(CartoonInter, NoiseRepaintsAlmostNothing) {
    TempDir dir;
    const int n = 6;
    const double target = 39;  // above what the polygons reach: the key frame needs stamps
    spt_test::write_frames(dir, n, noisy);
    paint(dir, "noisy.spt", target);
    expect_at_target(dir.file("noisy.spt"), n, target, noisy);
    auto rd = spt::Reader::open(dir.file("noisy.spt"));
    ASSERT_TRUE(rd) << rd.error().message;
    auto key = (*rd)->read_frame(0);
    ASSERT_TRUE(key);
    const Counts k = counts(*key);
    ASSERT_GE(k.stamps, 10u) << "the key frame should need stamps, or the test would not see them kept";
    Counts inter;
    for (size_t i = 1; i < size_t(n); ++i) {
        auto f = (*rd)->read_frame(i);
        ASSERT_TRUE(f);
        const Counts c = counts(*f);
        // The grain changed every pixel and every outline's trace; the picture did not.
        EXPECT_LE(c.polygons, 1u) << "frame " << i << " traced the grain";
        inter.stamps += c.stamps;
        inter.removed += c.removed;
    }
    // All inter frames together add and remove less than a third of the key frame's stamps.
    EXPECT_LE(inter.stamps, k.stamps / 3) << "the grain was painted again";
    EXPECT_LE(inter.removed, (k.stamps + k.polygons) / 3);
}

TEST(CartoonInter, ARetracedGroundDoesNotRedrawWhatStandsOnIt) {
    TempDir dir;
    const int n = 5;
    spt_test::write_frames(dir, n, bumpy);
    paint(dir, "bumpy.spt", 33);
    expect_at_target(dir.file("bumpy.spt"), n, 33, bumpy);
    auto rd = spt::Reader::open(dir.file("bumpy.spt"));
    ASSERT_TRUE(rd) << rd.error().message;
    auto key = (*rd)->read_frame(0);
    ASSERT_TRUE(key);
    const size_t key_polygons = counts(*key).polygons;
    ASSERT_GE(key_polygons, 12u);
    for (size_t i = 1; i < size_t(n); ++i) {
        auto f = (*rd)->read_frame(i);
        ASSERT_TRUE(f);
        // The ground (drawn early) changed; the flowers over it are not added again.
        EXPECT_LE(counts(*f).polygons, 3u) << "frame " << i;
    }
}

// The keep rule itself: of two old stamps, the one the new frame still agrees with stays, the
// one it contradicts goes; a stamp hidden under an added stroke is no reason to remove anything.
TEST(CartoonInter, AStampStaysWhileItHelps) {
    const uint32_t W = 64, H = 48;
    const auto setup = spt::paint::make_setup(W, H, {255, 255, 255}, spt::paint::default_sets(W, H),
                                              spt::paint::default_templates());
    auto renderer = spt::Renderer::create(setup.header, setup.templates);
    ASSERT_TRUE(renderer) << renderer.error().message;
    auto stamp = [](int x, int y, spt::Rgba8 c) {
        spt::StampStroke s;
        s.set = 3;
        s.x = x * 16 + 8;
        s.y = y * 16 + 8;
        s.color = c;
        return spt::Stroke::make_stamp(s);
    };
    const std::vector<spt::Stroke> old{stamp(16, 24, {200, 40, 40, 255}), stamp(48, 24, {40, 40, 200, 255})};
    // The new frame: white with the red patch still there (plus noise); the blue one is gone.
    spt::Canvas model(setup.header);
    ASSERT_TRUE((*renderer)->render(model, {old[0]}));
    cv::RNG rng(7);
    for (uint8_t& v : model.rgb) v = uint8_t(std::clamp(int(v) + int(rng.gaussian(3)), 0, 255));
    const spt::paint::ImageView view{W, H, model.rgb.data()};
    const auto removed = spt::cartoon::drop_unhelpful_stamps(old, {}, {}, view, **renderer, setup.header);
    EXPECT_EQ(removed, std::vector<uint32_t>{1});
}

}  // namespace
