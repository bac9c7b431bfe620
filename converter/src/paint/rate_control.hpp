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

// The measured best (lambda, colour step) for painting to a PSNR target in one pass
// (bench/rate_sweep.sh, README.md "Default lambda"): at 28 dB lambda 24 and step 12 code the
// fewest bytes (median over stills and 1280x720 frames); lower targets favour larger lambdas,
// higher ones smaller, and above 33 dB the colour step 12 costs more strokes than it saves.
// target_psnr <= 0 (no target) gives the 28 dB point.
struct RateDefaults {
    double lambda = 24;
    int color_step = 12;
};
RateDefaults rate_defaults(double target_psnr);

// A painting "reaches" a PSNR target when it is at most this far below it: the searches and
// the short-of-target warnings all judge by it, so one rule decides what counts as reached.
constexpr double kTargetSlackDb = 0.005;
inline bool reaches_target(double psnr, double target_psnr) {
    return !(target_psnr > 0) || psnr >= target_psnr - kTargetSlackDb;
}

// `trial(lambda)` paints at lambda and returns the coded size and PSNR. Returns the point with
// the largest size not above `target_bytes` (or the smallest point when none fits), after at
// most `max_trials` paints. Sizes within `tolerance` (relative) below the target stop early.
RatePoint search_bytes(const std::function<RatePoint(double)>& trial, uint64_t target_bytes,
                       double tolerance = 0.03, int max_trials = 9, double first_lambda = 24);

}  // namespace spt::paint
