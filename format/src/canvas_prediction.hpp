// Internal: predictions from the canvas painted so far (SPEC.md 7.7.4), which a coding-2
// decoder knows because it renders each stroke as it decodes it.
#pragma once

#include <cstdint>
#include <memory>
#include <unordered_map>
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

// A stamp footprint (Renderer::stamp_footprint) as one span of non-zero coverage per row, three
// bytes a pixel (the coverage repeated per channel), so that the sums over an RGB canvas row run
// as plain byte-wise vector loops and skip the zero corners of the footprint's box.
struct FootprintRows {
    struct Row {
        int32_t lo = 0;    // first column of the span, relative to x0
        uint32_t n = 0;    // pixels; 0: no coverage in this row
        uint32_t off = 0;  // byte offset of the span in cov3
    };
    static constexpr uint32_t kRowPad = 48;  // zero bytes after every span (one vector block)
    int32_t x0 = 0, y0 = 0;  // offset of column 0 / row 0 from the centre pixel
    std::vector<Row> rows;
    std::vector<uint8_t> cov3;
    explicit FootprintRows(const Mask& m);
};

// The prepared footprints of one frame's stamps, built on first use.
class FootprintTable {
public:
    explicit FootprintTable(const Renderer& r) : renderer_(r) {}
    const FootprintRows& get(uint8_t set, uint8_t tmpl, uint8_t orient);
private:
    const Renderer& renderer_;
    std::unordered_map<uint32_t, std::unique_ptr<FootprintRows>> map_;
};

FootprintMean footprint_mean(const Canvas& canvas, const FootprintRows& fp, int32_t px, int32_t py);
// The same from the footprint's Mask: the definition's direct form, kept as the reference
// (nothing in the decoder calls it).
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
