// SVG export: each stroke drawn the way spt::Renderer draws it, in vector form. Analytic
// templates become <ellipse>/<rect>/<polygon> in template space [-1,1]^2 under the stroke's
// matrix; bitmap templates become luminance masks holding an embedded PNG; curves become the
// union of discs at their points and the tangent hulls between them, drawn opaque inside a
// group that carries the stroke's alpha, so overlaps within one curve blend once, as in the
// renderer.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "spt_import/codec.hpp"
#include "spt_import/export.hpp"
#include "spt/atomic_file.hpp"
#include "spt/color.hpp"
#include "spt/display.hpp"

namespace spt::import {

namespace {

std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

// The sRGB colour SVG shows: colour encoding 1 (scene-linear half codes) through the sRGB
// curve, values above 1 clipped (spt/display.hpp's view); encoding 0 as it is.
Rgba8 shown(Rgba8 c, bool linear) {
    if (!linear) return c;
    Rgba8 s;
    s.a = c.a;
    uint8_t* out[3] = {&s.r, &s.g, &s.b};
    for (int k = 0; k < 3; ++k) {
        const uint16_t code = code16(c, k);
        *out[k] = unit_to_u8(srgb_encode(code <= kMaxHalfCode ? half_to_float(code) : 0.f));
    }
    return s;
}

std::string hex(Rgba8 c) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
    return buf;
}

std::string opacity(uint8_t a) {
    if (a == 255) return "";
    return " fill-opacity=\"" + num(a / 255.0) + "\"";
}

// The unit template shape, in template coordinates.
std::string template_shape(const Template& t, size_t id) {
    switch (t.kind) {
        case TemplateKind::Ellipse: return "<ellipse cx=\"0\" cy=\"0\" rx=\"1\" ry=\"1\"";
        case TemplateKind::Rectangle: return "<rect x=\"-1\" y=\"-1\" width=\"2\" height=\"2\"";
        case TemplateKind::Triangle: return "<polygon points=\"-1,-1 1,-1 -1,1\"";
        case TemplateKind::Bitmap:
            return "<rect x=\"-1\" y=\"-1\" width=\"2\" height=\"2\" mask=\"url(#t" + std::to_string(id) + ")\"";
    }
    return "";
}

// Polygon strokes: SVG's nonzero fill rule is the stroke's (SPEC.md 8.8). SVG renderers
// anti-alias, like a supersampled polygon; one sampled at pixel centres (grid 0) asks for
// crisp edges, which browsers draw without anti-aliasing, closer to the spec's pixels.
void polygon(std::string& o, const PolygonStroke& p, Rgba8 color) {
    o += "<polygon points=\"";
    for (size_t i = 0; i < p.points.size(); ++i) {
        if (i) o += " ";
        o += num(p.points[i].x / 16.0) + "," + num(p.points[i].y / 16.0);
    }
    o += "\" fill-rule=\"nonzero\" fill=\"" + hex(color) + "\"" + opacity(color.a);
    if (p.supersample == 0) o += " shape-rendering=\"crispEdges\"";
    o += "/>\n";
}

void curve(std::string& o, const CurveStroke& c, Rgba8 color) {
    const auto& P = c.points;
    // A line of one width (a cartoon's drawn lines) is a stroked polyline with round caps and
    // joins: the same shape (SPEC.md 8.5), and a path that vector editors edit as a line.
    bool constant = P.size() > 1 && P[0].width > 0;
    for (const CurvePoint& p : P) constant = constant && p.width == P[0].width;
    if (constant) {
        o += "<polyline points=\"";
        for (size_t i = 0; i < P.size(); ++i) {
            if (i) o += " ";
            o += num(P[i].x / 16.0) + "," + num(P[i].y / 16.0);
        }
        o += "\" fill=\"none\" stroke=\"" + hex(color) + "\" stroke-width=\"" + num(P[0].width / 16.0) +
             "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
        if (color.a != 255) o += " stroke-opacity=\"" + num(color.a / 255.0) + "\"";
        o += "/>\n";
        return;
    }
    o += "<g fill=\"" + hex(color) + "\"";
    if (color.a != 255) o += " opacity=\"" + num(color.a / 255.0) + "\"";
    o += ">";
    for (size_t i = 0; i < P.size(); ++i) {
        const double x = P[i].x / 16.0, y = P[i].y / 16.0, r = P[i].width / 32.0;
        if (r > 0) o += "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) + "\" r=\"" + num(r) + "\"/>";
        if (i + 1 == P.size()) break;
        const double x1 = P[i + 1].x / 16.0, y1 = P[i + 1].y / 16.0, r1 = P[i + 1].width / 32.0;
        const double dx = x1 - x, dy = y1 - y, d = std::hypot(dx, dy);
        if (d <= std::fabs(r - r1)) continue;  // one disc holds the other
        const double ex = dx / d, ey = dy / d, nx = -ey, ny = ex;
        const double s = (r - r1) / d, co = std::sqrt(std::max(0.0, 1 - s * s));
        const double ux = s * ex + co * nx, uy = s * ey + co * ny;  // tangent direction, one side
        const double vx = s * ex - co * nx, vy = s * ey - co * ny;  // the other side
        o += "<polygon points=\"" + num(x + r * ux) + "," + num(y + r * uy) + " " + num(x1 + r1 * ux) + "," + num(y1 + r1 * uy) + " " +
             num(x1 + r1 * vx) + "," + num(y1 + r1 * vy) + " " + num(x + r * vx) + "," + num(y + r * vy) + "\"/>";
    }
    o += "</g>\n";
}

}  // namespace

Result<std::string> export_svg(const StreamInfo& info, const std::vector<Stroke>& strokes) {
    const Header& h = info.header;
    std::string o = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    o += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + std::to_string(h.width) + "\" height=\"" +
         std::to_string(h.height) + "\" viewBox=\"0 0 " + std::to_string(h.width) + " " + std::to_string(h.height) + "\">\n";
    // Bitmap templates as luminance masks in template space, those the strokes draw.
    std::vector<bool> used(info.templates.size(), false);
    for (const Stroke& s : strokes) {
        const size_t t = s.kind == StrokeKind::Stamp ? s.stamp.tmpl : s.kind == StrokeKind::Affine ? s.affine.tmpl : used.size();
        if (t < used.size()) used[t] = true;
    }
    bool defs = false;
    for (size_t i = 0; i < info.templates.size(); ++i) {
        const Template& t = info.templates[i];
        if (t.kind != TemplateKind::Bitmap || !used[i]) continue;
        if (!defs) { o += "<defs>\n"; defs = true; }
        auto png = encode_png(t.width, t.height, 1, t.pixels.data());
        o += "<mask id=\"t" + std::to_string(i) + "\" maskUnits=\"userSpaceOnUse\" maskContentUnits=\"userSpaceOnUse\" x=\"-1\" y=\"-1\" width=\"2\" height=\"2\">";
        o += "<image x=\"-1\" y=\"-1\" width=\"2\" height=\"2\" preserveAspectRatio=\"none\" href=\"data:image/png;base64,";
        o += base64_encode(png.data(), png.size());
        o += "\"/></mask>\n";
    }
    if (defs) o += "</defs>\n";
    // An alpha canvas starts transparent: no background rectangle (the viewer's shows through).
    const bool linear = h.color == ColorEncoding::LinearHalf;
    if (!h.alpha) {
        Rgba8 bg{h.background.r, h.background.g, h.background.b, 255};
        bg.r_lo = h.background_lo.r, bg.g_lo = h.background_lo.g, bg.b_lo = h.background_lo.b;
        o += "<rect width=\"" + std::to_string(h.width) + "\" height=\"" + std::to_string(h.height) + "\" fill=\"" + hex(shown(bg, linear)) + "\"/>\n";
    }
    for (const Stroke& s : strokes) {
        if (s.kind == StrokeKind::Curve) { curve(o, s.curve, shown(s.curve.color, linear)); continue; }
        if (s.kind == StrokeKind::Polygon) { polygon(o, s.polygon, shown(s.polygon.color, linear)); continue; }
        uint8_t tmpl;
        double A, B, C, D, E, F;
        Rgba8 col;
        if (s.kind == StrokeKind::Affine) {
            const auto& a = s.affine;
            tmpl = a.tmpl; col = a.color;
            A = a.a / 16.0; B = a.c / 16.0; C = a.b / 16.0; D = a.d / 16.0; E = a.tx / 16.0; F = a.ty / 16.0;
        } else {
            const auto& st = s.stamp;
            if (st.set >= h.sets.size() || st.orient >= h.orientations.size())
                return make_error(Code::InvalidArgument, "stamp stroke refers to a missing set or orientation");
            tmpl = st.tmpl; col = st.color;
            const double c = h.orientations[st.orient].cos_q14 / 16384.0, sn = h.orientations[st.orient].sin_q14 / 16384.0;
            const double hw = h.sets[st.set].width / 2.0, hh = h.sets[st.set].height / 2.0;
            // Centred on the centre of the pixel holding (x, y); u along the rotated width.
            A = c * hw; B = sn * hw; C = -sn * hh; D = c * hh;
            E = (st.x >> 4) + 0.5; F = (st.y >> 4) + 0.5;
        }
        if (tmpl >= info.templates.size()) return make_error(Code::InvalidArgument, "stroke refers to missing template " + std::to_string(tmpl));
        o += template_shape(info.templates[tmpl], tmpl);
        o += " transform=\"matrix(" + num(A) + " " + num(B) + " " + num(C) + " " + num(D) + " " + num(E) + " " + num(F) + ")\" fill=\"" +
             hex(shown(col, linear)) + "\"" + opacity(col.a) + "/>\n";
    }
    o += "</svg>\n";
    return o;
}

Status write_file_atomic(const std::string& path, const std::string& data) {
    return spt::write_file_atomic(path, data.data(), data.size());
}

}  // namespace spt::import
