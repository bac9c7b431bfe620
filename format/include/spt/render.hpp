// Reference renderer: strokes to an RGB8 canvas, bit-exactly as SPEC.md "Rendering" defines.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt {

// A rendered frame. Which planes it has follows the header (SPEC.md 8): colour encoding 0 has
// `rgb`, encoding 1 `rgb16`; an alpha canvas also has `alpha`, and its colour planes are then
// premultiplied by it. Rows are top row first, pixels interleaved R, G, B.
struct Canvas {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgb;     // encoding 0: width * height * 3 sRGB-encoded values
    std::vector<uint16_t> rgb16;  // encoding 1: width * height * 3 half-float codes, scene-linear
    std::vector<uint8_t> alpha;   // alpha canvases: width * height, 0 transparent .. 255 opaque
    Canvas() = default;
    Canvas(uint32_t w, uint32_t h, Rgb8 fill = {255, 255, 255});
    // A canvas with the planes `h` defines, holding its starting canvas.
    explicit Canvas(const Header& h) { reset(h); }
    void fill(Rgb8 c);
    // Sizes the planes for `h` and clears them to its starting canvas: the background, or fully
    // transparent (all 0) on an alpha canvas. Planes the header does not use are emptied.
    void reset(const Header& h);
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

// The rendering work of a polygon stroke that Limits::max_polygon_work bounds (SPEC.md 10):
// its non-horizontal edges x the canvas rows its box covers x its samples per pixel (N² for
// an N x N grid, else 1). Readers reject a polygon above the limit; tools that make
// polygons can check before they render one.
uint64_t polygon_render_work(const PolygonStroke& p, uint32_t canvas_height);
// The rendering work of a curve stroke that Limits::max_curve_work bounds (SPEC.md 10): the
// canvas pixels of each segment's evaluation box (8.5), summed over its segments.
uint64_t curve_render_work(const CurveStroke& c, uint32_t canvas_width, uint32_t canvas_height);
// The rendering work of a stamp or affine stroke that Limits::max_fill_work bounds (SPEC.md
// 10): the canvas pixels of its evaluation box times its template's samples per pixel (N² for
// an analytic template with an N x N grid, else 1); 0 for other kinds or a missing template.
uint64_t fill_render_work(const Stroke& s, const Header& header, const std::vector<Template>& templates);

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
    // centre pixel. The Mask lives as long as the Renderer.
    virtual const Mask& stamp_footprint(uint8_t set, uint8_t tmpl, uint8_t orient) const = 0;

    // Bytes the Renderer holds for stamp footprints now (it keeps them between calls, within a
    // fixed budget; stamps over the budget are drawn without one, to the same pixels).
    virtual size_t footprint_cache_bytes() const = 0;
    // The pixel on whose centre a stamp with Q4 position (x, y) is rendered: the one holding it.
    static int32_t stamp_pixel(int32_t q4) { return q4 >> 4; }  // pixel containing q4

    // Composites one stroke onto the canvas.
    virtual Status draw(Canvas& canvas, const Stroke& s) const = 0;
    // Clears to the background and draws every stroke in order. Gives exactly the bytes of
    // canvas.fill(background) followed by draw() of every stroke, faster: strokes are binned
    // into 128 x 64 tiles rendered one at a time in cache. On an invalid stroke, the strokes
    // before it are drawn and the error names its index.
    virtual Status render(Canvas& canvas, const std::vector<Stroke>& strokes) const = 0;
    // The same with `threads` threads rendering tiles in parallel (0: one per hardware
    // thread). Identical bytes for every thread count.
    virtual Status render(Canvas& canvas, const std::vector<Stroke>& strokes, unsigned threads) const = 0;
};

}  // namespace spt
