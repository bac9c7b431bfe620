#include "cartoon/motion_field.hpp"

#include <algorithm>
#include <cstdlib>
#include <map>

#include "cartoon/frame_diff.hpp"
#include "cartoon/shape_cost.hpp"
#include "spt/reader.hpp"

namespace spt::cartoon {

namespace {

struct Shift {
    int32_t dx = 0, dy = 0;  // Q4
    auto operator<=>(const Shift&) const = default;
};

Stroke shifted(const Stroke& s, Shift t) {
    Stroke m = s;
    if (m.kind == StrokeKind::Polygon)
        for (PolygonVertex& v : m.polygon.points) {
            v.x += t.dx;
            v.y += t.dy;
        }
    else if (m.kind == StrokeKind::Stamp) {
        m.stamp.x += t.dx;
        m.stamp.y += t.dy;
    }
    return m;
}

// The Q4 point whose block moves the stroke (SPEC.md 5); strokes of other kinds never stay
// (frame_diff.hpp), the origin stands for them.
std::pair<int32_t, int32_t> anchor(const Stroke& s) {
    if (s.kind == StrokeKind::Polygon && !s.polygon.points.empty()) return {s.polygon.points[0].x, s.polygon.points[0].y};
    if (s.kind == StrokeKind::Stamp) return {s.stamp.x, s.stamp.y};
    return {0, 0};
}

int block_index(int32_t q4, int bs, int n) {
    const int32_t span = 16 * bs;
    const int32_t b = q4 >= 0 ? q4 / span : -((-q4 + span - 1) / span);
    return std::clamp(b, 0, n - 1);
}

// The source under `now` in `cur` equals the source under `before` in `prev` (no channel
// more than 24 levels apart: compressed video flickers where nothing moves).
bool ground_same(const cv::Mat& cur, const cv::Mat& prev, const cv::Rect& before, const cv::Rect& now) {
    if (before.size() != now.size() || now.area() == 0) return false;
    for (int y = 0; y < now.height; ++y) {
        const uint8_t* a = cur.ptr<uint8_t>(now.y + y) + 3 * now.x;
        const uint8_t* b = prev.ptr<uint8_t>(before.y + y) + 3 * before.x;
        for (int i = 0; i < 3 * now.width; ++i)
            if (std::abs(int(a[i]) - int(b[i])) > 24) return false;
    }
    return true;
}

// A polygon's shape up to translation: colour, grid and each vertex relative to the first.
std::vector<int32_t> shape_key(const PolygonStroke& p) {
    std::vector<int32_t> k{p.color.r, p.color.g, p.color.b, p.color.a, p.supersample};
    for (const PolygonVertex& v : p.points) {
        k.push_back(v.x - p.points[0].x);
        k.push_back(v.y - p.points[0].y);
    }
    return k;
}

// What keeping a stroke saves, roughly in coded bytes: a polygon's vertices, or a stamp.
int64_t weight(const Stroke& s) {
    return int64_t(shape_bytes(s, 6));
}

}  // namespace

MotionChoice choose_motion(const std::vector<Stroke>& old_live, const std::vector<Stroke>& polygons, const cv::Mat& cur,
                           const cv::Mat& prev, const Renderer& renderer, const Header& header,
                           const MotionOptions& opts) {
    const int W = cur.cols, H = cur.rows, bs = opts.block_size;
    const int cols = (W + bs - 1) / bs, rows = (H + bs - 1) / bs;
    auto block_of = [&](const Stroke& s) {
        const auto [x, y] = anchor(s);
        return block_index(y, bs, rows) * cols + block_index(x, bs, cols);
    };
    std::vector<Shift> vec(size_t(cols) * rows);
    if (opts.enabled) {
        std::vector<std::map<Shift, int64_t>> votes(vec.size());
        // Only rigid moves: the same vertices shifted. A polygon that moved and changed a
        // little (same coverage after a shift) cost more stamps than it saved on the clips
        // measured (taffy, butterfly).
        std::map<std::vector<int32_t>, std::vector<size_t>> shapes;  // new polygons by shape
        for (size_t j = 0; j < polygons.size(); ++j)
            if (polygons[j].kind == StrokeKind::Polygon && !polygons[j].polygon.points.empty())
                shapes[shape_key(polygons[j].polygon)].push_back(j);
        const int32_t reach = 16 * opts.search;
        for (const Stroke& o : old_live) {
            if (o.kind != StrokeKind::Polygon || o.polygon.points.empty()) continue;
            auto it = shapes.find(shape_key(o.polygon));
            if (it == shapes.end()) continue;
            std::vector<Shift> found;
            for (size_t j : it->second) {
                const Shift t{polygons[j].polygon.points[0].x - o.polygon.points[0].x,
                              polygons[j].polygon.points[0].y - o.polygon.points[0].y};
                if (std::abs(t.dx) <= reach && std::abs(t.dy) <= reach) found.push_back(t);
            }
            std::sort(found.begin(), found.end());
            found.erase(std::unique(found.begin(), found.end()), found.end());
            for (const Shift& t : found) votes[size_t(block_of(o))][t] += weight(o);
        }
        // Stamps vote for the shifts their block's polygons proposed, where the source under
        // them moved the same way, and for staying where it stayed.
        for (const Stroke& s : old_live) {
            if (s.kind != StrokeKind::Stamp) continue;
            auto& v = votes[size_t(block_of(s))];
            if (v.empty() || (v.size() == 1 && v.begin()->first == Shift{})) continue;
            const cv::Rect before = stroke_box(s, renderer, W, H);
            v[Shift{}];
            for (auto& [t, score] : v)
                if (ground_same(cur, prev, before, stroke_box(shifted(s, t), renderer, W, H))) score += weight(s);
        }
        for (size_t b = 0; b < vec.size(); ++b) {
            int64_t best = 0;
            if (auto z = votes[b].find(Shift{}); z != votes[b].end()) best = z->second;
            for (const auto& [t, score] : votes[b])
                if (score > best) {
                    best = score;
                    vec[b] = t;
                }
        }
    }
    MotionChoice m;
    m.moved = old_live;
    m.moving_blocks = uint64_t(std::count_if(vec.begin(), vec.end(), [](const Shift& t) { return t != Shift{}; }));
    if (m.moving_blocks) {
        m.field.block_size = uint16_t(bs);
        m.field.cols = uint16_t(cols);
        m.field.rows = uint16_t(rows);
        for (const Shift& t : vec) m.field.vectors.emplace_back(int16_t(t.dx), int16_t(t.dy));
        // The move as a decoder makes it (SPEC.md 5).
        Frame f;
        f.type = FrameType::Inter;
        f.motion = m.field;
        if (!apply_frame(m.moved, f, header)) {  // a vector leaving the coordinate range: stay still
            m = MotionChoice{};
            m.moved = old_live;
        }
    }
    return m;
}

int64_t kept_value(const std::vector<Stroke>& old_live, const std::vector<uint32_t>& removed) {
    int64_t v = 0;
    size_t r = 0;
    for (uint32_t i = 0; i < old_live.size(); ++i) {
        if (r < removed.size() && removed[r] == i) {
            ++r;
            continue;
        }
        v += weight(old_live[i]);
    }
    return v;
}

int64_t motion_cost(const MotionField& field) {
    int64_t c = 0;
    for (const auto& [dx, dy] : field.vectors) c += (dx != 0 || dy != 0) ? 4 : 0;
    return c;
}

}  // namespace spt::cartoon
