#include "cartoon/frame_diff.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>

#include "cartoon/draw_order.hpp"
#include "cartoon/shape_cost.hpp"

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
    if (s.kind == StrokeKind::Curve && !s.curve.points.empty()) {
        int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
        for (const CurvePoint& p : s.curve.points) {
            const int64_t r = p.width / 2 + 16;  // half the width, and the samples' half pixel
            x0 = std::min(x0, p.x - r); x1 = std::max(x1, p.x + r);
            y0 = std::min(y0, p.y - r); y1 = std::max(y1, p.y + r);
        }
        return cv::Rect(cv::Point(int(x0 >> 4), int(y0 >> 4)), cv::Point(int(x1 >> 4) + 1, int(y1 >> 4) + 1)) & canvas;
    }
    if (s.kind == StrokeKind::Stamp) {
        const Mask& m = renderer.stamp_footprint(s.stamp.set, s.stamp.tmpl, s.stamp.orient);
        const int cx = Renderer::stamp_pixel(s.stamp.x), cy = Renderer::stamp_pixel(s.stamp.y);
        return cv::Rect(cx + m.x0, cy + m.y0, int(m.w), int(m.h)) & canvas;
    }
    return canvas;
}

namespace {

// A shape (polygon or line) as a key for exact lookup.
std::vector<int32_t> key_of(const Stroke& s) {
    const Rgba8& c = s.color();
    if (s.kind == StrokeKind::Curve) {
        std::vector<int32_t> k{-1, c.r, c.g, c.b, c.a, s.curve.supersample};
        for (const CurvePoint& p : s.curve.points) { k.push_back(p.x); k.push_back(p.y); k.push_back(int32_t(p.width)); }
        return k;
    }
    const PolygonStroke& p = s.polygon;
    std::vector<int32_t> k{c.r, c.g, c.b, c.a, p.supersample};
    for (const PolygonVertex& v : p.points) { k.push_back(v.x); k.push_back(v.y); }
    return k;
}

// Polygons and lines are what the fill layer traces; stamps and the rest are not.
bool is_shape(const Stroke& s) { return s.kind == StrokeKind::Polygon || s.kind == StrokeKind::Curve; }

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

struct CoverageDiff {
    int64_t diff = INT64_MAX;    // over the pixels that show, 255 a pixel
    int64_t area = 0;            // of the first polygon
    int64_t wrong = INT64_MAX;   // of `diff`, over the pixels the previous frame gets wrong
};

// Coverage difference of two polygons over the pixels `shows`, and the area of the first.
// With `recolour` (b's colour is not a's), all of b that shows counts where the picture is wrong.
template <class Shows, class Wrong>
CoverageDiff coverage_diff(const Stroke& a, const Stroke& b, const Renderer& renderer, Shows shows, Wrong wrong,
                           bool recolour = false) {
    Mask ma, mb;
    if (!renderer.stroke_mask(a, ma) || !renderer.stroke_mask(b, mb)) return {};
    int64_t diff = 0, area = 0, bad = 0;
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
            if ((va != vb || (recolour && vb)) && shows(x, y)) {
                diff += std::abs(va - vb);
                if (wrong(x, y)) bad += recolour ? std::max(va, vb) : std::abs(va - vb);
            }
        }
    return {diff, area, bad};
}

// A polygon's coverage over the pixels `shows` (255 a pixel): what leaving it out changes.
template <class Shows>
int64_t visible_coverage(const Stroke& a, const Renderer& renderer, Shows shows) {
    Mask m;
    if (!renderer.stroke_mask(a, m)) return INT64_MAX;
    int64_t c = 0;
    for (uint32_t y = 0; y < m.h; ++y)
        for (uint32_t x = 0; x < m.w; ++x)
            if (shows(m.x0 + int32_t(x), m.y0 + int32_t(y))) c += m.a[size_t(y) * m.w + x];
    return c;
}

bool close_enough(const CoverageDiff& d) { return d.diff <= std::max<int64_t>(2 * 255, d.area / 500); }

bool same_colour(const Rgba8& a, const Rgba8& b, int tolerance = 4) {
    return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance && std::abs(a.b - b.b) <= tolerance;
}

// An old polygon this close in colour may stand for a retraced one (a small region's mean
// colour moves with the pixels noise adds to it or takes from it); where its colour shows
// wrong, that counts in its cost. (Butterfly, 12 frames at 36 dB: 8 gives 95,450 bytes, 16
// 91,611, 32 91,535.)
constexpr int kStandInColour = 16;

// How far apart two boxes' sides are, pixels (the largest of the four).
int box_offset(const cv::Rect& a, const cv::Rect& b) {
    return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.br().x - b.br().x),
                     std::abs(a.br().y - b.br().y)});
}

// An old polygon whose box is this close (pixels) may stand for a retraced one. (6 gives
// 90,709 bytes on the butterfly, for more coverage comparisons.)
constexpr int kStandInBox = 3;
// A new polygon whose correction costs at most this (bytes: about 40 visible pixels) may be
// left out. (Butterfly: none left out 118,774 bytes, 64 91,611, 256 the same: the new
// polygons compressed video makes are specks.)
constexpr int64_t kLeftOutBytes = 64;

// Roughly what coding a stroke again costs, bytes: a polygon's vertices, a stamp.
int64_t stroke_bytes(const Stroke& s) {
    return int64_t(shape_bytes(s, 6));
}

// What the stamps that correct a stand-in's coverage difference (`diff`, 255 a pixel) cost,
// bytes: about a byte and a half a pixel of difference (the smallest stamps cover 2-4 px and
// cost about 6 bytes; a difference is a sliver along the outline). Insensitive: 0.75 and 3 a
// pixel give 91,611 and 92,054 bytes on the butterfly.
int64_t stand_in_cost(int64_t diff) { return diff * 3 / (2 * 255); }

// What adding polygon j costs, bytes: itself, every later polygon that overlaps its box and
// would otherwise be kept (added polygons go on top, so those must be added again above it),
// and the old stamps in its box (an added polygon removes the stamps it draws over).
int64_t cascade_cost(size_t j, const cv::Rect& box, const std::vector<cv::Rect>& boxes,
                     const std::vector<char>& likely_kept, const std::vector<Stroke>& polygons,
                     const std::vector<cv::Rect>& stamp_boxes) {
    int64_t c = stroke_bytes(polygons[j]);
    for (size_t k = j + 1; k < polygons.size(); ++k)
        if (likely_kept[k] && (boxes[k] & box).area() > 0) c += stroke_bytes(polygons[k]);
    for (const cv::Rect& b : stamp_boxes)
        if ((b & box).area() > 0) c += 6;
    return c;
}

}  // namespace

FrameDiff diff_frame(const std::vector<Stroke>& old_live, const std::vector<Stroke>& polygons,
                     const Renderer& renderer, int W, int H, const DiffOptions& opts) {
    const std::vector<int32_t> owner = top_owner(polygons, renderer, W, H);
    std::map<std::vector<int32_t>, std::vector<uint32_t>> where;  // old polygon -> its indices
    for (uint32_t i = 0; i < old_live.size(); ++i)
        if (is_shape(old_live[i])) where[key_of(old_live[i])].push_back(i);
    std::vector<char> keep(old_live.size(), 0);
    // For the cascade's cost: the new polygons' boxes, which of them an old polygon of the same
    // colour and box could stand for, and the old stamps' boxes.
    std::vector<cv::Rect> boxes, old_boxes(old_live.size()), stamp_boxes;
    for (const Stroke& s : polygons) boxes.push_back(stroke_box(s, renderer, W, H));
    for (uint32_t i = 0; i < old_live.size(); ++i) {
        old_boxes[i] = stroke_box(old_live[i], renderer, W, H);
        if (old_live[i].kind == StrokeKind::Stamp) stamp_boxes.push_back(old_boxes[i]);
    }
    std::vector<char> likely_kept(polygons.size(), 0);
    for (size_t k = 0; k < polygons.size(); ++k) {
        if (where.count(key_of(polygons[k]))) { likely_kept[k] = 1; continue; }
        for (uint32_t i = 0; i < old_live.size() && !likely_kept[k]; ++i)
            likely_kept[k] = old_live[i].kind == polygons[k].kind &&
                             same_colour(old_live[i].color(), polygons[k].color()) &&
                             box_offset(old_boxes[i], boxes[k]) <= 1;
    }
    FrameDiff d;
    AddedCover cover(W, H);
    KeptOrder order(W, H);
    auto keep_old = [&](uint32_t i) {
        keep[i] = 1;
        order.keep(old_live[i], i, renderer);
    };
    for (size_t j = 0; j < polygons.size(); ++j) {
        const Stroke& s = polygons[j];
        const cv::Rect& box = boxes[j];
        bool kept = false;
        auto it = where.find(key_of(s));
        if (it != where.end() && !cover.hits(s, box, renderer)) {
            for (uint32_t i : it->second)
                if (!keep[i] && order.fits(old_live[i], i, renderer)) {
                    keep_old(i);
                    kept = true;
                    break;
                }
        }
        const auto shows = [&](int32_t x, int32_t y) {
            return x >= 0 && y >= 0 && x < W && y < H && owner[size_t(y) * W + x] <= int32_t(j);
        };
        // Where keeping the old picture costs stamps: pixels the previous frame shows visibly
        // wrong for this one (every pixel when the caller did not say).
        const auto wrong = [&](int32_t x, int32_t y) { return !opts.wrong || (*opts.wrong)[size_t(y) * W + x] != 0; };
        const auto shows_wrong = [&](int32_t x, int32_t y) { return shows(x, y) && wrong(x, y); };
        // Not traced identically (compressed video: noise moves an outline's vertices), but an
        // old polygon of nearly the same colour, box and coverage where it shows stands for
        // it: what stays still is not coded again, and the stamps correct the rest.
        uint32_t stand_in = UINT32_MAX;
        int64_t stand_in_diff = INT64_MAX;
        // Where the new polygon touches one added before it, the old picture is gone: neither a
        // stand-in nor leaving it out shows it there (it would be under the added one).
        const bool under_added = !kept && cover.hits(s, box, renderer);
        if (!kept && !under_added)
            for (uint32_t i = 0; i < old_live.size(); ++i) {
                const Stroke& o = old_live[i];
                if (o.kind != s.kind || keep[i]) continue;
                const bool same = same_colour(o.color(), s.color());
                if (!same && !(opts.stand_ins && same_colour(o.color(), s.color(), kStandInColour))) continue;
                const cv::Rect& ob = old_boxes[i];
                const int off = box_offset(ob, box);
                if (off > (opts.stand_ins ? kStandInBox : 1)) continue;
                if (cover.hits(o, ob, renderer) || !order.fits(o, i, renderer)) continue;
                const CoverageDiff cd = coverage_diff(s, o, renderer, shows, wrong, !same);
                if (same && off <= 1 && close_enough(cd)) {
                    keep_old(i);
                    kept = true;
                    break;
                }
                if (cd.wrong < stand_in_diff) {
                    stand_in_diff = cd.wrong;
                    stand_in = i;
                }
            }
        // Retraced a little more than that, or new and mostly hidden: adding it on top would
        // force every later polygon that overlaps it to be added again (the cascade), and the
        // old stamps under them to be painted again. When that costs more than the stamps that
        // correct the difference, the old polygon stays (or the new one is left out).
        if (!kept && !under_added && opts.stand_ins) {
            const int64_t cascade = cascade_cost(j, box, boxes, likely_kept, polygons, stamp_boxes);
            const int64_t hidden = stand_in_cost(visible_coverage(s, renderer, shows_wrong));
            const int64_t instead = stand_in == UINT32_MAX ? INT64_MAX : stand_in_cost(stand_in_diff);
            // A new polygon with an old counterpart is never left out: that would remove the
            // counterpart and the old picture with it.
            if (instead < cascade) {
                keep_old(stand_in);
                kept = true;
                ++d.stood_in;
            } else if (stand_in == UINT32_MAX && hidden < cascade && hidden <= kLeftOutBytes) {
                kept = true;  // left out
                ++d.left_out;
            }
        }
        if (!kept) {
            d.added.push_back(s);
            d.added_boxes.push_back(box);
            cover.add(s, box, renderer);
        }
    }
    for (uint32_t i = 0; i < old_live.size(); ++i) {
        if (is_shape(old_live[i]) || keep[i]) continue;
        // A stamp keeps its place in the old order; it goes where an added polygon draws (it
        // would be drawn under it). Whether the others still help is stamp_keep.hpp's rule.
        if (old_live[i].kind != StrokeKind::Stamp) continue;
        const cv::Rect& box = old_boxes[i];
        if (box.area() == 0 || cv::countNonZero(cover.drawn(box)) > 0) continue;
        keep[i] = 1;
    }
    for (uint32_t i = 0; i < old_live.size(); ++i)
        if (!keep[i]) d.removed.push_back(i);
    return d;
}

}  // namespace spt::cartoon
