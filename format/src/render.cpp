// spt::Renderer: SPEC.md section 8 (format/SPEC.md). Validation,
// single-stroke drawing and masks. Footprint caching is in render_cache.cpp, whole-frame
// (tiled) rendering in render_tiles.cpp. Thread-safe: footprints are built under a lock and
// published through atomics, per-draw scratch memory is thread-local.
#include <algorithm>
#include <string>

#include "raster_polygon.hpp"
#include "render_impl.hpp"

namespace spt {

Canvas::Canvas(uint32_t w, uint32_t h, Rgb8 fill_colour) : width(w), height(h) {
    rgb.resize(size_t(w) * h * 3);
    fill(fill_colour);
}

void Canvas::fill(Rgb8 c) {
    rgb.resize(size_t(width) * height * 3);
    for (size_t i = 0; i + 2 < rgb.size(); i += 3) {
        rgb[i] = c.r;
        rgb[i + 1] = c.g;
        rgb[i + 2] = c.b;
    }
}

Renderer::~Renderer() = default;

using namespace raster;

namespace {

constexpr int64_t kMaxCoord = RendererImpl::kMaxCoord;  // SPEC 4 value ranges
constexpr int64_t kMaxMatrix = int64_t(1) << 16;
constexpr uint32_t kMaxCurveWidth = 1u << 16;
constexpr uint64_t kMaxMaskPixels = uint64_t(1) << 26;  // stroke_mask() refuses larger boxes

Error bad(std::string msg) { return make_error(Code::InvalidArgument, std::move(msg)); }

bool in_range(int64_t v, int64_t lim) { return v >= -lim && v <= lim; }

Rgba8 colour_of(const Stroke& s) { return s.color(); }

std::vector<uint8_t>& scratch_cov() {
    thread_local std::vector<uint8_t> v;
    return v;
}

}  // namespace

RendererImpl::RendererImpl(const Header& h, const std::vector<Template>& t)
    : header_(h), templates_(t),
      span_slots_(h.sets.size() * t.size() * h.orientations.size()),
      mask_slots_(h.sets.size() * t.size() * h.orientations.size()) {
    for (auto& s : span_slots_) s.store(nullptr, std::memory_order_relaxed);
    for (auto& s : mask_slots_) s.store(nullptr, std::memory_order_relaxed);
}

Status RendererImpl::check(const Stroke& s) const {
    const Rgba8& col = s.color();
    if (header_.color == ColorEncoding::LinearHalf) {
        for (int ch = 0; ch < 3; ++ch)
            if (code16(col, ch) > kMaxHalfCode) return bad("stroke colour code " + std::to_string(code16(col, ch)) + " is not a finite half float >= 0");
    } else if (col.r_lo | col.g_lo | col.b_lo) {
        return bad("stroke colour has low bytes, which only colour encoding 1 has");
    }
    switch (s.kind) {
        case StrokeKind::Stamp: {
            const StampStroke& t = s.stamp;
            if (t.set >= header_.sets.size()) return bad("stamp stroke: set " + std::to_string(t.set) + " is not in the header");
            if (t.tmpl >= templates_.size()) return bad("stamp stroke: template " + std::to_string(t.tmpl) + " does not exist");
            if (t.orient >= header_.orientations.size()) return bad("stamp stroke: orientation " + std::to_string(t.orient) + " is not in the table");
            if (!in_range(t.x, kMaxCoord) || !in_range(t.y, kMaxCoord)) return bad("stamp stroke: position outside +-2^24");
            return {};
        }
        case StrokeKind::Affine: {
            const AffineStroke& t = s.affine;
            if (t.tmpl >= templates_.size()) return bad("affine stroke: template " + std::to_string(t.tmpl) + " does not exist");
            if (!in_range(t.tx, kMaxCoord) || !in_range(t.ty, kMaxCoord)) return bad("affine stroke: translation outside +-2^24");
            if (!in_range(t.a, kMaxMatrix) || !in_range(t.b, kMaxMatrix) || !in_range(t.c, kMaxMatrix) || !in_range(t.d, kMaxMatrix))
                return bad("affine stroke: matrix entry outside +-2^16");
            return {};
        }
        case StrokeKind::Curve: {
            const CurveStroke& t = s.curve;
            if (t.points.empty()) return bad("curve stroke: no points");
            if (t.supersample == 1 || t.supersample > 16)
                return bad("curve stroke: supersampling " + std::to_string(t.supersample) + " is not 0 or 2..16");
            for (size_t i = 0; i < t.points.size(); ++i) {
                const CurvePoint& p = t.points[i];
                if (!in_range(p.x, kMaxCoord) || !in_range(p.y, kMaxCoord) || p.width > kMaxCurveWidth)
                    return bad("curve stroke: point " + std::to_string(i) + " outside the ranges of SPEC 4");
            }
            return {};
        }
        case StrokeKind::Polygon: {
            const PolygonStroke& t = s.polygon;
            if (t.points.size() < 3) return bad("polygon stroke: " + std::to_string(t.points.size()) + " vertices, need 3 or more");
            if (t.supersample == 1 || t.supersample > 16)
                return bad("polygon stroke: supersampling " + std::to_string(t.supersample) + " is not 0 or 2..16");
            for (size_t i = 0; i < t.points.size(); ++i)
                if (!in_range(t.points[i].x, kMaxCoord) || !in_range(t.points[i].y, kMaxCoord))
                    return bad("polygon stroke: vertex " + std::to_string(i) + " outside +-2^24");
            return {};
        }
    }
    return bad("stroke of unknown kind " + std::to_string(int(s.kind)));
}

void RendererImpl::stroke_box(const Stroke& s, int64_t& x0, int64_t& y0, int64_t& x1, int64_t& y1) const {
    x0 = y0 = 0;
    x1 = y1 = -1;
    switch (s.kind) {
        case StrokeKind::Stamp: {
            const StampStroke& t = s.stamp;
            const int64_t cx = stamp_pixel(t.x), cy = stamp_pixel(t.y);
            if (const SpanMask* f = spans(t.set, t.tmpl, t.orient)) {
                if (f->rows.empty()) return;
                x0 = cx + f->x0; x1 = x0 + f->w - 1;
                y0 = cy + f->y0; y1 = y0 + int64_t(f->rows.size()) - 1;
            } else {
                const StrokeSet& ss = header_.sets[t.set];
                const InverseMap m = stamp_inverse_at(ss.width, ss.height, header_.orientations[t.orient], cx, cy,
                                                      templates_[t.tmpl].supersample);
                x0 = m.x0; x1 = m.x1; y0 = m.y0; y1 = m.y1;
            }
            return;
        }
        case StrokeKind::Affine: {
            InverseMap m;
            if (!affine_inverse(s.affine, m, templates_[s.affine.tmpl].supersample)) return;
            x0 = m.x0; x1 = m.x1; y0 = m.y0; y1 = m.y1;
            return;
        }
        case StrokeKind::Curve: curve_box(s.curve, x0, y0, x1, y1); return;
        case StrokeKind::Polygon: polygon_box(s.polygon, x0, y0, x1, y1); return;
    }
}

void RendererImpl::draw_map(const BlendTarget& t, const InverseMap& m, const Template& tp, Rgba8 c) const {
    const int64_t x0 = std::max<int64_t>(m.x0, t.x0), x1 = std::min<int64_t>(m.x1, t.x1 - 1);
    const int64_t y0 = std::max<int64_t>(m.y0, t.y0), y1 = std::min<int64_t>(m.y1, t.y1 - 1);
    if (x0 > x1 || y0 > y1) return;
    auto& cov = scratch_cov();
    if (cov.size() < size_t(x1 - x0 + 1)) cov.resize(size_t(x1 - x0 + 1));
    for (int64_t y = y0; y <= y1; ++y) {
        int64_t a = x0, b = x1;
        if (!map_row_range(m, y, a, b)) continue;
        rasterize_map_row(m, tp, y, a, b, cov.data());
        blend_cov_row(t, a, y, cov.data(), b - a + 1, c);
    }
}

void RendererImpl::draw_curve(const BlendTarget& t, const CurveStroke& s) const {
    int64_t x0, y0, x1, y1;
    curve_box(s, x0, y0, x1, y1);
    x0 = std::max<int64_t>(x0, t.x0); x1 = std::min<int64_t>(x1, t.x1 - 1);
    y0 = std::max<int64_t>(y0, t.y0); y1 = std::min<int64_t>(y1, t.y1 - 1);
    if (x0 > x1 || y0 > y1) return;
    const int64_t w = x1 - x0 + 1, h = y1 - y0 + 1;
    auto& cov = scratch_cov();
    if (cov.size() < size_t(w * h)) cov.resize(size_t(w * h));
    rasterize_curve(s, x0, y0, x1, y1, cov.data());
    for (int64_t y = y0; y <= y1; ++y) blend_cov_row(t, x0, y, &cov[size_t((y - y0) * w)], w, s.color);
}

namespace {

// Polygons (SPEC 8.8) are rasterised row by row, clipped to t, and composited with
// blend_cov_row; nothing is cached (a polygon is drawn once per frame).
void draw_polygon(const BlendTarget& t, const PolygonStroke& s) {
    int64_t x0, y0, x1, y1;
    polygon_box(s, x0, y0, x1, y1);
    x0 = std::max<int64_t>(x0, t.x0); x1 = std::min<int64_t>(x1, t.x1 - 1);
    y0 = std::max<int64_t>(y0, t.y0); y1 = std::min<int64_t>(y1, t.y1 - 1);
    if (x0 > x1 || y0 > y1) return;
    auto& cov = scratch_cov();
    if (cov.size() < size_t(x1 - x0 + 1)) cov.resize(size_t(x1 - x0 + 1));
    PolygonRaster r(s);
    for (int64_t y = y0; y <= y1; ++y) {
        r.row(y, x0, x1, cov.data());
        blend_cov_row(t, x0, y, cov.data(), x1 - x0 + 1, s.color);
    }
}

}  // namespace

void RendererImpl::draw_into(const BlendTarget& t, const Stroke& s) const {
    const Rgba8 c = colour_of(s);
    if (c.a == 0) return;
    switch (s.kind) {
        case StrokeKind::Stamp: {
            const StampStroke& st = s.stamp;
            const int64_t cx = stamp_pixel(st.x), cy = stamp_pixel(st.y);
            if (const SpanMask* f = spans(st.set, st.tmpl, st.orient)) {
                blend_spans(t, *f, cx + f->x0, cy + f->y0, c);
            } else {
                const StrokeSet& ss = header_.sets[st.set];
                draw_map(t, stamp_inverse_at(ss.width, ss.height, header_.orientations[st.orient], cx, cy,
                                             templates_[st.tmpl].supersample),
                         templates_[st.tmpl], c);
            }
            return;
        }
        case StrokeKind::Affine: {
            InverseMap m;
            if (affine_inverse(s.affine, m, templates_[s.affine.tmpl].supersample)) draw_map(t, m, templates_[s.affine.tmpl], c);
            return;
        }
        case StrokeKind::Curve: draw_curve(t, s.curve); return;
        case StrokeKind::Polygon: draw_polygon(t, s.polygon); return;
    }
}

Status RendererImpl::draw(Canvas& canvas, const Stroke& s) const {
    if (!header_.plain_color()) return draw_deep(canvas, s);
    if (canvas.rgb.size() != size_t(canvas.width) * canvas.height * 3)
        return bad("canvas: pixel buffer size does not match width x height x 3");
    if (Status st = check(s); !st) return st;
    BlendTarget t;
    t.px = canvas.rgb.data();
    t.stride = size_t(canvas.width) * 3;
    t.x1 = canvas.width;
    t.y1 = canvas.height;
    t.slack = false;  // the caller's canvas: touch nothing outside the stroke
    draw_into(t, s);
    return {};
}

Status RendererImpl::stroke_mask(const Stroke& s, Mask& out) const {
    out = Mask{};
    if (Status st = check(s); !st) return st;
    const uint32_t A = colour_of(s).a;
    int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    std::vector<uint8_t> cov;
    if (s.kind == StrokeKind::Stamp) {
        const Mask& f = stamp_footprint(s.stamp.set, s.stamp.tmpl, s.stamp.orient);
        if (f.w == 0) return {};
        x0 = int64_t(stamp_pixel(s.stamp.x)) + f.x0;
        y0 = int64_t(stamp_pixel(s.stamp.y)) + f.y0;
        x1 = x0 + f.w - 1;
        y1 = y0 + f.h - 1;
        cov = f.a;
    } else if (s.kind == StrokeKind::Affine) {
        InverseMap m;
        if (!affine_inverse(s.affine, m, templates_[s.affine.tmpl].supersample) || m.x1 < m.x0 || m.y1 < m.y0) return {};
        x0 = m.x0; y0 = m.y0; x1 = m.x1; y1 = m.y1;
        if (uint64_t(x1 - x0 + 1) * uint64_t(y1 - y0 + 1) > kMaxMaskPixels)
            return make_error(Code::LimitExceeded, "stroke_mask: affine stroke box above 2^26 pixels");
        cov.resize(size_t((x1 - x0 + 1) * (y1 - y0 + 1)));
        rasterize_map(m, templates_[s.affine.tmpl], x0, y0, x1, y1, cov.data());
    } else if (s.kind == StrokeKind::Polygon) {
        polygon_box(s.polygon, x0, y0, x1, y1);
        if (uint64_t(x1 - x0 + 1) * uint64_t(y1 - y0 + 1) > kMaxMaskPixels)
            return make_error(Code::LimitExceeded, "stroke_mask: polygon stroke box above 2^26 pixels");
        cov.resize(size_t((x1 - x0 + 1) * (y1 - y0 + 1)));
        rasterize_polygon(s.polygon, x0, y0, x1, y1, cov.data());
    } else {
        curve_box(s.curve, x0, y0, x1, y1);
        if (uint64_t(x1 - x0 + 1) * uint64_t(y1 - y0 + 1) > kMaxMaskPixels)
            return make_error(Code::LimitExceeded, "stroke_mask: curve stroke box above 2^26 pixels");
        cov.resize(size_t((x1 - x0 + 1) * (y1 - y0 + 1)));
        rasterize_curve(s.curve, x0, y0, x1, y1, cov.data());
    }
    out.x0 = int32_t(x0);
    out.y0 = int32_t(y0);
    out.w = uint32_t(x1 - x0 + 1);
    out.h = uint32_t(y1 - y0 + 1);
    for (auto& c : cov) c = uint8_t(stroke_alpha(c, A));
    out.a = std::move(cov);
    return {};
}

Result<std::unique_ptr<Renderer>> Renderer::create(const Header& h, const std::vector<Template>& templates) {
    if (h.width < 1 || h.height < 1 || h.width > kMaxCanvasSide || h.height > kMaxCanvasSide)
        return bad("header: canvas " + std::to_string(h.width) + "x" + std::to_string(h.height) +
                   " outside 1..2^20 per side");
    if (h.sets.empty() || h.sets.size() > 16) return bad("header: " + std::to_string(h.sets.size()) + " stroke sets, need 1..16");
    for (size_t i = 0; i < h.sets.size(); ++i)
        if (h.sets[i].width < 1 || h.sets[i].width > 4096 || h.sets[i].height < 1 || h.sets[i].height > 4096)
            return bad("header: stroke set " + std::to_string(i) + " size outside 1..4096");
    if (h.orientations.empty() || h.orientations.size() > 64)
        return bad("header: " + std::to_string(h.orientations.size()) + " orientations, need 1..64");
    for (size_t i = 0; i < h.orientations.size(); ++i) {
        const int64_t c = h.orientations[i].cos_q14, s = h.orientations[i].sin_q14;
        if (c * c + s * s > (int64_t(1) << 28) + (int64_t(1) << 16))
            return bad("header: orientation " + std::to_string(i) + " longer than unit length");
    }
    if (templates.size() > 255) return bad("templates: " + std::to_string(templates.size()) + ", at most 255");
    for (size_t i = 0; i < templates.size(); ++i) {
        const Template& t = templates[i];
        if (t.kind == TemplateKind::Bitmap) {
            if (t.width < 1 || t.width > 1024 || t.height < 1 || t.height > 1024)
                return bad("template " + std::to_string(i) + ": bitmap size outside 1..1024");
            if (t.pixels.size() != size_t(t.width) * t.height)
                return bad("template " + std::to_string(i) + ": " + std::to_string(t.pixels.size()) +
                           " samples for " + std::to_string(t.width) + "x" + std::to_string(t.height));
        } else if (t.kind != TemplateKind::Ellipse && t.kind != TemplateKind::Rectangle &&
                   t.kind != TemplateKind::Triangle) {
            return bad("template " + std::to_string(i) + ": unknown kind " + std::to_string(int(t.kind)));
        }
        if (t.kind == TemplateKind::Bitmap ? t.supersample != 0 : (t.supersample == 1 || t.supersample > 16))
            return bad("template " + std::to_string(i) + ": supersampling " + std::to_string(t.supersample) +
                       " (analytic kinds: 0 or 2..16; bitmaps: 0)");
    }
    return std::unique_ptr<Renderer>(new RendererImpl(h, templates));
}

}  // namespace spt
