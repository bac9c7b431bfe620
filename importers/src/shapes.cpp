// Shapes to strokes. Ellipses, rectangles, triangles and parallelograms are affine images of the
// analytic templates, so they are exact up to rounding the map to the Q4 grid; other polygons
// are polygon strokes (format 1.2), exact up to rounding their vertices.
#include "spt_import/shapes.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>

#include "number_cast.hpp"

namespace spt::import {

namespace {
constexpr double kMaxPos = double(1 << 24);   // |x|, |y|, |tx|, |ty| in Q4 (SPEC.md 4)
constexpr double kMaxAxis = double(1 << 16);  // |a|, |b|, |c|, |d| in Q4
constexpr double kPi = 3.14159265358979323846;
}  // namespace

Mat2x3 Mat2x3::rotate_deg(double deg) {
    // Exact for multiples of 90 degrees, so axis-aligned input stays exact.
    const double r = std::fmod(deg, 360.0);
    double c, s;
    if (r == 0) { c = 1; s = 0; }
    else if (r == 90 || r == -270) { c = 0; s = 1; }
    else if (r == 180 || r == -180) { c = -1; s = 0; }
    else if (r == 270 || r == -90) { c = 0; s = -1; }
    else { c = std::cos(r * kPi / 180.0); s = std::sin(r * kPi / 180.0); }
    return {c, s, -s, c, 0, 0};
}

Mat2x3 Mat2x3::operator*(const Mat2x3& o) const {
    return {a * o.a + c * o.b, b * o.a + d * o.b, a * o.c + c * o.d, b * o.c + d * o.d,
            a * o.e + c * o.f + e, b * o.e + d * o.f + f};
}

int32_t to_q4(double px) {
    double q = std::nearbyint(px * 16.0);
    if (!(q > -kMaxPos)) q = -kMaxPos;  // also catches NaN
    if (q > kMaxPos) q = kMaxPos;
    return int32_t(q);
}

void ImportReport::note(const std::string& n) {
    if (std::find(notes.begin(), notes.end(), n) == notes.end()) notes.push_back(n);
}

void ImportReport::merge(const ImportReport& o) {
    shapes += o.shapes;
    strokes += o.strokes;
    approximated += o.approximated;
    dropped += o.dropped;
    max_q4_error_px = std::max(max_q4_error_px, o.max_q4_error_px);
    for (const auto& n : o.notes) note(n);
    background_stated = background_stated && o.background_stated;
}

void StrokeSink::affine(uint8_t tmpl, const Mat2x3& m, Rgba8 color) {
    if (color.a == 0) { ++rep_.dropped; rep_.note("fully transparent shapes dropped"); return; }
    const double v[6] = {m.a, m.b, m.c, m.d, m.e, m.f};
    for (double x : v)
        if (!std::isfinite(x)) { ++rep_.dropped; rep_.note("shapes with non-finite geometry dropped"); return; }
    if (std::fabs(m.e * 16) > kMaxPos || std::fabs(m.f * 16) > kMaxPos) {
        ++rep_.dropped; rep_.note("shapes centred beyond the coordinate range (|x| > 2^20 px) dropped"); return;
    }
    for (int i = 0; i < 4; ++i)
        if (std::fabs(v[i] * 16) > kMaxAxis) {
            ++rep_.dropped; rep_.note("shapes larger than the stroke model's 8192 px span dropped"); return;
        }
    AffineStroke s;
    s.tmpl = tmpl;
    s.tx = to_q4(m.e); s.ty = to_q4(m.f);
    s.a = to_q4(m.a); s.c = to_q4(m.b);  // image of u
    s.b = to_q4(m.c); s.d = to_q4(m.d);  // image of v
    s.color = color;
    if (int64_t(s.a) * s.d - int64_t(s.b) * s.c == 0) {
        ++rep_.dropped; rep_.note("shapes thinner than 1/16 px (degenerate after rounding) dropped"); return;
    }
    // Largest displacement of a template corner caused by rounding.
    const double da = s.a / 16.0 - m.a, db = s.b / 16.0 - m.c, dc = s.c / 16.0 - m.b, dd = s.d / 16.0 - m.d;
    const double dx = s.tx / 16.0 - m.e, dy = s.ty / 16.0 - m.f;
    for (int u = -1; u <= 1; u += 2)
        for (int w = -1; w <= 1; w += 2) {
            double ex = dx + u * da + w * db, ey = dy + u * dc + w * dd;
            rep_.max_q4_error_px = std::max(rep_.max_q4_error_px, std::hypot(ex, ey));
        }
    out_.push_back(Stroke::make_affine(s));
    ++rep_.strokes;
}

void StrokeSink::ellipse(const Mat2x3& m, double cx, double cy, double rx, double ry, Rgba8 color) {
    affine(ids_.ellipse, m * Mat2x3::translate(cx, cy) * Mat2x3::scale(rx, ry), color);
}

void StrokeSink::rect(const Mat2x3& m, double x, double y, double w, double h, Rgba8 color) {
    affine(ids_.rectangle, m * Mat2x3::translate(x + w / 2, y + h / 2) * Mat2x3::scale(w / 2, h / 2), color);
}

void StrokeSink::triangle(Point p0, Point p1, Point p2, Rgba8 color) {
    // Template vertices (-1,-1), (1,-1), (-1,1) go to p0, p1, p2.
    Mat2x3 m{(p1.x - p0.x) / 2, (p1.y - p0.y) / 2, (p2.x - p0.x) / 2, (p2.y - p0.y) / 2,
             (p1.x + p2.x) / 2, (p1.y + p2.y) / 2};
    affine(ids_.triangle, m, color);
}

void StrokeSink::polygon(const std::vector<Point>& in, Rgba8 color) {
    ++rep_.shapes;
    std::vector<Point> p;
    for (const auto& q : in)
        if (p.empty() || q.x != p.back().x || q.y != p.back().y) p.push_back(q);
    while (p.size() > 1 && p.front().x == p.back().x && p.front().y == p.back().y) p.pop_back();
    if (p.size() < 3) { ++rep_.dropped; rep_.note("polygons with fewer than 3 distinct vertices dropped"); return; }
    if (p.size() == 3) { triangle(p[0], p[1], p[2], color); return; }
    if (p.size() == 4) {
        // A parallelogram (a rotated rectangle, as geometrize writes them) is one rectangle stroke.
        const double ex = (p[0].x + p[2].x) - (p[1].x + p[3].x), ey = (p[0].y + p[2].y) - (p[1].y + p[3].y);
        const double span = std::max({std::fabs(p[2].x - p[0].x), std::fabs(p[2].y - p[0].y), 1.0});
        if (std::hypot(ex, ey) <= 0.02 + 1e-5 * span) {
            const double cx = (p[0].x + p[1].x + p[2].x + p[3].x) / 4, cy = (p[0].y + p[1].y + p[2].y + p[3].y) / 4;
            // Corners (-1,-1), (1,-1), (1,1), (-1,1) go to p0, p1, p2, p3.
            Mat2x3 m{(p[1].x - p[0].x) / 2, (p[1].y - p[0].y) / 2, (p[3].x - p[0].x) / 2, (p[3].y - p[0].y) / 2, cx, cy};
            affine(ids_.rectangle, m, color);
            return;
        }
    }
    // One polygon stroke: exact up to the Q4 grid, whatever its shape (nonzero fill, as SVG's
    // default fill-rule), and a translucent fill blends once.
    if (p.size() > 4096) { ++rep_.dropped; rep_.note("polygons with more than 4096 vertices dropped"); return; }
    if (color.a == 0) { ++rep_.dropped; rep_.note("fully transparent shapes dropped"); return; }
    PolygonStroke pg;
    pg.color = color;
    pg.supersample = poly_aa_;
    for (const auto& q : p) {
        if (!std::isfinite(q.x) || !std::isfinite(q.y) || std::fabs(q.x * 16) > kMaxPos || std::fabs(q.y * 16) > kMaxPos) {
            ++rep_.dropped; rep_.note("polygons with vertices beyond the coordinate range dropped"); return;
        }
        const PolygonVertex v{to_q4(q.x), to_q4(q.y)};
        rep_.max_q4_error_px = std::max(rep_.max_q4_error_px, std::hypot(v.x / 16.0 - q.x, v.y / 16.0 - q.y));
        pg.points.push_back(v);
    }
    out_.push_back(Stroke::make_polygon(std::move(pg)));
    ++rep_.strokes;
}

void StrokeSink::polyline(const std::vector<Point>& pts, double width, Rgba8 color) {
    ++rep_.shapes;
    if (pts.empty() || color.a == 0 || !(width > 0)) { ++rep_.dropped; rep_.note("empty or invisible lines dropped"); return; }
    CurveStroke c;
    c.color = color;
    const uint32_t w = uint32_t(std::clamp(std::nearbyint(width * 16), 1.0, kMaxAxis));
    for (const auto& p : pts) {
        CurvePoint q{to_q4(p.x), to_q4(p.y), w};
        if (!c.points.empty() && c.points.back() == q) continue;
        c.points.push_back(q);
        rep_.max_q4_error_px = std::max(rep_.max_q4_error_px, std::hypot(q.x / 16.0 - p.x, q.y / 16.0 - p.y));
    }
    out_.push_back(Stroke::make_curve(std::move(c)));
    ++rep_.strokes;
}

namespace {
struct Named { const char* name; Rgb8 c; };
constexpr Named kNames[] = {
    {"black", {0, 0, 0}}, {"white", {255, 255, 255}}, {"red", {255, 0, 0}}, {"lime", {0, 255, 0}},
    {"green", {0, 128, 0}}, {"blue", {0, 0, 255}}, {"yellow", {255, 255, 0}}, {"cyan", {0, 255, 255}},
    {"aqua", {0, 255, 255}}, {"magenta", {255, 0, 255}}, {"fuchsia", {255, 0, 255}}, {"gray", {128, 128, 128}},
    {"grey", {128, 128, 128}}, {"silver", {192, 192, 192}}, {"maroon", {128, 0, 0}}, {"olive", {128, 128, 0}},
    {"navy", {0, 0, 128}}, {"purple", {128, 0, 128}}, {"teal", {0, 128, 128}}, {"orange", {255, 165, 0}},
};
int hexval(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}
std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace((unsigned char)s.front())) s.remove_prefix(1);
    while (!s.empty() && std::isspace((unsigned char)s.back())) s.remove_suffix(1);
    return s;
}
}  // namespace

bool parse_number(std::string_view s, double& v) {
    if (!s.empty() && s[0] == '+') s.remove_prefix(1);
    if (s.empty()) return false;
    auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(v);
}

bool parse_color(std::string_view s, Rgb8& out, bool& is_none) {
    s = trim(s);
    is_none = false;
    if (s == "none" || s == "transparent") { is_none = true; return true; }
    if (!s.empty() && s[0] == '#') {
        std::string_view h = s.substr(1);
        for (char c : h) if (hexval(c) < 0) return false;
        if (h.size() == 3) { out = {uint8_t(hexval(h[0]) * 17), uint8_t(hexval(h[1]) * 17), uint8_t(hexval(h[2]) * 17)}; return true; }
        if (h.size() == 6) {
            out = {uint8_t(hexval(h[0]) * 16 + hexval(h[1])), uint8_t(hexval(h[2]) * 16 + hexval(h[3])), uint8_t(hexval(h[4]) * 16 + hexval(h[5]))};
            return true;
        }
        return false;
    }
    if (s.substr(0, 4) == "rgb(" && s.back() == ')') {
        std::string_view body = s.substr(4, s.size() - 5);
        double v[3];
        for (int i = 0; i < 3; ++i) {
            size_t comma = body.find(',');
            if ((i < 2) != (comma != std::string_view::npos)) return false;
            std::string_view part = trim(i < 2 ? body.substr(0, comma) : body);
            if (i < 2) body = body.substr(comma + 1);
            bool pct = !part.empty() && part.back() == '%';
            if (pct) part.remove_suffix(1);
            if (!parse_number(part, v[i])) return false;
            if (pct) v[i] *= 2.55;
        }
        out = {clamp_round<uint8_t>(v[0], 0, 255), clamp_round<uint8_t>(v[1], 0, 255), clamp_round<uint8_t>(v[2], 0, 255)};
        return true;
    }
    for (const auto& n : kNames)
        if (s == n.name) { out = n.c; return true; }
    return false;
}

}  // namespace spt::import
