// `spt paint` of a still into an alpha canvas and/or colour encoding 1 (format 1.3, issue 17):
// which target the options and the input ask for, and the paint itself (paint/scene_paint.hpp).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/paint_options.hpp"
#include "frames/scene_image.hpp"
#include "paint/scene_paint.hpp"

namespace spt::cli {

// --color-encoding auto|srgb8|linear and --alpha auto|on|off against the input: auto paints
// linear for float input and with alpha when the input has alpha. Empty (std::nullopt) for a
// plain painting (sRGB8 without alpha), which keeps the 8-bit read_image path and its bytes.
// `img` receives the scene image when one was read (it is what the painting paints).
// Fails on an unknown option value or an unreadable input the options require.
Result<std::optional<paint::SceneTarget>> scene_target(const PaintCommandOptions& o, std::optional<io::SceneImage>& img);
// (With --colorspace or --layer, `img` is also set when the painting is 8-bit sRGB without
// alpha: the plain painter then paints source_view(img) instead of reading the file itself.)
// A scene image as 8-bit sRGB, flattened over `bg` (the plain painter's model).
std::vector<uint8_t> source_view(const io::SceneImage& img, Rgb8 bg);

// The options spelt for the painter.options metadata of a format 1.3 painting.
std::string scene_options_text(const paint::SceneTarget& t);

// Paints `img` to o.output with `target`. Returns the exit code.
int paint_scene_still(const PaintCommandOptions& o, const io::SceneImage& img, const paint::SceneTarget& target,
                      std::vector<std::pair<std::string, std::string>> metadata);

}  // namespace spt::cli
