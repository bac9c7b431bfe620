// Dense optical flow between consecutive frames and the block motion field (SPEC.md 5) that
// carries the live strokes from one frame to the next.
#pragma once

#include <cstdint>
#include <memory>

#include <opencv2/core.hpp>

#include "spt/types.hpp"
#include "video/video_paint.hpp"

namespace cv { class DenseOpticalFlow; }

namespace spt::video {

class FlowEstimator {
public:
    // Frames wider than `max_width` are analysed downscaled (the flow is scaled back up):
    // stroke motion needs the coarse field, not per-pixel detail.
    explicit FlowEstimator(FlowMethod method, int max_width = 640);
    ~FlowEstimator();
    // Forward flow: prev(p) ~ next(p + flow(p)). 8-bit gray in, CV_32FC2 out at the input size.
    void compute(const cv::Mat& prev_gray, const cv::Mat& next_gray, cv::Mat& flow);

private:
    FlowMethod method_;
    int max_width_;
    cv::Ptr<cv::DenseOpticalFlow> dis_;
};

// One vector per `block` x `block` tile: the component-wise median of the flow inside the
// tile (robust to the edges of moving objects), in Q4 and clamped to i16.
MotionField block_motion(const cv::Mat& flow, int block);

// True when every vector is (0, 0): the frame is then written without a motion field.
bool is_still(const MotionField& m);

// Moves each point of `flow`'s grid by its block's vector and measures the flow left over:
// mean |flow - block vector| in pixels (how well the block field explains the motion).
double block_residual(const cv::Mat& flow, const MotionField& m);

}  // namespace spt::video
