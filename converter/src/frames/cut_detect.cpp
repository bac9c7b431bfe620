#include "frames/cut_detect.hpp"

#include <algorithm>
#include <cmath>
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

CutFrame analyse_cut_frame(const cv::Mat& gray, const CutOptions& opts) {
    CutFrame f;
    // Analyse a small, slightly blurred copy: cuts are global events, and noise or grain at
    // full resolution would only add false edges.
    const int aw = std::max(16, opts.analysis_width);
    const int w = std::min(gray.cols, aw);
    const int h = std::max(1, int(std::lround(double(gray.rows) * w / gray.cols)));
    cv::resize(gray, f.small, cv::Size(w, h), 0, 0, cv::INTER_AREA);
    cv::GaussianBlur(f.small, f.small, cv::Size(3, 3), 0.8);
    // Edges of a contrast-normalised copy: a fade changes contrast, not the edges' places, and
    // should not look like a change of content.
    cv::Scalar mean, sdev;
    cv::meanStdDev(f.small, mean, sdev);
    cv::Mat norm;
    const double gain = sdev[0] > 2.0 ? 48.0 / sdev[0] : 0.0;
    f.small.convertTo(norm, CV_8U, gain, 128.0 - gain * mean[0]);
    cv::Canny(norm, f.edges, 40, 100);
    cv::dilate(f.edges, f.wide, cv::Mat::ones(5, 5, CV_8U));
    return f;
}

CutChange cut_change(const CutFrame& before, const CutFrame& after) {
    CutChange c;
    cv::Mat diff;
    cv::absdiff(after.small, before.small, diff);
    c.pixel_diff = cv::mean(diff)[0];
    const bool none_now = cv::countNonZero(after.edges) == 0;
    const bool none_before = cv::countNonZero(before.edges) == 0;
    if (none_now && none_before) {
        c.edge_diff = 0.0;
    } else if (none_now || none_before) {
        c.edge_diff = 1.0;  // edges appeared from or vanished into a flat frame
    } else {
        c.edge_diff = std::max(unmatched_edges(after.edges, before.wide), unmatched_edges(before.edges, after.wide));
    }
    return c;
}

CutScore judge_cut(const CutChange& change, const std::deque<double>& history, const CutOptions& opts) {
    CutScore s;
    s.pixel_diff = change.pixel_diff;
    s.edge_diff = change.edge_diff;
    s.product = s.pixel_diff * s.edge_diff;
    const double mean =
        history.empty() ? 0.0 : std::accumulate(history.begin(), history.end(), 0.0) / history.size();
    s.threshold = std::max(opts.factor * mean, opts.min_pixel_diff * opts.min_edge_diff);
    // A new shot needs a few frames of history before its own cuts can be judged.
    s.cut = int(history.size()) >= opts.min_history && s.product > s.threshold && s.pixel_diff >= opts.min_pixel_diff &&
            s.edge_diff >= opts.min_edge_diff;
    return s;
}

CutScore CutDetector::push(const cv::Mat& gray) {
    CutScore s;
    CutFrame f = analyse_cut_frame(gray, opts_);
    if (!prev_small_.empty() && prev_small_.size() == f.small.size()) {
        s = judge_cut(cut_change(CutFrame{prev_small_, prev_edges_, prev_edges_wide_}, f), history_, opts_);
        // A cut's product would inflate the mean of the next shot's first frames: keep it out.
        if (!s.cut) {
            history_.push_back(s.product);
            if (int(history_.size()) > opts_.window) history_.pop_front();
        } else {
            history_.clear();
        }
    }
    prev_small_ = f.small;
    prev_edges_ = f.edges;
    prev_edges_wide_ = f.wide;
    return s;
}

}  // namespace spt::video
