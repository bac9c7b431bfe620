// Where video frames come from: an image sequence (through spt::io) or a video file (through
// FFmpeg). Sources stream: one frame in memory at a time.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "io/image_io.hpp"
#include "frames/scene_image.hpp"
#include "io/sequence.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::video {

struct SourceFrame {
    long number = 0;        // the input's frame number (sequence number, or video position)
    io::Image image;        // 8-bit sRGB RGB (sources opened without scene reading)
    io::SceneImage scene;   // linear RGBA (sequences opened with scene reading, format 1.3)
    bool repeated = false;  // a bad frame replaced by the previous one (--skip-bad-frames)
    std::string problem;    // why it was repeated
};

class FrameSource {
public:
    virtual ~FrameSource() = default;
    // The next frame; false at the end. Frames all have the first frame's size: a frame of
    // another size is an error naming it (or a bad frame when skipping).
    virtual Result<bool> next(SourceFrame& out) = 0;
    // Frame rate stored in the container, when there is one.
    virtual bool has_fps() const { return false; }
    virtual Rational fps() const { return {}; }
    // Frames expected, or 0 when unknown (for progress).
    virtual uint64_t expected_frames() const = 0;
    // After next() returned false: why the source ended short of the frames it promised (a
    // damaged or cut-short video file), or empty.
    virtual std::string shortfall() const { return {}; }
    virtual std::string describe() const = 0;
};

// Opens a sequence pattern or folder (spt::io::list_sequence) or a video file
// (spt::io::is_video_file, frames/ffmpeg_video.hpp). `frames` is "A-B" or empty. With `scene`,
// a sequence's frames are read with io::read_scene_image into SourceFrame::scene, and a video's
// are converted the same way (frames/video_scene.hpp).
Result<std::unique_ptr<FrameSource>> open_source(const std::string& input, const std::string& frames,
                                                 bool skip_bad_frames, const io::SceneReadOptions* scene = nullptr);

// True when a --frames value selects consecutive frame numbers (one span, step 1, or all):
// then a painting's frame 0 may name its source frame (metadata source.first_frame).
bool frames_consecutive(const std::string& frames);

}  // namespace spt::video
