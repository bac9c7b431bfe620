// Straight sRGB views of canvases (spt/display.hpp).
#include "spt/display.hpp"

#include <cmath>

#include "spt/color.hpp"

namespace spt {

float srgb_encode(float v) {
    if (!(v > 0.f)) return 0.f;
    if (v >= 1.f) return 1.f;
    return v <= 0.0031308f ? v * 12.92f : 1.055f * std::pow(v, 1.f / 2.4f) - 0.055f;
}

float srgb_decode(float v) {
    if (!(v > 0.f)) return 0.f;
    if (v >= 1.f) return 1.f;
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

uint8_t unit_to_u8(float v) {
    if (!(v > 0.f)) return 0;
    if (v >= 1.f) return 255;
    return uint8_t(std::floor(v * 255.f + 0.5f));
}

namespace {

// The sRGB byte of every opaque half code: encoding 1 without alpha is a table look-up.
const std::vector<uint8_t>& opaque_table() {
    static const std::vector<uint8_t> t = [] {
        std::vector<uint8_t> v(size_t(kMaxHalfCode) + 1);
        for (uint32_t h = 0; h <= kMaxHalfCode; ++h) v[h] = unit_to_u8(srgb_encode(half_to_float(uint16_t(h))));
        return v;
    }();
    return t;
}

}  // namespace

void to_rgba8(const Canvas& c, const Header& h, std::vector<uint8_t>& out) {
    const size_t n = size_t(c.width) * c.height;
    out.assign(n * 4, 0);
    const bool alpha = h.alpha && c.alpha.size() == n;
    if (h.color == ColorEncoding::LinearHalf) {
        if (c.rgb16.size() != n * 3) return;
        const auto& table = opaque_table();
        for (size_t i = 0; i < n; ++i) {
            const uint32_t a = alpha ? c.alpha[i] : 255u;
            if (a == 0) continue;
            for (int k = 0; k < 3; ++k) {
                const uint16_t code = c.rgb16[i * 3 + k];
                out[i * 4 + k] = a == 255 ? (code <= kMaxHalfCode ? table[code] : 0)
                                          : unit_to_u8(srgb_encode(half_to_float(code) * 255.f / float(a)));
            }
            out[i * 4 + 3] = uint8_t(a);
        }
        return;
    }
    if (c.rgb.size() != n * 3) return;
    for (size_t i = 0; i < n; ++i) {
        const uint32_t a = alpha ? c.alpha[i] : 255u;
        for (int k = 0; k < 3; ++k) out[i * 4 + k] = a == 255 ? c.rgb[i * 3 + k] : unpremultiply8(c.rgb[i * 3 + k], a);
        out[i * 4 + 3] = uint8_t(a);
    }
}

float background_linear(const Header& h, int ch) {
    const uint8_t hi = ch == 0 ? h.background.r : ch == 1 ? h.background.g : h.background.b;
    if (h.color == ColorEncoding::LinearHalf) {
        const uint8_t lo = ch == 0 ? h.background_lo.r : ch == 1 ? h.background_lo.g : h.background_lo.b;
        const uint16_t code = uint16_t(hi << 8 | lo);
        return code <= kMaxHalfCode ? half_to_float(code) : 0.f;
    }
    return srgb_decode(hi / 255.f);
}

}  // namespace spt
