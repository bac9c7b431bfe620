// A region's outline as polygons: the region's coverage estimated per pixel from the source's
// anti-aliased edge colours (a blend of the region's colour and its neighbour's), upsampled,
// cut at half coverage and simplified (Douglas-Peucker). Vertices land on a 1/upsample pixel
// lattice, which the polygon coding's shift makes cheap.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "cartoon/regions.hpp"
#include "spt/types.hpp"

namespace spt::cartoon {

struct TraceOptions {
    int upsample = 8;          // sub-pixel resolution of the outline (1/upsample pixel)
    double epsilon = 0.35;     // simplification tolerance, pixels
    int extend = 2;            // a region reaches this far under regions drawn after it
    // Under a later region that covers part of a pixel (a thin outline between this fill and
    // the ground), the fill takes the share of the rest that the source gives it, not all of it.
    bool beside_ink = true;
    // Where that outline covers nearly all of a pixel, the fill ends under its middle.
    bool under_ink_middle = true;
    double min_area = 1.0;     // outlines enclosing less than this (pixels) are dropped
    bool fit = true;           // sides refitted to the contour (fit_outline.hpp)
    int lattice = 2;           // vertices on a lattice of this many Q4 units (4: 1/4 pixel)
    // The contour is averaged over +-smooth pixels before it is simplified (0: not): a blurred
    // or noisy edge's sub-pixel contour zigzags, and each zigzag past the tolerance is a vertex.
    double smooth = 0;
};

// The polygons (colour and vertices; supersample 0) of region `index` of `regs`.
std::vector<PolygonStroke> trace_region(const cv::Mat& rgb, const Regions& regs, int index, const TraceOptions& opts);

}  // namespace spt::cartoon
