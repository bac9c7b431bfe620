// TEMPORARY stand-in for the scene-input helper's read_scene_image (branch scene-input): just
// enough to paint RGBA/linear files in the painter branch. Drop this file at merge.
#include "io/scene_image.hpp"

#include <OpenImageIO/imageio.h>

#include <cmath>

namespace spt::io {

Result<SceneImage> read_scene_image(const std::string& path, const SceneReadOptions& opts) {
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);  // straight alpha from PNG/TIFF
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) return make_error(Code::IoError, path + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || uint64_t(spec.width) > opts.max_side || uint64_t(spec.height) > opts.max_side ||
        uint64_t(spec.width) * uint64_t(spec.height) > opts.max_pixels)
        return make_error(Code::InvalidArgument, path + ": unsupported image size");
    const int nc = spec.nchannels;
    std::vector<float> px(size_t(spec.width) * spec.height * nc);
    if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, px.data()))
        return make_error(Code::IoError, path + ": " + in->geterror());
    SceneImage out;
    out.width = uint32_t(spec.width);
    out.height = uint32_t(spec.height);
    out.is_float = spec.format.basetype == OIIO::TypeDesc::FLOAT || spec.format.basetype == OIIO::TypeDesc::HALF;
    const int ac = spec.alpha_channel >= 0 ? spec.alpha_channel : (nc == 4 ? 3 : -1);
    out.has_alpha = ac >= 0;
    out.colorspace = out.is_float ? "lin_rec709" : "sRGB";
    const size_t n = size_t(out.width) * out.height;
    out.rgba.resize(n * 4);
    uint64_t bad = 0;
    auto clean = [&](float v) {
        if (!std::isfinite(v)) { ++bad; return 0.0f; }
        return v < 0 ? 0.0f : v;
    };
    for (size_t i = 0; i < n; ++i) {
        const float* p = &px[i * nc];
        float rgb[3];
        for (int c = 0; c < 3; ++c) rgb[c] = clean(p[nc >= 3 ? c : 0]);
        float a = ac >= 0 ? std::min(1.0f, clean(p[ac])) : 1.0f;
        if (!out.is_float) {
            for (float& v : rgb) v = v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
            for (float& v : rgb) v *= a;  // straight to premultiplied
        }
        for (int c = 0; c < 3; ++c) out.rgba[4 * i + c] = rgb[c];
        out.rgba[4 * i + 3] = a;
    }
    if (bad) out.warnings.push_back(path + ": " + std::to_string(bad) + " NaN or infinite values set to 0");
    return out;
}

}  // namespace spt::io
