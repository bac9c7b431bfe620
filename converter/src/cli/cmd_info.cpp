// spt info: describe a .spt file (header, frames, strokes, bytes per section and per field).
#include <cmath>
#include <cstdio>
#include <map>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "spt_json/write.hpp"
#include "io/spt_file.hpp"
#include "spt/color.hpp"
#include "spt/concat.hpp"
#include "spt/spt.hpp"

namespace spt::cli {

namespace {

double degrees(const Orientation& o) {
    return std::atan2(double(o.sin_q14), double(o.cos_q14)) * 180.0 / 3.14159265358979323846;
}

// Byte counts of the file's sections, from the frame table alone (no decoding).
struct Sections {
    uint64_t total = 0, header = 0, frames = 0, strokes = 0, motion = 0, framing = 0, tail = 0;
};

Sections sections(const Reader& r) {
    Sections s;
    s.total = r.file_size();
    const auto& f = r.frames();
    s.header = f.empty() ? s.total : f.front().offset;
    uint64_t end = s.header;
    for (const auto& e : f) {
        s.frames += e.chunk_bytes;
        s.strokes += e.stroke_bytes;
        s.motion += e.motion_bytes;
        end = std::max(end, e.offset + e.chunk_bytes);
    }
    s.framing = s.frames - std::min(s.frames, s.strokes + s.motion);
    s.tail = s.total - std::min(s.total, end);
    return s;
}

// What the summary line says of a file that is not sound: the reader's last warning is where it
// stopped (a truncated tail, trailing bytes after the end chunk, a damaged chunk).
std::string soundness(const Reader& r) {
    if (r.complete()) return "";
    if (r.warnings().empty() || r.warnings().back().code == Code::Truncated) return ", INCOMPLETE (no end chunk)";
    return ", NOT SOUND (" + r.warnings().back().message + ")";
}

}  // namespace

int cmd_info(int argc, char** argv) {
    Args args("info", "describe a .spt file: header, frames, strokes, bytes per section",
              "spt info FILE.spt [--json] [--frames] [--no-fields]");
    args.positional("FILE.spt", "the file to describe")
        .flag("json", "print one JSON document on stdout (keys below)")
        .flag("frames", "list every frame: type, coding, offset, bytes, strokes added/removed/live "
                        "(decodes the whole file)")
        .flag("no-fields", "skip the per-field byte breakdown and the stroke kinds (they decode every frame)")
        .epilog(
            "Sections: header = everything before the first frame (signature, HEAD, templates, "
            "metadata); strokes / motion = frame payload coding added strokes / removals and "
            "motion; framing = frame chunk headers and checksums; tail = ROIs, index, end chunk.\n"
            "Fields: where frame-body bits go (range coding: information cost of each field's "
            "decisions; stored: exact bytes).\n\n"
            "JSON keys (stable): file, file_bytes, format_version, complete, has_index, canvas "
            "{width, height}, fps {num, den, value}, frame_count (header value, null when "
            "unknown), frames_found, first_frame_number (the source's number of frame 0, SPEC.md 3.3; 0 "
            "when the file has none), duration_seconds, color (\"srgb8\" or \"linear-half\"), color_encoding "
            "{id (0, 1), name (\"8-bit sRGB\", \"scene-linear half float\")}, alpha (true: an alpha canvas, "
            "format 1.3), curve_grid (true: curves carry a supersampling grid, anti-aliased, format 1.4), background [r, g, b] (the high bytes in colour encoding 1), background_codes [r, g, b] "
            "and background_linear [r, g, b] (colour encoding 1: the 16-bit half codes and their values), sets "
            "[{width, height}], orientations [{cos_q14, sin_q14, degrees}], templates [{kind, "
            "name, width, height}], metadata {key: value}, rois [{first_frame, last_frame, x, y, "
            "w, h}], key_frames [index...], strokes {added, removed, kinds {stamp, affine, curve, "
            "polygon} (added strokes by kind; absent with --no-fields), max_live (with --frames)}, "
            "bytes {total, header, frames, strokes, motion, framing, tail}, fields {name: "
            "bytes} (absent with --no-fields), warnings [text], and with --frames: frame_list "
            "[{index, number (first_frame_number + index), type, coding, offset, bytes, stroke_bytes, motion_bytes, added, removed, "
            "live}].");
    if (int rc = args.parse(argc, argv); rc >= 0) return rc;
    const std::string path = args.pos("FILE.spt");
    const bool json = args.has("json"), list = args.has("frames"), fields = !args.has("no-fields");

    auto opened = io::open_spt(path);
    if (!opened) {
        std::fprintf(stderr, "spt info: %s\n", opened.error().message.c_str());
        return 1;
    }
    Reader& r = **opened;
    const StreamInfo& info = r.info();
    const uint32_t first_number = first_frame_number(info);  // SPEC.md 3.3 source.first_frame
    const Header& h = info.header;
    const auto& frames = r.frames();
    const Sections sec = sections(r);

    uint64_t added = 0, removed = 0;
    std::vector<uint32_t> keys;
    for (const auto& f : frames) {
        added += f.added;
        removed += f.removed;
        if (f.type == FrameType::Key) keys.push_back(f.index);
    }
    // Live counts need every frame applied; only with --frames.
    std::vector<uint64_t> live;
    uint64_t max_live = 0;
    if (list) {
        for (size_t i = 0; i < frames.size(); ++i) {
            auto s = r.strokes_at(i);
            if (!s) {
                std::fprintf(stderr, "spt info: %s\n", io::frame_error(r, i, path, s.error()).c_str());
                return 1;
            }
            live.push_back((*s)->size());
            max_live = std::max<uint64_t>(max_live, (*s)->size());
        }
    }
    FieldStats fs;
    uint64_t kinds[4] = {0, 0, 0, 0};  // added strokes by StrokeKind
    static const char* const kKindNames[4] = {"stamp", "affine", "curve", "polygon"};
    if (fields) {
        for (size_t i = 0; i < frames.size(); ++i) {
            auto s = r.field_stats(i);
            auto f = s ? r.read_frame(i) : Result<Frame>(s.error());
            if (!f) {
                std::fprintf(stderr, "spt info: %s\n", io::frame_error(r, i, path, f.error()).c_str());
                return 1;
            }
            fs.add(*s);
            for (const Stroke& st : f->added) ++kinds[size_t(st.kind) & 3];
        }
    }
    const double fps = h.fps.den ? double(h.fps.num) / h.fps.den : 0.0;
    const char* color = color_encoding_name(h.color);
    const bool linear = h.color == ColorEncoding::LinearHalf;
    const char* encoding_text = linear ? "scene-linear half float" : h.color == ColorEncoding::Srgb8 ? "8-bit sRGB" : "unknown";
    uint16_t bg_codes[3] = {uint16_t(h.background.r << 8 | h.background_lo.r), uint16_t(h.background.g << 8 | h.background_lo.g),
                            uint16_t(h.background.b << 8 | h.background_lo.b)};

    if (json) {
        using json::Doc;
        Doc j = {{"file", path}, {"file_bytes", sec.total}};
        j["format_version"] = std::to_string(h.version_major) + "." + std::to_string(h.version_minor);
        j["complete"] = r.complete();
        j["has_index"] = r.has_index();
        j["canvas"] = {{"width", h.width}, {"height", h.height}};
        j["fps"] = {{"num", h.fps.num}, {"den", h.fps.den}, {"value", json::number(fps)}};
        j["frame_count"] = h.frame_count == kUnknownFrameCount ? Doc(nullptr) : Doc(h.frame_count);
        j["frames_found"] = uint64_t(frames.size());
        j["first_frame_number"] = first_number;
        j["duration_seconds"] = json::number(fps > 0 ? double(frames.size()) / fps : 0.0);
        j["color"] = color;
        j["color_encoding"] = {{"id", uint32_t(h.color)}, {"name", encoding_text}};
        j["alpha"] = h.alpha;
        j["curve_grid"] = h.curve_grid;
        j["background"] = Doc::array({h.background.r, h.background.g, h.background.b});
        if (linear) {
            j["background_codes"] = bg_codes;
            Doc& lin = j["background_linear"] = Doc::array();
            for (uint16_t c : bg_codes) lin.push_back(json::number(double(half_to_float(c))));
        }
        Doc& sets = j["sets"] = Doc::array();
        for (const auto& s : h.sets) sets.push_back({{"width", uint32_t(s.width)}, {"height", uint32_t(s.height)}});
        Doc& orients = j["orientations"] = Doc::array();
        for (const auto& o : h.orientations)
            orients.push_back({{"cos_q14", int(o.cos_q14)}, {"sin_q14", int(o.sin_q14)}, {"degrees", json::number(degrees(o))}});
        Doc& templates = j["templates"] = Doc::array();
        for (const auto& t : info.templates)
            templates.push_back({{"kind", template_kind_name(t.kind)}, {"name", t.name}, {"width", uint32_t(t.width)},
                                 {"height", uint32_t(t.height)}});
        Doc& metadata = j["metadata"] = Doc::object();
        std::map<std::string, std::string> meta(info.metadata.begin(), info.metadata.end());
        for (const auto& [k, v] : info.metadata) meta[k] = v;  // last value of a repeated key
        for (const auto& [k, v] : meta) metadata[k] = v;
        Doc& rois = j["rois"] = Doc::array();
        for (const auto& q : info.rois)
            rois.push_back({{"first_frame", q.first_frame}, {"last_frame", q.last_frame}, {"x", q.x}, {"y", q.y},
                            {"w", q.w}, {"h", q.h}});
        j["key_frames"] = keys;
        Doc& strokes = j["strokes"] = {{"added", added}, {"removed", removed}};
        if (fields) {
            Doc& k = strokes["kinds"] = Doc::object();
            for (size_t i = 0; i < 4; ++i) k[kKindNames[i]] = kinds[i];
        }
        if (list) strokes["max_live"] = max_live;
        j["bytes"] = {{"total", sec.total}, {"header", sec.header}, {"frames", sec.frames}, {"strokes", sec.strokes},
                      {"motion", sec.motion}, {"framing", sec.framing}, {"tail", sec.tail}};
        if (fields) {
            Doc& fj = j["fields"] = Doc::object();
            for (size_t i = 0; i < kFieldCount; ++i) fj[field_name(Field(i))] = json::number(fs.bits[i] / 8.0);
        }
        Doc& warnings = j["warnings"] = Doc::array();
        for (const auto& w : r.warnings()) warnings.push_back(io::describe_error(path, w));
        if (list) {
            Doc& fl = j["frame_list"] = Doc::array();
            for (size_t i = 0; i < frames.size(); ++i) {
                const auto& f = frames[i];
                fl.push_back({{"index", f.index}, {"number", uint64_t(first_number) + f.index},
                              {"type", f.type == FrameType::Key ? "key" : "inter"}, {"coding", coding_name(f.coding)},
                              {"offset", f.offset}, {"bytes", f.chunk_bytes}, {"stroke_bytes", f.stroke_bytes},
                              {"motion_bytes", f.motion_bytes}, {"added", f.added}, {"removed", f.removed},
                              {"live", live[i]}});
            }
        }
        std::printf("%s\n", json::dump(j, 2).c_str());
        return 0;
    }

    std::printf("%s: .spt %u.%u, %llu bytes%s%s\n", path.c_str(), h.version_major, h.version_minor,
                (unsigned long long)sec.total, soundness(r).c_str(),
                r.has_index() ? "" : ", no index");
    if (h.plain_color()) {
        std::printf("canvas      %u x %u, %u/%u fps (%.3f), colour %s, background #%02x%02x%02x\n", h.width,
                    h.height, h.fps.num, h.fps.den, fps, color, h.background.r, h.background.g, h.background.b);
    } else {
        std::printf("canvas      %u x %u, %u/%u fps (%.3f), colour %s (%s), %s, background ", h.width, h.height,
                    h.fps.num, h.fps.den, fps, color, encoding_text, h.alpha ? "alpha" : "no alpha");
        if (linear)
            std::printf("%g, %g, %g linear (codes %04x %04x %04x)", double(half_to_float(bg_codes[0])), double(half_to_float(bg_codes[1])),
                        double(half_to_float(bg_codes[2])), bg_codes[0], bg_codes[1], bg_codes[2]);
        else
            std::printf("#%02x%02x%02x", h.background.r, h.background.g, h.background.b);
        std::printf("%s\n", h.alpha ? " (shown behind the transparent canvas)" : "");
    }
    if (h.curve_grid) std::printf("curves      carry a supersampling grid (anti-aliased, format 1.4)\n");
    std::printf("frames      %zu found", frames.size());
    if (h.frame_count != kUnknownFrameCount) std::printf(" (header says %u)", h.frame_count);
    if (fps > 0) std::printf(", %.2f s", double(frames.size()) / fps);
    if (!frames.empty())
        std::printf(", numbered %llu-%llu%s", (unsigned long long)first_number,
                    (unsigned long long)(uint64_t(first_number) + frames.size() - 1),
                    has_first_frame_number(info) ? " (source frames)" : "");
    std::printf(", %zu key frames\n", keys.size());
    std::printf("sets        %zu:", h.sets.size());
    for (const auto& s : h.sets) std::printf(" %ux%u", s.width, s.height);
    std::printf("\norientations %zu:", h.orientations.size());
    for (const auto& o : h.orientations) std::printf(" %.1f", degrees(o));
    std::printf(" deg\ntemplates   %zu:", info.templates.size());
    for (const auto& t : info.templates) {
        std::printf(" %s", template_kind_name(t.kind));
        if (t.kind == TemplateKind::Bitmap) std::printf(" %ux%u", t.width, t.height);
        if (!t.name.empty()) std::printf(" \"%s\"", printable_text(t.name).c_str());
        std::printf(";");
    }
    std::printf("\nstrokes     %llu added", (unsigned long long)added);
    if (fields && added) {
        const char* sep = " (";
        for (size_t k = 0; k < 4; ++k)
            if (kinds[k]) std::printf("%s%llu %s", sep, (unsigned long long)kinds[k], kKindNames[k]), sep = ", ";
        std::printf(")");
    }
    std::printf(", %llu removed", (unsigned long long)removed);
    if (list) std::printf(", at most %llu live", (unsigned long long)max_live);
    std::printf("\n");
    // Text from the file, never raw to the terminal: an ESC in it would be acted on.
    for (const auto& [k, v] : info.metadata)
        std::printf("meta        %s = %s\n", printable_text(k).c_str(), printable_text(v).c_str());
    for (const auto& q : info.rois)
        std::printf("roi         frames %u-%u: %u,%u %ux%u\n", q.first_frame, q.last_frame, q.x, q.y, q.w, q.h);
    std::printf("key frames ");
    for (size_t i = 0; i < keys.size() && i < 32; ++i) std::printf(" %u", keys[i]);
    if (keys.size() > 32) std::printf(" ... (%zu in all)", keys.size());
    std::printf("\n\nbytes           %12s %8s\n", "bytes", "share");
    auto row = [&](const char* name, double v) {
        std::printf("  %-14s %12.0f %7.2f%%\n", name, v, sec.total ? 100.0 * v / double(sec.total) : 0.0);
    };
    row("header", double(sec.header));
    row("strokes", double(sec.strokes));
    row("motion", double(sec.motion));
    row("framing", double(sec.framing));
    row("tail", double(sec.tail));
    row("total", double(sec.total));
    if (fields) {
        std::printf("\nfields (frame bodies)\n");
        for (size_t i = 0; i < kFieldCount; ++i) row(field_name(Field(i)), fs.bits[i] / 8.0);
    }
    // A still has no meaningful bit rate: give bits per pixel instead.
    if (frames.size() > 1 && fps > 0)
        std::printf("\nbit rate    %.1f kbit/s\n", double(sec.total) * 8.0 / 1000.0 / (double(frames.size()) / fps));
    else if (frames.size() == 1 && h.width && h.height)
        std::printf("\nbits/pixel  %.4f\n", double(sec.total) * 8.0 / (double(h.width) * double(h.height)));
    for (const auto& w : r.warnings()) std::printf("warning: %s\n", io::describe_error(path, w).c_str());
    if (list) {
        std::printf("\n%7s %5s %6s %12s %9s %9s %8s %8s %8s\n", "frame", "type", "coding", "offset", "bytes",
                    "strokesB", "added", "removed", "live");
        for (size_t i = 0; i < frames.size(); ++i) {
            const auto& f = frames[i];
            std::printf("%7u %5s %6s %12llu %9llu %9llu %8u %8u %8llu\n", f.index,
                        f.type == FrameType::Key ? "key" : "inter", coding_name(f.coding),
                        (unsigned long long)f.offset, (unsigned long long)f.chunk_bytes,
                        (unsigned long long)f.stroke_bytes, f.added, f.removed, (unsigned long long)live[i]);
        }
    }
    return 0;
}

}  // namespace spt::cli
