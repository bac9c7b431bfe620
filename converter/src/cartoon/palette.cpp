#include "cartoon/palette.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace spt::cartoon {

namespace {

constexpr int kBits = 5;  // histogram bins per channel: 32 (8 levels a bin)

int bin_of(const cv::Vec3b& c) {
    return (c[0] >> (8 - kBits)) << (2 * kBits) | (c[1] >> (8 - kBits)) << kBits | (c[2] >> (8 - kBits));
}

int cheb(const cv::Vec3b& a, const cv::Vec3b& b) {
    return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// True when `c` lies within 10 levels of the segment between `a` and `b`, away from both ends:
// an anti-aliased edge between the two.
bool is_blend(const cv::Vec3b& c, const cv::Vec3b& a, const cv::Vec3b& b) {
    double ab2 = 0, t = 0;
    for (int k = 0; k < 3; ++k) {
        ab2 += (double(b[k]) - a[k]) * (double(b[k]) - a[k]);
        t += (double(c[k]) - a[k]) * (double(b[k]) - a[k]);
    }
    if (ab2 < 900) return false;
    t /= ab2;
    if (t < 0.1 || t > 0.9) return false;
    double d2 = 0;
    for (int k = 0; k < 3; ++k) {
        const double e = double(c[k]) - (a[k] + t * (double(b[k]) - a[k]));
        d2 += e * e;
    }
    return d2 < 100;
}

// Drops the peaks made by anti-aliasing: a colour between two others whose pixels are seldom
// flat (all four neighbours alike), as an edge's blend is. Flat grey fills stay.
std::vector<cv::Vec3b> drop_blends(const cv::Mat& rgb, const std::vector<cv::Vec3b>& palette, int radius) {
    std::vector<int64_t> near(palette.size(), 0), flat(palette.size(), 0);
    for (int y = 1; y + 1 < rgb.rows; ++y)
        for (int x = 1; x + 1 < rgb.cols; ++x) {
            const cv::Vec3b& p = rgb.at<cv::Vec3b>(y, x);
            for (size_t k = 0; k < palette.size(); ++k) {
                if (cheb(p, palette[k]) > radius) continue;
                ++near[k];
                if (cheb(p, rgb.at<cv::Vec3b>(y, x - 1)) <= 4 && cheb(p, rgb.at<cv::Vec3b>(y, x + 1)) <= 4 &&
                    cheb(p, rgb.at<cv::Vec3b>(y - 1, x)) <= 4 && cheb(p, rgb.at<cv::Vec3b>(y + 1, x)) <= 4)
                    ++flat[k];
                break;
            }
        }
    // Against every pair of the other peaks: a chain of blends (the grey steps of black text
    // on white) goes entirely, the extremes stay.
    std::vector<cv::Vec3b> kept;
    for (size_t k = 0; k < palette.size(); ++k) {
        bool blend = false;
        if (2 * flat[k] < near[k])
            for (size_t i = 0; i < palette.size() && !blend; ++i)
                for (size_t j = i + 1; j < palette.size() && !blend; ++j)
                    blend = i != k && j != k && is_blend(palette[k], palette[i], palette[j]);
        if (!blend) kept.push_back(palette[k]);
    }
    return kept;
}

}  // namespace

std::vector<cv::Vec3b> find_palette(const cv::Mat& rgb, const PaletteOptions& opts) {
    CV_Assert(rgb.type() == CV_8UC3);
    const int nbins = 1 << (3 * kBits);
    std::vector<int64_t> count(nbins, 0);
    std::vector<cv::Vec<int64_t, 3>> sum(nbins, cv::Vec<int64_t, 3>(0, 0, 0));
    for (int y = 0; y < rgb.rows; ++y) {
        const cv::Vec3b* row = rgb.ptr<cv::Vec3b>(y);
        for (int x = 0; x < rgb.cols; ++x) {
            const int b = bin_of(row[x]);
            ++count[size_t(b)];
            for (int c = 0; c < 3; ++c) sum[size_t(b)][c] += row[x][c];
        }
    }
    const int64_t total = int64_t(rgb.rows) * rgb.cols;
    const int64_t min_count = std::max<int64_t>(8, int64_t(opts.min_share * double(total)));
    std::vector<cv::Vec3b> palette;
    std::vector<char> used(size_t(nbins), 0);
    while (int(palette.size()) < opts.max_colors) {
        // The fullest bin left (lowest index among equals: deterministic).
        int best = -1;
        for (int b = 0; b < nbins; ++b)
            if (!used[size_t(b)] && (best < 0 || count[size_t(b)] > count[size_t(best)])) best = b;
        if (best < 0 || count[size_t(best)] < min_count) break;
        const int64_t n = count[size_t(best)];
        cv::Vec3b centre(uint8_t(sum[size_t(best)][0] / n), uint8_t(sum[size_t(best)][1] / n),
                         uint8_t(sum[size_t(best)][2] / n));
        // Suppress every bin whose mean lies near this peak: its pixels are the same fill
        // (noise, or a blend too close to tell apart).
        for (int b = 0; b < nbins; ++b) {
            if (used[size_t(b)] || count[size_t(b)] == 0) continue;
            const int64_t m = count[size_t(b)];
            const cv::Vec3b c(uint8_t(sum[size_t(b)][0] / m), uint8_t(sum[size_t(b)][1] / m), uint8_t(sum[size_t(b)][2] / m));
            if (cheb(c, centre) < opts.merge_distance) used[size_t(b)] = 1;
        }
        used[size_t(best)] = 1;
        bool near_existing = false;
        for (const cv::Vec3b& p : palette) near_existing |= cheb(p, centre) < opts.merge_distance / 2;
        if (!near_existing) palette.push_back(centre);
    }
    // Refine each colour to the mean of the pixels close to it (the bin mean is biased by the
    // bin's edges).
    const int radius = std::max(2, opts.merge_distance / 2);
    std::vector<cv::Vec<int64_t, 3>> acc(palette.size(), cv::Vec<int64_t, 3>(0, 0, 0));
    std::vector<int64_t> n(palette.size(), 0);
    for (int y = 0; y < rgb.rows; ++y) {
        const cv::Vec3b* row = rgb.ptr<cv::Vec3b>(y);
        for (int x = 0; x < rgb.cols; ++x)
            for (size_t k = 0; k < palette.size(); ++k)
                if (cheb(row[x], palette[k]) <= radius) {
                    ++n[k];
                    for (int c = 0; c < 3; ++c) acc[k][c] += row[x][c];
                    break;
                }
    }
    for (size_t k = 0; k < palette.size(); ++k)
        if (n[k] > 0)
            for (int c = 0; c < 3; ++c) palette[k][c] = uint8_t((acc[k][c] + n[k] / 2) / n[k]);
    return drop_blends(rgb, palette, radius);
}

cv::Mat label_pixels(const cv::Mat& rgb, const std::vector<cv::Vec3b>& palette) {
    cv::Mat labels(rgb.size(), CV_32S, cv::Scalar(0));
    for (int y = 0; y < rgb.rows; ++y) {
        const cv::Vec3b* row = rgb.ptr<cv::Vec3b>(y);
        int* out = labels.ptr<int>(y);
        for (int x = 0; x < rgb.cols; ++x) {
            int best = 0;
            int best_d = std::numeric_limits<int>::max();
            for (size_t k = 0; k < palette.size(); ++k) {
                int d = 0;
                for (int c = 0; c < 3; ++c) {
                    const int e = int(row[x][c]) - int(palette[k][c]);
                    d += e * e;
                }
                if (d < best_d) { best_d = d; best = int(k); }
            }
            // A blend with a rarer colour (palette order is by frequency) belongs to it from a
            // quarter coverage on: the ink of thin lines and small text is mostly blended, and
            // tracing measures each pixel's true share anyway.
            int rare = -1;
            double rare_err = 400;  // squared distance from the blend line, at most 20 levels
            for (size_t k = size_t(best) + 1; k < palette.size() && best_d > 900; ++k) {
                double ab2 = 0, t = 0;
                for (int c = 0; c < 3; ++c) {
                    const double ab = double(palette[k][c]) - palette[size_t(best)][c];
                    ab2 += ab * ab;
                    t += (double(row[x][c]) - palette[size_t(best)][c]) * ab;
                }
                if (ab2 < 900) continue;
                t /= ab2;
                if (t < 0.25 || t > 1) continue;
                double e2 = 0;
                for (int c = 0; c < 3; ++c) {
                    const double e = double(row[x][c]) - (palette[size_t(best)][c] + t * (double(palette[k][c]) - palette[size_t(best)][c]));
                    e2 += e * e;
                }
                if (e2 < rare_err) { rare_err = e2; rare = int(k); }
            }
            out[x] = rare >= 0 ? rare : best;
        }
    }
    return labels;
}

bool sparser_palette_has_fewer_colours(const cv::Mat& rgb, const PaletteOptions& opts, double share) {
    if (opts.min_share >= share) return false;
    PaletteOptions sparse = opts;
    sparse.min_share = share;
    return find_palette(rgb, sparse).size() < find_palette(rgb, opts).size();
}

}  // namespace spt::cartoon
