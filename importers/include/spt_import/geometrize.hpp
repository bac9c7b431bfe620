// Emulation of geometrize's own rasteriser, so that imported geometrize shapes render as
// geometrize rendered them (measured against its PNGs in media/foreign: bit-exact pixel sets).
//
// geometrize does not rasterise exact geometry: its shapes are pixel spans (circles: the
// integer disc x^2 + y^2 <= r^2 around a pixel; rectangles: rows y1..y2-1; triangles, rotated
// rectangles and rotated ellipses (20-gons): polygons whose float vertices are truncated to
// pixel indices and outlined with Bresenham lines, each row filled from its leftmost to its
// rightmost outline pixel), clipped to the canvas minus its last row and column, which it never
// paints. The importer reproduces each span set with the one affine stroke whose point-sampled
// coverage differs from it in the fewest pixels (a local search over the Q4 map), then paints
// the last row and column back in the canvas colour.
#pragma once

#include <cstdint>
#include <vector>

#include "spt/render.hpp"
#include "spt/types.hpp"
#include "spt_import/document.hpp"

namespace spt::import::geometrize {

struct Span { int32_t y, x0, x1; };  // pixels x0..x1 (inclusive) of row y

// The pixels geometrize paints for shape `type` (1 rectangle, 2 rotated rectangle, 4 triangle,
// 8 ellipse, 16 rotated ellipse, 32 circle) with its JSON `data` on a w x h canvas.
std::vector<Span> spans(int type, const std::vector<double>& data, uint32_t w, uint32_t h);

// Pixel vertices (pixel indices, as geometrize truncates them) of the polygon it outlines for
// types 2, 4 and 16; empty for the others.
std::vector<std::pair<int32_t, int32_t>> polygon(int type, const std::vector<double>& data);

// Fits an affine stroke of template `tmpl` (of `r`'s template list) to the pixel set `target`
// on a w x h canvas, starting from `start`: coordinate descent over tx, ty, a, b, c, d in Q4
// steps. Only pixels geometrize can paint (x < w-1, y < h-1) count. Returns the number of
// pixels that still differ.
uint64_t fit(const Renderer& r, const std::vector<Span>& target, uint32_t w, uint32_t h, AffineStroke& s);

// A polygon given by its float vertices (x0, y0, x1, y1, ...), as geometrize's SVG writes
// rotated rectangles: truncated and outlined like the shapes it computes itself.
constexpr int kExplicitPolygon = 1024;
std::vector<std::pair<int32_t, int32_t>> explicit_polygon(const std::vector<double>& xy);

// Appends the affine stroke closest to geometrize's pixels of shape (type, data) (types 1, 2,
// 4, 8, 16, 32 or kExplicitPolygon) with `colour`; counts it in `rep` and adds the pixels that
// still differ to `differing`. Shapes that paint nothing are dropped.
void append_shape(const Renderer& r, int type, const std::vector<double>& data, Rgba8 colour, uint32_t w, uint32_t h,
                  std::vector<Stroke>& out, ImportReport& rep, uint64_t& differing);

}  // namespace spt::import::geometrize
