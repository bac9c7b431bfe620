// Frame rates: a --fps value or a container's floating-point rate as the rational a .spt header
// stores. Shared by every reader of frames (sources, the plan's gray pass) and the painters.
#pragma once

#include <string>

#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::video {

// "24" -> 24/1, "30000/1001", "29.97" -> 30000/1001, "23.976" -> 24000/1001, "25.0" -> 25/1.
Result<Rational> parse_fps(const std::string& text);
// A container's floating-point rate as the rational it stands for (NTSC rates recognised).
Rational fps_from_double(double fps);

}  // namespace spt::video
