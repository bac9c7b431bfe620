// `spt paint --plan PLAN.json [--shot K] -o OUT.spt`: a farm task (one shot), or every shot of
// the plan in one process and their join. Both paint a shot the same way, from the plan alone,
// so shots painted anywhere join (spt cat) into the one-process file byte for byte.
#pragma once

#include <string>

#include "cli/paint_options.hpp"
#include "io/progress.hpp"
#include "plan/plan.hpp"
#include "video/video_paint.hpp"

namespace spt::cli {

int paint_plan(int argc, char** argv);

// Paints shot `shot` of `plan` into `output` (nothing is left there unless it succeeded).
// `threads` 0 = all cores. Returns the exit code.
int paint_shot(const plan::Plan& plan, size_t shot, const std::string& output, int threads, io::ProgressMode mode);

// cmd_paint.cpp: the video painter's options from parsed `spt paint` options; -1 = go on,
// otherwise the exit code (the error printed).
int video_options(const PaintCommandOptions& o, video::VideoPaintOptions& v);

}  // namespace spt::cli
