// Cut detection and the block motion field, on synthetic clips whose truth is known.
#include <gtest/gtest.h>
#include <unistd.h>

#include <opencv2/imgproc.hpp>

#include "synthetic.hpp"
#include "frames/cut_detect.hpp"
#include "video/motion.hpp"
#include "video/video_paint.hpp"

using namespace spt::video;

namespace {

cv::Mat gray_of(const std::vector<uint8_t>& rgb, uint32_t w, uint32_t h) {
    cv::Mat g;
    cv::cvtColor(cv::Mat(int(h), int(w), CV_8UC3, const_cast<uint8_t*>(rgb.data())), g, cv::COLOR_RGB2GRAY);
    return g;
}

}  // namespace

TEST(CutDetect, FindsHardCutsAndNothingElse) {
    const uint32_t w = 160, h = 96;
    CutDetector det;
    std::vector<int> cuts;
    int frame = 0;
    for (int shot = 0; shot < 3; ++shot) {
        for (int t = 0; t < 25; ++t, ++frame) {
            // Each shot moves differently; the second one pans faster.
            const auto rgb = spt_test::scene_frame(shot, t, w, h, shot == 1 ? 3.0 : 1.0, 0.5);
            if (det.push(gray_of(rgb, w, h)).cut) cuts.push_back(frame);
        }
    }
    EXPECT_EQ(cuts, (std::vector<int>{25, 50}));
}

TEST(CutDetect, NoCutOnFadeOrStillFrames) {
    const uint32_t w = 160, h = 96;
    CutDetector det;
    int cuts = 0;
    for (int t = 0; t < 40; ++t) {
        auto rgb = spt_test::scene_frame(0, t < 10 ? 0 : t - 10, w, h);
        // Fade to black over frames 20..39.
        const double k = t < 20 ? 1.0 : 1.0 - (t - 20) / 20.0;
        for (auto& v : rgb) v = uint8_t(v * k);
        if (det.push(gray_of(rgb, w, h)).cut) ++cuts;
    }
    EXPECT_EQ(cuts, 0);
}

TEST(Motion, BlockFieldMatchesATranslation) {
    const uint32_t w = 192, h = 128;
    const auto a = spt_test::scene_frame(0, 0, w, h, 1.0, 0.0);
    // Shift by (+3, -2) pixels: scene_frame moves by (vx t, vy t).
    const auto b = spt_test::scene_frame(0, 1, w, h, 3.0, -2.0);
    FlowEstimator est(FlowMethod::DisUltrafast);
    cv::Mat flow;
    est.compute(gray_of(a, w, h), gray_of(b, w, h), flow);
    const spt::MotionField m = block_motion(flow, 16);
    ASSERT_EQ(m.cols, 12);
    ASSERT_EQ(m.rows, 8);
    int good = 0, inner = 0;
    for (int by = 1; by + 1 < m.rows; ++by)
        for (int bx = 1; bx + 1 < m.cols; ++bx) {
            const auto v = m.vectors[size_t(by) * m.cols + bx];
            ++inner;
            if (std::abs(v.first - 48) <= 4 && std::abs(v.second + 32) <= 4) ++good;
        }
    EXPECT_GE(good, inner * 9 / 10) << "blocks within 1/4 px of (3, -2)";
    EXPECT_FALSE(is_still(m));
}

TEST(Motion, FlowIsDeterministicAcrossThreadCounts) {
    const uint32_t w = 320, h = 180;
    const auto a = gray_of(spt_test::scene_frame(1, 0, w, h), w, h);
    const auto b = gray_of(spt_test::scene_frame(1, 1, w, h, 2.0, 1.0), w, h);
    cv::Mat f1, f2;
    const int old = cv::getNumThreads();
    cv::setNumThreads(1);
    FlowEstimator(FlowMethod::DisUltrafast).compute(a, b, f1);
    cv::setNumThreads(4);
    FlowEstimator(FlowMethod::DisUltrafast).compute(a, b, f2);
    cv::setNumThreads(old);
    EXPECT_EQ(cv::norm(f1, f2, cv::NORM_INF), 0.0);
}

TEST(Fps, ParsesRationalsAndNtscRates) {
    auto r = parse_fps("30000/1001");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(*r, (spt::Rational{30000, 1001}));
    EXPECT_EQ(*parse_fps("24"), (spt::Rational{24, 1}));
    EXPECT_EQ(*parse_fps("29.97"), (spt::Rational{30000, 1001}));
    EXPECT_EQ(*parse_fps("23.976"), (spt::Rational{24000, 1001}));
    EXPECT_EQ(fps_from_double(25.0), (spt::Rational{25, 1}));
    EXPECT_EQ(fps_from_double(59.94006), (spt::Rational{60000, 1001}));
    EXPECT_EQ(fps_from_double(12.5), (spt::Rational{25, 2}));
    EXPECT_FALSE(parse_fps("0").ok());
    EXPECT_FALSE(parse_fps("abc").ok());
    EXPECT_FALSE(parse_fps("24/0").ok());
}
