// A rendered canvas of any kind (SPEC.md 8: 8-bit sRGB or scene-linear half codes, with or
// without alpha) to an image file, as `spt render` writes it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/view_transform.hpp"
#include "spt/render.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::io {

struct CanvasImageOptions {
    // Flatten an alpha canvas over this sRGB colour (for every format). Without it, formats
    // with alpha keep it and the others (JPEG) flatten over the header's background.
    std::optional<Rgb8> background;
    // 8 or 16 bits a channel for integer formats (PNG, TIFF); EXR is always half float.
    int depth = 8;
    // A display/view for integer formats; null: the sRGB curve, values above 1 clipped.
    const ViewTransform* view = nullptr;
};

// Writes the canvas by extension:
// - EXR: half float, scene-linear, premultiplied RGBA (A = a / 255) on alpha canvases.
//   Encoding 1: the codes as they are (they are half floats). Encoding 0: the sRGB values
//   linearized (straight value p / a through OpenImageIO's "sRGB" -> "linear", times a / 255).
// - PNG, TIFF, ...: straight alpha. Encoding 0: unpremultiply8 (spt/display.hpp) for 8 bits,
//   floor(65535 p / a + 1/2) for 16. Encoding 1: the linear value (divided by a / 255)
//   through the view (default the sRGB curve), floor(v * 255 + 1/2) or floor(v * 65535 + 1/2).
// - Flattening (options.background, or a format without alpha): encoding 0 in 8-bit sRGB
//   values, (255 p + bg (255 - a) + 127) / 255, as the renderer composites; encoding 1 in
//   linear light, lin + lin(bg) (1 - a / 255), bg through the inverse sRGB curve (the header's
//   background: its codes).
// A plain canvas (encoding 0, no alpha) with no view and 8 bits is write_image's, as always.
// `note`, when given, receives a line for the user when the output had to drop the alpha.
Status write_canvas(const std::string& path, const Canvas& canvas, const Header& header,
                    const CanvasImageOptions& options = {}, std::string* note = nullptr);

// The 8-bit RGB image an output without alpha gets (JPEG, a preview video): the canvas
// flattened as write_canvas flattens (over options.background, else the header's), through
// the view (default: the sRGB curve for encoding 1; encoding 0 as it is). w * h * 3 bytes.
std::vector<uint8_t> canvas_rgb8(const Canvas& canvas, const Header& header, const CanvasImageOptions& options = {});

}  // namespace spt::io
