// The fill layer of a cartoon painting: every flat region as a filled polygon, larger
// outlines first, all on the supersampling grid that best reproduces the source's edges.
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "cartoon/line_trace.hpp"
#include "cartoon/palette.hpp"
#include "cartoon/trace.hpp"
#include "spt/render.hpp"
#include "spt/types.hpp"

namespace spt::cartoon {

// The smallest regions trial paintings short of their target keep (FillOptions::min_region_pixels;
// smaller ones join their neighbours), beside the default 3; the smallest file wins. Compressed
// video's noise and ringing break its colours into many small regions, each a polygon of its own,
// where the residual stamps cost less; text's small regions are parts of its letters, and the
// stamps that replace them cost more. Bytes at 36 dB with 1 / 3 / 6 / 12 / 24 (every frame):
// butterfly frame 40 19,910 / 17,316 / 14,904 / 13,330 / 12,791, its 12 frames - / 37,613 /
// 34,464 / 31,764 / 36,916; taffy frame 30 20,347 / 21,283 / 21,450 / 21,616 / 24,826, its 12
// frames 201,155 / 207,271 / - / 216,189; the star within 0.5%.
constexpr int kMinRegionTrials[] = {1, 12};

struct FillOptions {
    PaletteOptions palette;
    TraceOptions trace;
    // Still pictures with a PSNR target: try coarser outlines first (cartoon_paint.hpp).
    bool search_tolerance = true;
    int min_region_pixels = 3;          // smaller components join their neighbours
    // Short of a PSNR target, a still and a sequence's key frame also try kMinRegionTrials.
    bool search_min_region = true;
    // ... and kSparsePaletteShares (palette.hpp) while they leave colours out and win.
    bool search_palette = true;
    std::vector<uint8_t> grids{4, 8};   // supersampling grids tried; the least error wins
    // Bound on the polygons' rendering work (SPEC.md 10), well inside the readers' 2^28.
    uint64_t max_work = uint64_t(1) << 26;
    // Thin regions become curves along their centreline where those are as close to the source
    // and smaller (format 1.4: the file needs the curve_grid flag).
    bool lines = true;
    LineOptions line;
    // Threads judging line candidates (1: the caller's only); the layer does not depend on it.
    int threads = 1;
};

struct FillLayer {
    std::vector<Stroke> strokes;        // polygons and lines (curves), drawing order
    std::vector<int> region;            // per stroke, the region it draws (ascending: drawing order)
    uint8_t grid = 0;                   // the supersampling grid chosen (polygons and curves)
    size_t lines = 0;                   // regions drawn as curves
    size_t colors = 0, regions = 0;
    std::vector<cv::Vec3b> palette;     // the flat colours used
    double tolerance = 0;               // the outline tolerance (fill_for_target)
    double smooth = 0;                  // the contour smoothing it was traced with (TraceOptions)
    int min_region = 0;                 // FillOptions::min_region_pixels it was traced with
};

// Traces `rgb` (CV_8UC3 RGB). Regions of the background colour drawn first are left to the
// canvas. `renderer` renders candidate grids to compare them with the source. With `palette`
// (a sequence's key frame palette) the colours are not searched again, so that what stays
// still traces to the same polygons frame after frame. With `previous` (the live list an inter
// frame follows) a region the previous frame drew as lines stays lines on the key frame's
// terms (LineOptions::max_error_ratio_inter).
FillLayer build_fill_layer(const cv::Mat& rgb, Rgb8 background, const Renderer& renderer, const FillOptions& opts,
                           const std::vector<cv::Vec3b>* palette = nullptr,
                           const std::vector<Stroke>* previous = nullptr);

}  // namespace spt::cartoon
