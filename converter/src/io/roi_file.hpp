// Regions of interest over frame ranges, read from a small JSON file (`spt paint --roi-file`),
// shared by the still painter and the video encoder:
//   {"rois": [{"x": 100, "y": 50, "w": 200, "h": 120, "frames": "10-40"}, ...]}
// "frames" is optional (all frames) and is "A-B" or "A" (inclusive), a number, or [A, B]. Frame
// numbers are those of the input (a still is frame 0; a sequence's own frame numbers; 0-based
// positions in a video file).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "spt/result.hpp"

namespace spt::io {

struct RoiRange {
    static constexpr uint32_t kAllFrames = 0xFFFFFFFFu;  // last_frame when "frames" is absent
    uint32_t first_frame = 0, last_frame = kAllFrames;  // inclusive
    int32_t x = 0, y = 0, w = 0, h = 0;
};

// Errors name `name` (the file) and the element (rois[i]), or the line and byte offset of bad JSON.
Result<std::vector<RoiRange>> parse_roi_json(std::string_view text, const std::string& name = "roi file");
Result<std::vector<RoiRange>> read_roi_file(const std::string& path);

}  // namespace spt::io
