// Reference renderer: strokes to an RGB8 canvas, bit-exactly as SPEC.md "Rendering" defines.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt {

struct Canvas {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgb;  // width * height * 3, row-major, top row first
    Canvas() = default;
    Canvas(uint32_t w, uint32_t h, Rgb8 fill = {255, 255, 255});
    void fill(Rgb8 c);
    uint8_t* row(uint32_t y) { return rgb.data() + size_t(y) * width * 3; }
    const uint8_t* row(uint32_t y) const { return rgb.data() + size_t(y) * width * 3; }
};

// A coverage mask in canvas pixel coordinates: alpha for pixel (x0 + i, y0 + j) is
// a[j * w + i] (0..255). Pixels outside the rectangle have coverage 0. The rectangle may
// extend past the canvas; draw() clips.
struct Mask {
    int32_t x0 = 0, y0 = 0;
    uint32_t w = 0, h = 0;
    std::vector<uint8_t> a;
};

// The exact compositing rule: dst' = (dst * (255 - alpha) + src * alpha + 127) / 255.
inline uint8_t blend8(uint8_t dst, uint8_t src, uint32_t alpha) {
    return uint8_t((uint32_t(dst) * (255u - alpha) + uint32_t(src) * alpha + 127u) / 255u);
}

class Renderer {
public:
    // Validates the header and templates; caches stamp footprints lazily.
    static Result<std::unique_ptr<Renderer>> create(const Header& header,
                                                    const std::vector<Template>& templates);
    virtual ~Renderer();

    // The coverage of one stroke (template coverage times the colour's alpha), exactly as
    // the spec defines it, clipped to nothing: callers clip.
    virtual Status stroke_mask(const Stroke& s, Mask& out) const = 0;
    // The footprint of a stamp stroke centred on pixel (0, 0): x0, y0 are offsets from the
    // centre pixel. Cached; the reference stays valid for the Renderer's lifetime.
    virtual const Mask& stamp_footprint(uint8_t set, uint8_t tmpl, uint8_t orient) const = 0;
    // The pixel on whose centre a stamp with Q4 position (x, y) is rendered: the one holding it.
    static int32_t stamp_pixel(int32_t q4) { return q4 >> 4; }  // pixel containing q4

    // Composites one stroke onto the canvas.
    virtual Status draw(Canvas& canvas, const Stroke& s) const = 0;
    // Clears to the background and draws every stroke in order.
    virtual Status render(Canvas& canvas, const std::vector<Stroke>& strokes) const = 0;
};

}  // namespace spt
