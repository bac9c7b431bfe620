// Frame rates as the rationals a .spt header stores (frame_rate.hpp).
#include "frames/frame_rate.hpp"

#include <cmath>
#include <cstdlib>

namespace spt::video {

Rational fps_from_double(double fps) {
    if (!(fps > 0) || !std::isfinite(fps) || fps > 1e6) return {24, 1};
    const double whole = std::round(fps);
    if (std::fabs(fps - whole) < 1e-3) return {uint32_t(whole), 1};
    // NTSC-family rates: N * 1000 / 1001 (23.976, 29.97, 59.94, 47.952, 119.88).
    const double n = std::round(fps * 1.001);
    if (std::fabs(fps - n * 1000.0 / 1001.0) < 2e-3 * fps / 30.0 + 1e-3) return {uint32_t(n * 1000), 1001};
    // Anything else to the nearest 1/1000.
    uint32_t num = uint32_t(std::llround(fps * 1000.0)), den = 1000;
    for (uint32_t p : {2u, 5u})
        while (num % p == 0 && den % p == 0) num /= p, den /= p;
    return {num, den};
}

Result<Rational> parse_fps(const std::string& text) {
    auto bad = [&] {
        return make_error(Code::InvalidArgument,
                          "frame rate '" + text + "': expected a positive number (24, 29.97) or a ratio (30000/1001)");
    };
    const size_t slash = text.find('/');
    char* end = nullptr;
    if (slash != std::string::npos) {
        const std::string a = text.substr(0, slash), b = text.substr(slash + 1);
        const unsigned long long num = std::strtoull(a.c_str(), &end, 10);
        if (a.empty() || *end) return bad();
        const unsigned long long den = std::strtoull(b.c_str(), &end, 10);
        if (b.empty() || *end || num == 0 || den == 0 || num > 0xFFFFFFFFull || den > 0xFFFFFFFFull) return bad();
        return Rational{uint32_t(num), uint32_t(den)};
    }
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end || !(v > 0) || v > 1e6) return bad();
    return fps_from_double(v);
}

}  // namespace spt::video
