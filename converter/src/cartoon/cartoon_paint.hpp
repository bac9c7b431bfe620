// `spt paint --style cartoon` for one picture: the fill layer (flat regions as anti-aliased
// polygons, fill_layer.hpp), then the stamp painter on what the polygons left wrong
// (gradients, texture), painting only where the error is.
#pragma once

#include <cstdint>
#include <vector>

#include "cartoon/fill_layer.hpp"
#include "paint/painter.hpp"
#include "spt/render.hpp"
#include "spt/types.hpp"

namespace spt::cartoon {

// How much more than the stamp painter's own the residual stamps of a cartoon must pay for
// themselves (paint::PaintOptions::lambda times this) when painted to a PSNR target (without
// one, lambda alone decides where painting stops, and it is left alone). A picture starts close
// to its target after its polygons (and an inter frame's kept strokes), and the painter, drawing
// candidates coarse to fine, would otherwise accept the first strokes that help a little, where
// fewer that help a lot reach the target too; short of it, the painter halves lambda (to 1/64)
// as always. Measured for sequences in inter_frame.cpp and cartoon_sequence.cpp, for stills in
// cartoon_paint.cpp.
constexpr double kResidualLambdaScale = 16;

struct CartoonStats {
    size_t colors = 0, regions = 0, polygons = 0, vertices = 0;
    size_t lines = 0, line_points = 0;  // thin regions drawn as curves
    uint8_t grid = 0;
    double fill_psnr = 0;        // after the polygons
    paint::PaintStats stamps;    // the residual painting (stamps.psnr: the final PSNR)
    // How the stamps were drawn (frame coding 2 codes them as replayed candidates after the
    // polygons and lines, SPEC.md 7.7.5); not present without stamps.
    ReplayInfo replay;
};

// Paints `model` onto `canvas` (the background): appends the polygons then the stamps to
// `out` and draws them, exactly as `renderer` renders them. `po` drives the residual stamp
// painter (its target PSNR, lambda, seed, threads); with a target the fill layer already
// reaches, no stamp is painted.
CartoonStats paint_cartoon(const paint::ImageView& model, Canvas& canvas, const Renderer& renderer,
                           const paint::PaintSetup& setup, const paint::PaintOptions& po, const FillOptions& fo,
                           std::vector<Stroke>& out);

// The fill layer of `rgb` drawn on `canvas` (cleared first), `psnr` its PSNR. With a target
// and FillOptions::search_tolerance, the coarsest of 1.0, 0.7, 0.5 px outlines that reaches
// the target, else the options' tolerance.
FillLayer fill_for_target(const cv::Mat& rgb, Rgb8 background, const Renderer& renderer, const FillOptions& fo,
                          double target_psnr, const std::vector<cv::Vec3b>* palette, Canvas& canvas, double& psnr);

// Where the residual painter may paint: pixels whose error (sum over channels) exceeds
// `threshold`, widened by `grow` pixels. Empty when no pixel does.
std::vector<uint8_t> residual_region(const paint::ImageView& model, const Canvas& canvas, int threshold, int grow);

}  // namespace spt::cartoon
