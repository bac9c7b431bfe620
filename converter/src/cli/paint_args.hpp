// Parsed `spt paint` options back to the command line that gives them (for farm plans, whose
// tasks re-parse them on other machines). Paths become absolute; the per-run options (input,
// output, --frames, --seed, --threads, --progress, --preview, --side-by-side) are left out.
#pragma once

#include <string>
#include <vector>

#include "cli/paint_options.hpp"

namespace spt::cli {

std::vector<std::string> paint_args(const PaintCommandOptions& o);

}  // namespace spt::cli
