#include "cartoon/cartoon_sequence.hpp"

#include <chrono>
#include <cstdio>

#include <opencv2/imgproc.hpp>

#include "cartoon/cartoon_paint.hpp"
#include "cartoon/frame_diff.hpp"
#include "cartoon/motion_field.hpp"
#include "spt/reader.hpp"
#include "spt/writer.hpp"
#include "video/frame_source.hpp"
#include "video/video_encoder.hpp"
#include "video/video_paint.hpp"

namespace spt::cartoon {

Status paint_sequence(const SequenceOptions& opts, SequenceReport& rep) {
    const auto t0 = std::chrono::steady_clock::now();
    auto src = video::open_source(opts.input, opts.frames, opts.skip_bad_frames);
    if (!src) return src.error();
    video::FrameSource& source = **src;
    Rational fps{24, 1};
    if (!opts.fps.empty()) {
        auto f = video::parse_fps(opts.fps);
        if (!f) return f.error();
        fps = *f;
    } else if (source.has_fps()) {
        fps = source.fps();
    }
    video::SourceFrame frame;
    auto got = source.next(frame);
    if (!got) return got.error();
    if (!*got) return make_error(Code::IoError, source.describe() + ": no frames to paint");
    const uint32_t W = frame.image.width, H = frame.image.height;

    paint::PaintSetup setup = paint::make_setup(W, H, opts.background, paint::default_sets(W, H, opts.sets),
                                                opts.templates.empty() ? paint::default_templates() : opts.templates);
    setup.header.fps = fps;
    rep.fps = fps;
    setup.header.frame_count = kUnknownFrameCount;
    auto renderer = Renderer::create(setup.header, setup.templates);
    if (!renderer) return renderer.error();
    StreamInfo info;
    info.header = setup.header;
    info.templates = setup.templates;
    info.metadata = opts.metadata;
    WriterOptions wo;
    wo.coding = opts.stored ? Coding::Stored : Coding::Range;
    wo.atomic_rename = opts.atomic_rename;
    auto writer = Writer::create(opts.output, info, wo);
    if (!writer) return writer.error();

    std::vector<Stroke> live;
    std::vector<cv::Vec3b> palette;
    FillOptions fo = opts.fill;
    io::Image prev;
    Canvas canvas(W, H, opts.background);
    double psnr_sum = 0;
    uint32_t index = 0, since_key = 0;
    for (;;) {
        const io::Image& img = frame.image;
        const cv::Mat rgb(int(H), int(W), CV_8UC3, const_cast<uint8_t*>(img.rgb.data()));
        const paint::ImageView model{W, H, img.rgb.data()};
        const bool key = index == 0 || since_key >= uint32_t(opts.keyframe_interval);
        // Key frames choose the palette, grid and outline tolerance for their interval, so that
        // what stays still traces the same in the frames after.
        FillLayer fill;
        if (key) {
            fo = opts.fill;
            double p = 0;
            fill = fill_for_target(rgb, opts.background, **renderer, fo, opts.paint.target_psnr, nullptr, canvas, p);
            palette = fill.palette;
            fo.grids = {fill.grid ? fill.grid : uint8_t(4)};
            fo.trace.epsilon = fill.tolerance;
        } else {
            fill = build_fill_layer(rgb, opts.background, **renderer, fo, &palette);
        }
        Frame f;
        f.index = index;
        if (key) {
            f.type = FrameType::Key;
            f.added = std::move(fill.strokes);
            rep.polygons_added += f.added.size();
            ++rep.key_frames;
            since_key = 0;
        } else {
            f.type = FrameType::Inter;
            const cv::Mat before(int(H), int(W), CV_8UC3, prev.rgb.data());
            MotionChoice m = choose_motion(live, fill.strokes, rgb, before, **renderer, setup.header, opts.motion);
            FrameDiff d = diff_frame(m.moved, fill.strokes, m.ground_still, **renderer, int(W), int(H));
            if (!m.field.empty()) {
                // The field pays only when it keeps more than it costs: a vector moves every
                // stroke of its block, and what it moves wrongly is drawn again.
                MotionOptions still = opts.motion;
                still.enabled = false;
                MotionChoice z = choose_motion(live, fill.strokes, rgb, before, **renderer, setup.header, still);
                FrameDiff dz = diff_frame(z.moved, fill.strokes, z.ground_still, **renderer, int(W), int(H));
                if (kept_value(live, dz.removed) >= kept_value(live, d.removed) - motion_cost(m.field)) {
                    m = std::move(z);
                    d = std::move(dz);
                }
            }
            if (!m.field.empty()) ++rep.motion_frames;
            f.motion = std::move(m.field);
            rep.polygons_kept += fill.strokes.size() - d.added.size();
            rep.polygons_added += d.added.size();
            rep.removed += d.removed.size();
            f.removed = std::move(d.removed);
            f.added = std::move(d.added);
        }
        // The canvas before the residual stamps: what a decoder shows with this frame's
        // polygons applied.
        std::vector<Stroke> next = live;
        if (Status s = apply_frame(next, f, setup.header); !s) return s;
        if (Status s = (*renderer)->render(canvas, next); !s) return s;
        paint::PaintOptions po = opts.paint;
        po.seed = video::frame_seed(opts.paint.seed, index);
        if (!(po.target_psnr > 0 && paint::psnr(model, canvas.rgb.data()) >= po.target_psnr)) {
            const std::vector<uint8_t> region = residual_region(model, canvas, 24, 2);
            if (!region.empty()) {
                std::vector<Stroke> stamps;
                paint::paint(model, canvas, **renderer, setup, po, stamps, &region);
                rep.stamps_added += stamps.size();
                f.added.insert(f.added.end(), stamps.begin(), stamps.end());
            }
        }
        if (Status s = (*writer)->append(f); !s) {
            (*writer)->abort();
            return s;
        }
        // The live list as a decoder keeps it.
        if (Status s = apply_frame(live, f, setup.header); !s) return s;
        const double p = paint::psnr(model, canvas.rgb.data());
        psnr_sum += p;
        rep.min_psnr = std::min(rep.min_psnr, p);
        ++rep.frames;
        ++index;
        ++since_key;
        prev = img;
        got = source.next(frame);
        if (!got) {
            (*writer)->abort();
            return got.error();
        }
        if (!*got) break;
    }
    if (Status s = (*writer)->finish(); !s) return s;
    rep.bytes = (*writer)->stats().total_bytes;
    rep.mean_psnr = rep.frames ? psnr_sum / double(rep.frames) : 0;
    rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return {};
}

}  // namespace spt::cartoon
