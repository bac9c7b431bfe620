#include "video/video_paint.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "io/sequence.hpp"
#include "frames/frame_source.hpp"
#include "io/roi_file.hpp"
#include "frames/stop_signal.hpp"
#include "video/video_encoder.hpp"
#include "frames/video_scene.hpp"
#include "spt/utf8.hpp"
#include "spt/concat.hpp"

namespace spt::video {

namespace {

// The least peak of a sequence's linear proxy (paint/linear_proxy.hpp): a dark first frame
// leaves room for highlights later.
constexpr double kSequencePeakMin = 16.0;

std::string options_text(const VideoPaintOptions& o) {
    std::ostringstream s;
    s << "sets=" << o.sets << " keyframe-interval=" << o.keyframe_interval << " cut-threshold=" << o.cut_threshold
      << " flow=" << flow_method_name(o.flow) << " block=" << o.block_size << " repaint-error=" << o.repaint_error
      << " max-strokes=" << o.paint.max_strokes << " max-inter-strokes=" << o.max_inter_strokes
      << " target-psnr=" << o.paint.target_psnr << " threshold=" << o.paint.threshold
      << " lambda=" << o.paint.lambda << " orient=" << (o.flow_orientation ? "flow+edges" : "edges");
    return s.str();
}

}  // namespace

void merge_metadata(std::vector<std::pair<std::string, std::string>>& meta,
                    const std::vector<std::pair<std::string, std::string>>& entries) {
    for (const auto& [k, v] : entries) {
        auto it = std::find_if(meta.begin(), meta.end(), [&](const auto& e) { return e.first == k; });
        if (it != meta.end()) it->second = v;
        else meta.emplace_back(k, v);
    }
}

// The first file of the whole sequence, read as scene-linear light.
Result<io::SceneImage> first_scene_file(const VideoPaintOptions& opts) {
    Result<std::vector<io::SequenceFile>> all = io::list_sequence(opts.input);
    if (!all) return all.error();
    if (all->empty()) return make_error(Code::IoError, opts.input + ": no frames found");
    return io::read_scene_image(all->front().path, opts.scene_read);
}

Status video_paint(const VideoPaintOptions& opts, io::Progress& progress, VideoPaintReport* report) {
    StopSignals guard(opts.install_signal_handlers);
    auto stop_requested = [&] {
        return StopSignals::requested() || (opts.stop && opts.stop->load());
    };

    if (opts.output.empty()) return make_error(Code::InvalidArgument, "no output file given");
    std::vector<io::RoiRange> rois;
    if (!opts.roi_file.empty()) {
        Result<std::vector<io::RoiRange>> r = io::read_roi_file(opts.roi_file);
        if (!r) return r.error();
        rois = std::move(*r);
    }
    // Format 1.3 targets. "auto" is decided on the first file of the whole sequence (not of
    // --frames), and so is the linear proxy's peak, so that every farm task of a plan paints
    // the same way as one process would; a video file's first frame decides for a video file.
    if (opts.color_encoding != "auto" && opts.color_encoding != "srgb8" && opts.color_encoding != "linear")
        return make_error(Code::InvalidArgument, "--color-encoding: expected auto, srgb8 or linear, got '" + opts.color_encoding + "'");
    if (opts.alpha != "auto" && opts.alpha != "on" && opts.alpha != "off")
        return make_error(Code::InvalidArgument, "--alpha: expected auto, on or off, got '" + opts.alpha + "'");
    const bool video = io::is_video_file(opts.input);
    bool video_alpha = false;
    if (video && opts.alpha == "auto" && opts.color_encoding != "linear") {
        Result<bool> a = video_has_alpha(opts.input);
        if (!a) return a.error();
        video_alpha = *a;
    }
    const bool want_scene = !(opts.color_encoding == "srgb8" && opts.alpha == "off") &&
                            !(video && opts.color_encoding != "linear" && opts.alpha != "on" && !video_alpha);
    paint::SceneTarget target = opts.scene;
    bool scene = false;
    double peak = 1.0;
    if (want_scene) {
        Result<io::SceneImage> first = video ? first_scene_frame(opts.input, opts.scene_read) : first_scene_file(opts);
        if (!first) return first.error();
        const paint::LinearView lv{first->width, first->height, first->rgba.data()};
        target.linear = opts.color_encoding == "linear" || (opts.color_encoding == "auto" && first->is_float);
        target.alpha = opts.alpha == "on" || (opts.alpha == "auto" && first->has_alpha && paint::has_transparency(lv));
        scene = target.linear || target.alpha;
        // Headroom over the first frame for brighter frames later in the shot.
        if (target.linear) peak = std::max(kSequencePeakMin, 2.0 * paint::proxy_for(lv).peak);
    }
    // The 8-bit sequence painter reads frames itself (read_image): refuse rather than ignore.
    if (!scene && (!opts.scene_read.colorspace.empty() || !opts.scene_read.layer.empty()))
        return make_error(Code::InvalidArgument,
                          opts.input + ": --colorspace and --layer apply to sequences painted with alpha or in "
                                       "scene-linear colour; this one paints as 8-bit sRGB (add --color-encoding "
                                       "linear, or leave out the flag)");
    Result<std::unique_ptr<FrameSource>> src = open_source(opts.input, opts.frames, opts.skip_bad_frames,
                                                           scene ? &opts.scene_read : nullptr);
    if (!src) return src.error();
    SourceFrame frame;
    Result<bool> got = (*src)->next(frame);
    if (!got) return got.error();
    if (!*got) {
        const std::string why = (*src)->shortfall();
        return make_error(Code::IoError, why.empty() ? (*src)->describe() + ": no frames to paint" : why);
    }
    FrameSource& source = **src;

    Rational fps{24, 1};
    if (!opts.fps.empty()) {
        Result<Rational> f = parse_fps(opts.fps);
        if (!f) return f.error();
        fps = *f;
    } else if (source.has_fps()) {
        fps = source.fps();
    }

    std::vector<std::pair<std::string, std::string>> meta = {
        {"software", "spt video painter"},
        {"source", printable_text(opts.input)},  // names need not be UTF-8
        {"painter.seed", std::to_string(opts.paint.seed)},
        {"painter.options", printable_text(options_text(opts) + (scene ? std::string(" alpha=") + (target.alpha ? "on" : "off") +
                                                                              " color-encoding=" + (target.linear ? "linear" : "srgb8")
                                                                        : std::string()))},
    };
    // SPEC.md 3.3: the source's own frame numbers, when the painted frames are consecutive.
    if (frame.number > 0 && frames_consecutive(opts.frames)) meta.emplace_back(kFirstFrameKey, std::to_string(frame.number));
    merge_metadata(meta, opts.metadata);
    VideoPaintOptions eo = opts;
    if (opts.target_bytes > 0) {
        // Per second: N / fps bytes a frame. Whole clip: N over the frames the source expects
        // (unknown: over one key frame interval, the best guess of a clip's length).
        const double per_frame = opts.target_bytes_per_second
                                     ? double(opts.target_bytes) * fps.den / std::max<uint32_t>(1, fps.num)
                                     : double(opts.target_bytes) /
                                           double(source.expected_frames() > 0 ? source.expected_frames()
                                                                               : uint64_t(opts.keyframe_interval));
        eo.frame_byte_budget = std::max(1.0, per_frame);
    }
    eo.scene = scene ? target : paint::SceneTarget{};
    eo.scene_peak = peak;
    const uint32_t fw = scene ? frame.scene.width : frame.image.width, fh = scene ? frame.scene.height : frame.image.height;
    Result<std::unique_ptr<VideoEncoder>> enc = VideoEncoder::create(eo, fw, fh, fps, rois, meta);
    if (!enc) return enc.error();
    VideoEncoder& encoder = **enc;

    progress.set_total(double(source.expected_frames()));
    uint64_t skipped = 0;
    bool interrupted = false;
    std::vector<uint8_t> proxy_rgb, proxy_alpha;
    for (;;) {
        if (frame.repeated) {
            ++skipped;
            std::fprintf(stderr, "spt paint: warning: %s; repeating the previous frame\n", frame.problem.c_str());
        }
        Result<FrameResult> r = make_error(Code::BadState, "no frame");
        if (scene) {
            // The frame's 8-bit proxy (premultiplied by its alpha), and the frame itself.
            for (const std::string& w : frame.scene.warnings) std::fprintf(stderr, "spt paint: warning: %s\n", w.c_str());
            const paint::LinearView lv{frame.scene.width, frame.scene.height, frame.scene.rgba.data()};
            const paint::ProxyTransform t = target.linear ? paint::ProxyTransform::with_peak(eo.scene_peak) : paint::ProxyTransform{};
            paint::make_proxy(lv, t, proxy_rgb, target.alpha ? &proxy_alpha : nullptr);
            r = encoder.add_frame(proxy_rgb.data(), target.alpha ? proxy_alpha.data() : nullptr, &lv, frame.number);
        } else {
            r = encoder.add_frame(frame.image.rgb.data(), frame.number);
        }
        if (!r) {
            encoder.abort();
            Error e = r.error();
            e.message = source.describe() + " frame " + std::to_string(frame.number) + ": " + e.message;
            return e;
        }
        const VideoPaintReport& rep = encoder.report();
        std::ostringstream detail;
        detail << (r->type == FrameType::Key ? "key" : "inter") << " frame " << r->index << ", " << r->added
               << " strokes added, " << r->live << " live, " << std::fixed;
        detail.precision(1);
        detail << r->psnr << " dB";
        progress.update(double(rep.frames), detail.str());
        if (opts.on_frame) opts.on_frame(rep.frames);
        if (stop_requested()) {
            interrupted = true;
            break;
        }
        got = source.next(frame);
        if (!got) {
            encoder.abort();
            return got.error();
        }
        if (!*got) {
            if (const std::string why = source.shortfall(); !why.empty())
                std::fprintf(stderr, "spt paint: warning: %s\n", why.c_str());
            break;
        }
    }
    Status st = encoder.finish();
    if (report) {
        *report = encoder.report();
        report->skipped_frames = skipped;
        report->interrupted = interrupted;
    }
    if (!st) return st;
    if (interrupted)
        return make_error(Code::BadState, "interrupted: " + opts.output + " holds the " +
                                              std::to_string(encoder.report().frames) + " finished frames");
    return {};
}

int run_video_paint(const VideoPaintOptions& opts, io::Progress& progress, VideoPaintReport* report) {
    VideoPaintReport local;
    if (!report) report = &local;
    Status st = video_paint(opts, progress, report);
    if (!st && report->interrupted && st.error().code == Code::BadState) {
        // Stopped by a signal after a finished frame: the output is valid (README: exit 3).
        progress.finish(false, st.error().message);
        std::fprintf(stderr, "spt paint: %s\n", st.error().message.c_str());
        return kExitInterrupted;
    }
    if (!st) {
        progress.finish(false, st.error().message);
        std::fprintf(stderr, "spt paint: %s\n", st.error().message.c_str());
        return st.error().code == Code::InvalidArgument ? 2 : 1;
    }
    progress.finish(true, opts.output);
    return 0;
}

}  // namespace spt::video
