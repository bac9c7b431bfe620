// fit_outline and fit_polyline: a Douglas-Peucker chord lies on the inside of the curve it
// replaces (up to the tolerance, all along a gentle bend); refitted, the outline or the line
// runs through the curve instead of inside it, on bends of every angle.
#include <gtest/gtest.h>

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "cartoon/fit_outline.hpp"

namespace {

constexpr double kPi = 3.14159265358979323846;

// The largest distance from the circle (centre c, radius r) of polyline `p`, sampled finely.
double worst_off_circle(const std::vector<cv::Point2d>& p, cv::Point2d c, double r) {
    double worst = 0;
    for (size_t i = 0; i + 1 < p.size(); ++i)
        for (int t = 0; t <= 20; ++t) {
            const cv::Point2d q = p[i] + (p[i + 1] - p[i]) * (t / 20.0);
            worst = std::max(worst, std::fabs(std::hypot(q.x - c.x, q.y - c.y) - r));
        }
    return worst;
}

TEST(FitOutline, AnOpenLineRunsThroughAGentleBendNotInsideIt) {
    // A line's centre points on a circle of 40 px, every 0.25 px, and every 24th kept (chords of
    // 6 px: 0.11 px inside the arc at their middles, 7 degrees between neighbours).
    const cv::Point2d c(100, 100);
    const double r = 40;
    std::vector<cv::Point2d> pts;
    for (int i = 0; i <= 480; ++i) pts.push_back(c + r * cv::Point2d(std::cos(i * 0.25 / r), std::sin(i * 0.25 / r)));
    std::vector<size_t> kept;
    for (size_t i = 0; i < pts.size(); i += 24) kept.push_back(i);
    std::vector<cv::Point2d> raw;
    for (size_t i : kept) raw.push_back(pts[i]);
    const std::vector<cv::Point2d> fitted = spt::cartoon::fit_polyline(pts, kept, 0.75);
    ASSERT_EQ(fitted.size(), kept.size());
    const double before = worst_off_circle(raw, c, r), after = worst_off_circle(fitted, c, r);
    EXPECT_LT(after, 0.75 * before) << "raw chords " << before << " px off the arc";
    std::printf("open line on a 40 px arc: %.3f px off, %.3f unfitted\n", after, before);
}

TEST(FitOutline, AClosedOutlineRunsThroughAGentleBendNotInsideIt) {
    // A disc of radius 40 sub-pixels traced and simplified at 2 sub-pixels, as trace.cpp does.
    const int R = 40;
    cv::Mat inside(120, 120, CV_8U, cv::Scalar(0));
    cv::circle(inside, cv::Point(60, 60), R, cv::Scalar(255), cv::FILLED, cv::LINE_8);
    std::vector<std::vector<cv::Point>> contours;
    cv::findContours(inside, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
    ASSERT_EQ(contours.size(), 1u);
    std::vector<cv::Point> simple;
    cv::approxPolyDP(contours[0], simple, 2.0, true);
    const std::vector<cv::Point2f> fitted = spt::cartoon::fit_outline(contours[0], simple, inside);
    ASSERT_EQ(fitted.size(), simple.size());
    // The traced edge lies half a sub-pixel outside the contour's centres: the disc's area is
    // that of a circle of R + 0.5.
    const double truth = kPi * (R + 0.5) * (R + 0.5);
    const double raw = cv::contourArea(simple), area = cv::contourArea(fitted);
    EXPECT_LT(std::fabs(area - truth), 0.5 * std::fabs(raw - truth)) << "unfitted " << raw << ", the disc " << truth;
    std::printf("closed outline of a %d sub-pixel disc: area %.1f, unfitted %.1f, the disc %.1f\n", R, area, raw, truth);
}

}  // namespace
