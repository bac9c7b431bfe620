// Range-checked conversions of parsed numbers to integers. A double converts to an integer
// type only when it is finite and inside the type's range (C++ leaves anything else undefined):
// every conversion of a number read from a file goes through these.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace spt::import {

// `d` rounded to the nearest integer into `out` when the result lies in [lo, hi]; false (out
// untouched) for NaN, infinities and anything outside.
template <class I>
bool round_to(double d, I lo, I hi, I& out) {
    const double r = std::nearbyint(d);
    if (!(r >= double(lo) && r <= double(hi))) return false;
    out = I(r);
    return true;
}

// `d` clamped to [lo, hi] then rounded; NaN gives lo. For values the format saturates
// (opacity, colour components), where out-of-range input has a meaning.
template <class I>
I clamp_round(double d, I lo, I hi) {
    if (!(d > double(lo))) return lo;
    if (d >= double(hi)) return hi;
    return I(std::nearbyint(d));
}

// A parsed number for a message, whatever its size ("1e+93", "640", "nan").
inline std::string number_text(double d) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", d);
    return b;
}

}  // namespace spt::import
