#include "video/motion.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

namespace spt::video {

FlowEstimator::FlowEstimator(FlowMethod method, int max_width)
    : method_(method), max_width_(std::max(32, max_width)) {
    int preset = cv::DISOpticalFlow::PRESET_ULTRAFAST;
    if (method == FlowMethod::DisFast) preset = cv::DISOpticalFlow::PRESET_FAST;
    if (method == FlowMethod::DisMedium) preset = cv::DISOpticalFlow::PRESET_MEDIUM;
    if (method != FlowMethod::Farneback) dis_ = cv::DISOpticalFlow::create(preset);
}

FlowEstimator::~FlowEstimator() = default;

void FlowEstimator::compute(const cv::Mat& prev_gray, const cv::Mat& next_gray, cv::Mat& flow) {
    cv::Mat a = prev_gray, b = next_gray;
    double scale = 1.0;
    if (prev_gray.cols > max_width_) {
        scale = double(prev_gray.cols) / max_width_;
        const cv::Size sz(max_width_, std::max(1, int(std::lround(prev_gray.rows / scale))));
        cv::resize(prev_gray, a, sz, 0, 0, cv::INTER_AREA);
        cv::resize(next_gray, b, sz, 0, 0, cv::INTER_AREA);
    }
    cv::Mat f;
    if (method_ == FlowMethod::Farneback) {
        cv::calcOpticalFlowFarneback(a, b, f, 0.5, 3, 15, 3, 5, 1.2, 0);
    } else {
        dis_->calc(a, b, f);
    }
    if (scale != 1.0) {
        cv::resize(f, flow, prev_gray.size(), 0, 0, cv::INTER_LINEAR);
        flow *= scale;
    } else {
        flow = f;
    }
}

namespace {

int16_t to_q4(float v) {
    const double q = std::nearbyint(double(v) * 16.0);
    return int16_t(std::clamp(q, -32768.0, 32767.0));
}

}  // namespace

MotionField block_motion(const cv::Mat& flow, int block) {
    MotionField m;
    block = std::clamp(block, 8, 256);
    m.block_size = uint16_t(block);
    m.cols = uint16_t((flow.cols + block - 1) / block);
    m.rows = uint16_t((flow.rows + block - 1) / block);
    m.vectors.resize(size_t(m.cols) * m.rows);
    std::vector<float> xs, ys;
    xs.reserve(size_t(block) * block);
    ys.reserve(size_t(block) * block);
    for (int by = 0; by < m.rows; ++by) {
        for (int bx = 0; bx < m.cols; ++bx) {
            xs.clear();
            ys.clear();
            const int y1 = std::min(flow.rows, (by + 1) * block);
            const int x1 = std::min(flow.cols, (bx + 1) * block);
            for (int y = by * block; y < y1; ++y) {
                const cv::Vec2f* row = flow.ptr<cv::Vec2f>(y);
                for (int x = bx * block; x < x1; ++x) {
                    if (!std::isfinite(row[x][0]) || !std::isfinite(row[x][1])) continue;
                    xs.push_back(row[x][0]);
                    ys.push_back(row[x][1]);
                }
            }
            std::pair<int16_t, int16_t> v{0, 0};
            if (!xs.empty()) {
                const size_t mid = xs.size() / 2;
                std::nth_element(xs.begin(), xs.begin() + mid, xs.end());
                std::nth_element(ys.begin(), ys.begin() + mid, ys.end());
                v = {to_q4(xs[mid]), to_q4(ys[mid])};
            }
            m.vectors[size_t(by) * m.cols + bx] = v;
        }
    }
    return m;
}

bool is_still(const MotionField& m) {
    return std::all_of(m.vectors.begin(), m.vectors.end(),
                       [](const auto& v) { return v.first == 0 && v.second == 0; });
}

double block_residual(const cv::Mat& flow, const MotionField& m) {
    if (m.vectors.empty() || flow.empty()) return 0.0;
    double sum = 0;
    for (int y = 0; y < flow.rows; ++y) {
        const cv::Vec2f* row = flow.ptr<cv::Vec2f>(y);
        const int by = std::min(int(m.rows) - 1, y / m.block_size);
        for (int x = 0; x < flow.cols; ++x) {
            const int bx = std::min(int(m.cols) - 1, x / m.block_size);
            const auto& v = m.vectors[size_t(by) * m.cols + bx];
            sum += std::hypot(row[x][0] - v.first / 16.0, row[x][1] - v.second / 16.0);
        }
    }
    return sum / (double(flow.rows) * flow.cols);
}

}  // namespace spt::video
