#include "cartoon/draw_order.hpp"

#include <algorithm>

#include "cartoon/mask_pixels.hpp"

namespace spt::cartoon {

AddedCover::AddedCover(int width, int height) : W_(width), H_(height), px_(height, width, CV_8U, cv::Scalar(0)) {}

bool AddedCover::hits(const Stroke& s, const cv::Rect& box, const Renderer& renderer) const {
    // Boxes first: most polygons touch no added box at all.
    const bool near =
        std::any_of(boxes_.begin(), boxes_.end(), [&](const cv::Rect& b) { return (box & b).area() > 0; });
    if (!near) return false;
    if (!renderer.stroke_mask(s, m_)) return true;  // cannot tell: as if it touched
    return visit_covered(m_, W_, H_,
                         [&](int32_t x, int32_t y, size_t, uint8_t) { return px_.at<uint8_t>(y, x) != 0; });
}

void AddedCover::add(const Stroke& s, const cv::Rect& box, const Renderer& renderer) {
    boxes_.push_back(box);
    if (renderer.stroke_mask(s, m_))
        visit_covered(m_, W_, H_, [&](int32_t x, int32_t y, size_t, uint8_t) { px_.at<uint8_t>(y, x) = 1; });
}

KeptOrder::KeptOrder(int width, int height) : W_(width), H_(height), top_(size_t(width) * height, -1) {}

bool KeptOrder::fits(const Stroke& old, uint32_t index, const Renderer& renderer) const {
    if (!renderer.stroke_mask(old, m_)) return false;
    const auto later_on_top = [&](int32_t x, int32_t y, size_t, uint8_t) {
        return top_[size_t(y) * W_ + x] > int64_t(index);
    };
    return !visit_covered(m_, W_, H_, later_on_top);
}

void KeptOrder::keep(const Stroke& old, uint32_t index, const Renderer& renderer) {
    if (!renderer.stroke_mask(old, m_)) return;
    visit_covered(m_, W_, H_, [&](int32_t x, int32_t y, size_t, uint8_t) {
        int64_t& t = top_[size_t(y) * W_ + x];
        t = std::max<int64_t>(t, index);
    });
}

}  // namespace spt::cartoon
