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

// The high 64 bits of the 128-bit product a * b in 64-bit arithmetic: four 32 x 32-bit
// products and their carries.
constexpr uint64_t mul_high64(uint64_t a, uint64_t b) {
    const uint64_t al = a & 0xFFFFFFFFu, ah = a >> 32, bl = b & 0xFFFFFFFFu, bh = b >> 32;
    const uint64_t ll = al * bl, lh = al * bh, hl = ah * bl;
    const uint64_t mid = (ll >> 32) + (lh & 0xFFFFFFFFu) + (hl & 0xFFFFFFFFu);
    return ah * bh + (lh >> 32) + (hl >> 32) + (mid >> 32);
}

// A uniform integer in [0, n): the high 64 bits of the 128-bit product r * n, in standard C++
// (mul_high64) so that every C++20 compiler can include this header. A 128-bit integer type
// would make it one multiply instruction, but none is standard (MSVC has none); the dozen
// 64-bit operations instead are not measurable in a paint (bench figures in the commit that
// made this change).
constexpr uint64_t below(uint64_t r, uint64_t n) { return mul_high64(r, n); }

// The pixels a candidate of one stroke set may land on, in raster order (SPEC.md 7.7.2): the
// canvas, intersected with the union of `rects` when present and with a block mask when
// present. Built from a ReplayRegion; memory grows with the number of rectangles and block
// rows, never with the pixel count.
class CandidateDomain {
public:
    CandidateDomain();
    ~CandidateDomain();
    CandidateDomain(const CandidateDomain&);
    CandidateDomain(CandidateDomain&&) noexcept;
    CandidateDomain& operator=(const CandidateDomain&);
    CandidateDomain& operator=(CandidateDomain&&) noexcept;
    // `region` must be valid for the canvas (check_region).
    CandidateDomain(uint32_t width, uint32_t height, const ReplayRegion& region);
    uint64_t size() const { return total_; }
    // The k-th allowed pixel in raster order, k < size().
    void pixel(uint64_t k, uint32_t& x, uint32_t& y) const;
    bool contains(uint32_t x, uint32_t y) const;

private:
    struct Band;  // rows sharing one list of allowed intervals (replay_generator.cpp)
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
