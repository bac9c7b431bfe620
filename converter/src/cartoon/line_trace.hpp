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
    // A thin region becomes lines when their error (drawn over the fill layer so far, on what
    // later regions leave visible) is at most this times its polygons' and they cost fewer bytes.
    // Butterfly, 12 frames at 36 dB (--no-lines 63,333 B): 1.02 60,139 B, 1.5 57,598 B, 2.0
    // 57,512 B; its frame 40 alone (27,055 B): 1.02 26,336, 1.5 26,016, 2.0 26,053, 3.0 26,377.
    double max_error_ratio = 1.5;
    // The same in a sequence's inter frames for a region the previous frame did not draw as
    // lines: there a new line must be as close as the outline, because grain or compression
    // moves a measured line from frame to frame and a moved line is added again with the stamps
    // around it (the grain test: 217 stamps added at 1.5, within its bound at 1.02). A region
    // that was lines keeps max_error_ratio, so that it can stay what the previous frame drew.
    double max_error_ratio_inter = 1.02;
};

// One branch of a region's skeleton: pixel centres and the region's distance to its edge there.
struct Centreline {
    std::vector<cv::Point> pts;
    std::vector<double> radius;  // pixels (distance transform, centre to the nearest outside centre)
    bool free_end[2] = {false, false};  // first, last point: an end of the line, not a junction
    // fit_to_source: per pixel of the branch, where the line's middle is (pixel coordinates,
    // centres at +0.5) and how wide it is.
    std::vector<cv::Point2d> centre;
    std::vector<double> width;
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

// False when region `index` is surely too wide for lines, without thinning it (thinning a fill
// costs its radius in passes over its box: a third of the butterfly's painting time). Its
// skeleton runs between its sides, so it is shorter than twice its edge pixels (those with a
// 4-neighbour outside): the mean width is at least pixels / (2 * edge pixels).
bool may_be_line(const Regions& regs, int index, const LineOptions& opts);

bool is_line(const LineShape& shape, const LineOptions& opts);

// Each branch's middle and width: from the skeleton (pixel centres averaged along it, the
// distance transform's 2 r - 1), then measured on `rgb` across the line where the ink `ink`
// stands out from both sides (the coverage's sum and mean position along the normal).
void fit_to_source(LineShape& shape, const cv::Mat& rgb, cv::Vec3b ink, bool measure = true);

// The fitted branches as curves in `color`, simplified, each width plus `widen` pixels (the
// caller tries a few and keeps the closest), on supersampling grid `grid`.
std::vector<CurveStroke> line_curves(const LineShape& shape, Rgba8 color, double widen, uint8_t grid,
                                     const LineOptions& opts);

}  // namespace spt::cartoon
