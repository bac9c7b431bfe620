// Render output as a compositor has it (issue 17): scene-linear RGBA in float, read through
// OpenImageIO's colour management. What the painter paints from when the file it writes has an
// alpha canvas or colour encoding 1 (format 1.3); 8-bit sRGB paintings keep read_image().
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "spt/result.hpp"

namespace spt::io {

// Linear Rec.709 RGBA, premultiplied (associated) alpha as EXR stores it, width * height * 4,
// row-major, top row first. Finite and >= 0 everywhere: bad source values are replaced as the
// warnings say. Sources without alpha have alpha 1.
struct SceneImage {
    uint32_t width = 0, height = 0;
    std::vector<float> rgba;
    bool has_alpha = false;    // the source had an alpha channel, or a data window that leaves
                               // part of the display window empty (transparent there)
    bool is_float = false;     // the source held float (or half) data: HDR-capable render output
    std::string colorspace;    // the input colour space it was converted from, as the config names
                               // it ("linear" and "sRGB" in OpenImageIO's built-in config)
    // Each names the file: NaN set to 0, +inf set to the largest finite value (65504 if none),
    // -inf and negatives (also those a gamut conversion makes) set to 0, alpha clamped to 0..1,
    // data window notes. e.g. "shot.0001.exr: 12 NaN values set to 0"
    std::vector<std::string> warnings;
};

struct SceneReadOptions {
    // The input colour space (an OCIO / OpenImageIO name, e.g. "ACEScg", "sRGB", "lin_rec709").
    // Empty: linear Rec.709 for float files, sRGB for 8- and 16-bit files.
    std::string colorspace;
    // An OCIO config file; empty: $OCIO, else OpenImageIO's built-in config.
    std::string ocio_config;
    // EXR layer (channel name prefix, e.g. "ViewLayer.Combined"); empty: the unnamed R, G, B, A
    // channels, else the first layer that has R, G, B.
    std::string layer;
    uint32_t max_side = 32768;
    uint64_t max_pixels = 1ull << 28;
};

// Reads any image OpenImageIO reads into a SceneImage. The output has the display window's size
// (pixels outside the data window are transparent black). Straight alpha (PNG, TIFF) is
// converted to linear, then premultiplied; premultiplied colour (EXR) goes through matrices as
// it is and through curves unpremultiplied. Config, colour space and layer come from
// io/color_config.hpp and io/exr_layers.hpp. Errors name the file and what is wrong: missing,
// unreadable or truncated files, unknown colour spaces (listing known ones), a missing layer
// (listing the layers), sizes over the limits (checked before any pixel is allocated).
Result<SceneImage> read_scene_image(const std::string& path, const SceneReadOptions& opts = {});

}  // namespace spt::io
