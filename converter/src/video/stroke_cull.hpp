// Removal of strokes that no longer show: those whose every canvas pixel is painted over with
// full coverage (255) by strokes drawn after them, and those entirely off the canvas. Removing
// them leaves every rendered pixel identical (a coverage-255 stroke replaces the pixel whatever
// was below: blend8(dst, src, 255) == src), and keeps the live list bounded over long shots.
#pragma once

#include <cstdint>
#include <vector>

#include "spt/render.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::video {

// Indices (strictly increasing) into `live` of the strokes that can go. Work is proportional
// to the total mask area of the live strokes; `opaque` is scratch memory (width * height).
Result<std::vector<uint32_t>> hidden_strokes(const std::vector<Stroke>& live, const Renderer& renderer,
                                             uint32_t width, uint32_t height,
                                             std::vector<uint8_t>& opaque);

}  // namespace spt::video
