#include "cartoon/fit_outline.hpp"

#include <cmath>

namespace spt::cartoon {

namespace {

struct Line {
    cv::Point2f p, d;  // a point and the unit direction
    bool ok = false;
};

bool inside_at(const cv::Mat& img, cv::Point2f q) {
    const int x = int(std::lround(q.x)), y = int(std::lround(q.y));
    return x >= 0 && y >= 0 && x < img.cols && y < img.rows && img.at<uint8_t>(y, x) != 0;
}

}  // namespace

std::vector<cv::Point2f> fit_outline(const std::vector<cv::Point>& contour, const std::vector<cv::Point>& simple,
                                     const cv::Mat& inside) {
    const size_t n = simple.size(), m = contour.size();
    std::vector<cv::Point2f> out(simple.begin(), simple.end());
    if (n < 3 || m < 3) return out;
    // Where each kept vertex lies on the contour (in order, searching forwards).
    std::vector<size_t> at(n);
    size_t j = 0;
    for (size_t i = 0; i < n; ++i) {
        size_t tries = 0;
        while (contour[j] != simple[i] && tries++ < m) j = (j + 1) % m;
        if (tries > m) return out;
        at[i] = j;
    }
    std::vector<Line> lines(n);
    for (size_t i = 0; i < n; ++i) {
        const size_t a = at[i], b = at[(i + 1) % n];
        const size_t len = (b + m - a) % m + 1;
        double sx = 0, sy = 0;
        for (size_t t = 0; t < len; ++t) {
            sx += contour[(a + t) % m].x;
            sy += contour[(a + t) % m].y;
        }
        const double cx = sx / double(len), cy = sy / double(len);
        double xx = 0, yy = 0, xy = 0;
        for (size_t t = 0; t < len; ++t) {
            const double dx = contour[(a + t) % m].x - cx, dy = contour[(a + t) % m].y - cy;
            xx += dx * dx;
            yy += dy * dy;
            xy += dx * dy;
        }
        const double ang = 0.5 * std::atan2(2 * xy, xx - yy);
        cv::Point2f d(float(std::cos(ang)), float(std::sin(ang)));
        const cv::Point2f ab = cv::Point2f(simple[(i + 1) % n] - simple[i]);
        if (d.dot(ab) < 0) d = -d;
        Line& l = lines[i];
        l.p = cv::Point2f(float(cx), float(cy));
        l.d = d;
        l.ok = len >= 3;
        // Outward: the side of the line the traced image is not on.
        cv::Point2f nrm(-d.y, d.x);
        if (inside_at(inside, l.p + 1.5f * nrm) && !inside_at(inside, l.p - 1.5f * nrm)) nrm = -nrm;
        l.p += 0.5f * nrm;
    }
    for (size_t i = 0; i < n; ++i) {
        const Line& a = lines[(i + n - 1) % n];
        const Line& b = lines[i];
        if (!a.ok || !b.ok) continue;
        const float cross = a.d.x * b.d.y - a.d.y * b.d.x;
        if (std::fabs(cross) < 0.2f) continue;  // nearly parallel: keep the contour point
        const cv::Point2f w = b.p - a.p;
        const float t = (w.x * b.d.y - w.y * b.d.x) / cross;
        const cv::Point2f q = a.p + t * a.d;
        const cv::Point2f o = cv::Point2f(simple[i]);
        if ((q - o).dot(q - o) <= 9.f) out[i] = q;  // at most 3 sub-pixels from the contour
    }
    return out;
}

}  // namespace spt::cartoon
