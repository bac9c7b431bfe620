// Small byte codecs the exporters and importers need: base64 and a PNG writer (libpng).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace spt::import {

std::string base64_encode(const uint8_t* data, size_t n);
// Strict decoding (RFC 4648 alphabet, padding optional, whitespace ignored); nullopt when bad.
std::optional<std::vector<uint8_t>> base64_decode(std::string_view s);

// An 8-bit PNG (1 channel gray, 3 RGB, 4 RGBA; sRGB) written by libpng; empty on failure.
std::vector<uint8_t> encode_png(uint32_t width, uint32_t height, int channels, const uint8_t* pixels);

}  // namespace spt::import
