// Frame sequences named the way VFX tools name them (OpenImageIO / oiiotool conventions).
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "spt/result.hpp"

namespace spt::io {

// "A-B" (inclusive), "A", a comma list "1-10,20,30-40", and steps "1-100x5" (every 5th frame
// from 1); empty = all. Frame numbers are >= 0.
struct FrameRange {
    std::vector<std::pair<long, long>> spans;
    std::vector<long> steps;  // one per span (1 when absent); may be empty = all steps 1
    bool contains(long f) const;
    bool empty() const { return spans.empty(); }
    long step(size_t span) const { return span < steps.size() ? steps[span] : 1; }
    // The frames of [lo, hi] the range selects, in the order the spans list them, without
    // repeats; an empty range selects all of [lo, hi]. At most `max_count` (then truncated).
    std::vector<long> frames_within(long lo, long hi, size_t max_count = 100000000) const;
    // How many frames of a video of `total` frames (0: unknown, then the spans as given) the
    // range selects; `total` itself when the range is empty. Steps are not counted (video
    // sources read every frame of a span).
    uint64_t count_in_video(uint64_t total) const {
        if (empty()) return total;
        uint64_t n = 0;
        for (const auto& s : spans) {
            const long hi = total ? std::min<long>(s.second, long(total) - 1) : s.second;
            if (hi >= s.first) n += uint64_t(hi - s.first + 1);
        }
        return n;
    }
};
Result<FrameRange> parse_frame_range(const std::string& text);

// True when `name` (its file-name part) holds a frame-number placeholder: "####", "#", "@@@",
// "%04d", "%d", or an oiiotool range "1-120#".
bool is_sequence_pattern(const std::string& name);

// Expands a pattern to one file name for frame `frame` ("####" -> 4 digits zero-padded, "#"
// alone -> 4 digits as in oiiotool, "@" -> 1 digit each, "%0Nd" -> N digits). An oiiotool
// range in front of the placeholder ("1-120#") is dropped from the name.
std::string format_frame(const std::string& pattern, long frame);

struct SequenceFile {
    long frame = 0;
    std::string path;
};

// Lists the input frames of a sequence: a pattern with a placeholder (frames found on disk, or
// the pattern's own range "1-120#", whose files must all exist), or a folder (its image files
// in name order, numbered 0..), filtered by `range`. An error names the pattern when nothing
// matches.
Result<std::vector<SequenceFile>> list_sequence(const std::string& pattern_or_dir,
                                                const FrameRange& range = {});

// True for file names OpenCV's video reader should open (.mp4, .mov, .mkv, .avi, .mpg, .webm...).
bool is_video_file(const std::string& path);

}  // namespace spt::io
