// Showing a rendered canvas on a screen: straight (unassociated) 8-bit sRGB RGBA for viewers
// and image writers, from any canvas kind (SPEC.md 8). Not part of the bit-exact decoding:
// the canvas is the decoder's output; this is one documented view of it.
#pragma once

#include <cstdint>
#include <vector>

#include "spt/render.hpp"
#include "spt/types.hpp"

namespace spt {

// The sRGB transfer curve (IEC 61966-2-1, piecewise) and its inverse, on [0, 1]; inputs
// outside [0, 1] (and NaN) are clipped first.
float srgb_encode(float linear);
float srgb_decode(float encoded);

// An 8-bit value of [0, 1]: floor(v * 255 + 0.5), clipped.
uint8_t unit_to_u8(float v);

// The straight colour of one premultiplied 8-bit channel `c` under alpha `a`:
// min(255, (c * 255 + a / 2) / a) in integers, 0 when a is 0.
inline uint8_t unpremultiply8(uint32_t c, uint32_t a) {
    if (a == 0) return 0;
    const uint32_t v = (c * 255u + a / 2u) / a;
    return uint8_t(v > 255u ? 255u : v);
}

// The canvas as straight sRGB RGBA, 8 bits a channel, w * h * 4 bytes, rows top first:
// - encoding 0: the values as they are; on alpha canvases unpremultiplied (unpremultiply8);
// - encoding 1 (scene-linear): the linear value, divided by alpha on alpha canvases, through
//   the sRGB curve (no tone mapping: values above 1 clip), then unit_to_u8.
// Canvases without alpha give a = 255. Pixels with alpha 0 are 0, 0, 0, 0.
void to_rgba8(const Canvas& canvas, const Header& header, std::vector<uint8_t>& rgba);

// The linear value (Rec.709 light, 1.0 = the sRGB white) of channel `ch` of the header's
// background: the 16-bit code in encoding 1, the sRGB curve's inverse of the 8-bit value in
// encoding 0.
float background_linear(const Header& header, int ch);

}  // namespace spt
