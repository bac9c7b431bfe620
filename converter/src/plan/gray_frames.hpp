// The frames of an input as the cut pass of `spt plan` needs them: 8-bit gray, in order, with
// their source numbers, the same gray the painter's reader gives (video::FrameSource, then
// RGB -> gray). Sequences of 8-bit files without alpha are read straight as bytes (without
// io::read_image's float strips, which were most of the pass's time), on several threads;
// video files go from the decoder's BGR to gray; everything else goes through FrameSource.
#pragma once

#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::plan {

class GrayFrames {
public:
    virtual ~GrayFrames() = default;
    // The next frame; false at the end.
    virtual Result<bool> next(long& number, cv::Mat& gray) = 0;
    virtual bool has_fps() const = 0;
    virtual Rational fps() const = 0;
    virtual uint64_t expected_frames() const = 0;
    // After next() returned false: why the frames ended short (video::FrameSource::shortfall).
    virtual std::string shortfall() const { return {}; }
    virtual std::string describe() const = 0;
};

// A sequence's frames by position (0 .. count-1, consecutive source numbers from `first`),
// for the sampled cut scan, which reads some frames only. `read` is safe to call on several
// threads at once and gives next()'s gray of a good frame; a bad frame (missing, unreadable,
// another size) is `problem`, and the caller decides whether to skip it.
class GrayFrameFiles {
public:
    struct Frame {
        cv::Mat gray;
        std::string problem;
    };
    virtual ~GrayFrameFiles() = default;
    virtual size_t count() const = 0;
    virtual long first() const = 0;
    virtual Frame read(size_t pos) const = 0;
    virtual std::string path(size_t pos) const = 0;  // the file of a present frame
    virtual std::string describe() const = 0;
};

// The sequence `input` (a pattern, not a video) by position; nullptr (no error) for inputs that
// only read in order (videos, folders), which the scan then reads through open_gray_frames.
Result<std::unique_ptr<GrayFrameFiles>> open_gray_frame_files(const std::string& input, const std::string& frames);

// `threads`: files of a sequence decode on this many threads (0: every core), in order; the
// frames are the same for any count.
Result<std::unique_ptr<GrayFrames>> open_gray_frames(const std::string& input, const std::string& frames,
                                                     bool skip_bad_frames, int threads = 1);

}  // namespace spt::plan
