// Running the farm's command-line clients (sbatch, squeue, scancel, scontrol): argv in, stdout
// out. Commands are started with posix_spawnp and an argv, never through a shell, so no
// argument is quoted or can be read as shell syntax.
#pragma once

#include <string>
#include <vector>

#include "spt/result.hpp"

namespace spt::farm {

// For the scripts spt writes for a farm to run with bash (task.sh, join.sh, the Slurm scripts):
// `s` as one single-quoted shell word, and argv as one command line of such words. Commands
// spt runs itself go through run_capture and are not quoted.
std::string shell_quote(const std::string& s);
std::string shell_line(const std::vector<std::string>& argv);

// Runs argv[0] (looked up on PATH) with argv, stdin from /dev/null, stderr into `stderr_file`
// (created or emptied; never through a symlink). Returns its stdout when it exits 0; else an
// error naming the command, its exit status, the last line of its stderr and the file that
// holds the rest.
Result<std::string> run_capture(const std::vector<std::string>& argv, const std::string& stderr_file);

// Where a command's stderr goes inside a farm state folder: logs/NAME.stderr, NAME being the
// command's file name (the last run of each client is kept for a person to read).
std::string stderr_file_for(const std::string& state_dir, const std::string& command);

}  // namespace spt::farm
