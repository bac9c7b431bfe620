// Colour management through OpenImageIO's OCIO support: which config, which colour space names,
// which transforms. Shared by the scene-linear reader (scene_image.cpp) and anything else that
// converts colour with a user's config (--ocio / $OCIO).
#pragma once

#include <OpenImageIO/color.h>

#include <memory>
#include <string>
#include <vector>

#include "spt/result.hpp"

namespace spt::io {

// A loaded OCIO config. OIIO::ColorConfig is thread-safe once built; building one parses the
// whole config, so each path is loaded once per process and shared.
struct ColorSetup {
    std::shared_ptr<const OIIO::ColorConfig> config;
    std::string source;  // the config file, or "OpenImageIO's built-in config"
    bool builtin = false;
    // Set when $OCIO names a config that cannot be loaded and the built-in one is used instead.
    std::string warning;
};

// `ocio_path` (--ocio FILE); empty: $OCIO; unset or empty too: OpenImageIO's built-in config,
// which knows "linear" (scene-linear Rec.709), "sRGB" and "Rec709". An explicit file that is
// missing or does not parse is an error that names it (OIIO itself would fall back silently);
// a $OCIO that cannot be loaded gives the built-in config and says why in `warning`.
Result<ColorSetup> color_config(const std::string& ocio_path);

// The config's linear Rec.709 space ("lin_rec709" in current configs; "Linear Rec.709 (sRGB)",
// "Utility - Linear - sRGB", "Linear" in older ones; "linear" in the built-in config). Not the
// scene_linear role: in ACES configs that is ACEScg.
Result<std::string> linear_rec709_space(const ColorSetup& cs);
// The config's sRGB-encoded Rec.709 space ("srgb_tx", "sRGB - Texture", "sRGB", ...).
Result<std::string> srgb_space(const ColorSetup& cs);

// The config's name for a colour space a user gave: a name, alias or role of the config, the
// conventional names "lin_rec709" and "sRGB" (matched to the spaces above, so they work with
// every config), or a name OpenImageIO resolves itself ("linear" = the scene_linear role).
// Errors name the space and the config and list some known names.
Result<std::string> find_colorspace(const ColorSetup& cs, const std::string& name);

// A conversion between two resolved names. `linear`: the transform is a linear map (a matrix),
// so premultiplied colour may go through it as is; otherwise unpremultiply first.
struct ColorTransform {
    OIIO::ColorProcessorHandle processor;  // null when identity
    bool identity = false;
    bool linear = true;
};
Result<ColorTransform> color_transform(const ColorSetup& cs, const std::string& from, const std::string& to);

// Up to `max` colour space names of the config, for messages ("a, b, c, ... (N in all)").
std::string known_colorspaces_text(const ColorSetup& cs, size_t max = 12);

}  // namespace spt::io
