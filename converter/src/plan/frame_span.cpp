#include "plan/frame_span.hpp"

#include <algorithm>


#include "io/sequence.hpp"
#include "plan/gray_frames.hpp"
#include "frames/ffmpeg_video.hpp"

namespace spt::plan {

namespace {

// The last source number a non-empty --frames range names.
long range_last(const io::FrameRange& r) {
    long hi = r.spans.front().second;
    for (const auto& sp : r.spans) hi = std::max(hi, sp.second);
    return hi;
}

}  // namespace

Result<uint64_t> count_video_packets(const std::string& path) { return video::count_video_packets(path); }

Result<FrameSpan> probe_frames(const std::string& input, const std::string& frames) {
    Result<io::FrameRange> range = io::parse_frame_range(frames);
    if (!range) return range.error();
    // The first frame, decoded as the cut scans read it: its number, the canvas and the rate.
    Result<std::unique_ptr<GrayFrames>> src = open_gray_frames(input, frames, false, 1);
    if (!src) return src.error();
    FrameSpan s;
    s.what = (*src)->describe();
    cv::Mat gray;
    Result<bool> got = (*src)->next(s.first, gray);
    if (!got) return got.error();
    if (!*got) {
        Result<uint64_t> n = io::is_video_file(input) ? count_video_packets(input) : Result<uint64_t>(uint64_t(0));
        if (n.ok() && *n > 0 && !range->empty())
            return make_error(Code::InvalidArgument, s.what + ": --frames " + frames + ": the video has frames 0-" +
                                                         std::to_string(*n - 1));
        return make_error(Code::IoError, s.what + ": no frames to plan");
    }
    s.width = uint32_t(gray.cols);
    s.height = uint32_t(gray.rows);
    s.has_fps = (*src)->has_fps();
    if (s.has_fps) s.fps = (*src)->fps();
    if (io::is_video_file(input)) {
        Result<uint64_t> n = count_video_packets(input);
        if (!n) return n.error();
        if (*n == 0) return make_error(Code::IoError, s.what + ": no frames to plan");
        s.last = range->empty() ? long(*n) - 1 : std::min(long(*n) - 1, range_last(*range));
        if (s.last < s.first)  // the decoder gave a frame past the packets counted: a damaged file
            return make_error(Code::Corrupt, s.what + ": frame " + std::to_string(s.first) + " decodes, but the file "
                                             "holds " + std::to_string(*n) + " frames");
        return s;
    }
    // A sequence or a folder: the numbers its painter walks, the range's own when one is given
    // (a missing file among them is reported or skipped by the task, as by spt paint).
    if (!range->empty()) {
        s.last = range_last(*range);
        return s;
    }
    Result<std::vector<io::SequenceFile>> files = io::list_sequence(input, *range);
    if (!files) return files.error();
    for (const auto& f : *files) s.last = std::max(s.last, f.frame);
    if (s.last < s.first) return make_error(Code::IoError, s.what + ": no frames to plan");
    return s;
}

}  // namespace spt::plan
