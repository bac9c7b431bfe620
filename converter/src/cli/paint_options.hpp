// `spt paint` options, parsed into one struct that both the still painter (cmd_paint.cpp) and
// the video encoder take: the video path gets the same sets, templates, ROIs and acceptance.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "job/paint_job.hpp"
#include "paint/painter.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::cli {

using RoiSpec = job::RoiSpec;
using PaintCommandOptions = job::PaintJob;
using job::paint_templates;

// Parses argv (argv[0] is the command name) with the shared command-line layer (args.hpp).
// Returns -1 when the command should run; otherwise the exit code to return at once: 0 after
// --help, 2 after a usage error (printed to stderr).
// `command` names the command in messages and --help (spt plan takes the same options).
int parse_paint_options(int argc, char** argv, PaintCommandOptions& out, const char* command = "paint");

}  // namespace spt::cli
