// The frames of a video file that a --frames range selects, decoded by FFmpeg
// (frames/ffmpeg_video.hpp), in order, with the file's own frame numbers. A range that starts
// past frame 0, or skips a stretch, seeks to the key frame before the frame it wants. Shared by
// the painter's video source (frame_source.cpp) and the plan's gray pass
// (plan/gray_frames.cpp), which convert the frames each their own way.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "io/sequence.hpp"
#include "spt/result.hpp"
#include "frames/ffmpeg_video.hpp"

namespace spt::video {

class VideoReader {
public:
    VideoReader(std::string path, io::FrameRange range) : path_(std::move(path)), range_(std::move(range)) {}

    Status open() {
        if (Status st = video_.open(path_); !st) return st;
        fps_ = video_.fps();
        total_ = video_.header_frames();
        if (!range_.empty()) {
            last_wanted_ = range_.spans.front().second;
            for (const auto& s : range_.spans) last_wanted_ = std::max(last_wanted_, s.second);
        }
        return {};
    }

    // The next selected frame into `frame` and its number; false at the end. `frame` is 8-bit
    // BGR, or with `deep` (only when deep()) 16-bit RGBA; its buffer is reused.
    Result<bool> next(long& number, cv::Mat& frame, bool deep = false) {
        for (;;) {
            if (!range_.empty() && pos_ > last_wanted_) return false;
            if (!range_.empty() && !range_.contains(pos_)) {
                if (Status st = video_.seek(next_wanted()); !st) return st.error();
                pos_ = next_wanted();
            }
            Result<bool> got = video_.next(pos_, deep || !video_.deep() ? frame : deep_);
            if (!got || !*got) {
                pos_ = video_.position();
                return got;
            }
            if (range_.empty() || range_.contains(pos_)) break;
            ++pos_;
        }
        ++delivered_;
        number = pos_++;
        if (!deep && video_.deep()) {  // 16-bit RGBA to 8-bit BGR, rounded
            cv::Mat bgr16;
            cv::cvtColor(deep_, bgr16, cv::COLOR_RGBA2BGR);
            bgr16.convertTo(frame, CV_8U, 255.0 / 65535.0);
        }
        return true;
    }
    bool deep() const { return video_.deep(); }
    bool has_alpha() const { return video_.has_alpha(); }
    int bit_depth() const { return video_.bit_depth(); }
    uint64_t decoded_frames() const { return video_.decoded_frames(); }

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
    // The first selected frame at or after pos_.
    long next_wanted() const {
        long best = last_wanted_ + 1;
        for (size_t i = 0; i < range_.spans.size(); ++i) {
            const auto& s = range_.spans[i];
            const long step = std::max(1L, range_.step(i));
            long f = std::max(s.first, pos_);
            f = s.first + (f - s.first + step - 1) / step * step;
            if (f <= s.second) best = std::min(best, f);
        }
        return best;
    }

    FfmpegVideo video_;
    cv::Mat deep_;
    double fps_ = 0;
    uint64_t total_ = 0;
    long pos_ = 0, last_wanted_ = 0;
    uint64_t delivered_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace spt::video
