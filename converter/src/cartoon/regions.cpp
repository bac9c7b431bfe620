#include "cartoon/regions.hpp"

#include <algorithm>
#include <numeric>

#include <opencv2/imgproc.hpp>

namespace spt::cartoon {

namespace {

// Components of equal labels, pixels within `reach` (Chebyshev) joined; label < 0 stays -1.
int components(const cv::Mat& labels, cv::Mat& comp, std::vector<int64_t>& sizes, int reach) {
    comp.create(labels.size(), CV_32S);
    comp.setTo(-1);
    sizes.clear();
    std::vector<cv::Point> stack;
    const int W = labels.cols, H = labels.rows;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const int l = labels.at<int>(y, x);
            if (l < 0 || comp.at<int>(y, x) >= 0) continue;
            const int c = int(sizes.size());
            int64_t n = 0;
            stack.assign(1, cv::Point(x, y));
            comp.at<int>(y, x) = c;
            while (!stack.empty()) {
                const cv::Point p = stack.back();
                stack.pop_back();
                ++n;
                for (int dy = -reach; dy <= reach; ++dy)
                    for (int dx = -reach; dx <= reach; ++dx) {
                        const int qx = p.x + dx, qy = p.y + dy;
                        if (qx < 0 || qy < 0 || qx >= W || qy >= H) continue;
                        int& q = comp.at<int>(qy, qx);
                        if (q >= 0 || labels.at<int>(qy, qx) != l) continue;
                        q = c;
                        stack.push_back(cv::Point(qx, qy));
                    }
            }
            sizes.push_back(n);
        }
    return int(sizes.size());
}

int dist2(const cv::Vec3b& a, const cv::Vec3b& b) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d += (int(a[c]) - int(b[c])) * (int(a[c]) - int(b[c]));
    return d;
}

// Gives every unlabelled pixel (-1) the label of a labelled 4-neighbour, the one whose palette
// colour is nearest its own, growing inwards from the labelled pixels.
void fill_unlabelled(const cv::Mat& rgb, cv::Mat& labels, const std::vector<cv::Vec3b>& palette) {
    const int W = labels.cols, H = labels.rows;
    std::vector<cv::Point> todo;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            if (labels.at<int>(y, x) < 0) todo.push_back(cv::Point(x, y));
    while (!todo.empty()) {
        std::vector<std::pair<cv::Point, int>> set;
        std::vector<cv::Point> left;
        for (const cv::Point& p : todo) {
            int best = -1, best_d = 0;
            const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
            for (int k = 0; k < 4; ++k) {
                const int qx = p.x + dx[k], qy = p.y + dy[k];
                if (qx < 0 || qy < 0 || qx >= W || qy >= H) continue;
                const int l = labels.at<int>(qy, qx);
                if (l < 0) continue;
                const int d = dist2(rgb.at<cv::Vec3b>(p), palette[size_t(l)]);
                if (best < 0 || d < best_d) { best = l; best_d = d; }
            }
            if (best >= 0) set.push_back({p, best});
            else left.push_back(p);
        }
        if (set.empty()) {  // nothing labelled at all: one colour everywhere
            for (const cv::Point& p : left) labels.at<int>(p) = 0;
            break;
        }
        for (const auto& [p, l] : set) labels.at<int>(p) = l;
        todo.swap(left);
    }
}

// A fill's colour: the mean of its interior pixels within a few levels of the most frequent
// one (flat art repeats one colour exactly; compressed video scatters it a little, and the
// blended pixels at the edge stay out). `flat` counts those pixels.
cv::Vec3b fill_colour(std::vector<uint32_t>& c, const cv::Vec3b& fallback, int64_t& flat) {
    flat = 0;
    if (c.empty()) return fallback;
    std::sort(c.begin(), c.end());
    uint32_t mode = c[0];
    size_t best = 0;
    for (size_t i = 0; i < c.size();) {
        size_t j = i;
        while (j < c.size() && c[j] == c[i]) ++j;
        if (j - i > best) { best = j - i; mode = c[i]; }
        i = j;
    }
    int64_t s[3] = {0, 0, 0}, n = 0;
    for (uint32_t v : c) {
        bool near = true;
        for (int k = 0; k < 3; ++k) near &= std::abs(int((v >> (16 - 8 * k)) & 255) - int((mode >> (16 - 8 * k)) & 255)) <= 6;
        if (!near) continue;
        ++n;
        for (int k = 0; k < 3; ++k) s[k] += (v >> (16 - 8 * k)) & 255;
    }
    flat = n;
    return cv::Vec3b(uint8_t((s[0] + n / 2) / n), uint8_t((s[1] + n / 2) / n), uint8_t((s[2] + n / 2) / n));
}

cv::Vec3b unpack(uint32_t v) { return cv::Vec3b(uint8_t(v >> 16), uint8_t(v >> 8), uint8_t(v)); }

// The ink of a region that has no flat inside (small anti-aliased text, hairlines): nearly all
// its pixels are blends of the ink with what lies around it, so their most frequent value is a
// blend, lighter than the ink, and tracing against it clamps every darker pixel. The ink is
// taken towards the far end of the blends: the mean of the half of its pixels farthest from the
// colour around the region. (Measured on the taffy and butterfly stills at 36 dB: the farthest
// 5% is noise on compressed video, all pixels' mean too light for text; see the commit.)
cv::Vec3b ink_colour(std::vector<uint32_t>& c, const cv::Vec3b& around) {
    std::sort(c.begin(), c.end(), [&](uint32_t a, uint32_t b) {
        const int da = dist2(unpack(a), around), db = dist2(unpack(b), around);
        return da != db ? da > db : a < b;
    });
    const size_t n = std::max<size_t>(1, c.size() / 2);
    int64_t s[3] = {0, 0, 0};
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) s[k] += unpack(c[i])[k];
    const int64_t h = int64_t(n) / 2;
    return cv::Vec3b(uint8_t((s[0] + h) / int64_t(n)), uint8_t((s[1] + h) / int64_t(n)), uint8_t((s[2] + h) / int64_t(n)));
}

}  // namespace

Regions find_regions(const cv::Mat& rgb, cv::Mat labels, const std::vector<cv::Vec3b>& palette, int min_pixels) {
    cv::Mat comp;
    std::vector<int64_t> sizes;
    components(labels, comp, sizes, 2);
    for (int y = 0; y < labels.rows; ++y)
        for (int x = 0; x < labels.cols; ++x)
            if (sizes[size_t(comp.at<int>(y, x))] < min_pixels) labels.at<int>(y, x) = -1;
    fill_unlabelled(rgb, labels, palette);
    // A line drawn thinner than a pixel breaks into dashes where its coverage drops below a
    // half; pixels of a label two apart are one region, which tracing joins again.
    const int n = components(labels, comp, sizes, 2);

    std::vector<Region> regs(static_cast<size_t>(n));
    std::vector<std::vector<uint32_t>> colours(static_cast<size_t>(n)), all(static_cast<size_t>(n));
    // The label most often found next to each region (what its edge pixels blend with).
    std::vector<std::vector<int64_t>> next_to(static_cast<size_t>(n), std::vector<int64_t>(palette.size(), 0));
    std::vector<int> x0(size_t(n), labels.cols), y0(size_t(n), labels.rows), x1(size_t(n), -1), y1(size_t(n), -1);
    for (int y = 0; y < labels.rows; ++y)
        for (int x = 0; x < labels.cols; ++x) {
            const int c = comp.at<int>(y, x);
            Region& r = regs[size_t(c)];
            r.label = labels.at<int>(y, x);
            ++r.pixels;
            x0[size_t(c)] = std::min(x0[size_t(c)], x);
            x1[size_t(c)] = std::max(x1[size_t(c)], x);
            y0[size_t(c)] = std::min(y0[size_t(c)], y);
            y1[size_t(c)] = std::max(y1[size_t(c)], y);
            // The colour is measured away from the edge, where the fill is not blended.
            bool interior = true;
            for (int d = 0; d < 4; ++d) {
                const int qx = x + (d == 0) - (d == 1), qy = y + (d == 2) - (d == 3);
                if (qx >= 0 && qy >= 0 && qx < labels.cols && qy < labels.rows && comp.at<int>(qy, qx) != c) {
                    interior = false;
                    const int l = labels.at<int>(qy, qx);
                    if (l >= 0 && l != r.label) ++next_to[size_t(c)][size_t(l)];
                }
            }
            const cv::Vec3b& p = rgb.at<cv::Vec3b>(y, x);
            const uint32_t packed = uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2];
            all[size_t(c)].push_back(packed);
            if (interior) colours[size_t(c)].push_back(packed);
        }
    for (int c = 0; c < n; ++c) {
        Region& r = regs[size_t(c)];
        r.box = cv::Rect(x0[size_t(c)], y0[size_t(c)], x1[size_t(c)] - x0[size_t(c)] + 1, y1[size_t(c)] - y0[size_t(c)] + 1);
        int64_t flat = 0;
        const int64_t interior = int64_t(colours[size_t(c)].size());
        r.color = fill_colour(colours[size_t(c)], palette[size_t(r.label)], flat);
        const std::vector<int64_t>& nb = next_to[size_t(c)];
        const size_t around = size_t(std::max_element(nb.begin(), nb.end()) - nb.begin());
        // Thin (most pixels on its edge) and under a quarter flat: ink, not a fill. (A fill of
        // compressed video is seldom flat either, but it is thick, and its extremes are noise.)
        if (2 * interior < r.pixels && 4 * flat < r.pixels && nb[around] > 0) {
            r.ink_candidate = true;
            r.ink = ink_colour(all[size_t(c)], palette[around]);
            r.around = palette[around];
        }
        // Filled area: the region's outer outlines drawn filled in its box, after closing gaps
        // of up to two pixels (tracing closes them too: a ring broken where its line thins
        // must still be drawn before the fill inside it).
        const int m = 3;
        cv::Mat mask(r.box.height + 2 * m, r.box.width + 2 * m, CV_8U, cv::Scalar(0));
        for (int y = 0; y < r.box.height; ++y)
            for (int x = 0; x < r.box.width; ++x)
                if (comp.at<int>(r.box.y + y, r.box.x + x) == c) mask.at<uint8_t>(y + m, x + m) = 255;
        cv::morphologyEx(mask, mask, cv::MORPH_CLOSE, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
        std::vector<std::vector<cv::Point>> outlines;
        cv::findContours(mask, outlines, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
        cv::drawContours(mask, outlines, -1, cv::Scalar(255), cv::FILLED);
        r.filled_area = cv::countNonZero(mask);
    }
    // Drawing order: larger filled outlines first; ties by first pixel (component number).
    std::vector<int> order(static_cast<size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return regs[size_t(a)].filled_area > regs[size_t(b)].filled_area; });
    std::vector<int> rank(static_cast<size_t>(n));
    Regions out;
    for (int i = 0; i < n; ++i) {
        rank[size_t(order[size_t(i)])] = i;
        out.list.push_back(regs[size_t(order[size_t(i)])]);
    }
    out.id.create(labels.size(), CV_32S);
    for (int y = 0; y < labels.rows; ++y)
        for (int x = 0; x < labels.cols; ++x) out.id.at<int>(y, x) = rank[size_t(comp.at<int>(y, x))];
    return out;
}

}  // namespace spt::cartoon
