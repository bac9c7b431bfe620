// PSNR and luma SSIM (see metrics.hpp). OpenCV does the Gaussian filtering.
#include "io/metrics.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <limits>

namespace spt::io {

namespace {

cv::Mat luma(const uint8_t* rgb, uint32_t w, uint32_t h) {
    cv::Mat y(int(h), int(w), CV_64F);
    for (uint32_t j = 0; j < h; ++j) {
        const uint8_t* p = rgb + size_t(j) * w * 3;
        double* o = y.ptr<double>(int(j));
        for (uint32_t i = 0; i < w; ++i, p += 3) o[i] = 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
    }
    return y;
}

double mean_ssim(const cv::Mat& x, const cv::Mat& y) {
    const double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
    auto blur = [](const cv::Mat& m) {
        cv::Mat o;
        cv::GaussianBlur(m, o, cv::Size(11, 11), 1.5, 1.5, cv::BORDER_REPLICATE);
        return o;
    };
    const cv::Mat mx = blur(x), my = blur(y);
    const cv::Mat sxx = blur(x.mul(x)) - mx.mul(mx);
    const cv::Mat syy = blur(y.mul(y)) - my.mul(my);
    const cv::Mat sxy = blur(x.mul(y)) - mx.mul(my);
    cv::Mat num = (2 * mx.mul(my) + c1).mul(2 * sxy + c2);
    cv::Mat den = (mx.mul(mx) + my.mul(my) + c1).mul(sxx + syy + c2);
    cv::Mat map;
    cv::divide(num, den, map);
    return cv::mean(map)[0];
}

}  // namespace

ImageMetrics compare_rgb8(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height) {
    ImageMetrics m;
    const size_t n = size_t(width) * height * 3;
    if (n == 0) return m;
    uint64_t sq = 0;
    for (size_t i = 0; i < n; ++i) {
        const int d = int(a[i]) - int(b[i]);
        sq += uint64_t(d * d);
    }
    m.mse = double(sq) / double(n);
    m.psnr = sq == 0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / m.mse);
    m.ssim = sq == 0 ? 1.0 : mean_ssim(luma(a, width, height), luma(b, width, height));
    return m;
}

}  // namespace spt::io
