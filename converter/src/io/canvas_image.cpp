// Canvases of every kind to image files (io/canvas_image.hpp).
#include "io/canvas_image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "io/image_io.hpp"
#include "spt/color.hpp"
#include "spt/display.hpp"

namespace spt::io {

namespace {

uint16_t unit_to_u16(float v) {
    if (!(v > 0.f)) return 0;
    if (v >= 1.f) return 65535;
    return uint16_t(std::floor(v * 65535.f + 0.5f));
}

uint8_t channel(const Rgb8& c, int k) { return k == 0 ? c.r : k == 1 ? c.g : c.b; }

// Encoding 0 flattened in 8-bit sRGB values, as strokes composite: a plain canvas.
std::vector<uint8_t> flatten8(const Canvas& c, Rgb8 bg) {
    const size_t n = size_t(c.width) * c.height;
    std::vector<uint8_t> rgb(n * 3);
    for (size_t i = 0; i < n; ++i) {
        const uint32_t a = c.alpha[i];
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = (uint32_t(c.rgb[i * 3 + k]) * 255u + uint32_t(channel(bg, k)) * (255u - a) + 127u) / 255u;
            rgb[i * 3 + k] = uint8_t(std::min(v, 255u));
        }
    }
    return rgb;
}

// Writes display-referred values (0..1, three a pixel) at `depth` bits, with the canvas's alpha
// as the 4th channel when `keep_alpha`.
Status write_display(const std::string& path, const Canvas& c, const std::vector<float>& v, int nch, bool keep_alpha,
                     int depth) {
    const size_t n = size_t(c.width) * c.height;
    if (depth == 8) {
        std::vector<uint8_t> px(n * nch);
        for (size_t i = 0; i < n; ++i) {
            for (int k = 0; k < 3; ++k) px[i * nch + k] = unit_to_u8(v[i * 3 + k]);
            if (keep_alpha) px[i * 4 + 3] = c.alpha[i];
        }
        return write_pixels(path, c.width, c.height, nch, PixelType::U8, px.data());
    }
    std::vector<uint16_t> px(n * nch);
    for (size_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) px[i * nch + k] = unit_to_u16(v[i * 3 + k]);
        if (keep_alpha) px[i * 4 + 3] = uint16_t(c.alpha[i] * 257u);
    }
    return write_pixels(path, c.width, c.height, nch, PixelType::U16, px.data());
}

}  // namespace

std::vector<uint8_t> canvas_rgb8(const Canvas& c, const Header& h, const CanvasImageOptions& o) {
    const size_t n = size_t(c.width) * c.height;
    const bool linear = h.color == ColorEncoding::LinearHalf;
    if ((linear ? c.rgb16.size() : c.rgb.size()) != n * 3 || (h.alpha && c.alpha.size() != n)) return std::vector<uint8_t>(n * 3, 0);
    std::vector<uint8_t> rgb;
    std::vector<float> lin;
    if (!linear) {
        rgb = h.alpha ? flatten8(c, o.background.value_or(h.background)) : c.rgb;
        if (!o.view) return rgb;
        lin.resize(n * 3);
        for (size_t i = 0; i < n * 3; ++i) lin[i] = rgb[i] / 255.f;
        srgb_to_linear(lin.data(), n);
    } else {
        float bg[3];
        for (int k = 0; k < 3; ++k) bg[k] = o.background ? srgb_decode(channel(*o.background, k) / 255.f) : background_linear(h, k);
        lin.resize(n * 3);
        for (size_t i = 0; i < n; ++i) {
            const float a = h.alpha ? c.alpha[i] / 255.f : 1.f;
            for (int k = 0; k < 3; ++k) lin[i * 3 + k] = half_to_float(c.rgb16[i * 3 + k]) + (h.alpha ? bg[k] * (1.f - a) : 0.f);
        }
    }
    if (o.view) o.view->apply(lin.data(), n);
    else
        for (auto& v : lin) v = srgb_encode(v);
    rgb.resize(n * 3);
    for (size_t i = 0; i < n * 3; ++i) rgb[i] = unit_to_u8(lin[i]);
    return rgb;
}

Status write_canvas(const std::string& path, const Canvas& c, const Header& h, const CanvasImageOptions& o,
                    std::string* note) {
    const size_t n = size_t(c.width) * c.height;
    const bool linear = h.color == ColorEncoding::LinearHalf;
    const bool has_alpha = h.alpha;
    if (c.width != h.width || c.height != h.height || (linear ? c.rgb16.size() : c.rgb.size()) != n * 3 ||
        (has_alpha && c.alpha.size() != n))
        return make_error(Code::InvalidArgument, path + ": the canvas does not have the planes its header defines");
    if (o.depth != 8 && o.depth != 16) return make_error(Code::InvalidArgument, path + ": depth must be 8 or 16");
    const std::string fmt = image_format_name(path);
    if (fmt.empty()) return make_error(Code::InvalidArgument, path + ": no image writer for this extension");
    const bool exr = fmt == "openexr";
    const bool keep_alpha = has_alpha && !o.background && image_supports_alpha(path);
    const bool flatten = has_alpha && !keep_alpha;
    if (flatten && !o.background && note) {
        char bg[96];
        if (linear)
            std::snprintf(bg, sizeof bg, "%g, %g, %g linear", double(background_linear(h, 0)), double(background_linear(h, 1)),
                          double(background_linear(h, 2)));
        else
            std::snprintf(bg, sizeof bg, "#%02x%02x%02x", h.background.r, h.background.g, h.background.b);
        *note = path + ": " + fmt + " has no alpha channel; the canvas is flattened over the file's background " + bg +
                " (--background to choose)";
    }
    const int nch = keep_alpha ? 4 : 3;
    const int depth = exr ? 0 : o.depth;

    if (!linear) {
        // Encoding 0: an 8-bit sRGB canvas, flattened first when the output has no alpha.
        std::vector<uint8_t> flat;
        const uint8_t* rgb = c.rgb.data();
        if (flatten) {
            flat = flatten8(c, o.background.value_or(h.background));
            rgb = flat.data();
        }
        if (!keep_alpha && (exr || (!o.view && depth == 8))) return write_image(path, c.width, c.height, rgb);
        if (!exr && !o.view && depth == 8) {  // straight 8-bit RGBA
            std::vector<uint8_t> px(n * 4);
            for (size_t i = 0; i < n; ++i) {
                const uint32_t a = c.alpha[i];
                for (int k = 0; k < 3; ++k) px[i * 4 + k] = a == 255 ? rgb[i * 3 + k] : unpremultiply8(rgb[i * 3 + k], a);
                px[i * 4 + 3] = uint8_t(a);
            }
            return write_pixels(path, c.width, c.height, 4, PixelType::U8, px.data());
        }
        if (!exr && !o.view && depth == 16) {
            std::vector<uint16_t> px(n * nch);
            for (size_t i = 0; i < n; ++i) {
                const uint32_t a = keep_alpha ? c.alpha[i] : 255u;
                for (int k = 0; k < 3; ++k) {
                    const uint32_t p = rgb[i * 3 + k];
                    px[i * nch + k] = a == 255 ? uint16_t(p * 257u) : a == 0 ? 0 : uint16_t(std::min<uint32_t>(65535u, (p * 65535u + a / 2u) / a));
                }
                if (keep_alpha) px[i * 4 + 3] = uint16_t(a * 257u);
            }
            return write_pixels(path, c.width, c.height, nch, PixelType::U16, px.data());
        }
        // EXR with alpha, or a view: straight values linearized (write_image's transform).
        std::vector<float> lin(n * 3);
        for (size_t i = 0; i < n; ++i) {
            const uint32_t a = keep_alpha ? c.alpha[i] : 255u;
            for (int k = 0; k < 3; ++k) lin[i * 3 + k] = a == 0 ? 0.f : a == 255 ? rgb[i * 3 + k] / 255.f
                                                                                : std::min(1.f, float(rgb[i * 3 + k]) / float(a));
        }
        srgb_to_linear(lin.data(), n);
        if (exr) {
            std::vector<float> px(n * nch);
            for (size_t i = 0; i < n; ++i) {
                const float a = keep_alpha ? c.alpha[i] / 255.f : 1.f;
                for (int k = 0; k < 3; ++k) px[i * nch + k] = lin[i * 3 + k] * a;
                if (keep_alpha) px[i * 4 + 3] = a;
            }
            return write_pixels(path, c.width, c.height, nch, PixelType::Half, px.data());
        }
        o.view->apply(lin.data(), n);
        return write_display(path, c, lin, nch, keep_alpha, depth);
    }

    // Encoding 1: scene-linear half codes, premultiplied on alpha canvases.
    float bg[3] = {0.f, 0.f, 0.f};
    if (flatten)
        for (int k = 0; k < 3; ++k)
            bg[k] = o.background ? srgb_decode(channel(*o.background, k) / 255.f) : background_linear(h, k);
    if (exr) {
        std::vector<float> px(n * nch);
        for (size_t i = 0; i < n; ++i) {
            const float a = has_alpha ? c.alpha[i] / 255.f : 1.f;
            for (int k = 0; k < 3; ++k) {
                const float v = half_to_float(c.rgb16[i * 3 + k]);  // exactly the half the file stores
                px[i * nch + k] = flatten ? v + bg[k] * (1.f - a) : v;
            }
            if (keep_alpha) px[i * 4 + 3] = a;
        }
        return write_pixels(path, c.width, c.height, nch, PixelType::Half, px.data());
    }
    if (!o.view && depth == 8 && !flatten) {  // the viewers' view: to_rgba8
        std::vector<uint8_t> px;
        to_rgba8(c, h, px);
        if (nch == 3) {
            for (size_t i = 0; i < n; ++i)
                for (int k = 0; k < 3; ++k) px[i * 3 + k] = px[i * 4 + k];
            px.resize(n * 3);
        }
        return write_pixels(path, c.width, c.height, nch, PixelType::U8, px.data());
    }
    // Straight linear values, then the view.
    std::vector<float> lin(n * 3);
    for (size_t i = 0; i < n; ++i) {
        const uint32_t a = has_alpha ? c.alpha[i] : 255u;
        for (int k = 0; k < 3; ++k) {
            const float v = half_to_float(c.rgb16[i * 3 + k]);
            lin[i * 3 + k] = flatten ? v + bg[k] * (1.f - a / 255.f) : a == 255 ? v : a == 0 ? 0.f : v * 255.f / float(a);
        }
    }
    if (o.view) o.view->apply(lin.data(), n);
    else
        for (auto& v : lin) v = srgb_encode(v);
    return write_display(path, c, lin, nch, keep_alpha, depth);
}

}  // namespace spt::io
