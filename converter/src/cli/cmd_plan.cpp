// spt plan: one cheap pass over a sequence or video that cuts it into shots (farm tasks) and
// writes the plan every task paints from (converter/src/plan/README.md).
#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "cli/plan_job.hpp"
#include "cli/paint_options.hpp"
#include "io/progress.hpp"
#include "io/sequence.hpp"
#include "plan/planner.hpp"
#include "spt/version.hpp"

namespace spt::cli {

int cmd_plan(int argc, char** argv) {
    PaintCommandOptions o;
    if (int rc = parse_paint_options(argc, argv, o, "plan"); rc >= 0) return rc;
    std::error_code ec;
    if (!io::is_sequence_pattern(o.input) && !io::is_video_file(o.input) && !std::filesystem::is_directory(o.input, ec)) {
        std::fprintf(stderr, "spt plan: %s: a plan is for an image sequence or a video; paint a still with spt paint\n",
                     o.input.c_str());
        return 2;
    }
    if (!o.set_sizes.empty()) {
        std::fprintf(stderr, "spt plan: --set-sizes is not supported for sequences yet; use --sets N\n");
        return 2;
    }
    plan::PlanOptions po;
    po.input = o.input;
    po.frames = o.frames;
    po.fps = o.fps;
    po.skip_bad_frames = o.skip_bad_frames;
    po.threads = o.paint.threads;
    po.cut_threshold = o.cut_threshold;
    po.keyframe_interval = o.keyframe_interval;
    po.max_task_frames = o.max_task_frames;
    po.cut_scan = o.cut_scan == "full"      ? plan::CutScan::Full
                  : o.cut_scan == "sampled" ? plan::CutScan::Sampled
                  : o.cut_scan == "tasks"   ? plan::CutScan::Tasks
                                            : plan::CutScan::Auto;
    po.cut_step = o.cut_step;
    po.cut_history = o.cut_history;
    po.seed = o.paint.seed;
    po.job = plan_job(o);
    po.spt_version = library_version();
    io::Progress progress(o.progress, "plan", 0);
    plan::PlanStats stats;
    Result<plan::Plan> p = plan::make_plan(po, progress, &stats);
    if (!p) {
        progress.finish(false, p.error().message);
        std::fprintf(stderr, "spt plan: %s\n", p.error().message.c_str());
        return p.error().code == Code::InvalidArgument ? 2 : 1;
    }
    if (Status st = plan::write_plan(*p, o.output); !st) {
        progress.finish(false, st.error().message);
        std::fprintf(stderr, "spt plan: %s\n", st.error().message.c_str());
        return 1;
    }
    // A tasks plan holds no cuts: its tasks find them as they paint.
    const std::string cuts = p->cut_scan == "tasks" ? std::string("cuts found by the tasks")
                                                    : std::to_string(p->cuts.size() - 1) + " cuts";
    char detail[320];
    std::snprintf(detail, sizeof detail,
                  "%llu frames %ld-%ld (%llu read, %s cut scan), %s, %zu shots, plan %s, %.2f s (%.2f ms a frame)",
                  (unsigned long long)stats.frames, p->first, p->last, (unsigned long long)stats.decoded,
                  p->cut_scan.c_str(), cuts.c_str(), p->shots.size(),
                  p->id.c_str(), stats.seconds, stats.frames ? 1000.0 * stats.seconds / double(stats.frames) : 0.0);
    progress.finish(true, detail);
    if (!stats.shortfall.empty()) std::fprintf(stderr, "spt plan: warning: %s\n", stats.shortfall.c_str());
    if (o.progress != io::ProgressMode::Json) std::fprintf(stderr, "spt plan: %s: %s\n", o.output.c_str(), detail);
    return 0;
}

}  // namespace spt::cli
