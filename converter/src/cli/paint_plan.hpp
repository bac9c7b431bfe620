// `spt paint --plan PLAN.json [--shot K] -o OUT.spt`: a farm task (one shot), or every shot of
// the plan in one process and their join. Both paint a shot the same way, from the plan alone,
// so shots painted anywhere join (spt cat) into the one-process file byte for byte.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "cli/paint_options.hpp"
#include "io/progress.hpp"
#include "plan/plan.hpp"
#include "video/video_paint.hpp"

namespace spt::cli {

int paint_plan(int argc, char** argv);

// Paints shot `shot` of `plan` (read from `plan_path`) into `output` (nothing is left there
// unless it succeeded). `threads` 0 = all cores. Returns the exit code.
int paint_shot(const plan::Plan& plan, const std::string& plan_path, size_t shot, const std::string& output, int threads,
               io::ProgressMode mode);

// A plan's shot as run_paint paints it: the file's metadata, whether the painter finds the cuts
// (the plan left them to its tasks), the progress label; and what came of it.
struct ShotRun {
    std::vector<std::pair<std::string, std::string>> metadata;
    bool detect_cuts = false;
    std::string label;
    uint64_t frames = 0;       // frames painted
    bool interrupted = false;  // stopped by a signal
};

// cmd_paint.cpp: the one place a job's style picks its painter: a still, a sequence or video,
// or (with `shot`) one shot of a plan. Returns the exit code.
int run_paint(const PaintCommandOptions& o, ShotRun* shot = nullptr);

// cmd_paint.cpp: the video painter's options from parsed `spt paint` options; -1 = go on,
// otherwise the exit code (the error printed).
int video_options(const PaintCommandOptions& o, video::VideoPaintOptions& v);

}  // namespace spt::cli
