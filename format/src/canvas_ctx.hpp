// Internal: predictions from the canvas painted so far (SPEC.md 7.7.4), which a coding-2
// decoder knows because it renders each stroke as it decodes it.
#pragma once

#include <cstdint>
#include <vector>

#include "spt/render.hpp"
#include "spt/types.hpp"

namespace spt::detail {

// The coverage-weighted mean colour of the canvas under a stamp footprint centred on pixel
// (px, py), and how much the canvas varies there (activity class 0..3).
struct FootprintMean {
    bool covered = false;  // false: no covered pixel on the canvas (mean is meaningless)
    Rgb8 mean;
    int activity = 0;
};
FootprintMean footprint_mean(const Canvas& canvas, const Mask& fp, int32_t px, int32_t py);

// The orientation table entry that runs along the canvas's local edge at pixel (px, py), from
// the structure tensor of the luma R + 2G + B over a 7x7 window, and the edge strength class
// 0..3 (0: flat, no preference).
struct OrientGuess {
    uint8_t orient = 0;
    int strength = 0;
};
OrientGuess gradient_orientation(const Canvas& canvas, uint32_t px, uint32_t py,
                                 const std::vector<Orientation>& table);

}  // namespace spt::detail
