// A thin region as drawn lines: curve strokes along its centreline (format 1.4 curves with a
// grid, SPEC.md 8.5), each point's width from the region's distance to its edge. A cartoon's
// ink lines are what curves describe: one centreline and a width cost about half the vertices
// of the two sides of a polygon outline, and they import into Grease Pencil as line strokes an
// animator can edit.
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "cartoon/regions.hpp"
#include "spt/types.hpp"

namespace spt::cartoon {

struct LineOptions {
    double max_mean_width = 5.0;  // pixels: wider regions are fills, not lines
    double min_length = 6.0;      // pixels of centreline: shorter ones stay polygons
    double epsilon = 0.75;        // centreline simplification, pixels (a skeleton's staircase is 0.5)
    double width_epsilon = 1.0;   // a width kept within this many pixels of the skeleton's
};

// One branch of a region's skeleton: pixel centres and the region's distance to its edge there.
struct Centreline {
    std::vector<cv::Point> pts;
    std::vector<double> radius;  // pixels (distance transform, centre to the nearest outside centre)
};

struct LineShape {
    std::vector<Centreline> paths;
    double length = 0;           // pixels of centreline
    int64_t pixels = 0;          // of the region
    // Mean width: the region's pixels over its centreline's length.
    double mean_width() const { return length > 0 ? double(pixels) / length : 1e9; }
};

// The skeleton of region `index` (Zhang-Suen thinning) split into branches at its ends and
// junctions.
LineShape centrelines(const Regions& regs, int index);

bool is_line(const LineShape& shape, const LineOptions& opts);

// The branches as curves in `color`, simplified, each width the skeleton's (2 r - 1) plus
// `widen` pixels (the caller tries a few and keeps the closest), on supersampling grid `grid`.
std::vector<CurveStroke> line_curves(const LineShape& shape, Rgba8 color, double widen, uint8_t grid,
                                     const LineOptions& opts);

}  // namespace spt::cartoon
