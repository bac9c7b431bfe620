// `spt paint --style cartoon`: stills through cartoon::paint_cartoon (converter/src/cartoon).
#pragma once

#include "cli/paint_options.hpp"

namespace spt::cli {

// Runs the command for options parsed with style "cartoon"; returns the exit code.
int paint_cartoon(const PaintCommandOptions& o);

}  // namespace spt::cli
