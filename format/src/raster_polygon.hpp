// Internal to libspt: the exact integer rasterisation of polygon strokes (SPEC.md 8.8).
// Sample points and vertices are compared in 1/256 pixel; a sample is inside when the nonzero
// winding number of the polygon around it, counted with the half-open edge rule of the spec,
// is not zero. Cost per pixel row: the edges that cross it, sorted, plus the row's pixels,
// times N^2 for an N x N supersampled polygon.
#pragma once

#include <cstdint>
#include <vector>

#include "spt/types.hpp"

namespace spt::raster {

// Inclusive pixel box outside which a polygon has no coverage (SPEC 8.8): the pixels holding
// the vertices' bounding box. Empty (x1 < x0) for a polygon without vertices.
void polygon_box(const PolygonStroke& s, int64_t& x0, int64_t& y0, int64_t& x1, int64_t& y1);

// Rasterises one polygon row by row. Construction prepares the edges once (O(n log n));
// row() then costs O(active edges x log + columns) per sample row.
class PolygonRaster {
public:
    explicit PolygonRaster(const PolygonStroke& s);
    // Coverage 0..255 of pixels [x0, x1] of row y into out[0 .. x1 - x0].
    void row(int64_t y, int64_t x0, int64_t x1, uint8_t* out);

private:
    struct Edge {
        int64_t xa, ya, xb, yb;  // 1/256 pixel; ya < yb
        int dir;                 // +1 when the polygon runs down this edge, -1 up
    };
    struct Crossing {
        int64_t x;  // first sample abscissa (1/256 px) at which the edge counts
        int dir;
    };
    void sample_row(int64_t Y, int64_t x0, int64_t w);

    std::vector<Edge> edges_;     // sorted by ya
    std::vector<Edge> active_;
    size_t next_ = 0;             // first edge of edges_ not yet activated
    int64_t last_Y_ = INT64_MIN;  // sample rows must come in increasing order
    uint32_t n_ = 1;              // samples per axis
    int64_t o_[16] = {};          // sample offsets within a pixel, 1/256 px
    std::vector<Crossing> cross_;
    std::vector<uint16_t> count_;
};

// Coverage of a polygon over the pixel box [x0, x1] x [y0, y1], row-major into `out`.
void rasterize_polygon(const PolygonStroke& s, int64_t x0, int64_t y0, int64_t x1, int64_t y1, uint8_t* out);

}  // namespace spt::raster
