#include "plan/planner.hpp"

#include <chrono>
#include <filesystem>

#include <opencv2/imgproc.hpp>

#include "io/sequence.hpp"
#include "plan/gray_frames.hpp"
#include "video/cut_detect.hpp"
#include "video/video_encoder.hpp"
#include "video/video_paint.hpp"

namespace spt::plan {

uint64_t shot_seed(uint64_t plan_seed, long first) { return video::frame_seed(plan_seed, uint32_t(first)); }

Result<Plan> make_plan(const PlanOptions& o, io::Progress& progress, PlanStats* stats) {
    const auto t0 = std::chrono::steady_clock::now();
    Result<io::FrameRange> range = io::parse_frame_range(o.frames);
    if (!range) return range.error();
    if (!range->empty() && (range->spans.size() != 1 || range->step(0) != 1))
        return make_error(Code::InvalidArgument, "--frames: a plan takes one range A-B of consecutive frames, got '" +
                                                     o.frames + "'");
    Result<std::unique_ptr<GrayFrames>> src = open_gray_frames(o.input, o.frames, o.skip_bad_frames, o.threads);
    if (!src) return src.error();
    GrayFrames& source = **src;

    Plan p;
    p.spt_version = o.spt_version;
    std::error_code ec;
    p.input = std::filesystem::absolute(o.input, ec).lexically_normal().string();
    if (ec) p.input = o.input;
    p.seed = o.seed;
    p.keyframe_interval = o.keyframe_interval;
    p.max_task_frames = o.max_task_frames;
    p.paint_args = o.paint_args;
    Rational fps{24, 1};
    if (!o.fps.empty()) {
        Result<Rational> f = video::parse_fps(o.fps);
        if (!f) return f.error();
        fps = *f;
    } else if (source.has_fps()) {
        fps = source.fps();
    }
    p.fps = std::to_string(fps.num) + "/" + std::to_string(fps.den);

    video::CutOptions co;
    co.factor = o.cut_threshold;
    co.window = o.cut_window;
    video::CutDetector cuts(co);
    progress.set_total(double(source.expected_frames()));
    cv::Mat gray;
    long number = 0, prev = -1;
    uint64_t n = 0;
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
    if (n == 0) return make_error(Code::IoError, source.describe() + ": no frames to plan");
    p.last = prev;

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
        stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    }
    return p;
}

}  // namespace spt::plan
