#include "job/still_setup.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace spt::job {

Result<StillSetup> still_setup(const PaintJob& o, uint32_t W, uint32_t H) {
    std::vector<StrokeSet> sets = o.set_sizes.empty() ? paint::default_sets(W, H, o.sets) : o.set_sizes;
    auto templates = paint_templates(o.templates_dir);
    if (!templates) return templates.error();
    StillSetup s;
    s.setup = paint::make_setup(W, H, o.background, std::move(sets), std::move(*templates));
    s.paint = o.paint;
    s.paint.rois.clear();
    for (const RoiSpec& r : o.rois) {
        if (r.first_frame > 0) continue;  // a still is frame 0
        if (int64_t(r.rect.x) >= W || int64_t(r.rect.y) >= H)
            return make_error(Code::InvalidArgument,
                              "region of interest " + std::to_string(r.rect.x) + "," + std::to_string(r.rect.y) + "," +
                                  std::to_string(r.rect.w) + "," + std::to_string(r.rect.h) + " lies outside the " +
                                  std::to_string(W) + "x" + std::to_string(H) + " image");
        s.paint.rois.push_back(r.rect);
        Roi roi;
        roi.first_frame = roi.last_frame = 0;
        roi.x = uint32_t(r.rect.x);
        roi.y = uint32_t(r.rect.y);
        roi.w = uint32_t(std::min<int64_t>(r.rect.w, int64_t(W) - r.rect.x));
        roi.h = uint32_t(std::min<int64_t>(r.rect.h, int64_t(H) - r.rect.y));
        s.rois.push_back(roi);
    }
    return s;
}

double search_target_bytes(const PaintJob& o, const std::function<paint::RatePoint(double)>& trial,
                           double lambda) {
    const paint::RatePoint best = paint::search_bytes(trial, o.target_bytes, 0.03, 9, lambda);
    std::fprintf(stderr, "spt paint: --target-bytes %llu: lambda %.4g gives %llu bytes (%+.1f%%), %.2f dB\n",
                 (unsigned long long)o.target_bytes, best.lambda, (unsigned long long)best.bytes,
                 100.0 * (double(best.bytes) - double(o.target_bytes)) / double(o.target_bytes), best.psnr);
    return best.lambda;
}

}  // namespace spt::job
