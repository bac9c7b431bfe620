// Colour encoding 1 (scene-linear half floats, format 1.3): the exact integer conversions of
// SPEC.md 8.6 between 16-bit half-float codes and linear values, and the per-pixel
// compositing rule of every canvas kind. Decoders use only the integer functions; the float
// ones are for painters and image writers.
#pragma once

#include <bit>
#include <cstdint>

namespace spt {

// A half code's linear value in units of 2^-24 (exact: half floats are multiples of 2^-24).
// Codes above 0x7BFF (infinities, NaNs, negatives) are not colour codes; callers check first.
inline uint64_t half_to_q24(uint16_t h) {
    const uint32_t e = (h >> 10) & 31, m = h & 1023;
    return e == 0 ? m : uint64_t(1024 + m) << (e - 1);
}

// The half code nearest to a linear value in units of 2^-24, ties to the even code; values
// above 65504 give 0x7BFF.
inline uint16_t q24_to_half(uint64_t v) {
    if (v < 2048) return uint16_t(v);  // subnormals and the first binade are the value itself
    int s = int(std::bit_width(v)) - 11;  // mantissa with its leading 1 in 1024..2047
    uint64_t mant = v >> s;
    const uint64_t rem = v & ((uint64_t(1) << s) - 1), half = uint64_t(1) << (s - 1);
    if (rem > half || (rem == half && (mant & 1))) ++mant;
    if (mant == 2048) { mant = 1024; ++s; }
    if (s + 1 > 30) return 0x7BFF;
    return uint16_t(((s + 1) << 10) | (mant - 1024));
}

// Float value of a half code (exact).
inline float half_to_float(uint16_t h) {
    return float(double(half_to_q24(h & 0x7FFF)) / 16777216.0) * ((h & 0x8000) ? -1.0f : 1.0f);
}

// The colour code of a linear value: negatives and NaN give 0, values above 65504 give 0x7BFF,
// others the nearest half (ties to even).
inline uint16_t float_to_half_code(float f) {
    if (!(f > 0)) return 0;
    if (f >= 65504.0f) return 0x7BFF;
    const double q = double(f) * 16777216.0;  // exact: a float times a power of two
    // The half nearest to floor(q) is within one code of the half nearest to q.
    const uint16_t h = q24_to_half(uint64_t(q));
    uint16_t best = h;
    double bd = q > double(half_to_q24(h)) ? q - double(half_to_q24(h)) : double(half_to_q24(h)) - q;
    for (int k = -1; k <= 1; k += 2) {
        const int c = int(h) + k;
        if (c < 0 || c > 0x7BFF) continue;
        const double v = double(half_to_q24(uint16_t(c))), d = q > v ? q - v : v - q;
        if (d < bd || (d == bd && (best & 1))) { best = uint16_t(c); bd = d; }
    }
    return best;
}

// SPEC.md 8.6, one channel of encoding 1: dst' = nearest half of
// (lin(dst) * (255 - alpha) + lin(src) * alpha + 127) / 255.
inline uint16_t blend_half(uint16_t dst, uint16_t src, uint32_t alpha) {
    return q24_to_half((half_to_q24(dst) * (255u - alpha) + half_to_q24(src) * alpha + 127u) / 255u);
}

}  // namespace spt
