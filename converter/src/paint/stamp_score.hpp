// Scoring one stamp candidate against the canvas: its least-squares colour and the exact change
// of the squared error it would cause, using the renderer's footprint and blend8, so the score
// is what a decoder would show.
#pragma once

#include <cstdint>
#include <vector>

#include "spt/render.hpp"

namespace spt::paint {

struct Plane {
    uint32_t width = 0, height = 0;
    const uint8_t* model = nullptr;  // RGB8 (premultiplied when the planes below are set)
    uint8_t* canvas = nullptr;       // RGB8, same size
    // Alpha canvases (format 1.3): the model's and the canvas's alpha planes (width * height),
    // both set or both null. The alpha channel is then a fourth channel of the error, of the
    // same weight as a colour channel, and composites as the renderer does: blend8(A, 255, a).
    const uint8_t* model_a = nullptr;
    uint8_t* canvas_a = nullptr;
    int32_t alpha_weight = 1;  // of the alpha channel's squared error (PaintOptions::alpha_weight)
    bool has_alpha() const { return canvas_a != nullptr; }
};

// The clipped pixel rectangle of a footprint centred on (px, py): mask columns [i0, i1) and rows
// [j0, j1). Empty when the footprint misses the canvas.
struct Clip {
    int32_t i0 = 0, i1 = 0, j0 = 0, j1 = 0;
    bool empty() const { return i0 >= i1 || j0 >= j1; }
};
Clip clip_footprint(const Mask& fp, int32_t px, int32_t py, uint32_t width, uint32_t height);

// Per-row extent of a footprint's non-zero coverage: rotated shapes leave much of their box
// empty, and skipping it is most of the scoring speed.
struct Spans {
    std::vector<int32_t> lo, hi;  // row j covers mask columns [lo[j], hi[j]); lo >= hi: empty row
};
Spans footprint_spans(const Mask& fp);

// Partial sums of the first scoring pass over some rows (they add up exactly, in any grouping).
struct ColourSums {
    int64_t saa = 0, num[3] = {0, 0, 0}, old_err = 0;
    int64_t sa = 0, sac[3] = {0, 0, 0};  // coverage and coverage-weighted canvas: its mean
    void add(const ColourSums& o) {
        saa += o.saa; old_err += o.old_err; sa += o.sa;
        for (int c = 0; c < 3; ++c) { num[c] += o.num[c]; sac[c] += o.sac[c]; }
    }
};
ColourSums colour_sums(const Plane& p, const Mask& fp, const Spans& sp, int32_t px, int32_t py,
                       int32_t j0, int32_t j1);
// The least-squares colour from the sums; false when nothing is covered. With `step` > 1 the
// colour is the nearest point of coding 2's colour lattice around the canvas mean under the
// footprint (SPEC.md 7.7.5): G = P.g + step*k, R = clamp(G + P.r - P.g) + step*k', B likewise.
bool best_colour(const ColourSums& s, Rgb8& out, int step = 1);
// The squared error under the footprint rows [j0, j1) after compositing `col` (with alpha
// planes: the alpha channel's error too).
int64_t new_error(const Plane& p, const Mask& fp, const Spans& sp, int32_t px, int32_t py,
                  int32_t j0, int32_t j1, Rgb8 col);

struct StampScore {
    bool valid = false;     // false: no covered pixel on the canvas
    Rgb8 color;
    int64_t delta = 0;      // new squared error - old, summed over the covered pixels and RGB (A)
};

// The colour c minimising sum_i (C_i + w_i (c - C_i) - M_i)^2 with w_i = a_i / 255 (canvas C,
// model M, coverage a): c = sum a (255 M - (255 - a) C) / sum a^2, per channel, rounded and
// clamped. Where coverage is full it is the mean of the model under the stroke; where it is
// partial the canvas showing through is accounted for. Then the exact error change with blend8.
StampScore score_stamp(const Plane& p, const Mask& fp, int32_t px, int32_t py, int step = 1);
StampScore score_stamp(const Plane& p, const Mask& fp, const Spans& sp, int32_t px, int32_t py, int step = 1);

// Composites the stamp exactly as Renderer::draw does for an opaque stamp: blend8 per channel,
// and blend8(A, 255, a) on an alpha plane.
void commit_stamp(const Plane& p, const Mask& fp, int32_t px, int32_t py, Rgb8 color);

}  // namespace spt::paint
