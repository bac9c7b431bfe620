#include "video/cut_detect.hpp"

#include <algorithm>
#include <numeric>

#include <opencv2/imgproc.hpp>

namespace spt::video {

namespace {

// Fraction of the edge pixels of `edges` that have no edge of `other_wide` (the other frame's
// edges dilated by one pixel, so that small motion is not counted as change).
double unmatched_edges(const cv::Mat& edges, const cv::Mat& other_wide) {
    const int n = cv::countNonZero(edges);
    if (n == 0) return 0.0;
    cv::Mat lost;
    cv::bitwise_and(edges, ~other_wide, lost);
    return double(cv::countNonZero(lost)) / n;
}

}  // namespace

CutDetector::CutDetector(const CutOptions& opts) : opts_(opts) {
    opts_.window = std::max(2, opts_.window);
    opts_.analysis_width = std::max(16, opts_.analysis_width);
}

void CutDetector::reset() {
    prev_small_.release();
    prev_edges_.release();
    prev_edges_wide_.release();
    history_.clear();
}

CutScore CutDetector::push(const cv::Mat& gray) {
    CutScore s;
    // Analyse a small, slightly blurred copy: cuts are global events, and noise or grain at
    // full resolution would only add false edges.
    cv::Mat small;
    const int w = std::min(gray.cols, opts_.analysis_width);
    const int h = std::max(1, int(std::lround(double(gray.rows) * w / gray.cols)));
    cv::resize(gray, small, cv::Size(w, h), 0, 0, cv::INTER_AREA);
    cv::GaussianBlur(small, small, cv::Size(3, 3), 0.8);
    // Edges of a contrast-normalised copy: a fade changes contrast, not the edges' places, and
    // should not look like a change of content.
    cv::Scalar mean, sdev;
    cv::meanStdDev(small, mean, sdev);
    cv::Mat norm;
    const double gain = sdev[0] > 2.0 ? 48.0 / sdev[0] : 0.0;
    small.convertTo(norm, CV_8U, gain, 128.0 - gain * mean[0]);
    cv::Mat edges, wide;
    cv::Canny(norm, edges, 40, 100);
    cv::dilate(edges, wide, cv::Mat::ones(5, 5, CV_8U));

    if (!prev_small_.empty() && prev_small_.size() == small.size()) {
        cv::Mat diff;
        cv::absdiff(small, prev_small_, diff);
        s.pixel_diff = cv::mean(diff)[0];
        const bool none_now = cv::countNonZero(edges) == 0;
        const bool none_before = cv::countNonZero(prev_edges_) == 0;
        if (none_now && none_before) {
            s.edge_diff = 0.0;
        } else if (none_now || none_before) {
            s.edge_diff = 1.0;  // edges appeared from or vanished into a flat frame
        } else {
            s.edge_diff = std::max(unmatched_edges(edges, prev_edges_wide_),
                                   unmatched_edges(prev_edges_, wide));
        }
        s.product = s.pixel_diff * s.edge_diff;
        const double mean = history_.empty()
                                ? 0.0
                                : std::accumulate(history_.begin(), history_.end(), 0.0) / history_.size();
        s.threshold = std::max(opts_.factor * mean, opts_.min_pixel_diff * opts_.min_edge_diff);
        // A new shot needs a few frames of history before its own cuts can be judged.
        s.cut = int(history_.size()) >= opts_.min_history && s.product > s.threshold && s.pixel_diff >= opts_.min_pixel_diff &&
                s.edge_diff >= opts_.min_edge_diff;
        // A cut's product would inflate the mean of the next shot's first frames: keep it out.
        if (!s.cut) {
            history_.push_back(s.product);
            if (int(history_.size()) > opts_.window) history_.pop_front();
        } else {
            history_.clear();
        }
    }
    prev_small_ = small;
    prev_edges_ = edges;
    prev_edges_wide_ = wide;
    return s;
}

}  // namespace spt::video
