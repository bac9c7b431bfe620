// The frames of a video file that a --frames range selects, as OpenCV decodes them (8-bit BGR,
// BGRA or gray), in order, with the file's own frame numbers. Frames the range skips are
// grabbed, not decoded. Shared by the painter's video source (frame_source.cpp) and the plan's
// gray pass (plan/gray_frames.cpp), which convert them each their own way.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>

#include <opencv2/videoio.hpp>

#include "io/sequence.hpp"
#include "spt/result.hpp"

namespace spt::video {

class VideoReader {
public:
    VideoReader(std::string path, io::FrameRange range) : path_(std::move(path)), range_(std::move(range)) {}

    Status open() {
        if (!cap_.open(path_)) return make_error(Code::IoError, path_ + ": OpenCV cannot open this video file");
        fps_ = cap_.get(cv::CAP_PROP_FPS);
        const double n = cap_.get(cv::CAP_PROP_FRAME_COUNT);
        total_ = n > 0 && n < 1e9 ? uint64_t(n) : 0;
        if (!range_.empty()) {
            last_wanted_ = range_.spans.front().second;
            for (const auto& s : range_.spans) last_wanted_ = std::max(last_wanted_, s.second);
        }
        return {};
    }

    // The next selected frame into `frame` (8-bit; its buffer is reused from call to call) and
    // its number; false at the end.
    bool next(long& number, cv::Mat& frame) {
        for (;;) {
            if (!range_.empty() && pos_ > last_wanted_) return false;
            if (!range_.empty() && !range_.contains(pos_)) {
                if (!cap_.grab()) return false;  // skipped frames are not decoded
                ++pos_;
                continue;
            }
            if (!cap_.read(frame) || frame.empty()) return false;
            break;
        }
        ++delivered_;
        number = pos_++;
        if (frame.depth() != CV_8U) frame.convertTo(frame, CV_8U);
        return true;
    }

    // Frames of a video of different sizes are refused: an error naming the file and frame.
    Status check_size(long number, int cols, int rows) {
        if (width_ == 0) { width_ = cols; height_ = rows; }
        if (cols != width_ || rows != height_)
            return make_error(Code::Corrupt, path_ + ": frame " + std::to_string(number) + " changes size");
        return {};
    }

    double fps() const { return fps_; }
    uint64_t expected_frames() const { return range_.count_in_video(total_); }
    // After next() returned false: why fewer frames came than the file's header promised for
    // the range, or empty. A damaged or cut-short file decodes up to the damage and then ends
    // like a whole one; the header's count is what tells them apart.
    std::string shortfall() const {
        const uint64_t expected = expected_frames();
        if (total_ == 0 || delivered_ >= expected) return {};
        return path_ + ": decoding stopped at frame " + std::to_string(pos_) + ", but its header says " +
               std::to_string(total_) + " frames (is the file damaged or cut short?): read " +
               std::to_string(delivered_) + " of the " + std::to_string(expected) + " frames asked for";
    }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    io::FrameRange range_;
    cv::VideoCapture cap_;
    double fps_ = 0;
    uint64_t total_ = 0;
    long pos_ = 0, last_wanted_ = 0;
    uint64_t delivered_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace spt::video
