#include "cartoon/draw_order.hpp"

#include <algorithm>

namespace spt::cartoon {

namespace {

// Calls f(x, y) on every canvas pixel the mask covers (any coverage); true as soon as f does.
template <class F>
bool visit(const Mask& m, int W, int H, F f) {
    for (uint32_t y = 0; y < m.h; ++y) {
        const int32_t py = m.y0 + int32_t(y);
        if (py < 0 || py >= H) continue;
        for (uint32_t x = 0; x < m.w; ++x) {
            const int32_t px = m.x0 + int32_t(x);
            if (px >= 0 && px < W && m.a[size_t(y) * m.w + x] && f(px, py)) return true;
        }
    }
    return false;
}

}  // namespace

AddedCover::AddedCover(int width, int height) : W_(width), H_(height), px_(height, width, CV_8U, cv::Scalar(0)) {}

bool AddedCover::hits(const Stroke& s, const cv::Rect& box, const Renderer& renderer) const {
    // Boxes first: most polygons touch no added box at all.
    const bool near = std::any_of(boxes_.begin(), boxes_.end(), [&](const cv::Rect& b) { return (box & b).area() > 0; });
    if (!near) return false;
    if (!renderer.stroke_mask(s, m_)) return true;  // cannot tell: as if it touched
    return visit(m_, W_, H_, [&](int x, int y) { return px_.at<uint8_t>(y, x) != 0; });
}

void AddedCover::add(const Stroke& s, const cv::Rect& box, const Renderer& renderer) {
    boxes_.push_back(box);
    if (renderer.stroke_mask(s, m_))
        visit(m_, W_, H_, [&](int x, int y) {
            px_.at<uint8_t>(y, x) = 1;
            return false;
        });
}

KeptOrder::KeptOrder(int width, int height) : W_(width), H_(height), top_(size_t(width) * height, -1) {}

bool KeptOrder::fits(const Stroke& old, uint32_t index, const Renderer& renderer) const {
    if (!renderer.stroke_mask(old, m_)) return false;
    return !visit(m_, W_, H_, [&](int x, int y) { return top_[size_t(y) * W_ + x] > int64_t(index); });
}

void KeptOrder::keep(const Stroke& old, uint32_t index, const Renderer& renderer) {
    if (!renderer.stroke_mask(old, m_)) return;
    visit(m_, W_, H_, [&](int x, int y) {
        int64_t& t = top_[size_t(y) * W_ + x];
        t = std::max<int64_t>(t, index);
        return false;
    });
}

}  // namespace spt::cartoon
