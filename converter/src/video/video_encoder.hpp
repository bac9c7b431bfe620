// The frame-by-frame video painter: decides key and inter frames, carries the live strokes
// with the motion field, repaints where the painting fell behind the source, and writes every
// frame through spt::Writer. The encoder keeps its live list by applying each frame exactly as
// a decoder does (spt::apply_frame), so its canvas is the decoder's canvas.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "frames/cut_detect.hpp"
#include "io/roi_file.hpp"
#include "paint/change_mask.hpp"
#include "paint/frame_seed.hpp"
#include "paint/painter.hpp"
#include "spt/render.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"
#include "spt/writer.hpp"
#include "video/band_render.hpp"
#include "video/motion.hpp"
#include "video/video_paint.hpp"

namespace spt::video {

// The still painter, replaceable for tests (same contract as spt::paint::paint).
using PaintFn = std::function<paint::PaintStats(const paint::ImageView&, Canvas&, const Renderer&,
                                                const paint::PaintSetup&, const paint::PaintOptions&,
                                                std::vector<Stroke>&, const std::vector<uint8_t>*)>;

// What happened to one frame.
struct FrameResult {
    uint32_t index = 0;
    long source_number = 0;
    FrameType type = FrameType::Key;
    bool cut = false;             // the cut detector fired
    CutScore cut_score;
    double repaint_fraction = 0;  // share of the canvas marked for repainting (inter frames)
    double rendered_fraction = 0; // share of the rows rendered again after the motion
    uint32_t added = 0, removed = 0, live = 0;
    double psnr = 0;
    double seconds = 0;
    double seconds_flow = 0, seconds_render = 0, seconds_paint = 0, seconds_cull = 0, seconds_orient = 0;
};

class VideoEncoder {
public:
    // Writes the stream header. `rois` use input frame numbers.
    static Result<std::unique_ptr<VideoEncoder>> create(const VideoPaintOptions& opts, uint32_t width,
                                                        uint32_t height, Rational fps,
                                                        std::vector<io::RoiRange> rois = {},
                                                        std::vector<std::pair<std::string, std::string>> metadata = {},
                                                        PaintFn painter = {});
    ~VideoEncoder();

    // Paints and writes the next frame (RGB8, width * height * 3).
    Result<FrameResult> add_frame(const uint8_t* rgb, long source_number) {
        return add_frame(rgb, nullptr, nullptr, source_number);
    }
    // The same for a format 1.3 target (VideoPaintOptions::scene): `rgb` is the frame's 8-bit
    // proxy, premultiplied by `alpha` (width * height) on alpha canvases, and `linear` the
    // frame itself for colour encoding 1 (both may be null when the target does not use them).
    Result<FrameResult> add_frame(const uint8_t* rgb, const uint8_t* alpha, const paint::LinearView* linear,
                                  long source_number);
    // Writes the ROI records, the index and the end; renames the output into place.
    Status finish();
    // Removes the partial output.
    void abort();

    // The painter's canvas (8-bit; the proxy for a linear target) and, for colour encoding 1,
    // the file's exact linear canvas.
    const Canvas& canvas() const { return canvas_; }
    const Canvas& linear_canvas() const { return lin_canvas_; }
    const Header& file_header() const { return file_header_; }
    const std::vector<Stroke>& live() const { return live_; }
    const paint::PaintSetup& setup() const { return setup_; }
    const Renderer& renderer() const { return *renderer_; }
    const VideoPaintReport& report() const { return report_; }
    uint64_t bytes_written() const;

private:
    VideoEncoder() = default;
    Status encode_key(const paint::ImageView& model, Frame& frame, FrameResult& r);
    // `unchanged`: nothing changed since the previous frame, and the frame codes nothing.
    Status encode_inter(const paint::ImageView& model, const cv::Mat& gray, Frame& frame, FrameResult& r,
                        bool& want_key, bool& unchanged);
    void error_map(const paint::ImageView& model, cv::Mat& err) const;
    Result<std::vector<uint32_t>> strokes_touching(const std::vector<uint32_t>& candidates,
                                                   const paint::ChangeMask& changed) const;
    cv::Mat touched_area(const paint::ChangeMask& changed, const Canvas& before) const;
    cv::Mat visibly_wrong(const paint::ImageView& model, const paint::ChangeMask& changed, double rms) const;
    // Alpha canvases: adds to frame.removed (indices into live_) the strokes that, after the
    // frame's removals and motion, lie mostly over transparent pixels of the model.
    Status remove_transparent(const paint::ImageView& model, Frame& frame, std::vector<Stroke>& moved);
    // Colour encoding 1: the frame as written, its new strokes refit against `linear`.
    Status linear_frame(const paint::LinearView& linear, const Frame& frame, Frame& out);
    paint::PaintOptions frame_paint_options(long source_number, uint32_t index) const;
    // The orientation field for this frame's new strokes (see VideoPaintOptions); `map` is the
    // backward warp of the previous frame (empty on key frames), `region` the repaint mask.
    void update_orientation(const paint::ImageView& model, const cv::Mat& map, const cv::Mat& region);

    VideoPaintOptions opts_;
    paint::PaintSetup setup_;   // the painter's (8-bit proxy) header
    Header file_header_;        // the header written (format 1.3 targets differ from setup_'s)
    bool linear_ = false;
    paint::ProxyTransform transform_;
    std::unique_ptr<Renderer> lin_renderer_;
    std::vector<Stroke> live_lin_;  // live_ with the file's linear colours
    Canvas lin_canvas_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<BandRenderer> band_;  // incremental update (VideoPaintOptions::incremental_render)
    std::unique_ptr<Writer> writer_;
    PaintFn painter_;
    std::unique_ptr<FlowEstimator> flow_;
    CutDetector cuts_;

    std::vector<io::RoiRange> rois_;
    std::vector<std::pair<long, long>> roi_used_;  // output frame range each ROI covered
    std::vector<Stroke> live_;
    Canvas canvas_;
    cv::Mat prev_gray_, flow_field_;
    std::vector<uint8_t> prev_rgb_, prev_alpha_;  // the previous source frame
    double last_psnr_ = 0;                        // the previous frame's painting
    cv::Mat ref_err_;  // error the painter left where it last painted, carried by the motion
    std::vector<uint8_t> orient_;      // per-pixel orientation indices (empty: painter's own)
    std::vector<uint8_t> paint_orient_;  // orient_ with this frame's flow orientations
    uint32_t since_orient_ = 0;        // frames since orient_ was computed from a source frame
    std::vector<uint32_t> pending_removals_;  // hidden strokes, removed by the next frame
    std::vector<uint8_t> scratch_;
    uint32_t next_index_ = 0, since_key_ = 0;
    VideoPaintReport report_;
    double psnr_sum_ = 0;
    double lambda_scale_ = 1.0;        // rate control: multiplies opts_.paint.lambda
    bool finished_ = false;
};

using paint::frame_seed;  // the per-frame seed (paint/frame_seed.hpp)

}  // namespace spt::video
