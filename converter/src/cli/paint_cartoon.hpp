// `spt paint --style cartoon`: stills through cartoon::paint_cartoon, sequences, videos and farm
// shots through cartoon::paint_sequence (converter/src/cartoon).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "cli/paint_options.hpp"
#include "job/cartoon_job.hpp"

namespace spt::cli {

using job::Metadata;

// Runs the command for options parsed with style "cartoon"; returns the exit code.
int paint_cartoon(const PaintCommandOptions& o);

// A farm shot (spt paint --plan PLAN --shot K) painted as a cartoon sequence: `o` holds the
// plan's options with the shot's frames and seed, `metadata` the entries that replace or join
// the file's (the plan's seed, the shot's place in the plan). `frames` gets the frames painted.
int paint_cartoon_shot(const PaintCommandOptions& o, const Metadata& metadata, uint64_t& frames);

}  // namespace spt::cli
