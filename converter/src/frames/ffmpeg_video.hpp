// A video file's frames through FFmpeg's libraries (libavformat, libavcodec, libswscale),
// frame-accurately: frame N is the Nth presentation timestamp of the video stream (README.md,
// "Frame numbers"), a seek goes to the key frame before it and decodes forward, and the
// picture is rotated as the file's display matrix says. 8-bit sources without alpha come out
// as OpenCV's VideoCapture gave them (BGR24 through swscale's bicubic path: the same bytes);
// deeper sources and sources with alpha come out as 16-bit RGBA at their own depth.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "spt/result.hpp"

namespace spt::video {

class FfmpegVideo {
public:
    FfmpegVideo();
    ~FfmpegVideo();
    FfmpegVideo(const FfmpegVideo&) = delete;
    FfmpegVideo& operator=(const FfmpegVideo&) = delete;

    // Opens the file's best video stream and, with `index`, reads its packets' timestamps (no
    // decoding; without them a seek decodes from the start and frames are counted). Errors
    // name the file: missing, not a video, no decoder for its codec.
    Status open(const std::string& path, bool index = true);

    int width() const;   // after rotation
    int height() const;
    // The header's rate as OpenCV's CAP_PROP_FPS gave it (average rate, else the stream's
    // base rate), and its frame count (the stream's count, else duration x rate).
    double fps() const;
    uint64_t header_frames() const;
    // Frames whose packets the file holds (a damaged or cut-short file holds fewer than its
    // header says).
    uint64_t packet_frames() const;
    // True when frames come out as 16-bit RGBA (alpha, or more than 8 bits a sample).
    bool deep() const;
    bool has_alpha() const;
    int bit_depth() const;
    int rotation() const;  // clockwise degrees applied: 0, 90, 180 or 270

    // The next next() returns frame `n` (or the first frame after it that decodes).
    Status seek(long n);
    // The next frame in presentation order into `out` (8-bit BGR when !deep(), else CV_16UC4
    // RGBA; its buffer is reused) and its number; false at the end of the stream. A packet
    // that does not decode ends the stream there (the caller compares with header_frames()).
    Result<bool> next(long& number, cv::Mat& out);
    // Frames the decoder gave since open(), including those a seek decoded and dropped.
    uint64_t decoded_frames() const;
    // The number after the last frame decoded (delivered or dropped).
    long position() const;

    struct Impl;

private:
    std::unique_ptr<Impl> d_;
};

// The video stream's frames, counted as packets (demuxed, never decoded).
Result<uint64_t> count_video_packets(const std::string& path);

}  // namespace spt::video
