// `spt paint` for image sequences and video files: one entry point the CLI calls.
//
// Key frames (the first frame, the first frame after a cut, every `keyframe_interval` frames)
// are painted fully by the still painter. Between key frames the live strokes travel with a
// block motion field measured by optical flow, strokes that later strokes cover completely are
// removed, and only the areas whose error grew (motion, disocclusion, changed content) are
// repainted. Every frame goes through spt::Writer, so the file has an index and seeks.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "io/progress.hpp"
#include "frames/scene_image.hpp"
#include "paint/painter.hpp"
#include "paint/scene_paint.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"
#include "frames/frame_rate.hpp"  // parse_fps for `fps`

namespace spt::video {

enum class FlowMethod { DisUltrafast, DisFast, DisMedium, Farneback };
bool parse_flow_method(const std::string& s, FlowMethod& out);
const char* flow_method_name(FlowMethod m);

struct VideoPaintOptions {
    // Input: a sequence pattern ("shot.####.exr", "shot.%04d.png", "shot.1-120#.png"), a folder
    // of frames, or a video file (anything FFmpeg's libraries decode: frames/ffmpeg_video.hpp).
    std::string input;
    std::string output;               // the .spt file
    bool atomic_rename = true;        // false: `output` is a trial file, written in place
    std::string frames;               // "A-B": sequence frame numbers, or 0-based video frames
    std::string fps;                  // "24", "30000/1001", "29.97"; empty = container or 24
    bool skip_bad_frames = false;     // repeat the previous frame instead of failing
    int keyframe_interval = 100;      // at most this many frames from one key frame to the next
    std::string roi_file;             // JSON {"rois":[{"frames":"10-40","x":..,"y":..,"w":..,"h":..}]} (io/roi_file.hpp)

    // Cut detection: a cut when (pixel difference x edge difference) exceeds `cut_threshold`
    // times the mean of that product over the look-back window (the paper's detector).
    double cut_threshold = 6.0;
    int cut_window = 12;
    // A key frame instead of an inter frame when more than this fraction of the canvas would
    // be repainted (dissolves, fades, fast motion): cheaper and cleaner than repainting on top.
    double repaint_key_fraction = 0.6;

    FlowMethod flow = FlowMethod::DisUltrafast;
    int block_size = 16;              // motion block in pixels (SPEC.md 5: 8..256)
    double repaint_error = 18.0;      // mean |painting - source| per channel that calls for repaint
    uint64_t max_inter_strokes = 4000;  // cap on strokes added per inter frame
    // Set-switching threshold of the repaint (PaintOptions::threshold) in inter frames; 0 = the
    // key frames' value. Higher stops each set sooner: fewer candidates, faster inter frames.
    double inter_threshold = 0;
    int cull_every = 1;               // remove covered strokes every N frames (0 = never)
    // Re-render only the canvas bands where strokes moved (same bytes as a full render).
    bool incremental_render = true;
    int flow_width = 640;             // optical flow on frames downscaled to at most this width
    // Stroke orientation for inter frames. The edge field of the key frame travels with the
    // motion and is recomputed from the source every `orient_refresh` frames (computing it
    // costs more than the rest of an inter frame). With `flow_orientation`, new strokes where
    // the flow is at least `flow_orient_min` pixels a frame are laid along the motion instead.
    int orient_refresh = 8;
    bool flow_orientation = false;
    double flow_orient_min = 1.0;

    // The still painter's options (seed, threads, max strokes per key frame, target PSNR,
    // threshold, orient) and its setup.
    paint::PaintOptions paint;
    int sets = 6;                     // stroke sets, coarse to fine
    std::vector<Template> templates;  // empty = paint::default_templates()
    Rgb8 background{255, 255, 255};
    bool stored_coding = false;       // coding 0 instead of range coding
    // 2: frame coding 2 where the painter's candidates replay (SPEC.md 7.7), else coding 1;
    // 1: coding 1 only.
    int coding = 2;
    // Rate control (`--target-bytes N[/s]`): a byte budget for the whole clip, or per second of
    // it. run_video_paint turns it into `frame_byte_budget`, which the encoder meets by scaling
    // each frame's lambda with the running overshoot (VideoEncoder::add_frame).
    uint64_t target_bytes = 0;
    bool target_bytes_per_second = false;
    double frame_byte_budget = 0;     // bytes per frame; 0 = no rate control

    // Compositing-grade output (format 1.3, issue 17): "auto" decides from the first frame of a
    // sequence, linear for float frames and an alpha canvas when they have alpha; the frames
    // are then read with io::read_scene_image(scene_read). Video files are always 8-bit.
    std::string color_encoding = "srgb8";  // auto|srgb8|linear
    std::string alpha = "off";             // auto|on|off
    io::SceneReadOptions scene_read;
    // What the encoder paints (video_paint sets them from the above; plain when neither):
    // strokes on an alpha canvas, and colour encoding 1 through the 8-bit proxy of peak
    // `scene_peak` (paint/linear_proxy.hpp; video_paint: twice the sequence's first file's
    // peak, at least 16) with every frame's new strokes refit in linear.
    paint::SceneTarget scene;
    double scene_peak = 1.0;
    // Alpha canvases: a live stroke whose coverage lies for more than this share on pixels the
    // source now has (nearly) transparent is removed, since over-compositing can only add
    // alpha: strokes of areas that became transparent do not linger. (orbit, 24 frames, worst
    // frame's mean alpha over clear pixels / bytes: 0.34 2.27% 28,177; 0.2 1.37% 28,600; 0.12
    // 1.00% 29,785; 0.1 0.69% 30,300; 0.05 0.35% 33,890. Issue 34 asks at most 1%.)
    double transparent_share = 0.1;

    // Farm plans (converter/src/plan): with false, key frames come only from the first frame,
    // the interval and repaint_key_fraction, never from the cut detector (the plan placed the cuts).
    bool detect_cuts = true;
    // Metadata entries written besides the painter's own; an entry of the same key replaces it.
    std::vector<std::pair<std::string, std::string>> metadata;

    // Set from anywhere (signal handler, test) to stop after the current frame; the output then
    // holds every finished frame. run_video_paint installs SIGINT/SIGTERM handlers that set it.
    std::atomic<bool>* stop = nullptr;
    bool install_signal_handlers = true;
    // Called after every finished frame with the number of frames written so far (benches,
    // tests, a GUI's preview).
    std::function<void(uint64_t frames_done)> on_frame;
};

// What an encode did, for reports and benches.
struct VideoPaintReport {
    uint64_t frames = 0, key_frames = 0, cuts = 0, skipped_frames = 0;
    uint64_t strokes_added = 0, strokes_removed = 0, max_live = 0;
    uint64_t bytes = 0;
    double seconds_key = 0, seconds_inter = 0;  // wall time spent in each kind of frame
    double mean_psnr = 0;
    double min_psnr = 99;                       // the lowest frame's
    uint32_t min_psnr_frame = 0;                // its output index
    uint64_t frames_short = 0;                  // frames short of --target-psnr (paint::reaches_target)
    bool interrupted = false;
    std::vector<uint32_t> key_frame_indices;    // output frame indices
};

// Exit status of a paint stopped by SIGINT/SIGTERM after a finished frame: the output is a
// valid .spt holding every finished frame (a failure is 1, bad options 2).
constexpr int kExitInterrupted = 3;

// Encodes `opts.input` into `opts.output`. Returns the process exit code (0 ok, 1 failure,
// 2 bad options, kExitInterrupted) and prints errors to stderr naming the file or frame.
// `report` may be null.
int run_video_paint(const VideoPaintOptions& opts, io::Progress& progress,
                    VideoPaintReport* report = nullptr);

// The same as a Status (for tests and callers that want the error text).
Status video_paint(const VideoPaintOptions& opts, io::Progress& progress,
                   VideoPaintReport* report = nullptr);

// Sets each of `entries` in `meta`: replacing the value of an entry of the same key, else
// appended (a farm shot's seed and place over a painter's own metadata).
void merge_metadata(std::vector<std::pair<std::string, std::string>>& meta,
                    const std::vector<std::pair<std::string, std::string>>& entries);

}  // namespace spt::video
