// The plan's coarse-to-fine cut scan (README.md "Cut scan"): the cut detector's exact
// per-frame verdict (video::judge_cut) on the frame pairs where a cut can hide, found from
// frames sampled every `step` source numbers, so that most frames are never decoded.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "spt/result.hpp"
#include "frames/cut_detect.hpp"

namespace spt::plan {

struct SampledCutOptions {
    video::CutOptions detector;
    int step = 16;       // samples at source numbers that are multiples of it, and the ends
    // A span a..b is split (and finally judged pair by pair) unless its change is below
    // `loose` times the detector's floors in pixel or in edge change; 0 judges every pair.
    double loose = 0.5;
    // A pair's verdict weighs it against the products of at most this many pairs before it
    // since the last cut (the full scan: the detector's `window`, 12); more reads more frames.
    int history = 4;
};

// The frames of one input by position 0, 1, ... as the detector sees them. `at` gives null past
// the last frame (then `count` is known); requests go forward except within `keep_behind`
// frames of the latest sample, so a reader that can only go forward keeps that many.
class CutFrames {
public:
    virtual ~CutFrames() = default;
    virtual Result<const video::CutFrame*> at(size_t pos) = 0;
    virtual size_t count() const = 0;    // valid once at() gave null, or known from the start
    virtual void forget_before(size_t pos) = 0;
};

size_t keep_behind(const SampledCutOptions& o);

struct SampledCutStats {
    size_t judged = 0;  // frame pairs given the exact verdict
};

// The positions (ascending, never 0) of the frames that start a shot. `first_number` is the
// source number of position 0 (the sample grid follows source numbers, so a plan of a
// sub-range samples the frames it shares with the whole); `on_sample` sees each sample.
Result<std::vector<size_t>> sampled_cuts(CutFrames& frames, long first_number, const SampledCutOptions& o,
                                         const std::function<void(size_t pos)>& on_sample,
                                         SampledCutStats* stats = nullptr);

}  // namespace spt::plan
