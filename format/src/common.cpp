// Small shared definitions: version string, names of error codes, codings, fields and template
// kinds, the default orientation table.
#include <cmath>

#include "spt/coding.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"
#include "spt/version.hpp"

namespace spt {

#define SPT_STR2(x) #x
#define SPT_STR(x) SPT_STR2(x)
// What `spt --version` advertises is the newest format feature this library writes.
static_assert(SPT_FORMAT_MAJOR == 1 && SPT_FORMAT_MINOR == kLeadMinorVersion,
              "SPT_FORMAT_MINOR must name the newest format minor version the library writes");

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

const char* coding_name(Coding c) {
    switch (c) {
        case Coding::Stored: return "stored";
        case Coding::Range: return "range";
        case Coding::Replay: return "replay";
    }
    return "reserved";
}

const char* field_name(Field f) {
    switch (f) {
        case Field::Count: return "counts";
        case Field::Kind: return "kind";
        case Field::SetTemplate: return "set/template";
        case Field::Orientation: return "orientation";
        case Field::Position: return "position";
        case Field::Color: return "colour";
        case Field::Alpha: return "alpha";
        case Field::Geometry: return "geometry";
        case Field::Removal: return "removals";
        case Field::Motion: return "motion";
        case Field::Candidates: return "candidates";
    }
    return "?";
}

const char* color_encoding_name(ColorEncoding e) {
    switch (e) {
        case ColorEncoding::Srgb8: return "srgb8";
        case ColorEncoding::LinearHalf: return "linear-half";
    }
    return "unknown";
}

const char* template_kind_name(TemplateKind k) {
    switch (k) {
        case TemplateKind::Bitmap: return "bitmap";
        case TemplateKind::Ellipse: return "ellipse";
        case TemplateKind::Rectangle: return "rectangle";
        case TemplateKind::Triangle: return "triangle";
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
