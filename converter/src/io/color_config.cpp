#include "io/color_config.hpp"

#include "io/ocio_references.hpp"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <strings.h>

namespace spt::io {

namespace {

bool same_name(const std::string& a, const std::string& b) {
    return a.size() == b.size() && strcasecmp(a.c_str(), b.c_str()) == 0;  // OCIO names ignore case
}

std::string first_line(std::string m) {
    m = m.substr(0, m.find('\n'));
    return m.empty() ? std::string("unknown error") : m;
}

// The config's space whose name or alias is `name` (case-insensitive); empty if none.
std::string space_named(const ColorSetup& cs, const std::string& name) {
    for (const std::string& s : cs.config->getColorSpaceNames()) {
        if (same_name(s, name)) return s;
        for (const std::string& a : cs.config->getAliases(s))
            if (same_name(a, name)) return s;
    }
    return {};
}

std::string first_space(const ColorSetup& cs, std::initializer_list<const char*> names) {
    for (const char* n : names)
        if (std::string s = space_named(cs, n); !s.empty()) return s;
    return {};
}

// Names that mean linear Rec.709 / sRGB Rec.709 in the common configs (ACES 1.x, ACES 2 studio
// and cg configs, Blender's, OIIO's built-in).
constexpr std::initializer_list<const char*> kLinearNames = {
    "lin_rec709", "Linear Rec.709 (sRGB)", "Utility - Linear - sRGB", "Linear Rec.709", "lin_srgb", "Linear"};
constexpr std::initializer_list<const char*> kSrgbNames = {
    "srgb_tx", "sRGB - Texture", "Utility - sRGB - Texture", "sRGB Encoded Rec.709 (sRGB)", "sRGB"};

bool is_one_of(const std::string& name, std::initializer_list<const char*> names) {
    for (const char* n : names)
        if (same_name(name, n)) return true;
    return false;
}

// Whether f(k x) = k f(x) on a few colours: true for matrices, false for transfer curves and
// LUTs (premultiplied colour must then be unpremultiplied around the transform).
bool is_linear(const OIIO::ColorProcessor& p) {
    const float base[3][3] = {{0.18f, 0.5f, 0.9f}, {1.f, 0.02f, 0.3f}, {0.05f, 0.05f, 0.05f}};
    for (const auto& b : base) {
        float x[3] = {b[0], b[1], b[2]}, y[3] = {4 * b[0], 4 * b[1], 4 * b[2]};
        p.apply(x, 1, 1, 3, sizeof(float), 3 * sizeof(float), 3 * sizeof(float));
        p.apply(y, 1, 1, 3, sizeof(float), 3 * sizeof(float), 3 * sizeof(float));
        for (int k = 0; k < 3; ++k)
            if (!(std::fabs(y[k] - 4 * x[k]) <= 1e-4f * (1 + std::fabs(y[k])))) return false;
    }
    return true;
}

}  // namespace

Result<ColorSetup> color_config(const std::string& ocio_path) {
    std::string path = ocio_path;
    if (path.empty())
        if (const char* env = std::getenv("OCIO")) path = env;
    static std::mutex mu;
    static std::map<std::string, ColorSetup> cache;
    std::lock_guard<std::mutex> lock(mu);
    if (auto it = cache.find(path); it != cache.end()) return it->second;

    ColorSetup cs;
    const std::string what = ocio_path.empty() ? "$OCIO config '" + path + "'" : "OCIO config '" + path + "'";
    auto builtin = [&] {
        // ColorConfig("") reads $OCIO itself: hide it, so that this is the built-in config.
        const char* env = std::getenv("OCIO");
        const std::string saved = env ? env : "";
        if (env) ::unsetenv("OCIO");
        cs.config = std::make_shared<const OIIO::ColorConfig>("");
        if (env) ::setenv("OCIO", saved.c_str(), 1);
        cs.source = "OpenImageIO's built-in config";
        cs.builtin = true;
    };
    Status loaded;
    if (path.empty()) {
        builtin();
    } else {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec)) {
            loaded = make_error(Code::IoError, what + ": no such file");
        } else if (!OIIO::ColorConfig::supportsOpenColorIO()) {
            loaded = make_error(Code::Unsupported, what + ": this OpenImageIO is built without OpenColorIO");
        } else if (Status refs = check_ocio_references(path); !refs) {
            // Before OCIO sees it: a loop of references overflows the stack inside OCIO.
            loaded = refs;
        } else {
            auto c = std::make_shared<OIIO::ColorConfig>(path);
            if (c->has_error() || c->getNumColorSpaces() <= 0)
                loaded = make_error(Code::Corrupt, what + ": cannot load it: " + first_line(c->geterror()));
            cs.config = std::move(c);
            cs.source = path;
        }
    }
    if (!loaded) {
        // An explicit --ocio is the user's word; $OCIO is often set by another program for its
        // own, newer config (Blender 5 sets it for the processes it starts): fall back, saying so.
        if (!ocio_path.empty()) return loaded.error();
        builtin();
        cs.warning = loaded.error().message + "; using OpenImageIO's built-in config instead";
    }
    (void)OIIO::geterror();  // a failed or default load leaves a global message behind
    cache.emplace(path, cs);
    return cs;
}

Result<std::string> linear_rec709_space(const ColorSetup& cs) {
    if (std::string s = first_space(cs, kLinearNames); !s.empty()) return s;
    std::string looked;
    for (const char* n : kLinearNames) looked += std::string(looked.empty() ? "" : ", ") + n;
    return make_error(Code::Unsupported, "the colour config " + cs.source +
                                             " has no linear Rec.709 colour space (looked for " + looked + ")");
}

Result<std::string> srgb_space(const ColorSetup& cs) {
    if (std::string s = first_space(cs, kSrgbNames); !s.empty()) return s;
    std::string looked;
    for (const char* n : kSrgbNames) looked += std::string(looked.empty() ? "" : ", ") + n;
    return make_error(Code::Unsupported, "the colour config " + cs.source + " has no sRGB colour space (looked for " +
                                             looked + "): give the input's with --colorspace");
}

std::string known_colorspaces_text(const ColorSetup& cs, size_t max) {
    std::vector<std::string> names = cs.config->getColorSpaceNames();
    if (cs.builtin) names.push_back("lin_rec709");
    std::string t;
    for (size_t i = 0; i < names.size() && i < max; ++i) t += (i ? ", " : "") + names[i];
    if (names.size() > max) t += ", ... (" + std::to_string(names.size()) + " in all)";
    return t;
}

Result<std::string> find_colorspace(const ColorSetup& cs, const std::string& name) {
    auto unknown = [&]() -> Error {
        return make_error(Code::InvalidArgument, "unknown colour space '" + name + "' in " + cs.source +
                                                     " (known: " + known_colorspaces_text(cs) + ")" +
                                                     (cs.builtin ? "; other spaces (ACEScg, ...) need an OCIO config: "
                                                                   "--ocio FILE or $OCIO" : ""));
    };
    if (name.empty()) return unknown();
    if (std::string s = space_named(cs, name); !s.empty()) return s;
    for (const std::string& role : cs.config->getRoles())
        if (same_name(role, name))
            if (const char* s = cs.config->getColorSpaceNameByRole(role)) return std::string(s);
    if (is_one_of(name, kLinearNames)) return linear_rec709_space(cs);
    if (is_one_of(name, kSrgbNames)) return srgb_space(cs);
    // What OIIO resolves on its own ("linear", "scene_linear" as roles, its built-in names).
    auto target = linear_rec709_space(cs);
    if (target && !same_name(*target, name) && cs.config->createColorProcessor(name, *target)) return name;
    (void)OIIO::geterror();
    return unknown();
}

Result<ColorTransform> color_transform(const ColorSetup& cs, const std::string& from, const std::string& to) {
    ColorTransform t;
    if (same_name(from, to)) {
        t.identity = true;
        return t;
    }
    t.processor = cs.config->createColorProcessor(from, to);
    if (!t.processor) {
        std::string msg = first_line(OIIO::geterror());
        return make_error(Code::Unsupported, "cannot convert colour from '" + from + "' to '" + to + "' with " +
                                                 cs.source + ": " + msg);
    }
    if (t.processor->isNoOp()) {
        t.identity = true;
        t.processor.reset();
        return t;
    }
    t.linear = is_linear(*t.processor);
    return t;
}

}  // namespace spt::io
