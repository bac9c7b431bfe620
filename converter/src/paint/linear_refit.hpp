// The colour refit of a scene-linear painting (README.md "Linear HDR"): the painter places its
// strokes on the 8-bit proxy (linear_proxy.hpp); this pass replays them in order on an exact
// linear canvas (colour encoding 1) and gives each the least-squares linear colour against the
// linear model, given the linear canvas under it, as a half code. The result renders exactly,
// in any decoder, to a close linear approximation with smooth darks (no 8-bit steps).
#pragma once

#include <cstdint>
#include <vector>

#include "paint/linear_proxy.hpp"
#include "spt/render.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::paint {

struct RefitOptions {
    // Mantissa bits kept of each half code (1..10): the codes lie on a coarser lattice of the
    // same range, nearest in linear value. 10 = every half. 7 (steps of 0.8%, below the ~1%
    // a gradient shows) saves 4-6% of the bytes at the same error (README.md "Linear HDR").
    int mantissa_bits = 7;
    // Weighted least squares, weight 1 / (1 + m)^2 per pixel (m its largest model channel):
    // absolute error below 1, relative error above, so highlights do not pull the colour of a
    // stroke that also covers darker pixels (measured, README.md "Linear HDR": on orbit the
    // error in stops falls by a quarter and the sRGB view gains 4 dB). false: plain linear.
    bool highlight_weight = true;
};

struct RefitStats {
    uint64_t refit = 0;      // strokes given their least-squares colour
    uint64_t converted = 0;  // strokes covering no canvas pixel: their proxy colour, converted
};

// The half code of a straight linear value on the lattice of `mantissa_bits`.
uint16_t linear_code(double value, int mantissa_bits = 10);

// Proxy colour (8-bit, in the proxy's encoding) to the colour-encoding-1 colour it stands for.
Rgba8 proxy_to_linear(const Rgba8& proxy, const ProxyTransform& t, int mantissa_bits = 10);

// Sets a linear header's background codes from an 8-bit sRGB background.
void set_linear_background(Header& h, Rgb8 srgb);
// The proxy's 8-bit background for an 8-bit sRGB background.
Rgb8 proxy_background(Rgb8 srgb, const ProxyTransform& t);

// `strokes` hold proxy colours; on return they hold linear half codes, drawn in order onto
// `canvas` (a Canvas(header) of the linear `header`, holding what is below them) by `renderer`
// (created for `header`). Sequential, so the result does not depend on any thread count.
Status refit_linear(const LinearView& model, const ProxyTransform& t, const Header& header,
                    const Renderer& renderer, Canvas& canvas, std::vector<Stroke>& strokes,
                    const RefitOptions& opts = {}, RefitStats* stats = nullptr);

// What the refit minimises: the sum over pixels and R, G, B of the squared difference between
// a colour-encoding-1 canvas and the linear model, weighted as RefitOptions::highlight_weight.
double refit_error(const LinearView& model, const Canvas& canvas, bool highlight_weight);

// Sum over pixels and R, G, B of the squared difference between a colour-encoding-1 canvas and
// the premultiplied linear model (and over A of alpha/255 - A when the canvas has alpha).
double linear_sse(const LinearView& model, const Canvas& canvas);

}  // namespace spt::paint
