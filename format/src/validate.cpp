// Value rules of SPEC.md 3.1, 3.2, 4 and 5.
#include "validate.hpp"

#include <algorithm>
#include <cstdlib>

#include "byte_io.hpp"
#include "spt/render.hpp"

namespace spt::detail {
namespace {
Error fail(Code code, const std::string& where, const std::string& msg, uint64_t offset) {
    return make_error(code, where + ": " + msg + " (byte offset " + std::to_string(offset) + ")", offset);
}
bool coord_ok(int64_t v) { return v >= -kMaxCoord && v <= kMaxCoord; }
bool matrix_ok(int64_t v) { return v >= -kMaxMatrix && v <= kMaxMatrix; }
}  // namespace

Status check_header(const Header& h, const Limits& lim, Code code, const std::string& where, uint64_t off) {
    if (h.version_major != 1)
        return fail(Code::Unsupported, where, "format major version " + std::to_string(h.version_major) + " is not 1", off);
    if (h.width < 1 || h.height < 1)
        return fail(code, where, "canvas " + std::to_string(h.width) + "x" + std::to_string(h.height) + " is empty", off);
    if (h.width > lim.max_width || h.height > lim.max_height ||
        uint64_t(h.width) * h.height > lim.max_pixels)
        return fail(Code::LimitExceeded, where, "canvas " + std::to_string(h.width) + "x" + std::to_string(h.height) +
                    " exceeds the limits", off);
    if (h.fps.num == 0 || h.fps.den == 0) return fail(code, where, "frame rate has a zero term", off);
    if (h.color != ColorEncoding::Srgb8 && h.color != ColorEncoding::LinearHalf)
        return fail(Code::Unsupported, where, "colour encoding " + std::to_string(int(h.color)) + " is reserved", off);
    if (!h.plain_color() && h.version_minor < kAlphaLinearMinorVersion)
        return fail(code, where, "an alpha canvas or colour encoding 1 needs format 1.3, the header says 1." +
                    std::to_string(h.version_minor), off);
    if (h.curve_grid && h.version_minor < kCurveGridMinorVersion)
        return fail(code, where, "anti-aliased curves (flag curve_grid) need format 1.4, the header says 1." +
                    std::to_string(h.version_minor), off);
    if (h.color == ColorEncoding::Srgb8 && h.background_lo != Rgb8{0, 0, 0})
        return fail(code, where, "background low bytes are set in colour encoding 0", off);
    if (h.color == ColorEncoding::LinearHalf)
        for (int ch = 0; ch < 3; ++ch) {
            const uint8_t hi = ch == 0 ? h.background.r : ch == 1 ? h.background.g : h.background.b;
            const uint8_t lo = ch == 0 ? h.background_lo.r : ch == 1 ? h.background_lo.g : h.background_lo.b;
            if ((hi << 8 | lo) > kMaxHalfCode)
                return fail(code, where, "background code " + std::to_string(hi << 8 | lo) + " is not a finite half float >= 0", off);
        }
    if (h.sets.empty() || h.sets.size() > kMaxSets)
        return fail(code, where, "set count " + std::to_string(h.sets.size()) + " is not 1..16", off);
    for (size_t i = 0; i < h.sets.size(); ++i)
        if (h.sets[i].width < 1 || h.sets[i].height < 1 || h.sets[i].width > kMaxSetSide || h.sets[i].height > kMaxSetSide)
            return fail(code, where, "set " + std::to_string(i) + " size is not 1..4096", off);
    if (h.orientations.empty() || h.orientations.size() > kMaxOrientations)
        return fail(code, where, "orientation count " + std::to_string(h.orientations.size()) + " is not 1..64", off);
    for (size_t i = 0; i < h.orientations.size(); ++i) {
        const int64_t c = h.orientations[i].cos_q14, s = h.orientations[i].sin_q14;
        if (c * c + s * s > (int64_t(1) << 28) + (int64_t(1) << 16))
            return fail(code, where, "orientation " + std::to_string(i) + " is longer than 1", off);
    }
    return {};
}

Status check_template(const Template& t, const Limits& lim, Code code, const std::string& where, uint64_t off) {
    if (uint8_t(t.kind) > 3) return fail(Code::Unsupported, where, "template kind " + std::to_string(int(t.kind)) + " is reserved", off);
    if (t.name.size() > 255) return fail(code, where, "template name is longer than 255 bytes", off);
    if (t.kind == TemplateKind::Bitmap) {
        if (t.width < 1 || t.height < 1 || t.width > kMaxTemplateSide || t.height > kMaxTemplateSide)
            return fail(code, where, "bitmap template size " + std::to_string(t.width) + "x" + std::to_string(t.height) +
                        " is not 1..1024", off);
        if (t.width > lim.max_template_side || t.height > lim.max_template_side)
            return fail(Code::LimitExceeded, where, "bitmap template size exceeds the limits", off);
        if (t.pixels.size() != size_t(t.width) * t.height)
            return fail(code, where, "bitmap template has " + std::to_string(t.pixels.size()) + " samples, not width*height", off);
        if (t.supersample) return fail(code, where, "bitmap template with supersampling", off);
    } else if (t.width || t.height || !t.pixels.empty()) {
        return fail(code, where, "analytic template has a size or samples", off);
    } else if (t.supersample == 1 || t.supersample > 16) {
        return fail(Code::Unsupported, where, "template supersampling " + std::to_string(t.supersample) + " is not 0 or 2..16", off);
    }
    return {};
}

Status check_stroke(const Stroke& s, const StreamShape& sh, const Limits& lim, Code code,
                    const std::string& where, uint64_t off) {
    if (!color_ok(s.color(), sh))
        return fail(code, where, sh.linear ? "colour code is not a finite half float >= 0 (0..0x7BFF)"
                                           : "colour has low bytes, which only colour encoding 1 has", off);
    switch (s.kind) {
        case StrokeKind::Stamp: {
            const auto& t = s.stamp;
            if (t.set >= sh.sets) return fail(code, where, "stamp set " + std::to_string(t.set) + " is not below the set count " + std::to_string(sh.sets), off);
            if (t.tmpl >= sh.templates) return fail(code, where, "template " + std::to_string(t.tmpl) + " is not below the template count " + std::to_string(sh.templates), off);
            if (t.orient >= sh.orientations) return fail(code, where, "orientation " + std::to_string(t.orient) + " is not below the orientation count " + std::to_string(sh.orientations), off);
            if (!coord_ok(t.x) || !coord_ok(t.y)) return fail(code, where, "stamp position is outside +-2^24", off);
            return {};
        }
        case StrokeKind::Affine: {
            const auto& t = s.affine;
            if (t.tmpl >= sh.templates) return fail(code, where, "template " + std::to_string(t.tmpl) + " is not below the template count " + std::to_string(sh.templates), off);
            if (!coord_ok(t.tx) || !coord_ok(t.ty)) return fail(code, where, "affine translation is outside +-2^24", off);
            if (!matrix_ok(t.a) || !matrix_ok(t.b) || !matrix_ok(t.c) || !matrix_ok(t.d))
                return fail(code, where, "affine matrix entry is outside +-2^16", off);
            if (int64_t(t.a) * t.d - int64_t(t.b) * t.c == 0) return fail(code, where, "affine matrix is singular", off);
            return {};
        }
        case StrokeKind::Curve: {
            const auto& c = s.curve;
            if (c.points.empty()) return fail(code, where, "curve has no points", off);
            if (c.supersample == 1 || c.supersample > 16)
                return fail(Code::Unsupported, where, "curve supersampling " + std::to_string(c.supersample) + " is reserved", off);
            if (c.supersample != 0 && !sh.curve_grid)
                return fail(code, where, "curve has a supersampling grid, which needs the header flag curve_grid (format 1.4)", off);
            if (c.points.size() > lim.max_curve_points)
                return fail(Code::LimitExceeded, where, "curve has " + std::to_string(c.points.size()) + " points, above the limit", off);
            for (const auto& p : c.points) {
                if (!coord_ok(p.x) || !coord_ok(p.y)) return fail(code, where, "curve point is outside +-2^24", off);
                if (p.width > kMaxWidthQ4) return fail(code, where, "curve width is above 2^16", off);
            }
            if (const uint64_t w = curve_render_work(c, sh.width, sh.height); w > lim.max_curve_work)
                return fail(Code::LimitExceeded, where,
                            "curve needs " + std::to_string(w) + " units of rendering work (pixels of its segments' boxes), above the limit " +
                                std::to_string(lim.max_curve_work),
                            off);
            return {};
        }
        case StrokeKind::Polygon: {
            const auto& p = s.polygon;
            if (p.points.size() < 3) return fail(code, where, "polygon has " + std::to_string(p.points.size()) + " vertices, not 3 or more", off);
            if (p.points.size() > lim.max_polygon_vertices)
                return fail(Code::LimitExceeded, where, "polygon has " + std::to_string(p.points.size()) + " vertices, above the limit", off);
            if (p.supersample == 1 || p.supersample > 16)
                return fail(Code::Unsupported, where, "polygon supersampling " + std::to_string(p.supersample) + " is not 0 or 2..16", off);
            for (size_t i = 0; i < p.points.size(); ++i)
                if (!coord_ok(p.points[i].x) || !coord_ok(p.points[i].y))
                    return fail(code, where, "polygon vertex " + std::to_string(i) + " is outside +-2^24", off);
            if (const uint64_t w = polygon_render_work(p, sh.height); w > lim.max_polygon_work)
                return fail(Code::LimitExceeded, where,
                            "polygon needs " + std::to_string(w) + " units of rendering work (edges x rows x samples), above the limit " +
                                std::to_string(lim.max_polygon_work),
                            off);
            return {};
        }
    }
    return fail(code, where, "stroke kind " + std::to_string(int(s.kind)) + " is reserved", off);
}

Status check_frame(const Frame& f, const StreamShape& sh, const Limits& lim, uint64_t prev_live,
                   Code code, const std::string& where, uint64_t off, size_t checked) {
    if (f.added.size() > lim.max_strokes_per_frame)
        return fail(Code::LimitExceeded, where, std::to_string(f.added.size()) + " strokes exceed the stroke limit of " + std::to_string(lim.max_strokes_per_frame) + " per frame (max_strokes_per_frame)", off);
    if (f.type == FrameType::Key) {
        if (!f.removed.empty() || !f.motion.empty()) return fail(code, where, "key frame has removals or motion", off);
        if (f.added.size() > lim.max_live_strokes) return fail(Code::LimitExceeded, where, "live list exceeds the limit", off);
    } else if (f.type == FrameType::Inter) {
        for (size_t i = 0; i < f.removed.size(); ++i) {
            if (f.removed[i] >= prev_live)
                return fail(code, where, "removed index " + std::to_string(f.removed[i]) + " is not below the live count " + std::to_string(prev_live), off);
            if (i && f.removed[i] <= f.removed[i - 1]) return fail(code, where, "removed indices are not strictly increasing", off);
        }
        if (prev_live != kUnknownLive && prev_live - f.removed.size() + f.added.size() > lim.max_live_strokes)
            return fail(Code::LimitExceeded, where, "live list exceeds the limit", off);
        if (!f.motion.empty()) {
            const auto& m = f.motion;
            if (m.block_size < 8 || m.block_size > 256) return fail(code, where, "motion block size " + std::to_string(m.block_size) + " is not 8..256", off);
            if (m.cols != blocks_for(sh.width, m.block_size) || m.rows != blocks_for(sh.height, m.block_size))
                return fail(code, where, "motion field is " + std::to_string(m.cols) + "x" + std::to_string(m.rows) + " blocks, not the canvas's", off);
            if (m.vectors.size() != size_t(m.cols) * m.rows) return fail(code, where, "motion field has the wrong vector count", off);
        }
    } else {
        return fail(Code::Unsupported, where, "frame type " + std::to_string(int(f.type)) + " is reserved", off);
    }
    // The message names the stroke; it is only built for a stroke that fails.
    // Stamps, most strokes of a painting, are checked inline: a Status per stroke costs more
    // than the comparisons.
    static const std::string kNone;
    for (size_t i = checked; i < f.added.size(); ++i) {
        const Stroke& s = f.added[i];
        if (s.kind == StrokeKind::Stamp && stamp_ok(s.stamp, sh)) continue;
        if (!check_stroke(s, sh, lim, code, kNone, off).ok())
            return check_stroke(s, sh, lim, code, where + ", stroke " + std::to_string(i), off);
    }
    return {};
}

}  // namespace spt::detail

namespace spt {

namespace {
// floor(v / 16): the pixel of a Q4 coordinate (arithmetic shift).
int64_t floor16(int64_t v) { return v >= 0 ? v / 16 : -((-v + 15) / 16); }
}  // namespace

uint64_t curve_render_work(const CurveStroke& c, uint32_t canvas_width, uint32_t canvas_height) {
    const size_t n = c.points.size();
    uint64_t work = 0;
    for (size_t k = 0; k < n; ++k) {
        if (k + 1 == n && n > 1) break;  // n - 1 segments; a one-point curve is one disc
        const CurvePoint& p = c.points[k];
        const CurvePoint& q = c.points[k + 1 < n ? k + 1 : k];
        // The segment's box of SPEC 8.5 (as raster_curve.cpp evaluates it), clipped to the canvas.
        const int64_t m = (std::max<int64_t>(p.width, q.width) + 1) / 2 + 1 + (c.supersample >= 2 ? 8 : 0);
        const int64_t x0 = std::max<int64_t>(-floor16(-(std::min<int64_t>(p.x, q.x) - m - 8)), 0);
        const int64_t x1 = std::min<int64_t>(floor16(std::max<int64_t>(p.x, q.x) + m - 8), int64_t(canvas_width) - 1);
        const int64_t y0 = std::max<int64_t>(-floor16(-(std::min<int64_t>(p.y, q.y) - m - 8)), 0);
        const int64_t y1 = std::min<int64_t>(floor16(std::max<int64_t>(p.y, q.y) + m - 8), int64_t(canvas_height) - 1);
        if (x1 >= x0 && y1 >= y0) work += uint64_t(x1 - x0 + 1) * uint64_t(y1 - y0 + 1);
    }
    const uint64_t side = c.supersample >= 2 ? c.supersample : 1;
    return work * side * side;
}

uint64_t fill_render_work(const Stroke& s, const Header& h, const std::vector<Template>& templates) {
    int64_t cx, cy, rx, ry;  // centre pixel and half extents of the evaluation box, pixels
    uint8_t tmpl;
    if (s.kind == StrokeKind::Stamp) {
        if (s.stamp.set >= h.sets.size() || s.stamp.orient >= h.orientations.size()) return 0;
        const int64_t w = h.sets[s.stamp.set].width, hh = h.sets[s.stamp.set].height;
        const int64_t C = std::abs(int64_t(h.orientations[s.stamp.orient].cos_q14));
        const int64_t S = std::abs(int64_t(h.orientations[s.stamp.orient].sin_q14));
        rx = (w * C + hh * S) / 32768 + 1;  // SPEC 8.3's box
        ry = (w * S + hh * C) / 32768 + 1;
        cx = floor16(s.stamp.x);
        cy = floor16(s.stamp.y);
        tmpl = s.stamp.tmpl;
    } else if (s.kind == StrokeKind::Affine) {
        const AffineStroke& a = s.affine;
        // |u|, |v| <= 1 map within (|a| + |b|, |c| + |d|) of (tx, ty), Q4; a pixel more each way.
        rx = (std::abs(int64_t(a.a)) + std::abs(int64_t(a.b))) / 16 + 2;
        ry = (std::abs(int64_t(a.c)) + std::abs(int64_t(a.d))) / 16 + 2;
        cx = floor16(a.tx);
        cy = floor16(a.ty);
        tmpl = a.tmpl;
    } else {
        return 0;
    }
    if (tmpl >= templates.size()) return 0;
    const int64_t x0 = std::max<int64_t>(cx - rx, 0), x1 = std::min<int64_t>(cx + rx, int64_t(h.width) - 1);
    const int64_t y0 = std::max<int64_t>(cy - ry, 0), y1 = std::min<int64_t>(cy + ry, int64_t(h.height) - 1);
    if (x1 < x0 || y1 < y0) return 0;
    const Template& t = templates[tmpl];
    const uint64_t m = t.kind != TemplateKind::Bitmap && t.supersample >= 2 ? t.supersample : 1;
    return uint64_t(x1 - x0 + 1) * uint64_t(y1 - y0 + 1) * m * m;
}

uint64_t polygon_render_work(const PolygonStroke& p, uint32_t canvas_height) {
    if (p.points.empty() || canvas_height == 0) return 0;
    uint64_t edges = 0;
    int64_t lo = p.points[0].y, hi = lo;
    for (size_t i = 0; i < p.points.size(); ++i) {
        edges += p.points[i].y != p.points[(i + 1) % p.points.size()].y;
        lo = std::min<int64_t>(lo, p.points[i].y);
        hi = std::max<int64_t>(hi, p.points[i].y);
    }
    // Canvas rows of the box (SPEC 8.8: floor_div(min y, 16) .. floor_div(max y, 16)).
    const int64_t r0 = std::max<int64_t>(floor16(lo), 0), r1 = std::min<int64_t>(floor16(hi), int64_t(canvas_height) - 1);
    if (r1 < r0) return 0;
    const uint64_t m = p.supersample >= 2 ? p.supersample : 1;
    return edges * uint64_t(r1 - r0 + 1) * m * m;
}

}  // namespace spt
