// What keeps a cartoon inter frame's drawing order right while it keeps old polygons. Kept
// strokes keep their old order and added ones go on top of them all; the frame renders as its
// traced polygons would wherever the two orders agree on every pair of strokes that touch.
// Touching is decided on pixels, not boxes: a sliver's box overlaps the boxes of every region
// around it, and deciding on boxes made one retraced polygon re-add all the polygons drawn
// after it (the cascade of issue 21).
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "spt/render.hpp"
#include "spt/types.hpp"

namespace spt::cartoon {

// The pixels the polygons added so far draw (any coverage). A polygon drawn after them in the
// new order may be kept only where it touches none of their pixels.
class AddedCover {
public:
    AddedCover(int width, int height);
    bool hits(const Stroke& s, const cv::Rect& box, const Renderer& renderer) const;
    void add(const Stroke& s, const cv::Rect& box, const Renderer& renderer);
    cv::Mat drawn(const cv::Rect& box) const { return px_(box); }  // 1 where an added polygon draws

private:
    int W_, H_;
    cv::Mat px_;
    std::vector<cv::Rect> boxes_;
    mutable Mask m_;
};

// The order of the kept polygons: per pixel, the highest old index of a kept polygon drawn
// there. The new frame's polygons are walked in drawing order, so an old polygon may be kept
// for the next one only where every kept polygon it touches is below it in the old list.
class KeptOrder {
public:
    KeptOrder(int width, int height);
    bool fits(const Stroke& old, uint32_t index, const Renderer& renderer) const;
    void keep(const Stroke& old, uint32_t index, const Renderer& renderer);

private:
    int W_, H_;
    std::vector<int64_t> top_;
    mutable Mask m_;
};

}  // namespace spt::cartoon
