// Image I/O through OpenImageIO: any readable image to 8-bit sRGB RGB, and RGB8 to files.
#include "io/image_io.hpp"

#include <OpenImageIO/color.h>
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/half.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <memory>
#include <system_error>

#include "io/private_output.hpp"
#include "spt/atomic_file.hpp"

namespace spt::io {

namespace fs = std::filesystem;
using OIIO::TypeDesc;

namespace {

Error io_error(const std::string& path, const std::string& what, Code code = Code::IoError) {
    return make_error(code, path + ": " + what);
}

// OIIO reports errors through a global string that may hold several lines: keep the first.
std::string oiio_message(const std::string& msg) {
    std::string m = msg.substr(0, msg.find('\n'));
    return m.empty() ? std::string("unknown OpenImageIO error") : m;
}

// The two transforms, made once: OIIO caches processors, but the config itself is heavy.
// The built-in config (no $OCIO) knows "linear" (scene-linear Rec.709) and "sRGB".
struct Transforms {
    OIIO::ColorConfig config;
    OIIO::ColorProcessorHandle to_srgb, to_linear;
    Transforms() {
        to_srgb = config.createColorProcessor("linear", "sRGB");
        to_linear = config.createColorProcessor("sRGB", "linear");
    }
};
const Transforms& transforms() {
    static const Transforms t;
    return t;
}

bool is_float_type(TypeDesc t) {
    return t.basetype == TypeDesc::HALF || t.basetype == TypeDesc::FLOAT ||
           t.basetype == TypeDesc::DOUBLE;
}

uint8_t quantize(float v) {
    if (!(v > 0.f)) return 0;  // also NaN
    if (v >= 1.f) return 255;
    return uint8_t(v * 255.f + 0.5f);
}

// How the file's channels map to colour and alpha.
struct Layout {
    int nread = 0;      // channels read: 0 .. nread-1
    int color[3] = {0, 0, 0};
    int alpha = -1;
};

Result<Layout> channel_layout(const std::string& path, const OIIO::ImageSpec& spec) {
    Layout l;
    const int n = spec.nchannels;
    if (n <= 0) return io_error(path, "has no channels", Code::Unsupported);
    if (n <= 2) {
        l.nread = n;
        if (n == 2) l.alpha = 1;  // gray + alpha
    } else {
        l.color[0] = 0, l.color[1] = 1, l.color[2] = 2;
        l.nread = 3;
        if (n >= 4 && (spec.alpha_channel == 3 || (n == 4 && spec.alpha_channel < 0))) {
            l.alpha = 3;
            l.nread = 4;
        }
    }
    return l;
}

}  // namespace

Result<Image> read_image(const std::string& path, const ReadOptions& opts) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return io_error(path, "no such file");
    if (fs::is_directory(path, ec)) return io_error(path, "is a folder, not an image");

    // Ask for alpha as stored (unassociated for PNG) so 8-bit colours survive unchanged.
    OIIO::ImageSpec hint;
    hint.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &hint);
    if (!in) return io_error(path, "cannot read image: " + oiio_message(OIIO::geterror()), Code::Corrupt);
    const OIIO::ImageSpec spec = in->spec();
    const int64_t w = spec.width, h = spec.height;
    if (w <= 0 || h <= 0 || spec.depth > 1)
        return io_error(path, "has zero size (" + std::to_string(w) + "x" + std::to_string(h) + ")",
                        Code::Corrupt);
    if (w > opts.max_side || h > opts.max_side || uint64_t(w) * uint64_t(h) > opts.max_pixels)
        return io_error(path, "is " + std::to_string(w) + "x" + std::to_string(h) +
                                  ", over the size limit (" + std::to_string(opts.max_side) +
                                  " per side, " + std::to_string(opts.max_pixels) + " pixels)",
                        Code::LimitExceeded);
    // A display window is the picture's frame (EXR, TIFF): one over the limits is refused here
    // as the scene reader refuses it, not painted as its data window alone.
    if (spec.full_width > 0 && spec.full_height > 0 &&
        (spec.full_width != w || spec.full_height != h || spec.full_x != spec.x || spec.full_y != spec.y) &&
        (spec.full_width > opts.max_side || spec.full_height > opts.max_side ||
         uint64_t(spec.full_width) * uint64_t(spec.full_height) > opts.max_pixels))
        return io_error(path, "has a display window of " + std::to_string(spec.full_width) + "x" +
                                  std::to_string(spec.full_height) + ", over the size limit (" + std::to_string(opts.max_side) +
                                  " per side, " + std::to_string(opts.max_pixels) + " pixels)",
                        Code::LimitExceeded);
    auto lay = channel_layout(path, spec);
    if (!lay) return lay.error();
    const Layout L = *lay;
    const bool linear = is_float_type(spec.format);
    // Integer files opened with the hint report unassociated alpha; otherwise OIIO (or the
    // file, as EXR) gives premultiplied colour.
    const bool premultiplied = linear || spec.get_int_attribute("oiio:UnassociatedAlpha", 0) == 0;

    float bg[3] = {opts.background.r / 255.f, opts.background.g / 255.f, opts.background.b / 255.f};
    if (linear) transforms().to_linear->apply(bg);

    Image img;
    img.width = uint32_t(w);
    img.height = uint32_t(h);
    img.rgb.resize(size_t(w) * size_t(h) * 3);

    // Scanline files are read in strips so the float buffer stays small; tiled files whole.
    const bool tiled = spec.tile_width > 0;
    const int64_t strip = tiled ? h : std::max<int64_t>(1, std::min<int64_t>(h, (1 << 22) / w));
    if (tiled && uint64_t(w) * uint64_t(h) * uint64_t(L.nread) > (1ull << 29))
        return io_error(path, "is a tiled image too large to read at once", Code::LimitExceeded);
    std::vector<float> buf(size_t(strip) * size_t(w) * size_t(L.nread));
    std::vector<float> rgbf(size_t(strip) * size_t(w) * 3);

    for (int64_t y0 = 0; y0 < h; y0 += strip) {
        const int64_t rows = std::min(strip, h - y0);
        bool ok = tiled ? in->read_image(0, 0, 0, L.nread, TypeDesc::FLOAT, buf.data())
                        : in->read_scanlines(0, 0, spec.y + int(y0), spec.y + int(y0 + rows), 0, 0,
                                             L.nread, TypeDesc::FLOAT, buf.data());
        if (!ok)
            return io_error(path, "cannot read pixels (row " + std::to_string(y0) + "): " +
                                      oiio_message(in->geterror()),
                            Code::Corrupt);
        const size_t npx = size_t(rows) * size_t(w);
        for (size_t i = 0; i < npx; ++i) {
            const float* p = &buf[i * L.nread];
            float c[3];
            if (L.nread <= 2) {
                c[0] = c[1] = c[2] = p[0];
            } else {
                c[0] = p[L.color[0]], c[1] = p[L.color[1]], c[2] = p[L.color[2]];
            }
            if (L.alpha >= 0) {
                float a = std::clamp(p[L.alpha], 0.f, 1.f);
                if (std::isnan(p[L.alpha])) a = 0.f;
                for (int k = 0; k < 3; ++k)
                    c[k] = (premultiplied ? c[k] : c[k] * a) + bg[k] * (1.f - a);
            }
            for (int k = 0; k < 3; ++k) rgbf[i * 3 + k] = std::isfinite(c[k]) ? c[k] : (c[k] > 0 ? 1e9f : 0.f);
        }
        if (linear) {
            // Linear Rec.709 -> sRGB, OIIO built-in "linear" -> "sRGB" (see kLinearToSrgbText).
            for (auto& v : rgbf) v = std::max(v, 0.f);
            transforms().to_srgb->apply(rgbf.data(), int(w), int(rows), 3, sizeof(float),
                                        3 * sizeof(float), 3 * sizeof(float) * w);
        }
        uint8_t* out = img.rgb.data() + size_t(y0) * size_t(w) * 3;
        for (size_t i = 0; i < npx * 3; ++i) out[i] = quantize(rgbf[i]);
    }
    in->close();
    return img;
}

const std::array<uint8_t, 65536>* half_to_srgb8() {
    // read_image's steps for a sample of a file it does not composite: the half as float, the
    // non-finite replaced, negatives clipped, OIIO's "linear" -> "sRGB" applied in the same
    // three-channel layout, quantized. Every half value is each of the three channels of one
    // pixel; should the processor give the channels different results (it does not), there
    // is no table and callers read the file the long way.
    static const std::unique_ptr<std::array<uint8_t, 65536>> table = [] {
        const int n = 65536;
        std::vector<float> v(size_t(n) * 3);
        for (int i = 0; i < n; ++i) {
            half h;
            h.setBits(uint16_t(i));
            float c = float(h);
            c = std::isfinite(c) ? c : (c > 0 ? 1e9f : 0.f);
            v[size_t(i) * 3] = v[size_t(i) * 3 + 1] = v[size_t(i) * 3 + 2] = std::max(c, 0.f);
        }
        transforms().to_srgb->apply(v.data(), n, 1, 3, sizeof(float), 3 * sizeof(float), 3 * sizeof(float) * size_t(n));
        auto t = std::make_unique<std::array<uint8_t, 65536>>();
        for (int i = 0; i < n; ++i) {
            const uint8_t q = quantize(v[size_t(i) * 3]);
            if (quantize(v[size_t(i) * 3 + 1]) != q || quantize(v[size_t(i) * 3 + 2]) != q) return std::unique_ptr<std::array<uint8_t, 65536>>();
            (*t)[size_t(i)] = q;
        }
        return t;
    }();
    return table.get();
}

bool is_writable_image_name(const std::string& path) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) {
        (void)OIIO::geterror();  // clear the global error
        return false;
    }
    return true;
}

namespace {

// Encodes `data` (buftype samples, spec.nchannels a pixel) with the plugin `out` chose for
// `path`, into memory, and writes the bytes through spt::AtomicFile.
Status write_encoded(const std::string& path, std::unique_ptr<OIIO::ImageOutput> out, const OIIO::ImageSpec& spec,
                     TypeDesc buftype, const void* data) {
    // The plugin was chosen from the final name. It encodes into memory (an OIIO IOProxy), and
    // the bytes go through spt::AtomicFile: no temporary name to redirect, none left if killed.
    // A plugin that cannot write to a proxy writes inside a fresh private folder instead.
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput proxy(bytes);
    const bool in_memory = out->supports("ioproxy");
    PrivateOutput named;
    auto fail = [&](const std::string& what) -> Status {
        out.reset();
        named.discard();
        return io_error(path, what);
    };
    if (in_memory) {
        if (!out->set_ioproxy(&proxy) || !out->open(path, spec)) return fail("cannot create file: " + oiio_message(out->geterror()));
    } else {
        auto p = PrivateOutput::create(path);
        if (!p) return p.error();
        named = std::move(*p);
        if (!out->open(named.file(), spec)) return fail("cannot create file: " + oiio_message(out->geterror()));
    }
    if (!out->write_image(buftype, data)) return fail("cannot write pixels: " + oiio_message(out->geterror()));
    if (!out->close()) return fail("cannot finish file: " + oiio_message(out->geterror()));
    out.reset();
    if (in_memory) return write_file_atomic(path, bytes.data(), bytes.size());
    return named.commit();
}

Result<std::unique_ptr<OIIO::ImageOutput>> create_output(const std::string& path, uint32_t width, uint32_t height,
                                                          const void* data) {
    if (width == 0 || height == 0 || !data)
        return io_error(path, "cannot write an empty image", Code::InvalidArgument);
    auto out = OIIO::ImageOutput::create(path);
    if (!out)
        return io_error(path, "no image writer for this extension (" + oiio_message(OIIO::geterror()) + ")",
                        Code::InvalidArgument);
    return out;
}

}  // namespace

Status write_image(const std::string& path, uint32_t width, uint32_t height, const uint8_t* rgb) {
    auto created = create_output(path, width, height, rgb);
    if (!created) return created.error();
    auto out = std::move(*created);
    const std::string fmt = out->format_name();
    const bool exr = fmt == "openexr";
    OIIO::ImageSpec spec(int(width), int(height), 3, exr ? TypeDesc::HALF : TypeDesc::UINT8);
    if (fmt == "jpeg") spec.attribute("CompressionQuality", 95);
    if (exr) spec.attribute("compression", "zip");
    spec.attribute("Software", "spt");
    if (!exr) return write_encoded(path, std::move(out), spec, TypeDesc::UINT8, rgb);
    const size_t n = size_t(width) * size_t(height) * 3;
    std::vector<float> f(n);
    for (size_t i = 0; i < n; ++i) f[i] = rgb[i] / 255.f;
    // sRGB -> linear, the inverse of read_image's transform.
    transforms().to_linear->apply(f.data(), int(width), int(height), 3, sizeof(float),
                                  3 * sizeof(float), 3 * sizeof(float) * width);
    return write_encoded(path, std::move(out), spec, TypeDesc::FLOAT, f.data());
}

Status write_pixels(const std::string& path, uint32_t width, uint32_t height, int channels, PixelType type,
                    const void* data) {
    if (channels != 3 && channels != 4) return io_error(path, "write_pixels: 3 or 4 channels", Code::InvalidArgument);
    auto created = create_output(path, width, height, data);
    if (!created) return created.error();
    auto out = std::move(*created);
    const std::string fmt = out->format_name();
    const bool exr = fmt == "openexr";
    const TypeDesc buf = type == PixelType::U8 ? TypeDesc::UINT8 : type == PixelType::U16 ? TypeDesc::UINT16 : TypeDesc::FLOAT;
    const TypeDesc file = type == PixelType::Half ? TypeDesc::HALF : buf;
    OIIO::ImageSpec spec(int(width), int(height), channels, file);
    if (channels == 4) {
        spec.alpha_channel = 3;
        // Straight alpha as given: OIIO would otherwise take it as premultiplied and divide.
        if (!exr) spec.attribute("oiio:UnassociatedAlpha", 1);
    }
    if (fmt == "jpeg") spec.attribute("CompressionQuality", 95);
    if (exr) spec.attribute("compression", "zip");
    spec.attribute("Software", "spt");
    return write_encoded(path, std::move(out), spec, buf, data);
}

std::string image_format_name(const std::string& path) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) {
        (void)OIIO::geterror();
        return "";
    }
    return out->format_name();
}

bool image_supports_alpha(const std::string& path) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) {
        (void)OIIO::geterror();
        return false;
    }
    return out->supports("alpha");
}

void srgb_to_linear(float* rgb, size_t n) {
    for (size_t at = 0; at < n;) {
        const size_t k = std::min<size_t>(n - at, size_t(1) << 20);
        transforms().to_linear->apply(rgb + at * 3, int(k), 1, 3, sizeof(float), 3 * sizeof(float), 3 * sizeof(float) * k);
        at += k;
    }
}

Status check_image_output(const std::string& path) {
    if (!is_writable_image_name(path)) return io_error(path, "no image writer for this extension", Code::InvalidArgument);
    return check_output_path(path);
}

}  // namespace spt::io
