// read_scene_image: any image OpenImageIO reads to scene-linear Rec.709 RGBA, premultiplied.
// Order of work: pick the channels (exr_layers), check the windows and limits, read the data
// window in strips into the display window, replace NaN/inf, convert colour (color_config),
// premultiply straight alpha, clamp negatives.
#include "frames/scene_image.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "io/color_config.hpp"
#include "frames/exr_layers.hpp"

namespace spt::io {

namespace fs = std::filesystem;
using OIIO::TypeDesc;

namespace {

Error file_error(const std::string& path, const std::string& what, Code code) {
    return make_error(code, path + ": " + what);
}

std::string oiio_message(const std::string& msg) {
    std::string m = msg.substr(0, msg.find('\n'));
    return m.empty() ? std::string("unknown OpenImageIO error") : m;
}

bool is_float_type(TypeDesc t) {
    return t.basetype == TypeDesc::HALF || t.basetype == TypeDesc::FLOAT || t.basetype == TypeDesc::DOUBLE;
}

// The parts (EXR subimages) and their channel names; at most kMaxParts are looked at.
constexpr int kMaxParts = 256;
std::vector<ImagePart> list_parts(OIIO::ImageInput& in) {
    std::vector<ImagePart> parts;
    for (int s = 0; s < kMaxParts && in.seek_subimage(s, 0); ++s) {
        const OIIO::ImageSpec& sp = in.spec();
        ImagePart p;
        p.name = sp.get_string_attribute("oiio:subimagename");
        p.channels = sp.channelnames;
        p.channels.resize(size_t(std::max(sp.nchannels, 0)));
        p.alpha_channel = sp.alpha_channel;
        parts.push_back(std::move(p));
    }
    (void)in.geterror();  // seeking past the last subimage sets an error
    return parts;
}

struct Window {
    int64_t x = 0, y = 0, w = 0, h = 0;
};

std::string window_text(const Window& w) {
    return std::to_string(w.w) + "x" + std::to_string(w.h) + " at (" + std::to_string(w.x) + "," +
           std::to_string(w.y) + ")";
}

// Counts of the values replaced, for the warnings.
struct Repairs {
    uint64_t nan = 0, pos_inf = 0, neg_inf = 0, negative = 0, alpha = 0;
};

// NaN -> 0, -inf -> 0, +inf -> the largest finite colour value of the image (65504 when none).
void replace_non_finite(std::vector<float>& rgba, Repairs& r, float& inf_value) {
    float max_finite = 0.f;
    for (size_t i = 0; i < rgba.size(); i += 4)
        for (int k = 0; k < 3; ++k)
            if (std::isfinite(rgba[i + k])) max_finite = std::max(max_finite, rgba[i + k]);
    inf_value = max_finite > 0.f ? max_finite : 65504.f;
    for (size_t i = 0; i < rgba.size(); i += 4) {
        for (int k = 0; k < 3; ++k) {
            float& v = rgba[i + k];
            if (std::isnan(v)) ++r.nan, v = 0.f;
            else if (std::isinf(v)) v > 0 ? (++r.pos_inf, v = inf_value) : (++r.neg_inf, v = 0.f);
        }
        float& a = rgba[i + 3];
        if (std::isnan(a)) ++r.nan, a = 0.f;
        else if (!(a >= 0.f && a <= 1.f)) ++r.alpha, a = std::clamp(a, 0.f, 1.f);
    }
}

}  // namespace

Result<SceneImage> read_scene_image(const std::string& path, const SceneReadOptions& opts) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return file_error(path, "no such file", Code::IoError);
    if (fs::is_directory(path, ec)) return file_error(path, "is a folder, not an image", Code::IoError);

    auto cs = color_config(opts.ocio_config);
    if (!cs) return file_error(path, cs.error().message, cs.error().code);
    std::vector<std::string> config_warnings;
    if (!cs->warning.empty()) config_warnings.push_back(cs->warning);

    // Straight alpha as PNG and TIFF store it, so that it is linearized before premultiplying.
    OIIO::ImageSpec hint;
    hint.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &hint);
    if (!in) return file_error(path, "cannot read image: " + oiio_message(OIIO::geterror()), Code::Corrupt);

    const std::vector<ImagePart> parts = list_parts(*in);
    auto pick = pick_channels(parts, opts.layer);
    if (!pick) return file_error(path, pick.error().message, pick.error().code);
    if (!in->seek_subimage(pick->subimage, 0))
        return file_error(path, "cannot read subimage " + std::to_string(pick->subimage) + ": " +
                                    oiio_message(in->geterror()), Code::Corrupt);
    const OIIO::ImageSpec spec = in->spec();

    const Window data{spec.x, spec.y, spec.width, spec.height};
    Window display{spec.full_x, spec.full_y, spec.full_width, spec.full_height};
    if (display.w <= 0 || display.h <= 0) display = data;  // formats without a display window
    if (data.w <= 0 || data.h <= 0 || display.w <= 0 || display.h <= 0 || spec.depth > 1)
        return file_error(path, "has zero size (" + std::to_string(data.w) + "x" + std::to_string(data.h) + ")",
                          Code::Corrupt);
    const auto over = [&](const Window& w) {
        return w.w > opts.max_side || w.h > opts.max_side || uint64_t(w.w) * uint64_t(w.h) > opts.max_pixels;
    };
    if (over(display) || data.w > opts.max_side || data.h > opts.max_side)
        return file_error(path, "is " + std::to_string(display.w) + "x" + std::to_string(display.h) +
                                    (over(display) ? "" : " with a data window of " + window_text(data)) +
                                    ", over the size limit (" + std::to_string(opts.max_side) + " per side, " +
                                    std::to_string(opts.max_pixels) + " pixels)",
                          Code::LimitExceeded);

    SceneImage img;
    img.warnings = std::move(config_warnings);
    if (!pick->warning.empty()) img.warnings.push_back(path + ": " + pick->warning);
    img.width = uint32_t(display.w);
    img.height = uint32_t(display.h);
    img.has_alpha = pick->alpha >= 0;
    img.is_float = true;
    for (int k = 0; k < 3; ++k) img.is_float = img.is_float && is_float_type(spec.channelformat(pick->color[k]));
    // EXR colour is premultiplied; OIIO tells with oiio:UnassociatedAlpha when it kept it straight.
    const bool straight = img.has_alpha && spec.get_int_attribute("oiio:UnassociatedAlpha", 0) != 0;

    // Colour spaces, resolved before the pixels are read so that a bad name fails fast.
    auto target = linear_rec709_space(*cs);
    if (!target) return file_error(path, target.error().message, target.error().code);
    auto from = opts.colorspace.empty() ? (img.is_float ? target : srgb_space(*cs)) : find_colorspace(*cs, opts.colorspace);
    if (!from)
        return file_error(path, (opts.colorspace.empty() ? "" : "--colorspace: ") + from.error().message,
                          from.error().code);
    img.colorspace = *from;
    auto transform = color_transform(*cs, *from, *target);
    if (!transform) return file_error(path, transform.error().message, transform.error().code);

    // The rows and columns of the data window inside the display window.
    const int64_t x0 = std::max(data.x, display.x), x1 = std::min(data.x + data.w, display.x + display.w);
    const int64_t y0 = std::max(data.y, display.y), y1 = std::min(data.y + data.h, display.y + display.h);
    const bool covers = x0 == display.x && x1 == display.x + display.w && y0 == display.y && y1 == display.y + display.h;
    if (!covers) {
        img.has_alpha = true;
        img.warnings.push_back(path + ": the data window (" + window_text(data) + ") does not cover the display window (" +
                               window_text(display) + "): the pixels outside it are transparent black");
    }
    if (data.x < display.x || data.y < display.y || data.x + data.w > display.x + display.w ||
        data.y + data.h > display.y + display.h)
        img.warnings.push_back(path + ": pixels of the data window outside the display window are dropped");

    img.rgba.assign(size_t(img.width) * img.height * 4, 0.f);
    if (pick->alpha < 0)  // opaque wherever there is data
        for (int64_t y = y0; y < y1; ++y)
            for (int64_t x = x0; x < x1; ++x) img.rgba[(size_t(y - display.y) * img.width + size_t(x - display.x)) * 4 + 3] = 1.f;

    // Read the channel range [cb, ce) of the rows that matter, in strips (tiled files: whole
    // rows of tiles) so that the buffer stays small whatever else the file holds.
    int cb = std::min({pick->color[0], pick->color[1], pick->color[2]}), ce = std::max({pick->color[0], pick->color[1], pick->color[2]});
    if (pick->alpha >= 0) cb = std::min(cb, pick->alpha), ce = std::max(ce, pick->alpha);
    ++ce;
    const int nch = ce - cb;
    const bool tiled = spec.tile_width > 0;
    const int64_t row_values = data.w * nch;
    int64_t strip = std::max<int64_t>(1, (int64_t(1) << 22) / row_values);
    if (tiled) strip = std::max<int64_t>(spec.tile_height, strip / spec.tile_height * spec.tile_height);
    if (uint64_t(strip) * uint64_t(row_values) > (uint64_t(1) << 28))
        return file_error(path, "has tiles too large to read (" + std::to_string(spec.tile_width) + "x" +
                                    std::to_string(spec.tile_height) + ", " + std::to_string(nch) + " channels)",
                          Code::LimitExceeded);
    std::vector<float> buf;
    for (int64_t ys = y0; ys < y1;) {
        // Tiled reads start on a tile row.
        const int64_t start = tiled ? data.y + (ys - data.y) / spec.tile_height * spec.tile_height : ys;
        const int64_t end = std::min(start + strip, data.y + data.h);
        buf.resize(size_t(end - start) * size_t(row_values));
        const bool ok = tiled ? in->read_tiles(pick->subimage, 0, int(data.x), int(data.x + data.w), int(start), int(end),
                                               spec.z, spec.z + std::max(1, spec.depth), cb, ce, TypeDesc::FLOAT, buf.data())
                              : in->read_scanlines(pick->subimage, 0, int(start), int(end), spec.z, cb, ce,
                                                   TypeDesc::FLOAT, buf.data());
        if (!ok)
            return file_error(path, "cannot read pixels (rows " + std::to_string(start) + ".." + std::to_string(end - 1) +
                                        "): " + oiio_message(in->geterror()), Code::Corrupt);
        for (int64_t y = std::max(ys, start); y < std::min(end, y1); ++y) {
            const float* row = buf.data() + size_t(y - start) * size_t(row_values);
            float* out = img.rgba.data() + size_t(y - display.y) * img.width * 4;
            for (int64_t x = x0; x < x1; ++x) {
                const float* p = row + size_t(x - data.x) * nch;
                float* o = out + size_t(x - display.x) * 4;
                for (int k = 0; k < 3; ++k) o[k] = p[pick->color[k] - cb];
                if (pick->alpha >= 0) o[3] = p[pick->alpha - cb];
            }
        }
        ys = std::min(end, y1);
    }
    in->close();

    Repairs rep;
    float inf_value = 0.f;
    replace_non_finite(img.rgba, rep, inf_value);

    // Colour: straight alpha is converted as it is, then premultiplied; premultiplied colour
    // goes through linear transforms as it is, through curves unpremultiplied and back.
    OIIO::ImageSpec bs(int(img.width), int(img.height), 4, TypeDesc::FLOAT);
    bs.alpha_channel = 3;
    OIIO::ImageBuf ib(bs, img.rgba.data());
    if (!transform->identity &&
        !OIIO::ImageBufAlgo::colorconvert(ib, ib, transform->processor.get(), !straight && !transform->linear))
        return file_error(path, "colour conversion from '" + *from + "' failed: " + oiio_message(ib.geterror()),
                          Code::Unsupported);
    if (straight && !OIIO::ImageBufAlgo::premult(ib, ib))
        return file_error(path, "premultiplying alpha failed: " + oiio_message(ib.geterror()), Code::Unsupported);

    // Conversions (ACEScg -> Rec.709) give negatives outside the gamut, curves could give NaN.
    Repairs after;
    float unused = 0.f;
    replace_non_finite(img.rgba, after, unused);
    for (size_t i = 0; i < img.rgba.size(); i += 4)
        for (int k = 0; k < 3; ++k)
            if (img.rgba[i + k] < 0.f) ++rep.negative, img.rgba[i + k] = 0.f;
    rep.nan += after.nan + after.pos_inf + after.neg_inf;

    const std::string conv = transform->identity ? "" : " (after converting from " + *from + ")";
    if (rep.nan) img.warnings.push_back(path + ": " + std::to_string(rep.nan) + " NaN values set to 0");
    if (rep.pos_inf) {
        char v[32];
        std::snprintf(v, sizeof v, "%g", inf_value);
        img.warnings.push_back(path + ": " + std::to_string(rep.pos_inf) + " +infinite values set to " + v +
                               " (the largest finite value)");
    }
    if (rep.neg_inf) img.warnings.push_back(path + ": " + std::to_string(rep.neg_inf) + " -infinite values set to 0");
    if (rep.negative)
        img.warnings.push_back(path + ": " + std::to_string(rep.negative) + " negative values set to 0" + conv);
    if (rep.alpha) img.warnings.push_back(path + ": " + std::to_string(rep.alpha) + " alpha values outside 0..1 clamped");
    return img;
}

}  // namespace spt::io
