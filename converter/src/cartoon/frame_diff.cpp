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

// Which polygon of the new frame shows at each pixel: the last one covering it fully (-1:
// none). A polygon is hidden where a later one covers it fully, so its outline there does not
// matter (the region under a moving figure, the outline of a fill under its own line).
std::vector<int32_t> top_owner(const std::vector<Stroke>& polygons, const Renderer& renderer, int W, int H) {
    std::vector<int32_t> owner(size_t(W) * H, -1);
    Mask m;
    for (size_t j = 0; j < polygons.size(); ++j) {
        if (!renderer.stroke_mask(polygons[j], m)) continue;
        for (uint32_t y = 0; y < m.h; ++y) {
            const int32_t py = m.y0 + int32_t(y);
            if (py < 0 || py >= H) continue;
            for (uint32_t x = 0; x < m.w; ++x) {
                const int32_t px = m.x0 + int32_t(x);
                if (px >= 0 && px < W && m.a[size_t(y) * m.w + x] == 255) owner[size_t(py) * W + px] = int32_t(j);
            }
        }
    }
    return owner;
}

// Coverage difference of two polygons over the pixels `shows`, and the area of the first.
template <class Shows>
std::pair<int64_t, int64_t> coverage_diff(const Stroke& a, const Stroke& b, const Renderer& renderer, Shows shows) {
    Mask ma, mb;
    if (!renderer.stroke_mask(a, ma) || !renderer.stroke_mask(b, mb)) return {INT64_MAX, 0};
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
            area += va;
            if (shows(x, y)) diff += std::abs(va - vb);
        }
    return {diff, area};
}

bool close_enough(std::pair<int64_t, int64_t> d) { return d.first <= std::max<int64_t>(2 * 255, d.second / 500); }

}  // namespace

FrameDiff diff_frame(const std::vector<Stroke>& old_live, const std::vector<Stroke>& polygons,
                     const std::vector<char>& ground_still, const Renderer& renderer, int W, int H) {
    const std::vector<int32_t> owner = top_owner(polygons, renderer, W, H);
    std::map<std::vector<int32_t>, std::vector<uint32_t>> where;  // old polygon -> its indices
    for (uint32_t i = 0; i < old_live.size(); ++i)
        if (old_live[i].kind == StrokeKind::Polygon) where[key_of(old_live[i].polygon)].push_back(i);
    std::vector<char> keep(old_live.size(), 0);
    FrameDiff d;
    int64_t last = -1;
    for (size_t j = 0; j < polygons.size(); ++j) {
        const Stroke& s = polygons[j];
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
        // old polygon of nearly the same colour, box and coverage where it shows stands for
        // it: what stays still is not coded again, and the stamps correct the rest.
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
                if (overlaps_any(ob, d.added_boxes)) continue;
                const auto shows = [&](int32_t x, int32_t y) {
                    return x >= 0 && y >= 0 && x < W && y < H && owner[size_t(y) * W + x] <= int32_t(j);
                };
                if (!close_enough(coverage_diff(s, o, renderer, shows))) continue;
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
    // Where the added polygons draw: a stamp there would be drawn under them. Their boxes
    // are too coarse (a fill's box spans the frame).
    cv::Mat drawn(H, W, CV_8U, cv::Scalar(0));
    Mask m;
    for (const Stroke& s : d.added) {
        if (!renderer.stroke_mask(s, m)) continue;
        for (uint32_t y = 0; y < m.h; ++y) {
            const int32_t py = m.y0 + int32_t(y);
            if (py < 0 || py >= H) continue;
            for (uint32_t x = 0; x < m.w; ++x) {
                const int32_t px = m.x0 + int32_t(x);
                if (px >= 0 && px < W && m.a[size_t(y) * m.w + x]) drawn.at<uint8_t>(py, px) = 1;
            }
        }
    }
    for (uint32_t i = 0; i < old_live.size(); ++i) {
        if (old_live[i].kind == StrokeKind::Polygon || keep[i]) continue;
        // A stamp keeps its place in the old order; it stays where nothing under it changed.
        if (old_live[i].kind != StrokeKind::Stamp) continue;
        const cv::Rect box = stroke_box(old_live[i], renderer, W, H);
        if (box.area() == 0 || !ground_still[i] || cv::countNonZero(drawn(box)) > 0) continue;
        keep[i] = 1;
    }
    for (uint32_t i = 0; i < old_live.size(); ++i)
        if (!keep[i]) d.removed.push_back(i);
    return d;
}

}  // namespace spt::cartoon
