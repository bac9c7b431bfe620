#include "job/paint_job.hpp"

#include <filesystem>
#include <sstream>

#include "io/template_loader.hpp"
#include "spt/utf8.hpp"
#include "spt/version.hpp"

namespace spt::job {

const char* orient_name(paint::OrientMode m) {
    switch (m) {
        case paint::OrientMode::Edges: return "edges";
        case paint::OrientMode::Gradient: return "gradient";
        case paint::OrientMode::Random: return "random";
    }
    return "?";
}

std::string PaintJob::canonical() const {
    std::ostringstream s;
    s << "sets=";
    if (set_sizes.empty()) s << sets;
    else
        for (size_t i = 0; i < set_sizes.size(); ++i) s << (i ? "," : "") << set_sizes[i].width << 'x' << set_sizes[i].height;
    s << " max-strokes=" << paint.max_strokes << " target-psnr=" << paint.target_psnr
      << " threshold=" << paint.threshold << " lambda=" << paint.lambda << " color-step=" << paint.color_step << " temperature=" << paint.temperature
      << " orient=" << orient_name(paint.orient) << " templates=" << (templates_dir.empty() ? "builtin" : "custom")
      << " background=" << int(background.r) << ',' << int(background.g) << ',' << int(background.b)
      << " rois=" << rois.size();
    if (style != "painterly") {  // painterly files keep their bytes
        s << " style=" << style << " outline-tolerance=" << outline_tolerance << " lines=" << (lines ? 1 : 0);
        if (outline_smooth >= 0) s << " outline-smooth=" << outline_smooth;  // files without it keep theirs
        if (min_region > 0) s << " min-region=" << min_region;
        if (min_color_share > 0) s << " min-color-share=" << min_color_share;
    }
    // Only when not the defaults, so that the files of earlier versions keep their bytes.
    if (color_encoding != "auto") s << " color-encoding=" << color_encoding;
    if (alpha != "auto") s << " alpha=" << alpha;
    if (!colorspace.empty()) s << " colorspace=" << colorspace;
    if (!ocio_config.empty()) s << " ocio=custom";  // no paths (see templates=)
    if (!layer.empty()) s << " layer=" << layer;
    return s.str();
}

std::vector<std::pair<std::string, std::string>> painting_metadata(const PaintJob& o) {
    return {
        {"software", std::string("spt ") + library_version()},
        {"source", printable_text(std::filesystem::path(o.input).filename().string())},  // names need not be UTF-8
        {"painter.seed", std::to_string(o.paint.seed)},
        {"painter.options", printable_text(o.canonical())},
    };
}

Result<std::vector<Template>> paint_templates(const std::string& templates_dir) {
    if (templates_dir.empty()) return paint::default_templates();
    return io::load_templates(templates_dir);
}

}  // namespace spt::job
