// OCIO display/view transforms through OpenImageIO's ColorConfig (io/view_transform.hpp).
#include "io/view_transform.hpp"

#include <OpenImageIO/color.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace spt::io {

namespace {

class OcioView final : public ViewTransform {
public:
    std::unique_ptr<OIIO::ColorConfig> config;
    OIIO::ColorProcessorHandle proc;
    std::string what;
    void apply(float* rgb, size_t n) const override {
        // OIIO processes an image of rows; one row of at most 2^20 pixels at a time.
        for (size_t at = 0; at < n;) {
            const size_t k = std::min<size_t>(n - at, size_t(1) << 20);
            proc->apply(rgb + at * 3, int(k), 1, 3, sizeof(float), 3 * sizeof(float), 3 * sizeof(float) * k);
            at += k;
        }
    }
    std::string description() const override { return what; }
};

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s.empty() ? "none" : s;
}

}  // namespace

Result<std::unique_ptr<ViewTransform>> ViewTransform::open(const ViewSpec& spec) {
    std::string file = spec.config;
    if (file.empty())
        if (const char* e = std::getenv("OCIO")) file = e;
    if (file.empty())
        return make_error(Code::InvalidArgument, "--view " + spec.view + " needs an OCIO config: give --ocio FILE or set $OCIO");
    auto v = std::make_unique<OcioView>();
    v->config = std::make_unique<OIIO::ColorConfig>(file);
    if (v->config->has_error() || v->config->getNumColorSpaces() <= 0) {
        std::string m = v->config->geterror();
        m = m.substr(0, m.find('\n'));
        return make_error(Code::InvalidArgument, file + ": not a usable OCIO config" + (m.empty() ? "" : " (" + m + ")"));
    }
    std::string display = spec.display;
    const auto displays = v->config->getDisplayNames();
    if (display.empty() && v->config->getDefaultDisplayName()) display = v->config->getDefaultDisplayName();
    if (std::find(displays.begin(), displays.end(), display) == displays.end())
        return make_error(Code::InvalidArgument, file + ": no display \"" + display + "\" (the config has: " + join(displays) + ")");
    const auto views = v->config->getViewNames(display);
    if (std::find(views.begin(), views.end(), spec.view) == views.end())
        return make_error(Code::InvalidArgument, file + ": display \"" + display + "\" has no view \"" + spec.view +
                                                     "\" (it has: " + join(views) + ")");
    const auto spaces = v->config->getColorSpaceNames();
    std::string from;
    for (const char* name : {"lin_rec709", "Linear Rec.709 (sRGB)", "Utility - Linear - sRGB", "linear", "Linear"})
        if (std::find(spaces.begin(), spaces.end(), name) != spaces.end()) { from = name; break; }
    if (from.empty())
        if (const char* r = v->config->getColorSpaceNameByRole("scene_linear")) from = r;
    if (from.empty())
        return make_error(Code::InvalidArgument, file + ": no linear Rec.709 colour space (lin_rec709, linear, or a scene_linear role)");
    v->proc = v->config->createDisplayTransform(display, spec.view, from);
    if (!v->proc) {
        std::string m = v->config->geterror();
        return make_error(Code::InvalidArgument, file + ": cannot make the display transform " + display + "/" + spec.view +
                                                     (m.empty() ? "" : ": " + m.substr(0, m.find('\n'))));
    }
    v->what = display + "/" + spec.view + " from " + from + " (OCIO config " + file + ")";
    return std::unique_ptr<ViewTransform>(std::move(v));
}

}  // namespace spt::io
