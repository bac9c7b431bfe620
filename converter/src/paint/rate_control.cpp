#include "paint/rate_control.hpp"

#include <algorithm>
#include <cmath>

namespace spt::paint {

RateDefaults rate_defaults(double target_psnr) {
    RateDefaults d;
    if (target_psnr <= 0) return d;
    // Measured optima: 24 dB -> 48, 28 dB -> 24, 32 dB -> 12: lambda halves every 4 dB.
    d.lambda = std::clamp(24.0 * std::exp2((28.0 - target_psnr) / 4.0), 8.0, 64.0);
    d.color_step = target_psnr > 33 ? 4 : 12;
    return d;
}

RatePoint search_bytes(const std::function<RatePoint(double)>& trial, uint64_t target_bytes, double tolerance,
                       int max_trials, double first_lambda) {
    // Bytes decrease with lambda. Bracket in log2(lambda) over [-4, 14] (1/16 .. 16384).
    double lo = -4, hi = 14;
    RatePoint best, smallest;
    bool have_best = false, have_any = false;
    for (int i = 0; i < max_trials; ++i) {
        const double mid = i == 0 ? std::clamp(std::log2(first_lambda), lo, hi) : 0.5 * (lo + hi);
        const RatePoint p = trial(std::exp2(mid));
        if (!have_any || p.bytes < smallest.bytes) smallest = p;
        have_any = true;
        if (p.bytes <= target_bytes) {
            if (!have_best || p.bytes > best.bytes) best = p;
            have_best = true;
            if (double(target_bytes - p.bytes) <= tolerance * double(target_bytes)) break;
            hi = mid;  // room left: smaller lambda, more strokes
        } else {
            lo = mid;
        }
    }
    return have_best ? best : smallest;
}

}  // namespace spt::paint
