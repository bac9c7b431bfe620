// Shot-cut detection as in the paper (section 3.1): for each pair of consecutive frames the mean
// absolute intensity difference is multiplied by the edge-map difference; a cut is declared
// when that product exceeds a constant times its running mean over a short look-back window.
// Streaming: only the previous frame and the window of past products are kept.
#pragma once

#include <deque>

#include <opencv2/core.hpp>

namespace spt::video {

struct CutOptions {
    double factor = 6.0;       // threshold = factor x mean product over the window
    int window = 12;           // look-back window (frames)
    // Floors that keep noise on static or nearly static shots from being called cuts: a cut
    // needs at least this mean intensity change (0..255) and this edge change ratio (0..1).
    double min_pixel_diff = 8.0;
    double min_edge_diff = 0.30;
    int analysis_width = 160;  // frames are analysed at this width (aspect kept)
    int min_history = 2;       // frames after a cut (or the start) before the next can be called
};

struct CutScore {
    double pixel_diff = 0;  // mean |I_t - I_t-1|, 0..255
    double edge_diff = 0;   // edge change ratio, 0..1
    double product = 0;
    double threshold = 0;
    bool cut = false;
};

// One frame as the detector sees it: a small blurred copy, its edges, and the edges dilated.
struct CutFrame {
    cv::Mat small, edges, wide;
};
CutFrame analyse_cut_frame(const cv::Mat& gray, const CutOptions& opts);

// The change from `before` to `after` (any two frames of one input, consecutive or not):
// pixel_diff and edge_diff of a CutScore.
struct CutChange {
    double pixel_diff = 0, edge_diff = 0;
};
CutChange cut_change(const CutFrame& before, const CutFrame& after);

// The verdict on a consecutive pair given the products of the non-cut frames before it since
// the last cut (the last `window` of them, oldest first): CutDetector's rule, shared with the
// plan's sampled scan.
CutScore judge_cut(const CutChange& change, const std::deque<double>& history, const CutOptions& opts);

class CutDetector {
public:
    explicit CutDetector(const CutOptions& opts = {});
    // Feeds the next frame (8-bit gray, any size; the same size every call). Returns the
    // score; `cut` is true when this frame starts a new shot. The first frame is never a cut.
    CutScore push(const cv::Mat& gray);
    void reset();

private:
    CutOptions opts_;
    cv::Mat prev_small_, prev_edges_, prev_edges_wide_;
    std::deque<double> history_;  // products of recent non-cut frames
};

}  // namespace spt::video
