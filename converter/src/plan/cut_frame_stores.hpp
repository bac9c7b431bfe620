// The two readers of the sampled cut scan's frames (sampled_cuts.hpp): a sequence's files read
// only when asked for (the samples decoded ahead on several threads), and an input that only
// reads in order (a video, a folder) read through, every frame analysed, the recent ones kept.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "plan/gray_frames.hpp"
#include "plan/sampled_cuts.hpp"

namespace spt::plan {

class PlanCutFrames : public CutFrames {
public:
    long first_number() const { return first_; }
    int width() const { return width_; }
    int height() const { return height_; }
    size_t decoded() const { return decoded_; }  // frames read (a frame read twice counts twice)
    // A video that ended short of its header's frame count (GrayFrames::shortfall), or empty.
    virtual std::string shortfall() const { return {}; }
    void forget_before(size_t pos) override { kept_.erase(kept_.begin(), kept_.lower_bound(pos)); }

protected:
    std::map<size_t, video::CutFrame> kept_;
    long first_ = 0;
    int width_ = 0, height_ = 0;
    size_t decoded_ = 0;
};

// `skip_bad_frames`: a bad frame is the nearest good one before it (the painter repeats the
// previous frame), as in the full scan; the first frame must be good.
std::unique_ptr<PlanCutFrames> cut_frames_of_files(std::unique_ptr<GrayFrameFiles> files, const SampledCutOptions& o,
                                                   bool skip_bad_frames, int threads);
std::unique_ptr<PlanCutFrames> cut_frames_in_order(std::unique_ptr<GrayFrames> frames, const SampledCutOptions& o);

}  // namespace spt::plan
