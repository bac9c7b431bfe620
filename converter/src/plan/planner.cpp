#include "plan/planner.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>

#include <opencv2/imgproc.hpp>

#include "frames/cut_detect.hpp"
#include "frames/frame_rate.hpp"
#include "io/sequence.hpp"
#include "paint/frame_seed.hpp"
#include "plan/cut_frame_stores.hpp"
#include "plan/frame_span.hpp"
#include "plan/gray_frames.hpp"
#include "plan/sampled_cuts.hpp"

namespace spt::plan {

uint64_t shot_seed(uint64_t plan_seed, long first) { return paint::frame_seed(plan_seed, uint32_t(first)); }

Result<Plan> make_plan(const PlanOptions& o, io::Progress& progress, PlanStats* stats) {
    const auto t0 = std::chrono::steady_clock::now();
    Result<io::FrameRange> range = io::parse_frame_range(o.frames);
    if (!range) return range.error();
    if (!range->empty() && (range->spans.size() != 1 || range->step(0) != 1))
        return make_error(Code::InvalidArgument, "--frames: a plan takes one range A-B of consecutive frames, got '" +
                                                     o.frames + "'");
    Plan p;
    p.spt_version = o.spt_version;
    std::error_code ec;
    p.input = std::filesystem::absolute(o.input, ec).lexically_normal().string();
    if (ec) p.input = o.input;
    p.seed = o.seed;
    p.keyframe_interval = o.keyframe_interval;
    p.max_task_frames = o.max_task_frames;
    p.job = o.job;
    // The frame rate: --fps, else the container's, else 24.
    auto set_fps = [&](bool has, Rational container) -> Status {
        Rational fps{24, 1};
        if (!o.fps.empty()) {
            Result<Rational> f = video::parse_fps(o.fps);
            if (!f) return f.error();
            fps = *f;
        } else if (has) {
            fps = container;
        }
        p.fps = std::to_string(fps.num) + "/" + std::to_string(fps.den);
        return {};
    };


    video::CutOptions co;
    co.factor = o.cut_threshold;
    co.window = o.cut_window;
    uint64_t n = 0, decoded = 0;
    const CutScan scan = o.cut_scan != CutScan::Auto ? o.cut_scan
                         : io::is_video_file(o.input) ? CutScan::Tasks
                                                      : CutScan::Sampled;
    if (scan == CutScan::Tasks) {
        // No scan: each task runs the painter's detector on the frames it decodes anyway, so
        // the plan only counts frames (one frame decoded, for the canvas).
        p.cut_scan = "tasks";
        p.cut_step = 0;
        p.cut_history = 0;
        Result<FrameSpan> span = probe_frames(o.input, o.frames);
        if (!span) return span.error();
        if (Status st = set_fps(span->has_fps, span->fps); !st) return st.error();
        p.first = span->first;
        p.last = span->last;
        p.width = span->width;
        p.height = span->height;
        p.cuts.push_back(p.first);
        n = p.frames();
        decoded = 1;
        progress.set_total(1);
        progress.update(1, "frame " + std::to_string(p.first));
    } else if (scan == CutScan::Full) {
        p.cut_scan = "full";
        p.cut_step = 1;
        p.cut_history = 0;
        Result<std::unique_ptr<GrayFrames>> src = open_gray_frames(o.input, o.frames, o.skip_bad_frames, o.threads);
        if (!src) return src.error();
        GrayFrames& source = **src;
        if (Status st = set_fps(source.has_fps(), source.has_fps() ? source.fps() : Rational{}); !st) return st.error();
        video::CutDetector cuts(co);
        progress.set_total(double(source.expected_frames()));
        cv::Mat gray;
        long number = 0, prev = -1;
        for (;;) {
            Result<bool> got = source.next(number, gray);
            if (!got) return got.error();
            if (!*got) break;
            if (prev >= 0 && number != prev + 1)
                return make_error(Code::InvalidArgument, source.describe() + ": frame " + std::to_string(number) +
                                                             " follows frame " + std::to_string(prev) +
                                                             ": a plan needs consecutive frame numbers");
            if (n == 0) {
                p.first = number;
                p.width = uint32_t(gray.cols);
                p.height = uint32_t(gray.rows);
            }
            // The painter's detector on the painter's gray (video_encoder.cpp add_frame).
            const video::CutScore s = cuts.push(gray);
            if (n == 0 || s.cut) p.cuts.push_back(number);
            prev = number;
            ++n;
            progress.update(double(n), "frame " + std::to_string(number));
        }
        if (n == 0) {
            const std::string why = source.shortfall();
            return make_error(Code::IoError, why.empty() ? source.describe() + ": no frames to plan" : why);
        }
        p.last = prev;
        decoded = n;
        if (stats) stats->shortfall = source.shortfall();
    } else {
        p.cut_scan = "sampled";
        p.cut_step = std::max(1, o.cut_step);
        SampledCutOptions so;
        so.detector = co;
        so.step = p.cut_step;
        so.history = std::clamp(o.cut_history, 1, std::max(2, o.cut_window));
        p.cut_history = so.history;
        Result<std::unique_ptr<GrayFrameFiles>> files = open_gray_frame_files(o.input, o.frames);
        if (!files) return files.error();
        std::unique_ptr<PlanCutFrames> frames;
        std::string what;
        if (*files) {
            what = (*files)->describe();
            progress.set_total(double((*files)->count()));
            if (Status st = set_fps(false, {}); !st) return st.error();
            frames = cut_frames_of_files(std::move(*files), so, o.skip_bad_frames, o.threads);
        } else {
            Result<std::unique_ptr<GrayFrames>> src = open_gray_frames(o.input, o.frames, o.skip_bad_frames, o.threads);
            if (!src) return src.error();
            what = (*src)->describe();
            progress.set_total(double((*src)->expected_frames()));
            if (Status st = set_fps((*src)->has_fps(), (*src)->has_fps() ? (*src)->fps() : Rational{}); !st)
                return st.error();
            frames = cut_frames_in_order(std::move(*src), so);
        }
        Result<const video::CutFrame*> f0 = frames->at(0);
        if (!f0) return f0.error();
        if (!*f0) return make_error(Code::IoError, what + ": no frames to plan");
        Result<std::vector<size_t>> cuts = sampled_cuts(*frames, frames->first_number(), so, [&](size_t pos) {
            progress.update(double(pos + 1), "frame " + std::to_string(frames->first_number() + long(pos)));
        });
        if (!cuts) return cuts.error();
        n = frames->count();
        decoded = frames->decoded();
        if (stats) stats->shortfall = frames->shortfall();
        p.first = frames->first_number();
        p.last = p.first + long(n) - 1;
        p.width = uint32_t(frames->width());
        p.height = uint32_t(frames->height());
        p.cuts.push_back(p.first);
        for (size_t c : *cuts) p.cuts.push_back(p.first + long(c));
    }

    for (size_t c = 0; c < p.cuts.size(); ++c) {
        const long a = p.cuts[c], b = c + 1 < p.cuts.size() ? p.cuts[c + 1] - 1 : p.last;
        const auto pieces = split_shot(a, b, o.keyframe_interval, o.max_task_frames);
        for (size_t k = 0; k < pieces.size(); ++k) {
            Shot s;
            s.index = p.shots.size();
            s.first = pieces[k].first;
            s.last = pieces[k].second;
            s.seed = shot_seed(o.seed, s.first);
            s.starts_at_cut = k == 0;
            for (long f = s.first; f <= s.last; f += std::max(1, o.keyframe_interval)) s.key_frames.push_back(f);
            p.shots.push_back(std::move(s));
        }
    }
    p.id = compute_id(p);
    if (stats) {
        stats->frames = n;
        stats->decoded = decoded;
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return p;
}

}  // namespace spt::plan
