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
        const cv::Point2f o = cv::Point2f(simple[i]);
        cv::Point2f q;
        if (std::fabs(cross) < 0.2f) {
            // Nearly parallel (a gentle bend): between the point's feet on the two lines.
            q = 0.5f * (a.p + (o - a.p).dot(a.d) * a.d + b.p + (o - b.p).dot(b.d) * b.d);
        } else {
            const cv::Point2f w = b.p - a.p;
            q = a.p + ((w.x * b.d.y - w.y * b.d.x) / cross) * a.d;
        }
        if ((q - o).dot(q - o) <= 9.f) out[i] = q;  // at most 3 sub-pixels from the contour
    }
    return out;
}

std::vector<cv::Point2d> fit_polyline(const std::vector<cv::Point2d>& pts, const std::vector<size_t>& kept, double reach) {
    const size_t n = kept.size();
    std::vector<cv::Point2d> out;
    for (size_t i : kept) out.push_back(pts[i]);
    if (n < 2) return out;
    struct Run {
        cv::Point2d p, d;
        bool ok = false;
    };
    std::vector<Run> runs(n - 1);
    for (size_t r = 0; r + 1 < n; ++r) {
        const size_t a = kept[r], b = kept[r + 1];
        if (b - a + 1 < 3) continue;  // two points: the line through them is the run itself
        cv::Point2d c(0, 0);
        for (size_t t = a; t <= b; ++t) c += pts[t];
        c /= double(b - a + 1);
        double xx = 0, yy = 0, xy = 0;
        for (size_t t = a; t <= b; ++t) {
            const cv::Point2d q = pts[t] - c;
            xx += q.x * q.x;
            yy += q.y * q.y;
            xy += q.x * q.y;
        }
        const double ang = 0.5 * std::atan2(2 * xy, xx - yy);
        runs[r] = {c, cv::Point2d(std::cos(ang), std::sin(ang)), true};
    }
    const double reach2 = reach * reach;
    auto near = [&](const cv::Point2d& q, size_t i) { return (q - out[i]).dot(q - out[i]) <= reach2; };
    for (size_t i = 1; i + 1 < n; ++i) {
        const Run &a = runs[i - 1], &b = runs[i];
        if (!a.ok || !b.ok) continue;
        const double cross = a.d.x * b.d.y - a.d.y * b.d.x;
        cv::Point2d q;
        if (std::fabs(cross) < 0.2) {
            // Nearly parallel (a gentle bend): between the point's feet on the two lines.
            q = 0.5 * (a.p + (out[i] - a.p).dot(a.d) * a.d + b.p + (out[i] - b.p).dot(b.d) * b.d);
        } else {
            const cv::Point2d w = b.p - a.p;
            q = a.p + ((w.x * b.d.y - w.y * b.d.x) / cross) * a.d;
        }
        if (near(q, i)) out[i] = q;
    }
    for (const auto& [i, r] : {std::pair<size_t, size_t>{0, 0}, {n - 1, n - 2}}) {
        const Run& run = runs[r];
        if (!run.ok) continue;
        const cv::Point2d q = run.p + (out[i] - run.p).dot(run.d) * run.d;
        if (near(q, i)) out[i] = q;
    }
    return out;
}

}  // namespace spt::cartoon
