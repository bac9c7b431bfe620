#include "paint/rate_control.hpp"

#include <cmath>

namespace spt::paint {

RatePoint search_bytes(const std::function<RatePoint(double)>& trial, uint64_t target_bytes, double tolerance,
                       int max_trials) {
    // Bytes decrease with lambda. Bracket in log2(lambda) over [-4, 14] (1/16 .. 16384).
    double lo = -4, hi = 14;
    RatePoint best, smallest;
    bool have_best = false, have_any = false;
    for (int i = 0; i < max_trials; ++i) {
        const double mid = i == 0 ? 6 : 0.5 * (lo + hi);  // start at the default lambda 64
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
