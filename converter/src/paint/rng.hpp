// Counter-based random numbers: every draw is a pure function of (seed, stream, counter), so a
// candidate's position, template and acceptance coin do not depend on which thread drew it or
// in what order. That is what makes `--seed` give identical bytes for any `--threads`.
#pragma once

#include <cstdint>

namespace spt::paint {

// SplitMix64's finaliser: a bijective mixer with good avalanche, enough for stochastic painting
// (we need decorrelated draws, not cryptographic ones).
inline uint64_t mix64(uint64_t z) {
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

// Streams keep independent draws of one candidate apart.
enum class RngStream : uint64_t { Position = 1, Template = 2, Orientation = 3, Accept = 4 };

inline uint64_t rng_draw(uint64_t seed, uint32_t set, uint64_t counter, RngStream stream) {
    uint64_t h = mix64(seed ^ 0x5350545061696E74ull);  // "SPTPaint"
    h = mix64(h ^ (uint64_t(set) << 56) ^ uint64_t(stream));
    return mix64(h ^ counter);
}

// Uniform integer in [0, n) by multiply-high (Lemire); the tiny bias for n << 2^64 is irrelevant.
inline uint64_t rng_below(uint64_t r, uint64_t n) {
    return uint64_t((__uint128_t(r) * n) >> 64);
}

// Uniform double in [0, 1) from the top 53 bits.
inline double rng_unit(uint64_t r) { return double(r >> 11) * (1.0 / 9007199254740992.0); }

}  // namespace spt::paint
