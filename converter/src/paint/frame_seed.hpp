// The per-frame seed: a mix of the user's seed and the frame index, so that a frame's strokes
// do not depend on how many random numbers earlier frames used. Every sequence painter (the
// video encoder, the cartoon painter) and the planner (a shot's seed) use it.
#pragma once

#include <cstdint>

#include "spt/replay.hpp"

namespace spt::paint {

inline uint64_t frame_seed(uint64_t seed, uint32_t index) {
    // SplitMix64's state after index + 1 steps from `seed` (mix64 adds the last step's
    // increment): well mixed, and the same on every platform.
    return replay::mix64(seed + 0x9E3779B97F4A7C15ull * uint64_t(index));
}

}  // namespace spt::paint
