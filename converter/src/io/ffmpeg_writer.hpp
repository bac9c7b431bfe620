// A preview video (spt render -o clip.mp4 / clip.avi) encoded with FFmpeg's libraries, so that
// spt needs no OpenCV video I/O: MPEG-4 part 2 in MP4 (and any other container FFmpeg names
// from the extension), Motion JPEG in AVI, as OpenCV's VideoWriter wrote them.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "spt/result.hpp"

namespace spt::video {

class VideoFileWriter {
public:
    VideoFileWriter();
    ~VideoFileWriter();
    VideoFileWriter(const VideoFileWriter&) = delete;
    VideoFileWriter& operator=(const VideoFileWriter&) = delete;

    // `file` is written; its extension names the container, `ext` (".avi" or other) the codec.
    // `name` is what errors call the output.
    Status open(const std::string& file, const std::string& ext, const std::string& name, double fps, uint32_t w,
                uint32_t h);
    // One frame of 8-bit RGB, w * h * 3, top row first.
    Status write_rgb(const uint8_t* rgb);
    // Flushes the encoder and writes the container's index.
    Status finish();

    struct Impl;

private:
    std::unique_ptr<Impl> d_;
};

}  // namespace spt::video
