// Image reading and writing through OpenImageIO. Every image the converter reads or writes
// goes through here.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "spt/render.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::io {

// An 8-bit sRGB RGB image: what the painter paints from.
struct Image {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgb;  // width * height * 3
};

struct ReadOptions {
    // Alpha (when present) is composited over this colour.
    Rgb8 background{255, 255, 255};
    // Checked before any pixel is allocated (the RGB8 result alone is 3 bytes per pixel).
    uint32_t max_side = 32768;
    uint64_t max_pixels = 1ull << 28;
};

// The colour transform applied to float input, quoted by --help texts.
inline constexpr const char* kLinearToSrgbText =
    "float images (EXR, float TIFF) are taken as scene-linear Rec.709 and converted with "
    "OpenImageIO's colorconvert \"linear\" -> \"sRGB\" (the sRGB transfer curve, no tone mapping; "
    "values above 1 clip)";

// Reads PNG, JPEG, TIFF, EXR, ... (anything OpenImageIO reads). 8/16-bit and float data are
// converted to 8-bit sRGB: float files (EXR, float TIFF) are taken as scene-linear Rec.709 and
// converted with OpenImageIO's colour management ("linear" -> "sRGB"). 1 channel is gray,
// 2 gray + alpha, 3 RGB, 4 RGBA; more channels: the first 3 (or 4 when the 4th is alpha).
// Alpha: integer files are composited in sRGB space (c*a + bg*(1-a), unassociated alpha as PNG
// stores it); float files are composited in linear light (premultiplied, as EXR stores it),
// the background being converted to linear first.
// Errors name the file.
Result<Image> read_image(const std::string& path, const ReadOptions& opts = {});

// What read_image makes of each half-float sample of a file it composites nothing into (no
// alpha): the 8-bit sRGB value of every half bit pattern, computed once by read_image's own
// steps, so that a reader of half files (spt plan's) can give read_image's bytes by table
// lookup. Null if the steps cannot be tabulated per sample.
const std::array<uint8_t, 65536>* half_to_srgb8();

// Writes by extension (.png, .exr, .tif, .jpg, ...). EXR is written as half float, linear
// (the inverse of read_image's transform), so that render output composes in VFX tools.
// PNG and TIFF are 8-bit, JPEG quality 95. The file is encoded in memory and written through
// spt::AtomicFile, so a failed or killed write never leaves a partial file.
Status write_image(const std::string& path, uint32_t width, uint32_t height, const uint8_t* rgb);
// A plain canvas (8-bit sRGB, no alpha); io::write_canvas (io/canvas_image.hpp) writes any kind.
inline Status write_image(const std::string& path, const Canvas& c) {
    return write_image(path, c.width, c.height, c.rgb.data());
}

// How write_pixels receives and stores samples: 8- or 16-bit integers, or floats stored as half.
enum class PixelType { U8, U16, Half };

// Writes `channels` interleaved channels (3: RGB; 4: RGBA, with straight alpha for every format
// but EXR, premultiplied for EXR as OpenEXR stores it; the channels are named R, G, B, A) by
// extension, through the same in-memory, atomic path as write_image. `data` holds width *
// height * channels samples of uint8_t (U8), uint16_t (U16) or float (Half).
Status write_pixels(const std::string& path, uint32_t width, uint32_t height, int channels, PixelType type,
                    const void* data);
// The OpenImageIO format name of a file's writer ("png", "openexr", "jpeg", ...), "" for none.
std::string image_format_name(const std::string& path);
// True when the writer for `path` stores an alpha channel (PNG, TIFF, EXR; not JPEG).
bool image_supports_alpha(const std::string& path);
// In place: `n` interleaved RGB values from sRGB-encoded to linear, the transform write_image
// uses for EXR (OpenImageIO's built-in "sRGB" -> "linear").
void srgb_to_linear(float* rgb, size_t n);

// True when OpenImageIO has a writer for the file's extension.
bool is_writable_image_name(const std::string& path);
// Before the work: OpenImageIO has a writer for the extension, and `path` can be created.
Status check_image_output(const std::string& path);

}  // namespace spt::io
