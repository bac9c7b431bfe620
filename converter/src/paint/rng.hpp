// Counter-based random numbers: every draw is a pure function of (seed, stream, counter), so a
// candidate's position, template and acceptance coin do not depend on which thread drew it or
// in what order. That is what makes `--seed` give identical bytes for any `--threads`.
// The draws are libspt's candidate generator (spt/replay.hpp, SPEC.md 7.7.1), so that a decoder
// can replay the painter's candidates and frame coding 2 codes only which were accepted.
#pragma once

#include <cstdint>

#include "spt/replay.hpp"

namespace spt::paint {

using replay::mix64;
using RngStream = replay::Stream;

inline uint64_t rng_draw(uint64_t seed, uint32_t set, uint64_t counter, RngStream stream) {
    return replay::draw(seed, set, counter, stream);
}

// Uniform integer in [0, n): the high half of r * n (SPEC.md 7.7.1).
inline uint64_t rng_below(uint64_t r, uint64_t n) { return replay::below(r, n); }

// Uniform double in [0, 1) from the top 53 bits.
inline double rng_unit(uint64_t r) { return double(r >> 11) * (1.0 / 9007199254740992.0); }

}  // namespace spt::paint
