// Frame sequences named the way VFX tools name them (OpenImageIO / oiiotool conventions).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spt/result.hpp"

namespace spt::io {

// "A-B" (inclusive), "A", or a comma list "1-10,20,30-40"; empty = all.
struct FrameRange {
    std::vector<std::pair<long, long>> spans;
    bool contains(long f) const;
    bool empty() const { return spans.empty(); }
};
Result<FrameRange> parse_frame_range(const std::string& text);

// True when `name` holds a frame-number placeholder: "####", "#", "@@@", "%04d", or an
// oiiotool range "1-120#".
bool is_sequence_pattern(const std::string& name);

// Expands a pattern to one file name for frame `frame` ("####" -> 4 digits zero-padded, "#"
// alone -> 4 digits as in oiiotool, "@" -> 1 digit each, "%0Nd" -> N digits).
std::string format_frame(const std::string& pattern, long frame);

struct SequenceFile {
    long frame = 0;
    std::string path;
};

// Lists the input frames of a sequence: a pattern with a placeholder (frames found on disk, or
// the pattern's own range "1-120#"), or a folder (its image files in name order, numbered 0..),
// filtered by `range`. An error names the pattern when nothing matches.
Result<std::vector<SequenceFile>> list_sequence(const std::string& pattern_or_dir,
                                                const FrameRange& range = {});

// True for file names OpenCV's video reader should open (.mp4, .mov, .mkv, .avi, .mpg, .webm...).
bool is_video_file(const std::string& path);

}  // namespace spt::io
