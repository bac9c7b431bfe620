#include "cli/still_setup.hpp"

#include <algorithm>
#include <string>

namespace spt::cli {

Result<StillSetup> still_setup(const PaintCommandOptions& o, uint32_t W, uint32_t H) {
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

}  // namespace spt::cli
