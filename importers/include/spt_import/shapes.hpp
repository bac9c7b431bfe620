// Geometry shared by the shape importers: 2-D affine transforms and the conversion of ellipses,
// rectangles, triangles and polygons into affine strokes of the analytic templates.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "spt/types.hpp"
#include "spt_import/document.hpp"

namespace spt::import {

// SVG's matrix(a b c d e f): x' = a x + c y + e, y' = b x + d y + f.
struct Mat2x3 {
    double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
    static Mat2x3 translate(double x, double y) { return {1, 0, 0, 1, x, y}; }
    static Mat2x3 scale(double x, double y) { return {x, 0, 0, y, 0, 0}; }
    static Mat2x3 rotate_deg(double deg);
    // this * o: apply o first, then this.
    Mat2x3 operator*(const Mat2x3& o) const;
    void apply(double x, double y, double& ox, double& oy) const { ox = a * x + c * y + e; oy = b * x + d * y + f; }
};

struct Point { double x = 0, y = 0; };

// Ids of the analytic templates within a document's template list (default: 0, 1, 2).
struct TemplateIds { uint8_t ellipse = 0, rectangle = 1, triangle = 2; };

// Appends strokes for shapes given in canvas pixel coordinates (after transforms). Positions
// are rounded to the Q4 grid; the report records the rounding error and any approximation.
// A shape that covers nothing (zero area, alpha 0) is dropped and counted.
class StrokeSink {
public:
    StrokeSink(std::vector<Stroke>& out, ImportReport& rep, TemplateIds ids = {}) : out_(out), rep_(rep), ids_(ids) {}
    // The unit template square [-1,1]^2 mapped by m (template point (u,v) -> m(u,v)).
    void affine(uint8_t tmpl, const Mat2x3& m, Rgba8 color);
    void ellipse(const Mat2x3& m, double cx, double cy, double rx, double ry, Rgba8 color);
    void rect(const Mat2x3& m, double x, double y, double w, double h, Rgba8 color);
    void triangle(Point p0, Point p1, Point p2, Rgba8 color);
    // Polygons: triangles exactly; parallelograms (rotated rectangles) exactly as one rectangle
    // stroke; others as one polygon stroke (format 1.2, nonzero fill), vertices rounded to Q4.
    void polygon(const std::vector<Point>& pts, Rgba8 color);
    // Supersampling grid of the polygon strokes (0 or 2..16, SPEC.md 8.2): as the analytic
    // templates', so that anti-aliased sources keep soft edges.
    void set_polygon_supersample(uint8_t n) { poly_aa_ = n; }
    // A polyline of constant width with round caps and joins (lines, Bezier curves).
    void polyline(const std::vector<Point>& pts, double width, Rgba8 color);
private:
    std::vector<Stroke>& out_;
    ImportReport& rep_;
    TemplateIds ids_;
    uint8_t poly_aa_ = 0;
};

// Rounds to Q4 (1/16 px), saturating to the spec's coordinate range.
int32_t to_q4(double px);

// Parses colours as SVG writes them: #rgb, #rrggbb, rgb(r,g,b), rgb(r%,g%,b%), a few names.
// Returns false for an unknown form; `none` sets is_none.
bool parse_color(std::string_view s, Rgb8& out, bool& is_none);

// Parses a decimal number the way SVG and JSON write them (locale-independent; a leading '+'
// is accepted). False unless the whole text is one finite number.
bool parse_number(std::string_view s, double& v);

}  // namespace spt::import
