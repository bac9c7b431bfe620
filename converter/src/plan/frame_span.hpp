// What a plan whose cuts its tasks find (--cut-scan tasks, README.md "Cut scan") needs of the
// input, read without decoding it: the source numbers of its frames, the canvas and the frame
// rate. A video's frames are counted as packets, demuxed by FFmpeg (no decoding: a 1080p
// H.264 clip counts in a few percent of its decoding time); a sequence's files are listed. Only
// the first frame is decoded, for the canvas.
#pragma once

#include <cstdint>
#include <string>

#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::plan {

struct FrameSpan {
    long first = 0, last = -1;     // source numbers, inclusive
    uint32_t width = 0, height = 0;
    bool has_fps = false;
    Rational fps{24, 1};
    std::string what;              // the input as errors name it
};

Result<FrameSpan> probe_frames(const std::string& input, const std::string& frames);

// The frames of a video file, as packets of its video stream (nothing is decoded).
Result<uint64_t> count_video_packets(const std::string& path);

}  // namespace spt::plan
