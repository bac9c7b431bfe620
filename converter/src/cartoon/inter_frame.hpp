// One cartoon inter frame, planned twice and the cheaper painting kept. The frame diff decides
// which old polygons stay (frame_diff.hpp), the stamp keep rule which old stamps
// (stamp_keep.hpp), and the stamp painter paints the rest to the target. Whether an old
// polygon may stand for a retraced one (and a small new one be left out) is a guess about what
// the stamps correcting it will cost: right on compressed video, whose noise retraces still
// outlines a little every frame; wrong on a morph, where every outline really changed. So both
// plans are made, strict and lenient; when they differ both are painted and the one that
// costs fewer bytes at the target is written.
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "cartoon/cartoon_paint.hpp"
#include "cartoon/motion_field.hpp"
#include "paint/painter.hpp"
#include "spt/render.hpp"
#include "spt/types.hpp"

namespace spt::cartoon {

struct InterInput {
    const std::vector<Stroke>* live = nullptr;      // the previous frame's live list
    const std::vector<Stroke>* polygons = nullptr;  // this frame's traced polygons, drawing order
    cv::Mat cur, prev;                              // this and the previous source frame (CV_8UC3)
    paint::ImageView model;                         // `cur`
    const Canvas* shown = nullptr;                  // the previous frame as a decoder showed it
    const Renderer* renderer = nullptr;
    const paint::PaintSetup* setup = nullptr;
    MotionOptions motion;
    paint::PaintOptions paint;                      // the residual stamps (this frame's seed)
};

struct InterFrame {
    Frame frame;                 // type, motion, removed, added (polygons then stamps); no index
    Canvas canvas;               // the frame as a decoder renders it
    uint64_t polygons_added = 0, polygons_kept = 0, stamps = 0;
    uint32_t stood_in = 0, left_out = 0;
    bool lenient = false;        // the lenient painting was the cheaper
    bool unchanged = false;      // the source did not change: the frame codes nothing
    bool patched = false;        // the patch (every stroke kept, stamps where it changed) won
    double cost = 0;             // estimated bytes
    double kept_psnr = 0;        // before the new stamps
};

// The frame: where the source did not change since the previous frame (by more than the
// target's RMS error), nothing is touched; a frame where nothing changed codes nothing.
// Otherwise the cheapest at the target of the patch (every stroke kept, stamps painted only
// where the source changed) and the retraced frame (paint_retraced).
Result<InterFrame> paint_inter_frame(const InterInput& in);

// The frame retraced: the strict and lenient plans above, the cheaper at the target.
Result<InterFrame> paint_retraced(const InterInput& in);


// Of `a` and `b`, painted to `target_psnr` of `model`, whether `b` is better: both reach the
// target and `b` costs fewer estimated bytes; only `b` reaches it; or neither does and `b` is
// closer. (The strict and lenient plans are chosen so, and the retrace trials.)
bool better_at_target(const InterFrame& a, const InterFrame& b, const paint::ImageView& model, double target_psnr);


// Roughly what a frame costs in bytes, range coded: per polygon its header and vertices, per
// stamp, per removal (measured with `spt info --json` on the butterfly: a stamp 5.6 bytes, a
// removal 0.3, a polygon vertex about 2).
double frame_cost(const Frame& f);

}  // namespace spt::cartoon
