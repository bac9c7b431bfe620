// Which strokes of the previous frame a cartoon frame keeps. The new frame's polygons N are in
// drawing order; the old live list L is kept where N repeats it. Walking N in order, a polygon
// found unchanged in L stays unless it touches (in pixels) a polygon added before it in N, or a
// polygon kept before it that is later in L (draw_order.hpp): added ones go on top of
// everything kept, kept ones keep their order in L. Then the drawing order of kept + added
// equals N's wherever two strokes touch, and the frame renders as N would. Leniently
// (DiffOptions), an old polygon that retraced a little differently also stays when adding the
// new one would cost more than the stamps correcting the difference (issue 21's cascade).
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
    uint32_t stood_in = 0;           // old polygons kept for a retraced one (the cascade's cost)
    uint32_t left_out = 0;           // new polygons left out, mostly hidden (the cascade's cost)
};

struct DiffOptions {
    // Lenient: an old polygon may stand for a retraced one that differs more than a little, and
    // a small new polygon be left out, where adding it would cost more (the cascade: every
    // later polygon it overlaps added again on top of it, with the stamps under them) than the
    // stamps correcting the difference. Strict: only what traced the same, or nearly, stays.
    bool stand_ins = false;
    // Per pixel (canvas_w * canvas_h), 1 where the previous frame's picture is visibly wrong for
    // this frame's source: a difference of outline elsewhere costs no stamp, and a new polygon
    // there is left out at no cost (the old picture already shows it). Null: every pixel.
    const std::vector<uint8_t>* wrong = nullptr;
};

// `old_live`: the previous frame's live list (polygons and stamps), after this frame's move
// (motion_field.hpp). Old stamps go where an added polygon draws; the others stay here, and
// stamp_keep.hpp's rule decides which of them still help.
FrameDiff diff_frame(const std::vector<Stroke>& old_live, const std::vector<Stroke>& polygons,
                     const Renderer& renderer, int canvas_w, int canvas_h, const DiffOptions& opts = {});

// The pixels a stroke may touch (polygon and stamp strokes; others: the whole canvas).
cv::Rect stroke_box(const Stroke& s, const Renderer& renderer, int canvas_w, int canvas_h);

}  // namespace spt::cartoon
