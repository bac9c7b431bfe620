// Regions of interest over frame ranges, read from a small JSON file:
//   {"rois": [{"frames": "10-40", "x": 100, "y": 50, "w": 200, "h": 120}, ...]}
// "frames" is "A-B" (inclusive), "A", or a number; frame numbers are those of the input (the
// sequence's frame numbers, or 0-based frame positions in a video file).
#pragma once

#include <string>
#include <vector>

#include "spt/result.hpp"

namespace spt::video {

struct RoiSpec {
    long first = 0, last = 0;  // input frame numbers, inclusive
    int x = 0, y = 0, w = 0, h = 0;
};

Result<std::vector<RoiSpec>> parse_roi_json(const std::string& text, const std::string& name = "roi file");
Result<std::vector<RoiSpec>> read_roi_file(const std::string& path);

}  // namespace spt::video
