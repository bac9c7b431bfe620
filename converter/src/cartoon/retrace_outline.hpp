// An inter frame that traced nearly every polygon anew (a morph: star's outline changes shape
// every frame) keeps nothing of its interval's outline tolerance, so it is free to trace at a
// coarser one; which tolerance trades vertices for stamps best changes as the shape does. Such a
// frame is painted again at each of kRetraceFactors times the interval's tolerance and the one
// of fewest estimated bytes at the target is written. A frame that keeps its polygons (still
// parts, compressed video) never tries: retracing them at another tolerance would add them all.
// A trial that loses makes the next one wait twice as long (taffy's warped glyphs are retraced
// every frame, and a coarser outline never pays there).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "cartoon/inter_frame.hpp"

namespace spt::cartoon {

// The tolerances tried, as factors of the interval's. The star's 61 frames at 36 dB (interval
// tolerance 0.5 px), bytes: 26,311 without trials, 24,248 with 1.2, 24,387 with 1.25, 24,968
// with 1.3, 23,863 with 1.2 and 1.4, 23,911 with 1.2 and 1.5, 24,168 with 1.15 and 1.3.
constexpr std::array<double, 2> kRetraceFactors = {1.2, 1.4};

// The share of its traced vertices (polygons and lines) a frame must add for the trials.
constexpr double kRetracedShare = 0.8;

// Trials so far in a key frame interval: a losing trial doubles the wait before the next.
struct RetraceTrials {
    uint32_t wait = 0;    // frames to skip before the next trial
    uint32_t period = 1;  // frames between trials, 1 after a trial that won, at most 16
};

// Vertices of the polygons and points of the curves in `strokes`.
uint64_t outline_vertices(const std::vector<Stroke>& strokes);

// Of `a` and `b`, painted to `target_psnr` of `model`, whether `b` is better: both reach the
// target and `b` costs fewer estimated bytes; only `b` reaches it; or neither does and `b` is
// closer.
bool better_at_target(const InterFrame& a, const InterFrame& b, const paint::ImageView& model, double target_psnr);

// `painted` is the frame painted at `tolerance` from `traced_vertices` traced ones; `paint_at(t)`
// paints it traced at tolerance t. Returns the frame to write: `painted`, or a coarser painting
// when the frame retraced nearly everything, a trial is due (`trials`) and it is better. With
// `parallel`, the trials run side by side; the choice never depends on it.
Result<InterFrame> choose_retrace_outline(InterFrame painted, uint64_t traced_vertices, double tolerance,
                                          double target_psnr, const paint::ImageView& model, RetraceTrials& trials,
                                          const std::function<Result<InterFrame>(double)>& paint_at, bool parallel);

}  // namespace spt::cartoon
