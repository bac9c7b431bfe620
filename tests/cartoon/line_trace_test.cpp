// may_be_line, the cheap test that spares fills the thinning: it must never turn away a region
// that centrelines + is_line would draw as lines, and it must turn away the wide fills.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "cartoon/line_trace.hpp"
#include "cartoon/palette.hpp"
#include "cartoon/regions.hpp"

namespace {

using spt::cartoon::LineOptions;

struct Shape {
    cv::Vec3b colour;
    bool wide;  // a fill: may_be_line must turn it away
};

// Crisp shapes in colours of their own on white: lines 1 to 6 px wide at several angles, a
// ring, a line with a blob on it, and wide fills (disk, rectangle, bar; the bound turns away
// what is about 10 px wide or more, so smaller fills are still thinned and found wide).
cv::Mat shapes_image(std::vector<Shape>& shapes) {
    cv::Mat img(330, 420, CV_8UC3, cv::Scalar(255, 255, 255));
    int n = 0;
    auto colour = [&](bool wide) {
        ++n;
        const cv::Vec3b c(uint8_t(20 + 9 * n), uint8_t(200 - 7 * n), uint8_t((60 * n) % 200));
        shapes.push_back({c, wide});
        return cv::Scalar(c[0], c[1], c[2]);
    };
    for (int w = 1; w <= 6; ++w) {
        cv::line(img, cv::Point(10, 10 + 14 * w), cv::Point(150, 14 + 14 * w + 3 * w), colour(false), w, cv::LINE_8);
        cv::line(img, cv::Point(170 + 20 * w, 10), cv::Point(160 + 20 * w, 90), colour(false), w, cv::LINE_8);
    }
    cv::circle(img, cv::Point(60, 170), 35, colour(false), 3, cv::LINE_8);
    const cv::Scalar blobbed = colour(false);
    cv::line(img, cv::Point(120, 200), cv::Point(200, 130), blobbed, 2, cv::LINE_8);
    cv::circle(img, cv::Point(160, 165), 5, blobbed, cv::FILLED, cv::LINE_8);
    cv::circle(img, cv::Point(250, 180), 40, colour(true), cv::FILLED, cv::LINE_8);
    cv::rectangle(img, cv::Rect(300, 100, 100, 60), colour(true), cv::FILLED);
    cv::rectangle(img, cv::Rect(10, 250, 150, 40), colour(true), cv::FILLED);
    return img;
}

TEST(LineTrace, MayBeLineNeverTurnsAwayALineAndTurnsAwayFills) {
    std::vector<Shape> shapes;
    const cv::Mat img = shapes_image(shapes);
    std::vector<cv::Vec3b> palette{cv::Vec3b(255, 255, 255)};
    for (const Shape& s : shapes) palette.push_back(s.colour);
    const spt::cartoon::Regions regs =
        spt::cartoon::find_regions(img, spt::cartoon::label_pixels(img, palette), palette, 3);
    const LineOptions opts;
    size_t lines = 0, fills_turned_away = 0, fills = 0;
    for (int i = 0; i < int(regs.list.size()); ++i) {
        const cv::Vec3b c = regs.list[size_t(i)].color;
        if (c == cv::Vec3b(255, 255, 255)) continue;
        const spt::cartoon::LineShape shape = spt::cartoon::centrelines(regs, i);
        const bool line = spt::cartoon::is_line(shape, opts);
        const bool may = spt::cartoon::may_be_line(regs, i, opts);
        if (line) {
            ++lines;
            EXPECT_TRUE(may) << "region " << i << " is drawn as lines (mean width " << shape.mean_width()
                             << ") but may_be_line turned it away";
        }
        // The bound holds with room: even regions twice as wide as a line are let through.
        if (!may) EXPECT_GT(shape.mean_width(), 2 * opts.max_mean_width) << "region " << i;
        for (const Shape& s : shapes)
            if (s.colour == c && s.wide) {
                ++fills;
                fills_turned_away += !may;
            }
    }
    EXPECT_GE(lines, 8u) << "the thin shapes are lines";
    EXPECT_EQ(fills, 3u);
    EXPECT_EQ(fills_turned_away, 3u) << "fills are never thinned";
}

}  // namespace
