// Cartoon inter frames move what moved (SPEC.md 5 motion field): a flat shape translating over
// a still background is coded as block vectors, not as removals and new polygons, renders
// within the target every frame (the reader's rendering, motion applied by the decoder), takes
// fewer bytes than the same sequence without motion, and is the same file for any thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <opencv2/imgproc.hpp>

#include "cartoon/cartoon_sequence.hpp"
#include "cartoon/cartoon_test_util.hpp"
#include "converter/cli_test_util.hpp"
#include "io/image_io.hpp"
#include "spt/spt.hpp"

namespace {

using spt_test::TempDir;

// A still blue bar and a green disc with a black outline; an orange square sliding 4 px right
// and 2 px down a frame (whole pixels: it traces to the same vertices, shifted).
cv::Mat frame_art(int i) {
    const int k = 8, w = 192, h = 128;
    cv::Mat big(h * k, w * k, CV_8UC3, cv::Scalar(255, 255, 255));
    cv::rectangle(big, cv::Rect(10 * k, 90 * k, 170 * k, 20 * k), cv::Scalar(40, 60, 200), cv::FILLED);
    cv::circle(big, cv::Point(150 * k, 40 * k), 25 * k, cv::Scalar(30, 180, 60), cv::FILLED);
    cv::circle(big, cv::Point(150 * k, 40 * k), 25 * k, cv::Scalar(0, 0, 0), 3 * k);
    cv::rectangle(big, cv::Rect((20 + 4 * i) * k, (15 + 2 * i) * k, 28 * k, 24 * k), cv::Scalar(250, 140, 20), cv::FILLED);
    cv::Mat small;
    cv::resize(big, small, cv::Size(w, h), 0, 0, cv::INTER_AREA);
    return small;
}

constexpr int kFrames = 6;
constexpr double kTarget = 34;

void write_frames(const TempDir& dir) { spt_test::write_frames(dir, kFrames, frame_art); }

spt::cartoon::SequenceReport paint(const TempDir& dir, const std::string& out, bool motion, int threads) {
    spt::cartoon::SequenceOptions o;
    o.input = dir.file("f.####.png");
    o.output = dir.file(out);
    o.paint.target_psnr = kTarget;
    o.paint.threads = threads;
    o.fill.trace.upsample = 4;  // as the CLI paints sequences
    o.motion.enabled = motion;
    spt::cartoon::SequenceReport r;
    const spt::Status s = spt::cartoon::paint_sequence(o, r);
    EXPECT_TRUE(s) << (s ? "" : s.error().message);
    return r;
}

std::string bytes_of(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

TEST(CartoonMotion, ATranslatingShapeIsMovedNotRedrawn) {
    TempDir dir;
    write_frames(dir);
    const auto with = paint(dir, "motion.spt", true, 2);
    const auto without = paint(dir, "still.spt", false, 2);
    EXPECT_EQ(with.motion_frames, uint64_t(kFrames - 1));
    EXPECT_EQ(without.motion_frames, 0u);
    EXPECT_LT(with.bytes, without.bytes);
    EXPECT_GE(with.polygons_kept, without.polygons_kept + kFrames - 1);

    auto rd = spt::Reader::open(dir.file("motion.spt"));
    ASSERT_TRUE(rd) << rd.error().message;
    ASSERT_EQ((*rd)->frames().size(), size_t(kFrames));
    for (size_t i = 1; i < size_t(kFrames); ++i) {
        auto f = (*rd)->read_frame(i);
        ASSERT_TRUE(f);
        EXPECT_EQ(f->type, spt::FrameType::Inter);
        ASSERT_FALSE(f->motion.empty()) << "frame " << i;
        // The square's vector (4, 2) px in Q4 is in the field; most blocks stay still.
        size_t moving = 0, square = 0;
        for (const auto& [dx, dy] : f->motion.vectors) {
            moving += dx != 0 || dy != 0;
            square += dx == 64 && dy == 32;
        }
        EXPECT_GE(square, 1u) << "frame " << i;
        EXPECT_LT(moving, f->motion.vectors.size() / 4) << "frame " << i;
        // Nothing but the square moved, and it moved rigidly: no polygon is traced again.
        size_t polygons = 0;
        for (const spt::Stroke& s : f->added) polygons += s.kind == spt::StrokeKind::Polygon;
        EXPECT_EQ(polygons, 0u) << "frame " << i;
        spt::Canvas c;
        ASSERT_TRUE((*rd)->render_frame(i, c));
        EXPECT_GE(spt_test::psnr_of(c.rgb, frame_art(int(i)).data), kTarget) << "frame " << i;
    }
    // The painter's own PSNR is that of its canvas, the decoder's rendering.
    EXPECT_GE(with.min_psnr, kTarget);
    const auto v = spt_test::run_spt(dir, {"verify", dir.file("motion.spt")});
    EXPECT_EQ(v.code, 0) << v.out << v.err;
}

TEST(CartoonMotion, SameBytesForAnyThreadCount) {
    TempDir dir;
    write_frames(dir);
    paint(dir, "t1.spt", true, 1);
    paint(dir, "t2.spt", true, 2);
    const std::string a = bytes_of(dir.file("t1.spt")), b = bytes_of(dir.file("t2.spt"));
    ASSERT_FALSE(a.empty());
    EXPECT_EQ(a, b);
}

}  // namespace
