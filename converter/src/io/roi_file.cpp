// The --roi-file reader: the importers' strict JSON parser (line numbers, depth and size limits)
// plus the schema checks of io/roi_file.hpp.
#include "io/roi_file.hpp"

#include <cmath>
#include <fstream>

#include "spt_json/json.hpp"

namespace spt::io {

namespace {

constexpr size_t kMaxFileBytes = size_t(16) << 20;
constexpr double kMaxCoord = double(1 << 24);
constexpr double kMaxFrame = 4294967294.0;  // 0xFFFFFFFF means "all frames"

bool integer_in(const json::Value* v, double lo, double hi, double& out) {
    if (!v || !v->is_number() || v->number != std::floor(v->number) || v->number < lo || v->number > hi) return false;
    out = v->number;
    return true;
}

// One decimal frame number, digits only (no sign, no spaces).
bool frame_number(std::string_view s, uint32_t& out) {
    if (s.empty() || s.size() > 10) return false;
    uint64_t v = 0;
    for (char c : s) {
        if (c < '0' || c > '9') return false;
        v = v * 10 + uint64_t(c - '0');
    }
    if (double(v) > kMaxFrame) return false;
    out = uint32_t(v);
    return true;
}

// "frames": "A", "A-B", a number, or [A, B]; A <= B.
bool frame_range(const json::Value& f, uint32_t& first, uint32_t& last) {
    double a = 0, b = 0;
    if (f.is_string()) {
        const std::string_view t = f.text;
        const size_t dash = t.find('-');
        if (dash == std::string_view::npos) {
            if (!frame_number(t, first)) return false;
            last = first;
        } else if (!frame_number(t.substr(0, dash), first) || !frame_number(t.substr(dash + 1), last)) {
            return false;
        }
        return first <= last;
    }
    if (f.is_number()) {
        if (!integer_in(&f, 0, kMaxFrame, a)) return false;
        first = last = uint32_t(a);
        return true;
    }
    if (!f.is_array() || f.items.size() != 2 || !integer_in(&f.items[0], 0, kMaxFrame, a) ||
        !integer_in(&f.items[1], 0, kMaxFrame, b) || b < a)
        return false;
    first = uint32_t(a);
    last = uint32_t(b);
    return true;
}

}  // namespace

Result<std::vector<RoiRange>> parse_roi_json(std::string_view text, const std::string& name) {
    json::ParseLimits lim;
    lim.max_bytes = kMaxFileBytes;
    lim.max_depth = 32;
    Result<json::Value> root = json::parse(text, name, lim);
    if (!root) {  // the parser names the line; add the byte offset too
        const Error& e = root.error();
        return make_error(e.code, e.message + " (byte " + std::to_string(e.offset) + ")", e.offset);
    }
    const json::Value* rois = root->is_object() ? root->find("rois") : nullptr;
    if (!rois || !rois->is_array())
        return make_error(Code::InvalidArgument, name + ": expected an object with a \"rois\" array");
    std::vector<RoiRange> out;
    out.reserve(rois->items.size());
    for (size_t i = 0; i < rois->items.size(); ++i) {
        const json::Value& r = rois->items[i];
        const std::string where = name + ":" + std::to_string(r.line) + ": rois[" + std::to_string(i) + "]: ";
        if (!r.is_object()) return make_error(Code::InvalidArgument, where + "not an object");
        RoiRange s;
        int32_t* dst[] = {&s.x, &s.y, &s.w, &s.h};
        const char* keys[] = {"x", "y", "w", "h"};
        for (int k = 0; k < 4; ++k) {
            const double lo = k < 2 ? 0 : 1;  // x, y >= 0; w, h >= 1
            double v = 0;
            if (!integer_in(r.find(keys[k]), lo, kMaxCoord, v))
                return make_error(Code::InvalidArgument, where + "\"" + keys[k] + "\" must be an integer in " +
                                                             (k < 2 ? "0" : "1") + "..16777216");
            *dst[k] = int32_t(v);
        }
        if (const json::Value* f = r.find("frames"); f && !frame_range(*f, s.first_frame, s.last_frame))
            return make_error(Code::InvalidArgument,
                              where + "\"frames\" must be \"A-B\", \"A\", a number or [A, B] with 0 <= A <= B");
        out.push_back(s);
    }
    return out;
}

Result<std::vector<RoiRange>> read_roi_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return make_error(Code::IoError, path + ": cannot open the ROI file");
    // Reads in chunks up to one byte past the limit, so a huge (or endless) file is refused cheaply.
    std::string text;
    char chunk[1 << 16];
    while (text.size() <= kMaxFileBytes && in.read(chunk, sizeof chunk).gcount() > 0)
        text.append(chunk, size_t(in.gcount()));
    if (text.size() > kMaxFileBytes) return make_error(Code::LimitExceeded, path + ": ROI file larger than 16 MiB");
    return parse_roi_json(text, path);
}

}  // namespace spt::io
