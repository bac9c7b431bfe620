// Which strokes of the previous frame a cartoon frame keeps. The new frame's polygons N are in
// drawing order; the old live list L is kept where N repeats it. Walking N in order, a polygon
// found unchanged in L (later in L than the last one kept) stays, unless it overlaps a polygon
// added before it in N: the added ones go on top of everything kept, so a kept polygon above
// an added one in N must not touch it. Then the drawing order of kept + added equals N's
// wherever two strokes overlap, and the frame renders as N would.
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "spt/render.hpp"
#include "spt/types.hpp"

namespace spt::cartoon {

struct FrameDiff {
    std::vector<uint32_t> removed;   // indices into the old live list, increasing
    std::vector<Stroke> added;       // the polygons of N not kept, in N's order
    std::vector<cv::Rect> added_boxes;
};

// `old_live`: the previous frame's live list (polygons and stamps), after this frame's move
// (motion_field.hpp). Old stamps stay where no added polygon touches them and the source under
// them did not change, or moved with them (`ground_still`, per old stroke), else they go.
FrameDiff diff_frame(const std::vector<Stroke>& old_live, const std::vector<Stroke>& polygons,
                     const std::vector<char>& ground_still, const Renderer& renderer, int canvas_w, int canvas_h);

// The pixels a stroke may touch (polygon and stamp strokes; others: the whole canvas).
cv::Rect stroke_box(const Stroke& s, const Renderer& renderer, int canvas_w, int canvas_h);

}  // namespace spt::cartoon
