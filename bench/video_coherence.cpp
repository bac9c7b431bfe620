// video_coherence: temporal steadiness of a painting against its source.
//
//   video_coherence SOURCE.rgb PAINT.rgb WIDTH HEIGHT [KEYFRAMES]
//
// Both files are raw rgb24 frames of the same size. For each pair (t, t+1) the optical flow is
// computed on the source (DIS medium, from t+1 back to t) and both frame t's are warped onto
// t+1. The motion-compensated residual is mean |X(t+1) - warp(X(t))|. The ratio
// painting / source says how much less steady the painting is than the source along the
// motion (1.0: as steady). Pairs whose source residual is above 25 (cuts) are left out, and so
// are pairs ending on the listed key frames (comma list) if given.
#include <cstdio>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

namespace {

double residual(const cv::Mat& next, const cv::Mat& prev, const cv::Mat& map) {
    cv::Mat warped, diff;
    cv::remap(prev, warped, map, cv::noArray(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    cv::absdiff(next, warped, diff);
    const cv::Scalar m = cv::mean(diff);
    return (m[0] + m[1] + m[2]) / 3.0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 5) {
        std::fprintf(stderr, "usage: video_coherence SOURCE.rgb PAINT.rgb WIDTH HEIGHT [KEYFRAMES]\n");
        return 2;
    }
    const int w = std::atoi(argv[3]), h = std::atoi(argv[4]);
    std::set<long> keys;
    if (argc > 5) {
        std::stringstream ss(argv[5]);
        std::string item;
        while (std::getline(ss, item, ',')) keys.insert(std::atol(item.c_str()));
    }
    FILE* fs = std::fopen(argv[1], "rb");
    FILE* fp = std::fopen(argv[2], "rb");
    if (!fs || !fp || w <= 0 || h <= 0) {
        std::fprintf(stderr, "cannot open inputs\n");
        return 1;
    }
    const size_t n = size_t(w) * h * 3;
    cv::Mat s0(h, w, CV_8UC3), p0(h, w, CV_8UC3), s1(h, w, CV_8UC3), p1(h, w, CV_8UC3);
    if (std::fread(s0.data, 1, n, fs) != n || std::fread(p0.data, 1, n, fp) != n) return 1;
    auto dis = cv::DISOpticalFlow::create(cv::DISOpticalFlow::PRESET_MEDIUM);
    cv::Mat g0, g1, flow, map(h, w, CV_32FC2);
    cv::cvtColor(s0, g0, cv::COLOR_RGB2GRAY);
    double sum_s = 0, sum_p = 0;
    long pairs = 0, t = 1;
    for (;; ++t) {
        if (std::fread(s1.data, 1, n, fs) != n || std::fread(p1.data, 1, n, fp) != n) break;
        cv::cvtColor(s1, g1, cv::COLOR_RGB2GRAY);
        dis->calc(g1, g0, flow);  // for each pixel of t+1, where it was in t
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const cv::Vec2f f = flow.at<cv::Vec2f>(y, x);
                map.at<cv::Vec2f>(y, x) = cv::Vec2f(x + f[0], y + f[1]);
            }
        const double rs = residual(s1, s0, map);
        if (rs <= 25.0 && !keys.count(t)) {
            const double rp = residual(p1, p0, map);
            sum_s += rs;
            sum_p += rp;
            ++pairs;
        }
        std::swap(s0, s1);
        std::swap(p0, p1);
        std::swap(g0, g1);
    }
    if (pairs == 0) {
        std::printf("pairs 0\n");
        return 0;
    }
    std::printf("pairs %ld source_residual %.3f paint_residual %.3f ratio %.3f\n", pairs, sum_s / pairs,
                sum_p / pairs, sum_p / sum_s);
    return 0;
}
