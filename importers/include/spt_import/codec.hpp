// Small byte codecs the exporters and importers need: base64 and a minimal PNG writer.
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

// An 8-bit PNG (colour type 0 gray, or 6 RGBA) compressed with stored deflate blocks: no
// compression, standard library only, read by every PNG decoder.
std::vector<uint8_t> encode_png(uint32_t width, uint32_t height, int channels, const uint8_t* pixels);

}  // namespace spt::import
