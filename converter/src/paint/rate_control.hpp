// Rate control by lambda search: the painter's Lagrangian acceptance (README.md) trades strokes
// for error, so bytes fall and PSNR falls as lambda grows. A byte or PSNR target is reached by
// bisection on log(lambda), each step a full paint; the best point found is returned.
#pragma once

#include <cstdint>
#include <functional>

namespace spt::paint {

struct RatePoint {
    double lambda = 0;
    uint64_t bytes = 0;
    double psnr = 0;
};

// `trial(lambda)` paints at lambda and returns the coded size and PSNR. Returns the point with
// the largest size not above `target_bytes` (or the smallest point when none fits), after at
// most `max_trials` paints. Sizes within `tolerance` (relative) below the target stop early.
RatePoint search_bytes(const std::function<RatePoint(double)>& trial, uint64_t target_bytes,
                       double tolerance = 0.03, int max_trials = 9);

}  // namespace spt::paint
