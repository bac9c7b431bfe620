// Running the farm's command-line clients (sbatch, squeue, scancel): argv in, stdout out.
#pragma once

#include <string>
#include <vector>

#include "spt/result.hpp"

namespace spt::farm {

std::string shell_quote(const std::string& s);
std::string shell_line(const std::vector<std::string>& argv);
// Runs argv (through /bin/sh, quoted); returns its stdout when it exits 0, else an error with
// its stderr's last line.
Result<std::string> run_capture(const std::vector<std::string>& argv);

}  // namespace spt::farm
