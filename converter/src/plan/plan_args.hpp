// What a plan's `paint_args` may hold (README.md, "What a plan may do"): only painter options
// from the list below, each with its value. A plan comes from anywhere and its id is a checksum
// anyone can recompute, so a task must not let it name the output, the input, another plan or
// shot, the thread count, or any file to write.
#pragma once

#include <string>
#include <vector>

#include "spt/result.hpp"

namespace spt::plan {

// Refuses (naming `source` and the argument) any entry that is not an allowed painter option or
// the value that follows one.
Status check_paint_args(const std::vector<std::string>& args, const std::string& source);

}  // namespace spt::plan
