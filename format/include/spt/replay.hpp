// Decoder-replayed candidates (frame coding 2, SPEC.md 7.7): the pseudo-random generator a
// painter draws its candidate strokes from, and the candidate regions. A painter that draws
// from these functions lets the writer code only which candidates it accepted (and what the
// decoder cannot derive: colours, orientations from the source's edges), not their positions.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "spt/types.hpp"

namespace spt::replay {

// SplitMix64's output function (SPEC.md 7.7.1): a bijective 64-bit mixer.
constexpr uint64_t mix64(uint64_t z) {
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// Independent draws of one candidate.
enum class Stream : uint64_t { Position = 1, Template = 2, Orientation = 3, Accept = 4 };

// The draw of candidate `counter` of stroke set `set` in the frame seeded with `seed`: a pure
// function, so candidates can be drawn in any order and on any thread.
constexpr uint64_t draw(uint64_t seed, uint32_t set, uint64_t counter, Stream stream) {
    uint64_t h = mix64(seed ^ 0x5350545061696E74ull);  // "SPTPaint"
    h = mix64(h ^ (uint64_t(set) << 56) ^ uint64_t(stream));
    return mix64(h ^ counter);
}

// A uniform integer in [0, n): the high 64 bits of the 128-bit product r * n.
inline uint64_t below(uint64_t r, uint64_t n) { return uint64_t((__uint128_t(r) * n) >> 64); }

// The pixels a candidate of one stroke set may land on, in raster order (SPEC.md 7.7.2): the
// canvas, intersected with the union of `rects` when present and with a block mask when
// present. Built from a ReplayRegion; memory grows with the number of rectangles and block
// rows, never with the pixel count.
class CandidateDomain {
public:
    CandidateDomain() = default;
    // `region` must be valid for the canvas (check_region).
    CandidateDomain(uint32_t width, uint32_t height, const ReplayRegion& region);
    uint64_t size() const { return total_; }
    // The k-th allowed pixel in raster order, k < size().
    void pixel(uint64_t k, uint32_t& x, uint32_t& y) const;
    bool contains(uint32_t x, uint32_t y) const;

private:
    struct Band {
        uint32_t y0 = 0, y1 = 0;             // rows [y0, y1)
        uint64_t start = 0;                  // allowed pixels before the band
        uint64_t per_row = 0;                // allowed pixels in each of its rows
        std::vector<uint32_t> x0, x1;        // sorted disjoint intervals [x0, x1)
        std::vector<uint64_t> before;        // allowed pixels of a row before interval i
    };
    uint32_t width_ = 0, height_ = 0;
    bool all_ = true;
    uint64_t total_ = 0;
    std::vector<Band> bands_;
};

// One candidate as the generator gives it. `orient` is meaningful only when the frame draws
// orientations at random.
struct Candidate {
    uint32_t x = 0, y = 0;
    uint8_t tmpl = 0, orient = 0;
};
// Requires domain.size() > 0 and templates > 0.
Candidate candidate(uint64_t seed, uint32_t set, uint64_t counter, const CandidateDomain& domain,
                    uint32_t templates, uint32_t orientations);

// Empty when `region` can be coded for a canvas of this size, else what is wrong.
std::string check_region(const ReplayRegion& region, uint32_t width, uint32_t height);

}  // namespace spt::replay
