#include "cartoon/frame_diff.hpp"

#include <algorithm>
#include <cstdlib>
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

// Two polygons cover nearly the same pixels: their coverage differs by at most two pixels'
// worth, or 1/500 of their area.
bool same_coverage(const Stroke& a, const Stroke& b, const Renderer& renderer) {
    Mask ma, mb;
    if (!renderer.stroke_mask(a, ma) || !renderer.stroke_mask(b, mb)) return false;
    int64_t diff = 0, area = 0;
    const int32_t x0 = std::min(ma.x0, mb.x0), y0 = std::min(ma.y0, mb.y0);
    const int32_t x1 = std::max(ma.x0 + int32_t(ma.w), mb.x0 + int32_t(mb.w));
    const int32_t y1 = std::max(ma.y0 + int32_t(ma.h), mb.y0 + int32_t(mb.h));
    auto at = [](const Mask& m, int32_t x, int32_t y) -> int {
        if (x < m.x0 || y < m.y0 || x >= m.x0 + int32_t(m.w) || y >= m.y0 + int32_t(m.h)) return 0;
        return m.a[size_t(y - m.y0) * m.w + size_t(x - m.x0)];
    };
    for (int32_t y = y0; y < y1; ++y)
        for (int32_t x = x0; x < x1; ++x) {
            const int va = at(ma, x, y), vb = at(mb, x, y);
            diff += std::abs(va - vb);
            area += va;
        }
    return diff <= std::max<int64_t>(2 * 255, area / 500);
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
        // Not traced identically (compressed video: noise moves an outline's vertices), but an
        // old polygon of nearly the same colour, box and coverage stands for it: what stays
        // still is not coded again, and the stamps correct the rest.
        if (!kept && !overlaps_any(box, d.added_boxes))
            for (uint32_t i = uint32_t(last + 1); i < old_live.size(); ++i) {
                const Stroke& o = old_live[i];
                if (o.kind != StrokeKind::Polygon || keep[i]) continue;
                const Rgba8& a = o.polygon.color;
                const Rgba8& b = s.polygon.color;
                if (std::abs(a.r - b.r) > 4 || std::abs(a.g - b.g) > 4 || std::abs(a.b - b.b) > 4) continue;
                const cv::Rect ob = stroke_box(o, renderer, W, H);
                if (std::abs(ob.x - box.x) > 1 || std::abs(ob.y - box.y) > 1 || std::abs(ob.br().x - box.br().x) > 1 ||
                    std::abs(ob.br().y - box.br().y) > 1)
                    continue;
                if (!same_coverage(o, s, renderer)) continue;
                keep[i] = 1;
                last = i;
                kept = true;
                break;
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
