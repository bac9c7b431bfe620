// Storing option values through the table's rows, and the checks between options.
#include <algorithm>

#include "io/color_config.hpp"
#include "io/roi_file.hpp"
#include "job/option_table.hpp"
#include "job/option_text.hpp"
#include "paint/rate_control.hpp"

namespace spt::job {

namespace {

bool given_in(const std::vector<std::string>& given, const char* name) {
    return std::find(given.begin(), given.end(), name) != given.end();
}

std::string range_text(const OptionRow& r) {
    std::string s = "expected " + plain(r.lo) + ".." + plain(r.hi);
    return r.unit.empty() ? s : s + " " + r.unit;
}

std::string choices_text(const std::vector<std::string>& c) {
    std::string s = "expected ";
    for (size_t i = 0; i < c.size(); ++i) s += (i == 0 ? "" : i + 1 == c.size() ? " or " : ", ") + c[i];
    return s;
}

// The options the cartoon painter cannot honour (it paints the whole frame in 8-bit sRGB over
// --background) are said, not ignored; so are its own options without it.
std::string style_check(const PaintJob& j, const std::vector<std::string>& given) {
    for (const std::string& name : given) {
        const OptionRow* r = find_option(name);
        if (!r || (r->styles & style_bit(j.style))) continue;
        if (r->styles == style_bit(Style::Cartoon)) return "--" + name + " applies to --style cartoon only";
        return std::string("--style ") + style_name(j.style) + " does not support --" + name;
    }
    for (const OptionRow& r : option_rows())
        if (r.check)
            if (std::string e = r.check(j); !e.empty()) return e;
    return {};
}

// A config or colour space name that cannot work is a usage error now rather than a failure
// after the first frame is read.
std::string colour_check(const PaintJob& j) {
    if (j.colorspace.empty() && j.ocio_config.empty()) return {};
    auto cs = io::color_config(j.ocio_config);
    if (!cs) return (j.ocio_config.empty() ? "--colorspace: " : "--ocio: ") + cs.error().message;
    if (!j.colorspace.empty())
        if (auto n = io::find_colorspace(*cs, j.colorspace); !n)
            return "--colorspace: " + n.error().message + (cs->warning.empty() ? "" : " (" + cs->warning + ")");
    return {};
}

}  // namespace

std::string apply_option(const OptionRow& row, const std::string& value, PaintJob& job) {
    const std::string opt = "--" + row.name;
    auto bad = [&](const std::string& expected) { return opt + ": " + expected + ", got '" + value + "'"; };
    long l = 0;
    double d = 0;
    switch (row.kind) {
        case OptionKind::Integer:
            if (!parse_long(value, long(row.lo), long(row.hi), l)) return bad(range_text(row));
            break;
        case OptionKind::Number:
            if (!parse_double(value, row.lo, row.hi, d)) return bad(range_text(row));
            break;
        case OptionKind::Choice:
            if (std::find(row.choices.begin(), row.choices.end(), value) == row.choices.end()) return bad(choices_text(row.choices));
            break;
        case OptionKind::Flag:
        case OptionKind::Text:
        case OptionKind::Path:
        case OptionKind::List:
            break;
    }
    const std::string err = row.set(job, value);
    return err.empty() ? err : bad(err);
}

std::string finish_job(PaintJob& j, const std::vector<std::string>& given) {
    if (std::string e = style_check(j, given); !e.empty()) return e;
    // Defaults chosen by measurement (paint/rate_control.hpp); with --target-psnr they follow
    // the target unless given.
    const paint::RateDefaults rd = paint::rate_defaults(j.paint.target_psnr);
    if (!given_in(given, "lambda")) j.paint.lambda = rd.lambda;
    if (!given_in(given, "color-step")) j.paint.color_step = rd.color_step;
    if (given_in(given, "sets") && !j.set_sizes.empty()) return "give --sets or --set-sizes, not both";
    if (std::string e = colour_check(j); !e.empty()) return e;
    j.cli_roi_count = j.rois.size();
    if (!j.roi_file.empty()) {
        auto r = io::read_roi_file(j.roi_file);
        if (!r) return "--roi-file " + r.error().message;
        for (const io::RoiRange& f : *r) {
            RoiSpec s;
            s.first_frame = f.first_frame;
            s.last_frame = f.last_frame;
            s.rect = paint::Rect{f.x, f.y, f.w, f.h};
            j.rois.push_back(s);
        }
    }
    return {};
}

}  // namespace spt::job
