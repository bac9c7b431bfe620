#include "cartoon/retrace_outline.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <optional>

namespace spt::cartoon {

uint64_t outline_vertices(const std::vector<Stroke>& strokes) {
    uint64_t n = 0;
    for (const Stroke& s : strokes) {
        if (s.kind == StrokeKind::Polygon) n += s.polygon.points.size();
        if (s.kind == StrokeKind::Curve) n += s.curve.points.size();
    }
    return n;
}

bool better_at_target(const InterFrame& a, const InterFrame& b, const paint::ImageView& model, double target_psnr) {
    const double pa = paint::psnr(model, a.canvas.rgb.data());
    const double pb = paint::psnr(model, b.canvas.rgb.data());
    const bool reach_a = pa >= target_psnr - 0.005, reach_b = pb >= target_psnr - 0.005;
    if (reach_a != reach_b) return reach_b;
    if (!reach_a) return pb > pa;
    return b.cost < a.cost;
}

Result<InterFrame> choose_retrace_outline(InterFrame painted, uint64_t traced_vertices, double tolerance,
                                          double target_psnr, const paint::ImageView& model, RetraceTrials& trials,
                                          const std::function<Result<InterFrame>(double)>& paint_at, bool parallel) {
    if (!(target_psnr > 0) || traced_vertices == 0 ||
        double(outline_vertices(painted.frame.added)) < kRetracedShare * double(traced_vertices))
        return painted;
    if (trials.wait > 0) {
        --trials.wait;
        return painted;
    }
    // The first factor beside the others with threads; chosen in factor order either way.
    auto first = std::async(parallel ? std::launch::async : std::launch::deferred,
                            [&] { return paint_at(tolerance * kRetraceFactors[0]); });
    std::vector<Result<InterFrame>> tried;
    for (size_t i = 1; i < kRetraceFactors.size(); ++i) tried.push_back(paint_at(tolerance * kRetraceFactors[i]));
    tried.insert(tried.begin(), first.get());
    bool won = false;
    for (size_t i = 0; i < tried.size(); ++i) {
        if (!tried[i]) return tried[i].error();
        if (std::getenv("SPT_CARTOON_DEBUG"))
            std::fprintf(stderr, "  outline %.2f px: cost %.0f against %.0f\n", tolerance * kRetraceFactors[i],
                         tried[i]->cost, painted.cost);
        if (better_at_target(painted, *tried[i], model, target_psnr)) {
            painted = std::move(*tried[i]);
            won = true;
        }
    }
    trials.period = won ? 1 : std::min<uint32_t>(trials.period * 2, 16);
    trials.wait = trials.period - 1;
    return painted;
}

}  // namespace spt::cartoon
