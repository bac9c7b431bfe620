// Option values as text: the parsers the option table's rows store with, and the spellings a plan
// stores and painter.options shows. Every number written reads back to the same value.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "paint/painter.hpp"
#include "spt/types.hpp"

namespace spt::job {

bool parse_u64(const std::string& s, uint64_t& v);  // decimal, no sign
bool parse_long(const std::string& s, long lo, long hi, long& v);
bool parse_double(const std::string& s, double lo, double hi, double& v);  // finite, in lo..hi
bool parse_set_sizes(const std::string& s, std::vector<StrokeSet>& out);   // WxH,WxH,...
bool parse_rect(const std::string& s, paint::Rect& r);                     // x,y,w,h
bool parse_rgb(const std::string& s, Rgb8& c);                             // R,G,B
bool parse_byte_size(const std::string& s, uint64_t& bytes);  // N, NK, NM or NG (binary units)
bool parse_target_bytes(const std::string& s, uint64_t& bytes, bool& per_second);  // N or N/s, N >= 64

std::string byte_size_text(uint64_t bytes);  // as parse_byte_size reads it: 8G, 512M, 1000
std::string exact(double v);  // the shortest text strtod reads back to v
std::string plain(double v);  // the same without an exponent, as people write bounds: 0.000001
std::string set_sizes_text(const std::vector<StrokeSet>& sizes);
std::string rect_text(const paint::Rect& r);
std::string rgb_text(const Rgb8& c);

}  // namespace spt::job
