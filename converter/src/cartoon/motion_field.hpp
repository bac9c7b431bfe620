// The motion field of a cartoon inter frame (SPEC.md 5): what moved is moved, not redrawn.
// An old polygon that reappears translated in the new frame (same colour, grid and vertices,
// shifted) votes for its shift in the block holding its first vertex; a stamp votes for a shift under which the source beneath it moved
// with it. Each block takes the vector with the most votes (weighted by what keeping the
// stroke saves), so whatever a block's vector would move wrongly (a still stroke in a moving
// block) is removed (frame_diff.hpp, stamp_keep.hpp) and drawn again.
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "spt/render.hpp"
#include "spt/types.hpp"

namespace spt::cartoon {

struct MotionChoice {
    MotionField field;                // empty when every block stays still
    std::vector<Stroke> moved;        // the old live list after the move
    uint64_t moving_blocks = 0;
};

struct MotionOptions {
    bool enabled = true;
    uint16_t block_size = 16;         // pixels
    int search = 48;                  // largest shift tried, pixels
};

// `old_live`: the previous live list; `polygons`: the new frame's traced polygons (drawing
// order); `cur`, `prev`: the source frames (CV_8UC3). With motion disabled, or no block
// moving, the field is empty and `moved` is `old_live`.
MotionChoice choose_motion(const std::vector<Stroke>& old_live, const std::vector<Stroke>& polygons, const cv::Mat& cur,
                           const cv::Mat& prev, const Renderer& renderer, const Header& header,
                           const MotionOptions& opts);

// What keeping the strokes of `old_live` not in `removed` (increasing) saves, roughly in coded
// bytes: a polygon's vertices, a stamp.
int64_t kept_value(const std::vector<Stroke>& old_live, const std::vector<uint32_t>& removed);

// A field's cost, roughly in coded bytes: its vectors that differ from zero.
int64_t motion_cost(const MotionField& field);

}  // namespace spt::cartoon
