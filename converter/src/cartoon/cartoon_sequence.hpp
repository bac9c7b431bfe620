// `spt paint --style cartoon` for image sequences and videos. Each frame is traced to polygons
// with the key frame's palette; an inter frame (inter_frame.hpp) keeps the polygons that
// traced the same (frame_diff.hpp) and the stamps that still help (stamp_keep.hpp), moves what
// reappears translated (motion_field.hpp), removes the rest, adds the new polygons and paints
// stamps where the error is.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cartoon/fill_layer.hpp"
#include "cartoon/motion_field.hpp"
#include "io/progress.hpp"
#include "paint/painter.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::cartoon {

struct SequenceOptions {
    std::string input, output, frames, fps;
    bool skip_bad_frames = false;
    int keyframe_interval = 100;
    paint::PaintOptions paint;          // the residual stamps: target PSNR, lambda, seed, threads
    int sets = 6;
    std::vector<Template> templates;    // empty: the built-in set
    Rgb8 background{255, 255, 255};
    bool stored = false;
    // false when `output` is a rate search's trial file (io/trial_output.hpp), written in place
    bool atomic_rename = true;
    FillOptions fill;
    // Inputs whose frames need more (memory_bound.hpp) are refused before they are painted; 0: not.
    uint64_t max_memory = 0;
    // A key frame short of its target also tries outlines smoothed by kShortKeySmooth
    // (cartoon_sequence.cpp); false when the caller chose fill.trace.smooth.
    bool smooth_short_keys = true;
    MotionOptions motion;
    std::vector<std::pair<std::string, std::string>> metadata;
    // Told the frame count (when the source knows it) and each frame as it is written; the
    // caller finishes it. Null: nothing reported.
    io::Progress* progress = nullptr;
    // SIGINT/SIGTERM stop the painting after a finished frame (video/stop_signal.hpp); the
    // file then holds the frames done and paint_sequence says so (report.interrupted).
    bool install_signal_handlers = true;
};

struct SequenceReport {
    uint64_t frames = 0, key_frames = 0, motion_frames = 0, bytes = 0;
    uint64_t polygons_added = 0, polygons_kept = 0, stamps_added = 0, removed = 0;
    double mean_psnr = 0, min_psnr = 99, seconds = 0;
    uint32_t min_psnr_frame = 0;  // the frame (0-based, in the file) of min_psnr
    uint64_t frames_short = 0;    // frames below the PSNR target (by more than 0.005 dB)
    Rational fps{24, 1};  // the file's frame rate
    bool interrupted = false;  // stopped by a signal: the file is valid and holds `frames`
};

// Fails with Code::BadState and report.interrupted set when a signal stopped it after a
// finished frame (the output is then a valid file of those frames).
Status paint_sequence(const SequenceOptions& opts, SequenceReport& report);

}  // namespace spt::cartoon
