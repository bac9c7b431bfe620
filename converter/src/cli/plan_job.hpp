// A paint job as a farm plan stores it, and back: the option table's painting rows by name
// (job/option_table.hpp), so that a task on another machine paints with exactly the options
// the plan was made with. Paths are stored absolute.
#pragma once

#include <string>
#include <vector>

#include "cli/paint_options.hpp"
#include "plan/plan.hpp"

namespace spt::cli {

std::vector<plan::JobOption> plan_job(const PaintCommandOptions& o);

// Stores the plan's job into `o` (input, output and the per-shot values are the caller's).
// Refuses, naming `plan_path` and the option, any option that is not a painter option: a plan
// can name no file to write and no run setting. Returns "" or the message.
std::string apply_plan_job(const plan::Plan& p, const std::string& plan_path, PaintCommandOptions& o);

}  // namespace spt::cli
