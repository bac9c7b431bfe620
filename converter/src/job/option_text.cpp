#include "job/option_text.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace spt::job {

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out;
    std::string cur;
    for (char c : s) {
        if (c == sep) { out.push_back(cur); cur.clear(); } else cur += c;
    }
    out.push_back(cur);
    return out;
}

}  // namespace

bool parse_u64(const std::string& s, uint64_t& v) {
    if (s.empty() || s[0] == '-' || s[0] == '+') return false;
    char* end = nullptr;
    errno = 0;
    const unsigned long long x = std::strtoull(s.c_str(), &end, 10);
    if (errno || *end) return false;
    v = x;
    return true;
}

bool parse_long(const std::string& s, long lo, long hi, long& v) {
    char* end = nullptr;
    errno = 0;
    const long x = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || errno || *end || x < lo || x > hi) return false;
    v = x;
    return true;
}

bool parse_double(const std::string& s, double lo, double hi, double& v) {
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(s.c_str(), &end);
    if (s.empty() || errno || *end || !std::isfinite(x) || x < lo || x > hi) return false;
    v = x;
    return true;
}

bool parse_set_sizes(const std::string& s, std::vector<StrokeSet>& out) {
    out.clear();
    for (const auto& item : split(s, ',')) {
        const auto wh = split(item, 'x');
        long w, h;
        if (wh.size() != 2 || !parse_long(wh[0], 1, 4096, w) || !parse_long(wh[1], 1, 4096, h)) return false;
        out.push_back(StrokeSet{uint16_t(w), uint16_t(h)});
    }
    return !out.empty();
}

bool parse_rect(const std::string& s, paint::Rect& r) {
    const auto p = split(s, ',');
    long v[4];
    if (p.size() != 4) return false;
    for (int i = 0; i < 4; ++i)
        if (!parse_long(p[size_t(i)], 0, 1L << 24, v[i])) return false;
    if (v[2] <= 0 || v[3] <= 0) return false;
    r = paint::Rect{int32_t(v[0]), int32_t(v[1]), int32_t(v[2]), int32_t(v[3])};
    return true;
}

bool parse_rgb(const std::string& s, Rgb8& c) {
    const auto p = split(s, ',');
    long v[3];
    if (p.size() != 3) return false;
    for (int i = 0; i < 3; ++i)
        if (!parse_long(p[size_t(i)], 0, 255, v[i])) return false;
    c = Rgb8{uint8_t(v[0]), uint8_t(v[1]), uint8_t(v[2])};
    return true;
}

bool parse_byte_size(const std::string& s, uint64_t& bytes) {
    std::string num = s;
    int shift = 0;
    if (!num.empty()) {
        const char unit = num.back();
        shift = unit == 'K' || unit == 'k' ? 10 : unit == 'M' || unit == 'm' ? 20 : unit == 'G' || unit == 'g' ? 30 : 0;
        if (shift > 0) num.pop_back();
    }
    uint64_t n = 0;
    if (!parse_u64(num, n) || n > (~uint64_t(0) >> shift)) return false;
    bytes = n << shift;
    return true;
}

std::string byte_size_text(uint64_t bytes) {
    for (auto [shift, unit] : {std::pair{30, "G"}, {20, "M"}, {10, "K"}})
        if (bytes != 0 && bytes % (uint64_t(1) << shift) == 0) return std::to_string(bytes >> shift) + unit;
    return std::to_string(bytes);
}

bool parse_target_bytes(const std::string& s, uint64_t& bytes, bool& per_second) {
    std::string num = s;
    const bool ps = num.size() > 2 && num.compare(num.size() - 2, 2, "/s") == 0;
    if (ps) num.resize(num.size() - 2);
    uint64_t n = 0;
    if (!parse_u64(num, n) || n < 64) return false;
    bytes = n;
    per_second = ps;
    return true;
}

namespace {

// The fewest digits (from `first`) in `format` ("%.*g" or "%.*f") that strtod reads back to v.
std::string shortest(double v, const char* format, int first) {
    char buf[64];
    for (int prec = first; prec <= 17; ++prec) {
        std::snprintf(buf, sizeof buf, format, prec, v);
        if (std::strtod(buf, nullptr) == v) break;
    }
    return buf;
}

}  // namespace

std::string exact(double v) { return shortest(v, "%.*g", 6); }
std::string plain(double v) { return shortest(v, "%.*f", 0); }

std::string set_sizes_text(const std::vector<StrokeSet>& sizes) {
    std::string s;
    for (size_t i = 0; i < sizes.size(); ++i)
        s += (i ? "," : "") + std::to_string(sizes[i].width) + "x" + std::to_string(sizes[i].height);
    return s;
}

std::string rect_text(const paint::Rect& r) {
    return std::to_string(r.x) + "," + std::to_string(r.y) + "," + std::to_string(r.w) + "," + std::to_string(r.h);
}

std::string rgb_text(const Rgb8& c) {
    return std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b);
}

}  // namespace spt::job
