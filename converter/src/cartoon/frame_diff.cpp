#include "cartoon/frame_diff.hpp"

#include <algorithm>
#include <map>

namespace spt::cartoon {

cv::Rect stroke_box(const Stroke& s, const Renderer& renderer, int W, int H) {
    const cv::Rect canvas(0, 0, W, H);
    if (s.kind == StrokeKind::Polygon && !s.polygon.points.empty()) {
        int32_t x0 = s.polygon.points[0].x, x1 = x0, y0 = s.polygon.points[0].y, y1 = y0;
        for (const PolygonVertex& v : s.polygon.points) {
            x0 = std::min(x0, v.x); x1 = std::max(x1, v.x);
            y0 = std::min(y0, v.y); y1 = std::max(y1, v.y);
        }
        return cv::Rect(cv::Point(x0 >> 4, y0 >> 4), cv::Point((x1 >> 4) + 1, (y1 >> 4) + 1)) & canvas;
    }
    if (s.kind == StrokeKind::Stamp) {
        const Mask& m = renderer.stamp_footprint(s.stamp.set, s.stamp.tmpl, s.stamp.orient);
        const int cx = Renderer::stamp_pixel(s.stamp.x), cy = Renderer::stamp_pixel(s.stamp.y);
        return cv::Rect(cx + m.x0, cy + m.y0, int(m.w), int(m.h)) & canvas;
    }
    return canvas;
}

namespace {

bool overlaps_any(const cv::Rect& r, const std::vector<cv::Rect>& boxes) {
    for (const cv::Rect& b : boxes)
        if ((r & b).area() > 0) return true;
    return false;
}

// A polygon as a key for exact lookup.
std::vector<int32_t> key_of(const PolygonStroke& p) {
    std::vector<int32_t> k{p.color.r, p.color.g, p.color.b, p.color.a, p.supersample};
    for (const PolygonVertex& v : p.points) { k.push_back(v.x); k.push_back(v.y); }
    return k;
}

}  // namespace

FrameDiff diff_frame(const std::vector<Stroke>& old_live, const std::vector<Stroke>& polygons, const cv::Mat& changed,
                     const Renderer& renderer) {
    const int W = changed.cols, H = changed.rows;
    std::map<std::vector<int32_t>, std::vector<uint32_t>> where;  // old polygon -> its indices
    for (uint32_t i = 0; i < old_live.size(); ++i)
        if (old_live[i].kind == StrokeKind::Polygon) where[key_of(old_live[i].polygon)].push_back(i);
    std::vector<char> keep(old_live.size(), 0);
    FrameDiff d;
    int64_t last = -1;
    for (const Stroke& s : polygons) {
        const cv::Rect box = stroke_box(s, renderer, W, H);
        bool kept = false;
        auto it = where.find(key_of(s.polygon));
        if (it != where.end() && !overlaps_any(box, d.added_boxes)) {
            for (uint32_t i : it->second)
                if (int64_t(i) > last && !keep[i]) {
                    keep[i] = 1;
                    last = i;
                    kept = true;
                    break;
                }
        }
        if (!kept) {
            d.added.push_back(s);
            d.added_boxes.push_back(box);
        }
    }
    for (uint32_t i = 0; i < old_live.size(); ++i) {
        if (old_live[i].kind == StrokeKind::Polygon || keep[i]) continue;
        // A stamp keeps its place in the old order; it stays where nothing under it changed.
        if (old_live[i].kind != StrokeKind::Stamp) continue;
        const cv::Rect box = stroke_box(old_live[i], renderer, W, H);
        if (box.area() == 0 || overlaps_any(box, d.added_boxes) || cv::countNonZero(changed(box)) > 0) continue;
        keep[i] = 1;
    }
    for (uint32_t i = 0; i < old_live.size(); ++i)
        if (!keep[i]) d.removed.push_back(i);
    return d;
}

}  // namespace spt::cartoon
