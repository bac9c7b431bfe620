// Small shared definitions: version string, error code names, default orientation table.
#include <cmath>

#include "spt/result.hpp"
#include "spt/types.hpp"
#include "spt/version.hpp"

namespace spt {

#define SPT_STR2(x) #x
#define SPT_STR(x) SPT_STR2(x)
const char* library_version() {
    return SPT_STR(SPT_VERSION_MAJOR) "." SPT_STR(SPT_VERSION_MINOR) "." SPT_STR(SPT_VERSION_PATCH);
}

const char* code_name(Code c) {
    switch (c) {
        case Code::Ok: return "ok";
        case Code::IoError: return "i/o error";
        case Code::NotSpt: return "not an .spt file";
        case Code::Unsupported: return "unsupported";
        case Code::Corrupt: return "corrupt";
        case Code::Truncated: return "truncated";
        case Code::LimitExceeded: return "limit exceeded";
        case Code::InvalidArgument: return "invalid argument";
        case Code::BadState: return "bad state";
    }
    return "unknown";
}

// The table is computed here once, by the encoder side; files store it, so decoders never
// evaluate cos/sin (SPEC.md 3.1).
std::vector<Orientation> default_orientations(int n) {
    std::vector<Orientation> t;
    if (n < 1) n = 1;
    for (int k = 0; k < n; ++k) {
        const double ang = M_PI * k / n;
        t.push_back({int16_t(std::lround(16384.0 * std::cos(ang))), int16_t(std::lround(16384.0 * std::sin(ang)))});
    }
    return t;
}

}  // namespace spt
