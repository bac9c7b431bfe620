// `spt plan`'s pass over the input: the cut detector of the video painter run on every frame
// or on the frames the sampled scan asks for, or left to the tasks (README.md "Cut scan"), and
// the shots split into balanced tasks at forced key frames.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/progress.hpp"
#include "plan/plan.hpp"
#include "spt/result.hpp"

namespace spt::plan {

// How a plan finds its cuts (README.md "Cut scan"). Auto: Tasks for a video file (read in
// order, so any scan decodes every frame: as much as 2.5% of painting it), Sampled otherwise.
enum class CutScan { Auto, Sampled, Full, Tasks };

struct PlanOptions {
    std::string input;               // as given; the plan records its absolute form
    std::string frames;              // "" or one range "A-B" of source numbers
    std::string fps;                 // "" = the container's, or 24
    bool skip_bad_frames = false;
    int threads = 0;                 // decoding threads (0: every core); the plan never depends on it
    double cut_threshold = 6.0;      // the video painter's (VideoPaintOptions)
    int cut_window = 12;
    CutScan cut_scan = CutScan::Auto;
    int cut_step = 16;               // the sampled scan's step (README.md "Cut scan")
    int cut_history = 4;             // the pairs its verdicts weigh a pair against
    int keyframe_interval = 100;
    long max_task_frames = 240;
    uint64_t seed = 1;
    std::vector<JobOption> job;
    std::string spt_version;
};

struct PlanStats {
    double seconds = 0;              // the whole pass
    uint64_t frames = 0;
    uint64_t decoded = 0;            // frames read and analysed (all of them in a full scan)
    std::string shortfall;           // a video that ended short of its header's frame count, or empty
};

Result<Plan> make_plan(const PlanOptions& o, io::Progress& progress, PlanStats* stats = nullptr);

// The seed of a shot starting at source frame `first` (splitmix64 of the plan's seed and it):
// a shot's strokes depend on its own frames only, not on where other shots begin.
uint64_t shot_seed(uint64_t plan_seed, long first);

}  // namespace spt::plan
