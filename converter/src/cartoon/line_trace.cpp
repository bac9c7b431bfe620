#include "cartoon/line_trace.hpp"

#include "cartoon/fit_outline.hpp"
#include "cartoon/thinning.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include <opencv2/imgproc.hpp>

namespace spt::cartoon {

namespace {

// Skeleton neighbours: the 4-neighbours, and the diagonal ones not reached through a
// 4-neighbour (a staircase is one path, not a triangle of three). Symmetric.
int neighbours(const cv::Mat& sk, cv::Point p, cv::Point out[8]) {
    auto on = [&](int x, int y) { return x >= 0 && y >= 0 && x < sk.cols && y < sk.rows && sk.at<uint8_t>(y, x); };
    int n = 0;
    const bool e = on(p.x + 1, p.y), w = on(p.x - 1, p.y), s = on(p.x, p.y + 1), nn = on(p.x, p.y - 1);
    if (e) out[n++] = {p.x + 1, p.y};
    if (w) out[n++] = {p.x - 1, p.y};
    if (s) out[n++] = {p.x, p.y + 1};
    if (nn) out[n++] = {p.x, p.y - 1};
    if (on(p.x + 1, p.y + 1) && !e && !s) out[n++] = {p.x + 1, p.y + 1};
    if (on(p.x - 1, p.y + 1) && !w && !s) out[n++] = {p.x - 1, p.y + 1};
    if (on(p.x + 1, p.y - 1) && !e && !nn) out[n++] = {p.x + 1, p.y - 1};
    if (on(p.x - 1, p.y - 1) && !w && !nn) out[n++] = {p.x - 1, p.y - 1};
    return n;
}

// An edge between two skeleton pixels of a mask `cols` wide, as one number: the pixels' indices
// (below 2^32: a mask is a region's box, and no image this painter holds has 2^32 pixels).
uint64_t edge_key(cv::Point a, cv::Point b, int cols) {
    const uint64_t ka = uint64_t(a.y) * uint64_t(cols) + uint64_t(a.x), kb = uint64_t(b.y) * uint64_t(cols) + uint64_t(b.x);
    return ka < kb ? (ka << 32) | kb : (kb << 32) | ka;
}

// Douglas-Peucker over position (and width: a point whose width differs from the chord's
// interpolation by more than width_eps stays).
void simplify(const std::vector<cv::Point2d>& p, const std::vector<double>& w, size_t a, size_t b, double eps,
              double width_eps, std::vector<char>& keep) {
    if (b <= a + 1) return;
    const cv::Point2d d = p[b] - p[a];
    const double len = std::hypot(d.x, d.y);
    double worst = 0;
    size_t at = 0;
    for (size_t i = a + 1; i < b; ++i) {
        const cv::Point2d q = p[i] - p[a];
        const double dist = len > 0 ? std::abs(q.x * d.y - q.y * d.x) / len : std::hypot(q.x, q.y);
        const double t = double(i - a) / double(b - a);
        const double dw = std::abs(w[i] - (w[a] + t * (w[b] - w[a]))) * eps / width_eps;
        const double e = std::max(dist, dw);
        if (e > worst) { worst = e; at = i; }
    }
    if (worst <= eps) return;
    keep[at] = 1;
    simplify(p, w, a, at, eps, width_eps, keep);
    simplify(p, w, at, b, eps, width_eps, keep);
}

// The skeleton's branches as pixel paths: from every end and junction to the next one, then
// the closed loops left.
std::vector<std::vector<cv::Point>> branches(const cv::Mat& sk) {
    std::vector<std::vector<cv::Point>> out;
    std::unordered_set<uint64_t> used;  // skeleton edges walked
    auto walk = [&](cv::Point start, cv::Point first) {
        std::vector<cv::Point> path{start};
        used.insert(edge_key(start, first, sk.cols));
        cv::Point prev = start, cur = first;
        for (;;) {
            path.push_back(cur);
            cv::Point nb[8];
            const int n = neighbours(sk, cur, nb);
            if (n != 2) break;  // an end or a junction
            const cv::Point next = nb[0] == prev ? nb[1] : nb[0];
            if (used.count(edge_key(cur, next, sk.cols))) break;  // a loop closed
            used.insert(edge_key(cur, next, sk.cols));
            prev = cur;
            cur = next;
        }
        out.push_back(std::move(path));
    };
    std::vector<cv::Point> pixels;
    cv::findNonZero(sk, pixels);
    for (int pass = 0; pass < 2; ++pass)
        for (const cv::Point& p : pixels) {
            cv::Point nb[8];
            const int n = neighbours(sk, p, nb);
            if (n == 0) {
                if (pass == 0) out.push_back({p});
                continue;
            }
            if (pass == 0 && n == 2) continue;
            for (int k = 0; k < n; ++k)
                if (!used.count(edge_key(p, nb[k], sk.cols))) walk(p, nb[k]);
        }
    return out;
}

}  // namespace

LineShape centrelines(const Regions& regs, int index) {
    LineShape out;
    const Region& reg = regs.list[size_t(index)];
    const cv::Rect img(0, 0, regs.id.cols, regs.id.rows);
    const cv::Rect box = cv::Rect(reg.box.x - 1, reg.box.y - 1, reg.box.width + 2, reg.box.height + 2) & img;
    // Padded by a pixel of outside, so that the distance transform sees the canvas edge as
    // outside too and thinning has room.
    cv::Mat mask(box.height + 2, box.width + 2, CV_8U, cv::Scalar(0));
    for (int y = 0; y < box.height; ++y)
        for (int x = 0; x < box.width; ++x)
            if (regs.id.at<int>(box.y + y, box.x + x) == index) {
                mask.at<uint8_t>(y + 1, x + 1) = 255;
                ++out.pixels;
            }
    if (out.pixels == 0) return out;
    cv::Mat sk, dist;
    thin_zhang_suen(mask, sk);
    cv::distanceTransform(mask, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
    // Spurs: a branch from an end to a junction no longer than the line is wide there is the
    // thinning's answer to a corner or a bump, not a line; dropped, its junction joins the
    // branches on either side into one.
    for (const std::vector<cv::Point>& b : branches(sk)) {
        if (b.size() < 2) continue;
        cv::Point nb[8];
        const int na = neighbours(sk, b.front(), nb), nz = neighbours(sk, b.back(), nb);
        const bool spur_a = na == 1 && nz >= 3, spur_z = nz == 1 && na >= 3;
        if (!spur_a && !spur_z) continue;
        const cv::Point j = spur_a ? b.back() : b.front();
        if (double(b.size()) > std::max(3.0, 2.0 * double(dist.at<float>(j.y, j.x)))) continue;
        for (const cv::Point& p : b)
            if (p != j) sk.at<uint8_t>(p.y, p.x) = 0;
    }
    const cv::Point origin(box.x - 1, box.y - 1);  // mask pixel -> canvas pixel
    for (std::vector<cv::Point>& b : branches(sk)) {
        Centreline c;
        cv::Point nb[8];
        c.free_end[0] = neighbours(sk, b.front(), nb) == 1;
        c.free_end[1] = neighbours(sk, b.back(), nb) == 1;
        for (cv::Point& p : b) {
            c.radius.push_back(double(dist.at<float>(p.y, p.x)));
            c.pts.push_back(p + origin);
        }
        for (size_t i = 1; i < c.pts.size(); ++i)
            out.length += std::hypot(double(c.pts[i].x - c.pts[i - 1].x), double(c.pts[i].y - c.pts[i - 1].y));
        out.paths.push_back(std::move(c));
    }
    return out;
}

bool may_be_line(const Regions& regs, int index, const LineOptions& opts) {
    const Region& reg = regs.list[size_t(index)];
    const cv::Rect img(0, 0, regs.id.cols, regs.id.rows);
    const cv::Rect box = reg.box & img;
    int64_t pixels = 0, edge = 0;
    auto inside = [&](int x, int y) { return x >= 0 && y >= 0 && x < img.width && y < img.height && regs.id.at<int>(y, x) == index; };
    for (int y = box.y; y < box.br().y; ++y)
        for (int x = box.x; x < box.br().x; ++x) {
            if (regs.id.at<int>(y, x) != index) continue;
            ++pixels;
            edge += !inside(x - 1, y) || !inside(x + 1, y) || !inside(x, y - 1) || !inside(x, y + 1);
        }
    return double(pixels) <= 2.0 * double(edge) * opts.max_mean_width;
}

bool is_line(const LineShape& shape, const LineOptions& opts) {
    return !shape.paths.empty() && shape.length >= opts.min_length && shape.mean_width() <= opts.max_mean_width;
}

namespace {

// Bilinear sample of an RGB image at pixel coordinates (pixel centres at +0.5), clamped.
cv::Vec3d sample(const cv::Mat& rgb, cv::Point2d q) {
    const double x = std::clamp(q.x - 0.5, 0.0, double(rgb.cols - 1)), y = std::clamp(q.y - 0.5, 0.0, double(rgb.rows - 1));
    const int x0 = int(x), y0 = int(y), x1 = std::min(x0 + 1, rgb.cols - 1), y1 = std::min(y0 + 1, rgb.rows - 1);
    const double fx = x - x0, fy = y - y0;
    cv::Vec3d v;
    for (int k = 0; k < 3; ++k)
        v[k] = (1 - fy) * ((1 - fx) * rgb.at<cv::Vec3b>(y0, x0)[k] + fx * rgb.at<cv::Vec3b>(y0, x1)[k]) +
               fy * ((1 - fx) * rgb.at<cv::Vec3b>(y1, x0)[k] + fx * rgb.at<cv::Vec3b>(y1, x1)[k]);
    return v;
}

}  // namespace

constexpr double kEndReach = 1.0;  // pixels

void fit_to_source(LineShape& shape, const cv::Mat& rgb, cv::Vec3b ink, bool measure) {
    const cv::Vec3d L(ink[0], ink[1], ink[2]);
    for (Centreline& c : shape.paths) {
        const size_t n = c.pts.size();
        c.centre.assign(n, {});
        c.width.assign(n, 0);
        std::vector<double> offset(n, 0), measured(n, -1);
        for (size_t i = 0; i < n; ++i) {
            // Pixel centres, averaged along the branch: a skeleton steps between the two middle
            // pixels of a line of even width, and its mean runs down the middle (ends keep
            // their pixel: they pin the branch to its junctions).
            cv::Point2d m(0, 0);
            const size_t k0 = i >= 2 ? i - 2 : 0, k1 = std::min(n, i + 3);
            const bool end = i == 0 || i + 1 == n;
            for (size_t k = k0; k < k1; ++k) m += cv::Point2d(c.pts[k].x, c.pts[k].y);
            m = end ? cv::Point2d(c.pts[i].x, c.pts[i].y) : m / double(k1 - k0);
            c.centre[i] = m + cv::Point2d(0.5, 0.5);
            // The distance transform steps by whole and diagonal pixels, and a staircase
            // skeleton leaves the middle at every step: the median over a few pixels is the
            // line's width, not its steps.
            std::vector<double> near;
            for (size_t k = i >= 3 ? i - 3 : 0; k < std::min(n, i + 4); ++k) near.push_back(c.radius[k]);
            std::nth_element(near.begin(), near.begin() + long(near.size() / 2), near.end());
            c.width[i] = std::max(0.0, 2 * near[near.size() / 2] - 1);
        }
        if (n < 3 || !measure) continue;
        // The source across the line: each sample's coverage is its colour's place between the
        // colour on its side (the profile's end) and the ink; their sum is the width and their
        // mean position the centre (exact for an anti-aliased line on a flat ground).
        for (size_t i = 0; i < n; ++i) {
            const cv::Point2d d = c.centre[std::min(n - 1, i + 2)] - c.centre[i >= 2 ? i - 2 : 0];
            const double len = std::hypot(d.x, d.y);
            if (len < 1e-6) continue;
            const cv::Point2d nrm(-d.y / len, d.x / len);
            const double R = std::min(c.width[i] / 2 + 2.5, 6.0);
            const cv::Vec3d left = sample(rgb, c.centre[i] - R * nrm), right = sample(rgb, c.centre[i] + R * nrm);
            const cv::Vec3d dl = L - left, dr = L - right;
            const double nl = dl.dot(dl), nr = dr.dot(dr);
            if (nl < 400 || nr < 400) continue;  // the ink barely differs from what is around it
            double sum = 0, moment = 0;
            constexpr double kStep = 0.25;
            for (double t = -R + kStep / 2; t < R; t += kStep) {
                const cv::Vec3d v = sample(rgb, c.centre[i] + t * nrm);
                const cv::Vec3d& bg = t < 0 ? left : right;
                const double cov = std::clamp((v - bg).dot(t < 0 ? dl : dr) / (t < 0 ? nl : nr), 0.0, 1.0);
                sum += cov * kStep;
                moment += cov * t * kStep;
            }
            if (sum <= 0.1) continue;
            measured[i] = sum;
            offset[i] = std::clamp(moment / sum, -1.5, 1.5);
        }
        // A thinned line's last pixels curl toward a corner of its end, and stop short of it by
        // about a pixel: a free end's last two points are put back on the line the branch
        // follows before them, the last one that pixel farther, so that its round cap ends where
        // the source's does.
        for (int side = 0; side < 2 && n >= 7; ++side) {
            if (!c.free_end[side]) continue;
            auto at = [&](size_t k) -> cv::Point2d& { return c.centre[side ? n - 1 - k : k]; };
            const cv::Point2d d = at(2) - at(5);
            const double len = std::hypot(d.x, d.y);
            if (len < 1e-6) continue;
            const cv::Point2d u = d / len;
            const double reach = std::hypot(at(0).x - at(2).x, at(0).y - at(2).y);
            at(1) = at(2) + u * (reach / 2);
            at(0) = at(2) + u * (reach + kEndReach);
        }
        // Smoothed along the branch (junctions and crossings disturb single profiles).
        for (size_t i = 0; i < n; ++i) {
            std::vector<double> ws, os;
            for (size_t k = i >= 3 ? i - 3 : 0; k < std::min(n, i + 4); ++k)
                if (measured[k] >= 0) { ws.push_back(measured[k]); os.push_back(offset[k]); }
            if (ws.size() < 3) continue;
            std::nth_element(ws.begin(), ws.begin() + long(ws.size() / 2), ws.end());
            std::nth_element(os.begin(), os.begin() + long(os.size() / 2), os.end());
            const cv::Point2d d = c.centre[std::min(n - 1, i + 2)] - c.centre[i >= 2 ? i - 2 : 0];
            const double len = std::hypot(d.x, d.y);
            c.width[i] = ws[ws.size() / 2];
            if (len > 1e-6 && i > 0 && i + 1 < n) c.centre[i] += os[os.size() / 2] * cv::Point2d(-d.y / len, d.x / len);
        }
    }
    // Near a junction a profile crosses the branches that meet there: there a branch takes the
    // width of its own middle (a short spur, the corner of a bend, keeps what it measured: the
    // filled corner is that wide).
    constexpr size_t kNear = 3;
    std::vector<double> all;
    for (const Centreline& c : shape.paths)
        for (size_t i = 0; i < c.width.size(); ++i)
            if ((c.free_end[0] || i >= kNear) && (c.free_end[1] || i + kNear < c.width.size())) all.push_back(c.width[i]);
    if (all.empty()) return;
    std::nth_element(all.begin(), all.begin() + long(all.size() / 2), all.end());
    const double line_width = all[all.size() / 2];
    for (Centreline& c : shape.paths) {
        const size_t n = c.width.size();
        std::vector<double> mid;
        for (size_t i = 0; i < n; ++i)
            if ((c.free_end[0] || i >= kNear) && (c.free_end[1] || i + kNear < n)) mid.push_back(c.width[i]);
        double w = line_width;
        if (mid.size() >= 3) {
            std::nth_element(mid.begin(), mid.begin() + long(mid.size() / 2), mid.end());
            w = mid[mid.size() / 2];
        }
        for (size_t i = 0; i < n; ++i)
            if ((!c.free_end[0] && i < kNear) || (!c.free_end[1] && i + kNear >= n)) c.width[i] = std::min(c.width[i], w);
    }
}

std::vector<CurveStroke> line_curves(const LineShape& shape, Rgba8 color, double widen, uint8_t grid,
                                     const LineOptions& opts) {
    std::vector<CurveStroke> out;
    for (const Centreline& c : shape.paths) {
        std::vector<cv::Point2d> p = c.centre;
        std::vector<double> w;
        for (double x : c.width) w.push_back(std::max(0.0, x + widen));
        std::vector<char> keep(p.size(), 0);
        keep.front() = keep.back() = 1;
        simplify(p, w, 0, p.size() - 1, opts.epsilon, opts.width_epsilon, keep);
        std::vector<size_t> kept;
        for (size_t i = 0; i < p.size(); ++i)
            if (keep[i]) kept.push_back(i);
        // Douglas-Peucker keeps centre points, and its chords lie inside every bend: refitted.
        const std::vector<cv::Point2d> at = fit_polyline(p, kept, 0.75);
        CurveStroke cv;
        cv.color = color;
        cv.supersample = grid;
        for (size_t k = 0; k < kept.size(); ++k)
            cv.points.push_back({int32_t(std::lround(at[k].x * 16)), int32_t(std::lround(at[k].y * 16)),
                                 uint32_t(std::lround(w[kept[k]] * 16))});
        out.push_back(std::move(cv));
    }
    return out;
}

}  // namespace spt::cartoon
