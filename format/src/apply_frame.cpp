// The state update of SPEC.md 5: remove, move by the block motion field, append.
#include <algorithm>

#include "spt/reader.hpp"
#include "spt/render.hpp"
#include "validate.hpp"

namespace spt {
namespace {

int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

struct Mover {
    const MotionField& m;
    std::pair<int16_t, int16_t> at(int32_t x, int32_t y) const {
        const int64_t span = int64_t(16) * m.block_size;
        const int64_t c = std::clamp<int64_t>(floor_div(x, span), 0, int64_t(m.cols) - 1);
        const int64_t r = std::clamp<int64_t>(floor_div(y, span), 0, int64_t(m.rows) - 1);
        return m.vectors[size_t(r) * m.cols + size_t(c)];
    }
    // Moves one anchor; false when it would leave the coordinate range.
    bool move(int32_t& x, int32_t& y) const {
        const auto [dx, dy] = at(x, y);
        const int64_t nx = int64_t(x) + dx, ny = int64_t(y) + dy;
        if (nx < -detail::kMaxCoord || nx > detail::kMaxCoord || ny < -detail::kMaxCoord || ny > detail::kMaxCoord)
            return false;
        x = int32_t(nx);
        y = int32_t(ny);
        return true;
    }
};

// Every frame renders its whole live list: its polygons, curves, and stamps and affine strokes
// may together need at most Limits::max_polygon_work, max_curve_work and max_fill_work (SPEC.md
// 10), or a small file (a few edges or segments across the canvas, or millions of canvas-sized
// strokes of a few bits each) could keep a renderer busy for hours.
Status check_render_work(const std::vector<Stroke>& live, const Header& header, const Limits& limits,
                         const std::vector<Template>* templates, const std::string& where) {
    uint64_t polygons = 0, curves = 0, fills = 0;
    for (const Stroke& s : live) {
        if (templates && (s.kind == StrokeKind::Stamp || s.kind == StrokeKind::Affine)) {
            fills += fill_render_work(s, header, *templates);
            if (fills > limits.max_fill_work)
                return make_error(Code::LimitExceeded, where + ": the stamps and affine strokes of the live list need more than " +
                                                           std::to_string(limits.max_fill_work) +
                                                           " units of rendering work (box pixels x samples), the limit");
            continue;
        }
        if (s.kind == StrokeKind::Polygon) {
            polygons += polygon_render_work(s.polygon, header.height);
            if (polygons > limits.max_polygon_work)
                return make_error(Code::LimitExceeded, where + ": the polygons of the live list need more than " +
                                                           std::to_string(limits.max_polygon_work) +
                                                           " units of rendering work (edges x rows x samples), the limit");
        } else if (s.kind == StrokeKind::Curve) {
            curves += curve_render_work(s.curve, header.width, header.height);
            if (curves > limits.max_curve_work)
                return make_error(Code::LimitExceeded, where + ": the curves of the live list need more than " +
                                                           std::to_string(limits.max_curve_work) +
                                                           " units of rendering work (pixels of their segments' boxes), the limit");
        }
    }
    return {};
}

}  // namespace

Status apply_frame(std::vector<Stroke>& live, const Frame& frame, const Header& header, const Limits& limits,
                   const std::vector<Template>* templates) {
    const std::string where = "frame " + std::to_string(frame.index);
    if (frame.type == FrameType::Key) {
        if (frame.added.size() > limits.max_live_strokes)
            return make_error(Code::LimitExceeded, where + ": live list exceeds the limit");
        if (Status s = check_render_work(frame.added, header, limits, templates, where); !s) return s;
        live = frame.added;
        return {};
    }
    // Validate everything before changing `live`, so that a failed frame leaves it intact.
    for (size_t i = 0; i < frame.removed.size(); ++i) {
        if (frame.removed[i] >= live.size())
            return make_error(Code::Corrupt, where + ": removed index " + std::to_string(frame.removed[i]) +
                                                 " is not below the live count " + std::to_string(live.size()));
        if (i && frame.removed[i] <= frame.removed[i - 1])
            return make_error(Code::Corrupt, where + ": removed indices are not strictly increasing");
    }
    if (live.size() - frame.removed.size() + frame.added.size() > limits.max_live_strokes)
        return make_error(Code::LimitExceeded, where + ": live list exceeds the limit");
    const bool moving = !frame.motion.empty();
    if (moving) {
        const auto& m = frame.motion;
        if (m.block_size < 8 || m.block_size > 256 || m.cols != detail::blocks_for(header.width, m.block_size) ||
            m.rows != detail::blocks_for(header.height, m.block_size) || m.vectors.size() != size_t(m.cols) * m.rows)
            return make_error(Code::Corrupt, where + ": motion field does not match the canvas");
    }
    std::vector<Stroke> next;
    next.reserve(live.size() - frame.removed.size() + frame.added.size());
    size_t r = 0;
    const Mover mover{frame.motion};
    for (size_t i = 0; i < live.size(); ++i) {
        if (r < frame.removed.size() && frame.removed[r] == i) { ++r; continue; }
        Stroke s = live[i];
        if (moving) {
            bool ok = true;
            switch (s.kind) {
                case StrokeKind::Stamp: ok = mover.move(s.stamp.x, s.stamp.y); break;
                case StrokeKind::Affine: ok = mover.move(s.affine.tx, s.affine.ty); break;
                case StrokeKind::Curve:
                    for (auto& p : s.curve.points) ok = ok && mover.move(p.x, p.y);
                    break;
                case StrokeKind::Polygon: {
                    // A polygon moves rigidly, by the vector of its first vertex's block
                    // (SPEC.md 5), so that motion never folds its outline.
                    if (s.polygon.points.empty()) break;
                    const auto [dx, dy] = mover.at(s.polygon.points[0].x, s.polygon.points[0].y);
                    for (auto& p : s.polygon.points) {
                        const int64_t nx = int64_t(p.x) + dx, ny = int64_t(p.y) + dy;
                        if (nx < -detail::kMaxCoord || nx > detail::kMaxCoord || ny < -detail::kMaxCoord || ny > detail::kMaxCoord) {
                            ok = false;
                            break;
                        }
                        p.x = int32_t(nx);
                        p.y = int32_t(ny);
                    }
                    break;
                }
            }
            if (!ok)
                return make_error(Code::Corrupt, where + ": motion moves stroke " + std::to_string(i) +
                                                     " outside the coordinate range +-2^24");
        }
        next.push_back(std::move(s));
    }
    next.insert(next.end(), frame.added.begin(), frame.added.end());
    if (Status s = check_render_work(next, header, limits, templates, where); !s) return s;
    live = std::move(next);
    return {};
}

}  // namespace spt
