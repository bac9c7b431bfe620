#include "cli/paint_args.hpp"

#include <cstdio>
#include <filesystem>

namespace spt::cli {

namespace {

// Shortest text strtod reads back to the same double.
std::string exact(double v) {
    char buf[40];
    for (int prec = 6; prec <= 17; ++prec) {
        std::snprintf(buf, sizeof buf, "%.*g", prec, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
}

std::string absolute(const std::string& p) {
    std::error_code ec;
    const auto a = std::filesystem::absolute(p, ec);
    return ec ? p : a.lexically_normal().string();
}


}  // namespace

// Every option written here must be in plan/plan_args.cpp's list, or plans that carry it are
// refused when read.
std::vector<std::string> paint_args(const PaintCommandOptions& o) {
    std::vector<std::string> a;
    auto opt = [&](const char* name, const std::string& v) { a.push_back(name); a.push_back(v); };
    // The painter first: a plan's tasks paint in the style it was made with.
    if (o.style != "painterly") {
        opt("--style", o.style);
        if (o.outline_tolerance > 0) opt("--outline-tolerance", exact(o.outline_tolerance));
        if (o.outline_smooth >= 0) opt("--outline-smooth", exact(o.outline_smooth));
        if (o.min_region > 0) opt("--min-region", std::to_string(o.min_region));
        if (o.min_color_share > 0) opt("--min-color-share", exact(o.min_color_share));
        if (!o.lines) a.push_back("--no-lines");
    }
    if (o.set_sizes.empty()) {
        opt("--sets", std::to_string(o.sets));
    } else {
        std::string s;
        for (size_t i = 0; i < o.set_sizes.size(); ++i)
            s += (i ? "," : "") + std::to_string(o.set_sizes[i].width) + "x" + std::to_string(o.set_sizes[i].height);
        opt("--set-sizes", s);
    }
    opt("--max-strokes", std::to_string(o.paint.max_strokes));
    if (o.paint.target_psnr > 0) opt("--target-psnr", exact(o.paint.target_psnr));
    opt("--threshold", exact(o.paint.threshold));
    opt("--lambda", exact(o.paint.lambda));
    opt("--temperature", exact(o.paint.temperature));
    opt("--color-step", std::to_string(o.paint.color_step));
    opt("--orient", job::orient_name(o.paint.orient));
    if (!o.templates_dir.empty()) opt("--templates", absolute(o.templates_dir));
    for (size_t i = 0; i < o.cli_roi_count && i < o.rois.size(); ++i) {
        const paint::Rect& r = o.rois[i].rect;
        opt("--roi", std::to_string(r.x) + "," + std::to_string(r.y) + "," + std::to_string(r.w) + "," + std::to_string(r.h));
    }
    if (!o.roi_file.empty()) opt("--roi-file", absolute(o.roi_file));
    opt("--background", std::to_string(o.background.r) + "," + std::to_string(o.background.g) + "," +
                            std::to_string(o.background.b));
    if (o.stored) a.push_back("--stored");
    opt("--coding", std::to_string(o.coding));
    if (o.target_bytes > 0) opt("--target-bytes", std::to_string(o.target_bytes) + (o.target_bytes_per_second ? "/s" : ""));
    if (!o.fps.empty()) opt("--fps", o.fps);
    if (o.skip_bad_frames) a.push_back("--skip-bad-frames");
    opt("--keyframe-interval", std::to_string(o.keyframe_interval));
    opt("--cut-threshold", exact(o.cut_threshold));
    opt("--flow", o.flow);
    opt("--max-inter-strokes", std::to_string(o.max_inter_strokes));
    opt("--motion-block", std::to_string(o.block_size));
    if (o.flow_orientation) a.push_back("--flow-orientation");
    if (o.color_encoding != "auto") opt("--color-encoding", o.color_encoding);
    if (o.alpha != "auto") opt("--alpha", o.alpha);
    if (!o.colorspace.empty()) opt("--colorspace", o.colorspace);
    if (!o.ocio_config.empty()) opt("--ocio", absolute(o.ocio_config));
    if (!o.layer.empty()) opt("--layer", o.layer);
    return a;
}

}  // namespace spt::cli
