#include "cartoon/retrace_outline.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <future>

namespace spt::cartoon {

std::vector<bool> retraced_regions(const FillLayer& traced, const Frame& painted) {
    const int regions = traced.region.empty() ? 0 : *std::max_element(traced.region.begin(), traced.region.end()) + 1;
    std::vector<bool> retraced(size_t(regions), false), seen(size_t(regions), false);
    for (size_t i = 0; i < traced.strokes.size() && i < traced.region.size(); ++i) {
        const size_t r = size_t(traced.region[i]);
        const bool added = std::any_of(painted.added.begin(), painted.added.end(), [&](const Stroke& a) {
            return a.kind != StrokeKind::Stamp && a == traced.strokes[i];
        });
        retraced[r] = (seen[r] ? retraced[r] : true) && added;
        seen[r] = true;
    }
    return retraced;
}

std::vector<Stroke> with_coarser_regions(const FillLayer& interval, const FillLayer& coarse,
                                         const std::vector<bool>& retraced) {
    auto is_retraced = [&](int r) { return r >= 0 && size_t(r) < retraced.size() && retraced[size_t(r)]; };
    std::vector<Stroke> out;
    size_t a = 0, b = 0;
    const size_t na = std::min(interval.strokes.size(), interval.region.size());
    const size_t nb = std::min(coarse.strokes.size(), coarse.region.size());
    // Both lists are in region order (drawing order); merge them region by region.
    while (a < na || b < nb) {
        const int ra = a < na ? interval.region[a] : INT32_MAX, rb = b < nb ? coarse.region[b] : INT32_MAX;
        const int r = std::min(ra, rb);
        for (; a < na && interval.region[a] == r; ++a)
            if (!is_retraced(r)) out.push_back(interval.strokes[a]);
        for (; b < nb && coarse.region[b] == r; ++b)
            if (is_retraced(r)) out.push_back(coarse.strokes[b]);
    }
    return out;
}

Result<InterFrame> choose_retrace_outline(InterFrame painted, bool any_retraced, double tolerance, double target_psnr,
                                          const paint::ImageView& model, RetraceTrials& trials,
                                          const std::function<Result<InterFrame>(double)>& paint_at, bool parallel) {
    if (!(target_psnr > 0) || !any_retraced) return painted;
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
