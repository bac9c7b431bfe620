#include "plan/plan_args.hpp"

#include <algorithm>
#include <iterator>

namespace spt::plan {

namespace {

// The options `spt plan` writes (converter/src/cli/paint_args.cpp): they shape the painting and
// read files at most (--templates, --roi-file, --ocio); none names a file to write.
constexpr const char* kWithValue[] = {
    "alpha", "background", "color-encoding", "color-step", "coding", "colorspace", "cut-threshold",
    "flow", "fps", "keyframe-interval", "lambda", "layer", "max-inter-strokes", "max-strokes",
    "min-color-share", "min-region", "motion-block", "ocio", "orient", "outline-smooth",
    "outline-tolerance", "roi", "roi-file", "set-sizes", "sets", "style", "target-bytes",
    "target-psnr", "temperature", "templates", "threshold",
};
constexpr const char* kFlags[] = {"flow-orientation", "no-lines", "skip-bad-frames", "stored"};

bool listed(const std::string& name, const char* const* first, const char* const* last) {
    return std::find_if(first, last, [&](const char* n) { return name == n; }) != last;
}

}  // namespace

Status check_paint_args(const std::vector<std::string>& args, const std::string& source) {
    auto refuse = [&](size_t i, const std::string& why) {
        return make_error(Code::InvalidArgument, source + ": \"paint_args\" entry " + std::to_string(i) + " '" + args[i] +
                                                     "' " + why + " (a plan may hold only painter options)");
    };
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a.size() < 3 || a.compare(0, 2, "--") != 0)
            return refuse(i, a.empty() || a[0] != '-' ? "is not an option: a plan names no input or output file here"
                                                      : "is not a painter option");
        const size_t eq = a.find('=');
        const std::string name = a.substr(2, eq == std::string::npos ? std::string::npos : eq - 2);
        if (listed(name, std::begin(kFlags), std::end(kFlags))) {
            if (eq != std::string::npos) return refuse(i, "is a flag and takes no value");
            continue;
        }
        if (!listed(name, std::begin(kWithValue), std::end(kWithValue))) return refuse(i, "is not a painter option");
        if (eq != std::string::npos) continue;
        // The value: never something the command line would read as an option.
        if (++i >= args.size()) return refuse(i - 1, "has no value");
        if (!args[i].empty() && args[i][0] == '-') return refuse(i, "is not a value of " + a);
    }
    return {};
}

}  // namespace spt::plan
