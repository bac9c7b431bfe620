// cartoon/thinning.hpp against the function it stands in for, OpenCV's
// cv::ximgproc::thinning (Zhang-Suen), which the test links and spt does not: the same skeleton
// pixel for pixel on random blobs, lines and the region masks of the shared cartoon frames.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc.hpp>

#include "cartoon/thinning.hpp"
#include "io/image_io.hpp"

namespace {

void expect_same_skeleton(const cv::Mat& mask, const std::string& what) {
    cv::Mat ours, theirs;
    spt::cartoon::thin_zhang_suen(mask, ours);
    cv::ximgproc::thinning(mask, theirs, cv::ximgproc::THINNING_ZHANGSUEN);
    ASSERT_EQ(ours.size(), theirs.size());
    ASSERT_EQ(ours.type(), theirs.type());
    EXPECT_EQ(cv::countNonZero(ours != theirs), 0) << what;
    EXPECT_GT(cv::countNonZero(theirs), 0) << what << ": an empty skeleton proves nothing";
}

}  // namespace

TEST(Thinning, MatchesOpenCvOnRandomShapes) {
    std::mt19937 rng(7);
    for (int t = 0; t < 60; ++t) {
        cv::Mat m(40 + int(rng() % 80), 40 + int(rng() % 80), CV_8UC1, cv::Scalar(0));
        for (int k = 0; k < 1 + int(rng() % 6); ++k) {
            const cv::Point a(int(rng() % m.cols), int(rng() % m.rows)), b(int(rng() % m.cols), int(rng() % m.rows));
            if (rng() % 2) cv::line(m, a, b, cv::Scalar(255), 1 + int(rng() % 9));
            else cv::ellipse(m, a, cv::Size(3 + int(rng() % 20), 2 + int(rng() % 15)), double(rng() % 180), 0, 360,
                             cv::Scalar(255), -1);
        }
        if (t % 3 == 0)  // noise at the edges: spurs and holes
            for (int k = 0; k < 200; ++k) m.at<uint8_t>(int(rng() % m.rows), int(rng() % m.cols)) ^= 255;
        expect_same_skeleton(m, "shape " + std::to_string(t));
    }
}

TEST(Thinning, MatchesOpenCvOnTheSharedCartoonFrames) {
    for (const char* f : {"cartoon/star/f.0000.png", "cartoon/star/f.0030.png", "cartoon/taffy/f.0010.png"}) {
        const std::string path = std::string(SPT_MEDIA_DIR) + "/" + f;
        auto img = spt::io::read_image(path);
        ASSERT_TRUE(img.ok()) << path << ": " << img.error().message;
        cv::Mat rgb(int(img->height), int(img->width), CV_8UC3, img->rgb.data()), gray, dark;
        cv::cvtColor(rgb, gray, cv::COLOR_RGB2GRAY);
        cv::threshold(gray, dark, 100, 255, cv::THRESH_BINARY_INV);  // the outlines and the text
        expect_same_skeleton(dark, path);
    }
}
