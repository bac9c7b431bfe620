#include "cartoon/trace.hpp"

#include "cartoon/fit_outline.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace spt::cartoon {

namespace {

// Douglas-Peucker between contour points a and b (indices modulo the contour's length, a < b),
// measured on `pts` (the smoothed contour): the indices it keeps, in order. Iterative: a long
// contour could otherwise recurse once per point.
std::vector<size_t> simplify_range(const std::vector<cv::Point2f>& pts, size_t a, size_t b, double eps) {
    const size_t m = pts.size();
    std::vector<size_t> keep;
    std::vector<std::pair<size_t, size_t>> todo{{a, b}};
    while (!todo.empty()) {
        const auto [lo, hi] = todo.back();
        todo.pop_back();
        const cv::Point2f A = pts[lo % m], d = pts[hi % m] - A;
        const double len = std::hypot(d.x, d.y);
        double best = -1;
        size_t at = 0;
        for (size_t i = lo + 1; i < hi; ++i) {
            const cv::Point2f q = pts[i % m] - A;
            const double dist = len > 1e-9 ? std::fabs(double(d.x) * q.y - double(d.y) * q.x) / len : std::hypot(q.x, q.y);
            if (dist > best) { best = dist; at = i; }
        }
        if (best <= eps) continue;
        keep.push_back(at);
        todo.push_back({lo, at});
        todo.push_back({at, hi});
    }
    std::sort(keep.begin(), keep.end());
    for (size_t& i : keep) i %= m;
    return keep;
}

// The points of closed contour `c` that Douglas-Peucker keeps (tolerance `eps`) on the contour
// averaged over +-r points, so that the fit (fit_outline.hpp) still sees the true contour.
std::vector<cv::Point> simplify_smoothed(const std::vector<cv::Point>& c, double eps, int r) {
    const size_t m = c.size();
    std::vector<cv::Point2f> avg(m);
    for (size_t i = 0; i < m; ++i) {
        double sx = 0, sy = 0;
        for (int t = -r; t <= r; ++t) {
            const cv::Point& q = c[(i + m + size_t(int64_t(m) + t)) % m];
            sx += q.x;
            sy += q.y;
        }
        avg[i] = cv::Point2f(float(sx / (2 * r + 1)), float(sy / (2 * r + 1)));
    }
    // Split at the point farthest from the first, as approxPolyDP does for closed curves.
    size_t far = 0;
    double far_d = -1;
    for (size_t i = 0; i < m; ++i)
        if (const double dd = std::hypot(avg[i].x - avg[0].x, avg[i].y - avg[0].y); dd > far_d) { far_d = dd; far = i; }
    std::vector<size_t> keep{0};
    for (size_t i : simplify_range(avg, 0, far, eps)) keep.push_back(i);
    keep.push_back(far);
    for (size_t i : simplify_range(avg, far, m, eps)) keep.push_back(i);
    std::vector<cv::Point> out;
    out.reserve(keep.size());
    for (size_t i : keep) out.push_back(c[i]);
    return out;
}

// Coverage of colour `a` in a pixel `p` blended from `a` and `b`: the projection of p - b on
// a - b, clamped to 0..1; -1 when the two colours are too close to tell.
float blend_share(const cv::Vec3b& p, const cv::Vec3b& a, const cv::Vec3b& b) {
    double num = 0, den = 0;
    for (int c = 0; c < 3; ++c) {
        const double ab = double(a[c]) - double(b[c]);
        num += (double(p[c]) - double(b[c])) * ab;
        den += ab * ab;
    }
    if (den < 300) return -1.f;
    return float(std::clamp(num / den, 0.0, 1.0));
}

// Pixel `p` as a blend of a fill `a`, the thin outline `ink` drawn over it later and the
// ground `b` beyond: the least-squares p = b + s (a - b) + k (ink - b), with s and k in 0..1.
struct InkBlend {
    double s = 0, k = 0;
    bool fits = false;  // colours far enough apart to tell, and the fit within 20 levels
};

InkBlend blend_with_ink(const cv::Vec3b& p, const cv::Vec3b& a, const cv::Vec3b& ink, const cv::Vec3b& b) {
    double u[3], v[3], d[3];
    for (int c = 0; c < 3; ++c) {
        u[c] = double(a[c]) - b[c];
        v[c] = double(ink[c]) - b[c];
        d[c] = double(p[c]) - b[c];
    }
    const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2], vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    const double uv = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    const double ud = u[0] * d[0] + u[1] * d[1] + u[2] * d[2], vd = v[0] * d[0] + v[1] * d[1] + v[2] * d[2];
    const double det = uu * vv - uv * uv;
    InkBlend r;
    if (uu < 300 || vv < 300 || det < 1e-3 * uu * vv) return r;
    r.s = std::clamp((ud * vv - vd * uv) / det, 0.0, 1.0);
    r.k = std::clamp((vd * uu - ud * uv) / det, 0.0, 1.0);
    double e2 = 0;
    for (int c = 0; c < 3; ++c) {
        const double e = d[c] - r.s * u[c] - r.k * v[c];
        e2 += e * e;
    }
    r.fits = e2 <= 400;
    return r;
}

// Share of colour `a` in the part of pixel `p` that colour `ink` leaves uncovered (s / (1 - k)
// of the blend above); -1 when the blend does not fit or the ink covers nearly all of p (what
// lies under it does not show).
float share_beside_ink(const cv::Vec3b& p, const cv::Vec3b& a, const cv::Vec3b& ink, const cv::Vec3b& b) {
    const InkBlend f = blend_with_ink(p, a, ink, b);
    if (!f.fits || f.k > 0.9) return -1.f;
    return float(std::clamp(f.s / (1 - f.k), 0.0, 1.0));
}

// The fill's share of pixel (x, y) of `rgb` that the ink covers nearly all of: the part on the
// fill's side of the ink's middle, so that the fill ends under the middle of the outline. The
// source shows nothing of the fill there; the middle is where its pixels' blends say the line
// is (the ink-weighted centroid across it, along the row or the column that crosses it more
// steeply), which follows the drawn line to a fraction of a pixel where a pixel-wise rule
// would step from pixel to pixel. -1 when neither crossing runs from the fill to the ground.
float share_under_ink_middle(const cv::Mat& rgb, int x, int y, const cv::Vec3b& fill, const cv::Vec3b& ink,
                             const cv::Vec3b& ground) {
    constexpr int reach = 4;            // pixels each way: outlines are thin
    constexpr double faint = 0.03;      // less ink than this ends the crossing
    float best = -1;
    double best_width = 1e9;
    for (int axis = 0; axis < 2; ++axis) {
        const int sx = axis == 0 ? 1 : 0, sy = axis == 0 ? 0 : 1;
        auto blend = [&](int t) {
            const int qx = x + sx * t, qy = y + sy * t;
            if (qx < 0 || qy < 0 || qx >= rgb.cols || qy >= rgb.rows) return InkBlend{};
            return blend_with_ink(rgb.at<cv::Vec3b>(qy, qx), fill, ink, ground);
        };
        const InkBlend here = blend(0);
        if (!here.fits) continue;
        double mass = here.k, moment = here.k * 0.5;
        int ends[2] = {0, 0};  // the first pixel past the ink on each side
        bool ok = true;
        for (int side = 0; side < 2 && ok; ++side) {
            const int dir = side == 0 ? -1 : 1;
            int t = dir;
            for (;; t += dir) {
                if (std::abs(t) > reach) { ok = false; break; }
                const InkBlend f = blend(t);
                if (!f.fits) { ok = false; break; }
                if (f.k < faint) break;
                mass += f.k;
                moment += f.k * (t + 0.5);
            }
            ends[side] = t;
        }
        const int lo = ends[0], hi = ends[1];
        if (!ok || mass <= 0) continue;
        const bool fill_low = blend(lo).s > 0.5, fill_high = blend(hi).s > 0.5;
        if (fill_low == fill_high) continue;
        const double middle = moment / mass;  // along the axis, pixel (x, y) spanning 0..1
        const double share = std::clamp(fill_high ? 1.0 - middle : middle, 0.0, 1.0);
        if (mass < best_width) { best_width = mass; best = float(share); }
    }
    return best;
}

}  // namespace

std::vector<PolygonStroke> trace_region(const cv::Mat& rgb, const Regions& regs, int index, const TraceOptions& opts) {
    const Region& reg = regs.list[size_t(index)];
    const int margin = opts.extend + 2;
    const cv::Rect img(0, 0, rgb.cols, rgb.rows);
    const cv::Rect box = cv::Rect(reg.box.x - margin, reg.box.y - margin, reg.box.width + 2 * margin,
                                  reg.box.height + 2 * margin) & img;
    const cv::Mat id = regs.id(box);

    // Distance (pixels) to the region, to reach under the regions drawn after it.
    cv::Mat outside(box.size(), CV_8U);
    for (int y = 0; y < box.height; ++y)
        for (int x = 0; x < box.width; ++x) outside.at<uint8_t>(y, x) = id.at<int>(y, x) == index ? 0 : 255;
    cv::Mat dist;
    cv::distanceTransform(outside, dist, cv::DIST_L2, 3);

    cv::Mat field(box.size(), CV_32F, cv::Scalar(0));
    for (int y = 0; y < box.height; ++y)
        for (int x = 0; x < box.width; ++x) {
            const int r = id.at<int>(y, x);
            if (r == index || (r > index && dist.at<float>(y, x) <= float(opts.extend))) field.at<float>(y, x) = 1.f;
        }
    // Edges against what stays visible (earlier regions, or later ones beyond the reach):
    // the source's blend says how much of the pixel the region covers.
    cv::Mat share = field.clone();
    const cv::Vec3b mine = reg.color;
    for (int y = 0; y < box.height; ++y)
        for (int x = 0; x < box.width; ++x) {
            const bool in = field.at<float>(y, x) > 0.5f;
            const int r = id.at<int>(y, x);
            if (!in) {
                // Within two pixels: a thin line's faint pixels (a quarter covered) lie
                // beside pixels that are no more than half covered either.
                const bool next_to_region = dist.at<float>(y, x) <= 2.f;
                if (!next_to_region) continue;
                const float a = blend_share(rgb.at<cv::Vec3b>(box.y + y, box.x + x), mine, regs.list[size_t(r)].color);
                if (a >= 0) share.at<float>(y, x) = a;
            } else if (r != index && opts.beside_ink) {
                // Under a later region that covers part of the pixel (a thin outline between
                // this fill and the ground): as much of the rest as the source shows this fill,
                // the least share any ground around explains (a fill showing past the outline
                // costs more stamps than a sliver of ground under it).
                float best = -1;
                int ground = -1;
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx) {
                        const int qx = x + dx, qy = y + dy;
                        if (qx < 0 || qy < 0 || qx >= box.width || qy >= box.height) continue;
                        const int o = id.at<int>(qy, qx);
                        if (o == index || o == r || field.at<float>(qy, qx) > 0.5f) continue;
                        const float a = share_beside_ink(rgb.at<cv::Vec3b>(box.y + y, box.x + x), mine,
                                                         regs.list[size_t(r)].color, regs.list[size_t(o)].color);
                        if (a >= 0 && (best < 0 || a < best)) best = a;
                        if (ground < 0) ground = o;
                    }
                // Where the outline hides the pixel, the source says nothing of the fill: under
                // the outline's middle.
                if (best < 0 && ground >= 0 && opts.under_ink_middle)
                    best = share_under_ink_middle(rgb, box.x + x, box.y + y, mine, regs.list[size_t(r)].color,
                                                  regs.list[size_t(ground)].color);
                if (best >= 0) share.at<float>(y, x) = best;
            } else if (r == index) {
                // The neighbour this pixel blends with: the first visible one around it.
                int other = -1;
                for (int dy = -1; dy <= 1 && other < 0; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int qx = x + dx, qy = y + dy;
                        if (qx >= 0 && qy >= 0 && qx < box.width && qy < box.height && field.at<float>(qy, qx) < 0.5f) {
                            other = id.at<int>(qy, qx);
                            break;
                        }
                    }
                if (other < 0) continue;
                const float a = blend_share(rgb.at<cv::Vec3b>(box.y + y, box.x + x), mine, regs.list[size_t(other)].color);
                if (a >= 0) share.at<float>(y, x) = a;
            }
        }

    // Two pixels of replicated border: a region at the image's edge runs out past it.
    const int pad = 2;
    cv::Mat padded;
    cv::copyMakeBorder(share, padded, pad, pad, pad, pad, cv::BORDER_REPLICATE);
    const int k = std::max(1, opts.upsample);
    // Each pixel gets exactly its share of the k x k sub-pixels: the ones where the smooth
    // field is highest. Thresholding the field at one half would lose lines thinner than a
    // pixel (two neighbours at half coverage); counting keeps their width and position.
    cv::Mat bin(padded.rows * k, padded.cols * k, CV_8U, cv::Scalar(0));
    std::vector<std::pair<float, int>> sub(size_t(k * k));
    // The bilinear field upsampled a band of rows at a time: whole, it would take 4 k^2 bytes
    // a pixel (256 at k = 8) for the largest region. A band resized with one row of context
    // each way gives the same values as the whole image does (output row y k + r reads source
    // rows y - 1 .. y + 1, and with k a power of two its weights are exact either way).
    const bool pow2 = (k & (k - 1)) == 0;
    const int band = pow2 ? 16 : padded.rows;
    cv::Mat up;
    for (int y0 = 0; y0 < padded.rows; y0 += band) {
        const int y1 = std::min(padded.rows, y0 + band);
        const int s0 = std::max(0, y0 - 1), s1 = std::min(padded.rows, y1 + 1);
        cv::resize(padded.rowRange(s0, s1), up, cv::Size(padded.cols * k, (s1 - s0) * k), 0, 0, cv::INTER_LINEAR);
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < padded.cols; ++x) {
                const int n = int(std::lround(double(padded.at<float>(y, x)) * k * k));
                if (n <= 0) continue;
                for (int j = 0; j < k * k; ++j) sub[size_t(j)] = {-up.at<float>((y - s0) * k + j / k, x * k + j % k), j};
                if (n < k * k) std::sort(sub.begin(), sub.end());
                for (int j = 0; j < n; ++j) bin.at<uint8_t>(y * k + sub[size_t(j)].second / k, x * k + sub[size_t(j)].second % k) = 255;
            }
    }
    up.release();

    // Outlines with their holes. A hole over pixels of a region drawn earlier must stay open
    // (a ring whose line breaks in the source traces closed, and its fill would cover what it
    // encloses); holes over later regions only are filled, the later regions cover them.
    std::vector<std::vector<cv::Point>> outlines;
    std::vector<cv::Vec4i> tree;
    cv::findContours(bin, outlines, tree, cv::RETR_CCOMP, cv::CHAIN_APPROX_NONE);
    const double unit = 16.0 / k, step = opts.lattice;
    auto simplify = [&](const std::vector<cv::Point>& c) {
        std::vector<cv::Point> simple;
        const int r = int(std::lround(opts.smooth * k));
        if (r > 0 && c.size() > size_t(4 * r + 4)) simple = simplify_smoothed(c, opts.epsilon * k, r);
        else cv::approxPolyDP(c, simple, opts.epsilon * k, true);
        if (simple.size() < 3) return std::vector<cv::Point2f>();
        return opts.fit ? fit_outline(c, simple, bin) : std::vector<cv::Point2f>(simple.begin(), simple.end());
    };
    auto over_earlier = [&](const std::vector<cv::Point>& hole) {
        const cv::Rect hb = cv::boundingRect(hole);
        for (int y = hb.y / k; y <= (hb.y + hb.height) / k; ++y)
            for (int x = hb.x / k; x <= (hb.x + hb.width) / k; ++x) {
                const int ix = x - pad, iy = y - pad;  // box pixel
                if (ix < 0 || iy < 0 || ix >= box.width || iy >= box.height || id.at<int>(iy, ix) >= index) continue;
                if (cv::pointPolygonTest(hole, cv::Point2f(float(x * k) + 0.5f * float(k - 1), float(y * k) + 0.5f * float(k - 1)), false) > 0)
                    return true;
            }
        return false;
    };
    std::vector<PolygonStroke> out;
    for (size_t o = 0; o < outlines.size(); ++o) {
        if (tree[o][3] >= 0) continue;  // a hole: handled with its outline
        if (cv::contourArea(outlines[o]) < opts.min_area * k * k) continue;
        std::vector<cv::Point2f> ring = simplify(outlines[o]);
        if (ring.size() < 3) continue;
        for (int h = tree[o][2]; h >= 0; h = tree[size_t(h)][0]) {
            const auto& hole = outlines[size_t(h)];
            if (cv::contourArea(hole) < opts.min_area * k * k || !over_earlier(hole)) continue;
            const std::vector<cv::Point2f> hr = simplify(hole);
            if (hr.size() < 3) continue;
            // Joined by a bridge there and back: the two bridge edges cancel under the nonzero
            // rule, and the hole's reversed direction winds to zero inside it.
            size_t bi = 0, bj = 0;
            float best = -1;
            for (size_t a = 0; a < ring.size(); ++a)
                for (size_t b = 0; b < hr.size(); ++b) {
                    const cv::Point2f d = ring[a] - hr[b];
                    const float dd = d.dot(d);
                    if (best < 0 || dd < best) { best = dd; bi = a; bj = b; }
                }
            std::vector<cv::Point2f> joined(ring.begin(), ring.begin() + std::ptrdiff_t(bi) + 1);
            for (size_t t = 0; t <= hr.size(); ++t) joined.push_back(hr[(bj + t) % hr.size()]);
            joined.insert(joined.end(), ring.begin() + std::ptrdiff_t(bi), ring.end());
            ring.swap(joined);
        }
        PolygonStroke p;
        p.color = Rgba8{mine[0], mine[1], mine[2], 255};
        // Upsampled pixel X has its centre at image position box.x - pad + (X + 0.5) / k;
        // vertices are rounded to the lattice of `opts.lattice` Q4 units through it.
        for (const cv::Point2f& v : ring) {
            PolygonVertex q;
            q.x = int32_t(16 * (box.x - pad) + 8 / k + int32_t(std::lround(v.x * unit / step) * step));
            q.y = int32_t(16 * (box.y - pad) + 8 / k + int32_t(std::lround(v.y * unit / step) * step));
            p.points.push_back(q);
        }
        out.push_back(std::move(p));
    }
    return out;
}

}  // namespace spt::cartoon
