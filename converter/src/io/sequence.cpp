// Frame ranges, sequence patterns (#, @, %0Nd, oiiotool "1-120#") and sequence listing.
#include "io/sequence.hpp"

#include <OpenImageIO/filesystem.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <system_error>

namespace spt::io {

namespace fs = std::filesystem;

namespace {

constexpr long kMaxFrameNumber = 999999999;  // 9 digits: keeps arithmetic far from overflow

Error range_error(const std::string& text, const std::string& what) {
    return make_error(Code::InvalidArgument, "frame range '" + text + "': " + what);
}

// Parses a non-negative decimal number filling all of `s`.
bool parse_number(const std::string& s, long& out) {
    if (s.empty() || s.size() > 9) return false;
    long v = 0;
    for (char c : s) {
        if (!std::isdigit(uint8_t(c))) return false;
        v = v * 10 + (c - '0');
    }
    out = v;
    return true;
}

std::string trim(const std::string& s) {
    size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// Where the frame number goes in a pattern.
struct Placeholder {
    size_t begin = 0, end = 0;  // the characters replaced, range prefix included
    int width = 0;              // zero-padded digits; 0 = no padding
    std::optional<FrameRange> range;  // oiiotool "1-120#"
};

size_t name_start(const std::string& s) {
    size_t slash = s.find_last_of('/');
    return slash == std::string::npos ? 0 : slash + 1;
}

// OpenImageIO's parse_pattern finds the placeholder (#, @, %0Nd, %d) and an oiiotool range in
// front of it, in the file-name part only (a '#' in a folder name is not one). The width is
// ours: "####" is 4 digits as Blender, Nuke and ffmpeg write them, where OIIO counts 4 per '#'.
std::optional<Placeholder> find_placeholder(const std::string& s) {
    const size_t ns = name_start(s);
    const std::string name = s.substr(ns);
    std::string normalized, framespec;
    if (!OIIO::Filesystem::parse_pattern(name.c_str(), 0, normalized, framespec)) return std::nullopt;
    // normalized = prefix + "%0Nd" (or "%d") + suffix, with prefix and suffix as in `name`.
    // The placeholder starts where the two first differ, or, when the name already is printf
    // style, at its first "%[0-9]*d".
    size_t pct = 0;
    while (pct < name.size() && pct < normalized.size() && name[pct] == normalized[pct]) ++pct;
    if (pct == normalized.size()) {
        for (pct = normalized.find('%'); pct != std::string::npos; pct = normalized.find('%', pct + 1)) {
            size_t k = pct + 1;
            while (k < normalized.size() && std::isdigit(uint8_t(normalized[k]))) ++k;
            if (k < normalized.size() && normalized[k] == 'd') break;
        }
    }
    if (pct >= normalized.size() || normalized[pct] != '%') return std::nullopt;  // %V views: no frame
    size_t d = pct + 1;
    while (d < normalized.size() && std::isdigit(uint8_t(normalized[d]))) ++d;
    if (d >= normalized.size() || normalized[d] != 'd') return std::nullopt;
    const size_t suffix = normalized.size() - d - 1;
    if (name.size() < pct + suffix || name.compare(0, pct, normalized, 0, pct) != 0) return std::nullopt;
    Placeholder p{ns + pct, ns + name.size() - suffix, 0, std::nullopt};
    std::string_view text = std::string_view(name).substr(pct, name.size() - suffix - pct);
    if (!framespec.empty() && text.compare(0, framespec.size(), framespec) == 0) {
        if (auto r = parse_frame_range(framespec); r.ok() && !r->empty()) p.range = std::move(*r);
        else p.begin += framespec.size();  // a range we do not take (OIIO's "y" steps): part of the name
        text.remove_prefix(framespec.size());
    }
    if (text.empty()) return std::nullopt;
    const char c = text.back();
    if (c == '#') p.width = text.size() == 1 ? 4 : int(text.size());
    else if (c == '@') p.width = int(text.size());
    else if (text == "%d") p.width = 0;
    else if (text.size() >= 4 && text[1] == '0' && text.size() <= 5) p.width = std::atoi(std::string(text.substr(2, text.size() - 3)).c_str());
    else return std::nullopt;  // "%4d" (space padded): not a file-name convention
    return p;
}

std::string pad_number(long frame, int width) {
    char b[32];
    if (frame < 0)
        std::snprintf(b, sizeof b, "-%0*ld", width, -frame);
    else
        std::snprintf(b, sizeof b, "%0*ld", width, frame);
    return b;
}

std::string lower_ext(const std::string& path) {
    std::string e = fs::path(path).extension().string();
    for (auto& c : e) c = char(std::tolower(uint8_t(c)));
    return e;
}

bool is_image_name(const std::string& path) {
    static const std::set<std::string> kExt = {".png", ".jpg", ".jpeg", ".tif", ".tiff", ".exr",
                                               ".bmp", ".tga", ".dpx", ".hdr", ".webp", ".jxl",
                                               ".gif", ".ppm", ".pgm", ".pnm", ".sgi", ".jp2"};
    return kExt.count(lower_ext(path)) > 0;
}

}  // namespace

bool FrameRange::contains(long f) const {
    if (spans.empty()) return true;
    for (size_t i = 0; i < spans.size(); ++i) {
        const auto [a, b] = spans[i];
        if (f >= a && f <= b && (f - a) % step(i) == 0) return true;
    }
    return false;
}

std::vector<long> FrameRange::frames_within(long lo, long hi, size_t max_count) const {
    std::vector<long> out;
    if (hi < lo) return out;
    if (spans.empty()) {
        for (long f = lo; f <= hi && out.size() < max_count; ++f) out.push_back(f);
        return out;
    }
    std::set<long> seen;
    for (size_t i = 0; i < spans.size() && out.size() < max_count; ++i) {
        const long st = step(i);
        long f = spans[i].first;
        if (f < lo) f += (lo - f + st - 1) / st * st;
        for (; f <= std::min(spans[i].second, hi) && out.size() < max_count; f += st)
            if (seen.insert(f).second) out.push_back(f);
    }
    return out;
}

// Ours, not OIIO's enumerate_sequence: that one expands every frame into a vector ("0-999999999"
// is 4 GB) and takes the reversed and negative spans --frames refuses.
Result<FrameRange> parse_frame_range(const std::string& text) {
    FrameRange r;
    const std::string t = trim(text);
    if (t.empty()) return r;
    size_t pos = 0;
    while (pos <= t.size()) {
        size_t comma = t.find(',', pos);
        if (comma == std::string::npos) comma = t.size();
        std::string part = trim(t.substr(pos, comma - pos));
        if (part.empty()) return range_error(text, "empty item in the list");
        long step = 1;
        if (size_t x = part.find('x'); x != std::string::npos) {
            if (!parse_number(part.substr(x + 1), step) || step < 1)
                return range_error(text, "bad step in '" + part + "' (expected A-BxN, N >= 1)");
            part = part.substr(0, x);
        }
        long a = 0, b = 0;
        if (size_t dash = part.find('-', 1); dash != std::string::npos) {
            if (!parse_number(part.substr(0, dash), a) || !parse_number(part.substr(dash + 1), b))
                return range_error(text, "bad span '" + part + "' (expected A-B with frame numbers >= 0)");
            if (b < a) return range_error(text, "span '" + part + "' ends before it starts");
        } else {
            if (!parse_number(part, a)) return range_error(text, "bad frame number '" + part + "'");
            b = a;
        }
        if (b > kMaxFrameNumber) return range_error(text, "frame number too large");
        r.spans.emplace_back(a, b);
        r.steps.push_back(step);
        pos = comma + 1;
    }
    return r;
}

bool is_sequence_pattern(const std::string& name) { return find_placeholder(name).has_value(); }

// Substitution, not OIIO's enumerate_file_sequence: that one passes the whole name to printf,
// so any other '%' in it ("100%_####.png") would be read as a conversion.
std::string format_frame(const std::string& pattern, long frame) {
    auto p = find_placeholder(pattern);
    if (!p) return pattern;
    return pattern.substr(0, p->begin) + pad_number(frame, p->width) + pattern.substr(p->end);
}

bool is_video_file(const std::string& path) {
    static const std::set<std::string> kExt = {".mp4", ".mov", ".mkv", ".avi", ".mpg", ".mpeg",
                                               ".webm", ".m4v", ".wmv", ".flv", ".ogv", ".mxf",
                                               ".ts", ".m2ts", ".y4m"};
    return kExt.count(lower_ext(path)) > 0;
}

Result<std::vector<SequenceFile>> list_sequence(const std::string& pattern_or_dir,
                                                const FrameRange& range) {
    std::vector<SequenceFile> out;
    std::error_code ec;
    const std::string& pat = pattern_or_dir;

    if (fs::is_directory(pat, ec)) {
        std::vector<std::string> names;
        for (fs::directory_iterator it(pat, ec), end; !ec && it != end; it.increment(ec))
            if (it->is_regular_file(ec) && is_image_name(it->path().string()))
                names.push_back(it->path().string());
        if (ec) return make_error(Code::IoError, pat + ": cannot list the folder: " + ec.message());
        std::sort(names.begin(), names.end());
        for (size_t i = 0; i < names.size(); ++i)
            if (range.contains(long(i))) out.push_back({long(i), names[i]});
        if (out.empty())
            return make_error(Code::IoError, pat + ": no image files in this folder" +
                                                 std::string(range.empty() ? "" : " within the frame range"));
        return out;
    }

    auto p = find_placeholder(pat);
    if (!p) return make_error(Code::InvalidArgument, pat + ": not a folder nor a sequence pattern (use ####, @, %04d)");

    if (p->range) {
        // The pattern names its frames: every one must exist.
        for (long f : p->range->frames_within(0, kMaxFrameNumber)) {
            if (!range.contains(f)) continue;
            std::string path = format_frame(pat, f);
            if (!fs::exists(path, ec))
                return make_error(Code::IoError, pat + ": frame " + std::to_string(f) + " is missing (" + path + ")");
            out.push_back({f, std::move(path)});
        }
        if (out.empty()) return make_error(Code::InvalidArgument, pat + ": no frame of the pattern's range is within the frame range");
        return out;
    }

    // Find the frames on disk: prefix + digits + suffix within the pattern's folder. Ours, not
    // OIIO's scan_for_matching_filenames: its regex leaves '+', '^', '$' and '|' unescaped
    // ("take+1.####.png" finds nothing), it needs a width ("%d" fails) and it keeps mis-padded
    // names ("f.00003.png" for ####).
    const size_t ns = name_start(pat);
    const std::string dir = ns == 0 ? std::string(".") : pat.substr(0, ns);
    const std::string prefix = pat.substr(ns, p->begin - ns), suffix = pat.substr(p->end);
    if (!fs::is_directory(dir, ec))
        return make_error(Code::IoError, pat + ": folder '" + dir + "' does not exist");
    std::map<long, std::string> found;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= prefix.size() + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
            continue;
        const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
        long f = 0;
        if (!parse_number(digits, f)) continue;
        // Padded to exactly `width`, or longer without a leading zero (frame 10000 of "####").
        const bool width_ok = int(digits.size()) == p->width ||
                              ((int(digits.size()) > p->width) && (digits[0] != '0' || digits.size() == 1));
        if (!width_ok || !range.contains(f)) continue;
        found.emplace(f, ns == 0 ? name : (fs::path(dir) / name).string());
    }
    if (ec) return make_error(Code::IoError, pat + ": cannot list folder '" + dir + "': " + ec.message());
    for (auto& [f, path] : found) out.push_back({f, path});
    if (out.empty())
        return make_error(Code::IoError, pat + ": no files match this pattern" +
                                             std::string(range.empty() ? "" : " within the frame range"));
    return out;
}

}  // namespace spt::io
