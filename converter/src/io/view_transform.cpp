// OCIO display/view transforms through OpenImageIO's ColorConfig (io/view_transform.hpp).
#include "io/view_transform.hpp"

#include <OpenImageIO/color.h>

#include "io/color_config.hpp"

#include <algorithm>
#include <vector>

namespace spt::io {

namespace {

class OcioView final : public ViewTransform {
public:
    ColorSetup setup;  // keeps the config the processor belongs to
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
    auto cs = color_config(spec.config);  // --ocio, else $OCIO; loaded once, shared (io/color_config)
    if (!cs) return cs.error();
    if (cs->builtin)
        return make_error(Code::InvalidArgument, "--view " + spec.view + " needs an OCIO config: give --ocio FILE or set $OCIO");
    auto v = std::make_unique<OcioView>();
    v->setup = *cs;
    const OIIO::ColorConfig& config = *cs->config;
    const std::string& file = cs->source;
    std::string display = spec.display;
    const auto displays = config.getDisplayNames();
    if (display.empty() && config.getDefaultDisplayName()) display = config.getDefaultDisplayName();
    if (std::find(displays.begin(), displays.end(), display) == displays.end())
        return make_error(Code::InvalidArgument, file + ": no display \"" + display + "\" (the config has: " + join(displays) + ")");
    const auto views = config.getViewNames(display);
    if (std::find(views.begin(), views.end(), spec.view) == views.end())
        return make_error(Code::InvalidArgument, file + ": display \"" + display + "\" has no view \"" + spec.view +
                                                     "\" (it has: " + join(views) + ")");
    auto from = linear_rec709_space(*cs);  // encoding 1's primaries, not the scene_linear role
    if (!from) return from.error();
    v->proc = config.createDisplayTransform(display, spec.view, *from);
    if (!v->proc) {
        std::string m = const_cast<OIIO::ColorConfig&>(config).geterror();
        return make_error(Code::InvalidArgument, file + ": cannot make the display transform " + display + "/" + spec.view +
                                                     (m.empty() ? "" : ": " + m.substr(0, m.find('\n'))));
    }
    v->what = display + "/" + spec.view + " from " + *from + " (OCIO config " + file + ")";
    return std::unique_ptr<ViewTransform>(std::move(v));
}

}  // namespace spt::io
