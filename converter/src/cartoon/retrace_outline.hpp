// The regions an inter frame traced anew (every stroke of theirs added, none kept: a morph, a
// moving butterfly) keep nothing of their interval's outline tolerance, so they are free to be
// traced at a coarser one; which tolerance trades vertices for stamps best changes as the shapes
// do. Such a frame is painted again with those regions traced at each of kRetraceFactors times
// the interval's tolerance, the other regions as they were (so that what was kept stays kept),
// and the better painting at the target is written (better_at_target, inter_frame.hpp). A trial
// that loses makes the next wait twice as long (taffy's warped glyphs are retraced every frame,
// and a coarser outline never pays there).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "cartoon/fill_layer.hpp"
#include "cartoon/inter_frame.hpp"

namespace spt::cartoon {

// The tolerances tried, as factors of the interval's. At 36 dB, bytes without trials / with
// 1.2 / 1.4 / 1.2 and 1.4 / 1.3 and 1.6 / 1.2, 1.4 and 1.7: butterfly 61 frames 95,362 / 93,460
// / 92,975 / 92,173 / 94,286 / 94,495. Star 61 frames, trying only frames that added at least
// 80% of their vertices: 26,311 / 24,248 / - / 23,891, 24,387 with 1.25 and 24,968 with 1.3.
constexpr std::array<double, 2> kRetraceFactors = {1.2, 1.4};

// Trials so far in a key frame interval: a losing trial doubles the wait before the next.
struct RetraceTrials {
    uint32_t wait = 0;    // frames to skip before the next trial
    uint32_t period = 1;  // frames between trials, 1 after a trial that won, at most 16
};

// Per region of `traced` (indexed by FillLayer::region), whether `painted` added every stroke of
// the region (equal strokes among its added ones); regions without strokes are false.
std::vector<bool> retraced_regions(const FillLayer& traced, const Frame& painted);

// The strokes of `interval`, except that the regions `retraced` marks are drawn with their
// strokes in `coarse` (the same picture traced at another tolerance), in region order.
std::vector<Stroke> with_coarser_regions(const FillLayer& interval, const FillLayer& coarse,
                                         const std::vector<bool>& retraced);

// `painted` is the frame painted at `tolerance`, and `any_retraced` says whether it traced a
// region anew; `paint_at(t)` paints it with those regions traced at tolerance t. Returns the
// frame to write: `painted`, or a coarser painting when a trial is due (`trials`) and it is
// better. Only with a target. With `parallel`, the trials run side by side; the choice never
// depends on it.
Result<InterFrame> choose_retrace_outline(InterFrame painted, bool any_retraced, double tolerance, double target_psnr,
                                          const paint::ImageView& model, RetraceTrials& trials,
                                          const std::function<Result<InterFrame>(double)>& paint_at, bool parallel);

}  // namespace spt::cartoon
