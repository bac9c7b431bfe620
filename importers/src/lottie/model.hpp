// The Lottie importer's shared pieces: the parse context (limits, warnings named once), the
// evaluation of keyframed properties, Bezier paths and their flattening, and the conversion of
// filled and stroked outlines to spt strokes. One idea a file: props.cpp (keyframes, easing),
// paths.cpp (shapes to Bezier paths, flattening, trim), outline.cpp (fills and strokes to
// polygons and curves), layers.cpp (layers, transforms, parenting, precomps).
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "spt/result.hpp"
#include "spt/types.hpp"
#include "spt_import/document.hpp"
#include "spt_import/shapes.hpp"
#include "spt_json/json.hpp"

namespace spt::import::lottie {

using json::Value;

// Bounds of one import (hostile input is refused with a message naming the file).
struct Bounds {
    uint32_t max_precomp_depth = 16;       // nested precomposition layers
    size_t max_keyframes = 1u << 16;       // keyframes of one property
    size_t max_path_vertices = 1u << 16;   // Bezier vertices of one path, and flattened points of one outline
    uint64_t max_total_points = 1ull << 27;  // flattened points summed over every frame (evaluation work)
    uint32_t max_frames = 1u << 16;
};

// What the import cannot keep, each named once (ImportReport::note adds once).
struct Ctx {
    std::string file;
    Bounds bounds;
    ImportReport* report = nullptr;
    std::string error;  // set by the first failure; evaluation stops
    uint64_t points_done = 0;
    double tolerance = 1.0 / 64;  // flattening tolerance in canvas pixels (see README)
    uint8_t grid = 8;             // supersampling grid of polygons and curves
    void warn(const std::string& what) { report->note("warning: " + what); }
    bool fail(const std::string& what) { if (error.empty()) error = file + ": " + what; return false; }
    bool ok() const { return error.empty(); }
};

// ---- props.cpp: keyframed values -------------------------------------------------------------

// A property's value at frame t: the static value, or the keyframes interpolated with their
// easing (cubic Bezier time curves per dimension, hold keyframes) and, for positions, their
// spatial tangents (arc-length parametrised as lottie-web does). Missing: `def`.
std::vector<double> prop(Ctx& c, const Value* p, double t, std::vector<double> def);
double prop1(Ctx& c, const Value* p, double t, double def);
// Warns (once per file) about expressions, which are not evaluated: the keyframes are used.
void check_expression(Ctx& c, const Value* p);

// ---- paths.cpp: Bezier paths ------------------------------------------------------------------

struct Vec { double x = 0, y = 0; };
struct BezPath {  // vertices with in/out tangents relative to the vertex, as Lottie stores them
    std::vector<Vec> v, i, o;
    bool closed = false;
};
// A shape item (sh, rc, el, sr) at frame t as Bezier paths in its own coordinates; false on error.
bool shape_paths(Ctx& c, const Value& item, double t, std::vector<BezPath>& out);
// Interpolated shape value ({"i","o","v","c"}) of a path property.
bool shape_value(Ctx& c, const Value* ks, double t, BezPath& out);
// Flattens a path mapped by m into canvas points within the tolerance.
bool flatten(Ctx& c, const BezPath& p, const Mat2x3& m, std::vector<Point>& out);
struct Poly { std::vector<Point> pts; bool closed = false; };
// Trim paths (start, end in 0..1, offset in turns) applied to flattened polylines, either over
// their joined length ("simultaneously" = false) or each one alone.
void trim(std::vector<Poly>& polys, double start, double end, double offset, bool individually);
// Dashes: the pattern's lengths (dash, gap, dash, gap ...) laid along each polyline from
// `offset` into the pattern, in canvas pixels. False (nothing changed) when that would make
// more than `max_dashes` dashes.
bool dash(std::vector<Poly>& polys, const std::vector<double>& pattern, double offset, size_t max_dashes);

// ---- outline.cpp: fills and strokes ------------------------------------------------------------

struct StrokeStyle { double width = 1; int cap = 2, join = 2; double miter = 4; };
// One filled polygon of every contour (nonzero rule; contours joined by bridges that cancel).
void fill_polys(Ctx& c, const std::vector<Poly>& polys, Rgba8 colour, std::vector<Stroke>& out);
// The outline of stroked polylines: curves for round caps and joins, else a polygon of the
// segments' quads, joins and caps, all wound the same way (their union under nonzero).
void stroke_polys(Ctx& c, const std::vector<Poly>& polys, const StrokeStyle& st, Rgba8 colour, std::vector<Stroke>& out);

// ---- layers.cpp: the composition ----------------------------------------------------------------

struct Comp {
    const Value* root = nullptr;
    std::map<std::string, const Value*> assets;  // precomp id -> its layers array
    double fr = 30;
};
// The strokes of the whole composition at frame t, bottom layer first.
bool render_comp(Ctx& c, const Comp& comp, double t, std::vector<Stroke>& out);

// Colour from Lottie's 0..1 (or 0..255 in old files) channels and an opacity 0..1.
Rgba8 colour(const std::vector<double>& rgb, double opacity);

}  // namespace spt::import::lottie
