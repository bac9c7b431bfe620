// spt export: a .spt file as the JSON stroke list, or as SVG (one file per frame).
#include <cstdio>
#include <string>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/export_web.hpp"
#include "io/sequence.hpp"
#include "io/spt_file.hpp"
#include "spt_import/export.hpp"
#include "spt_import/importer.hpp"
#include "spt/utf8.hpp"

namespace spt::cli {

namespace {

bool ends_with(std::string s, const std::string& suffix) {
    for (auto& c : s) c = char(std::tolower((unsigned char)c));
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

int fail(const std::string& msg) { return command_failed("export", msg); }

// The frames at `positions` checked as spt verify checks them, before anything is written: an
// export of a file that verify and render refuse would carry fewer frames, or frames that do
// not import again, with exit 0. Damage that costs nothing asked for is said on stderr.
bool frames_sound(Reader& r, const std::string& in, const std::vector<size_t>& positions, bool lost_matter, int& rc) {
    std::vector<std::string> warnings;
    if (Status s = io::check_frames(r, in, positions, lost_matter, warnings); !s) {
        rc = fail(s.error().message);
        return false;
    }
    for (const auto& w : warnings) std::fprintf(stderr, "spt export: warning: %s\n", w.c_str());
    return true;
}

// Every frame of `r` checked as verify checks them, then read into `doc`: -1, or the exit code.
int read_document(Reader& r, const std::string& in, import::Document& doc) {
    const size_t n = r.frames().size();
    std::vector<size_t> every(n);
    for (size_t i = 0; i < n; ++i) every[i] = i;
    if (int rc = 0; !frames_sound(r, in, every, true, rc)) return rc;
    doc.info = r.info();
    for (size_t i = 0; i < n; ++i) {
        auto f = r.read_frame(i);
        if (!f) return fail(io::frame_place(r, i) + ": " + io::describe_error(in, f.error()));
        doc.frames.push_back(std::move(*f));
    }
    return -1;
}

// spt export IN.spt -o OUT.json --lottie: every frame read, then written as one Lottie file.
int export_lottie_file(const std::string& in, const std::string& out, bool vector_only) {
    auto reader = io::open_spt(in);
    if (!reader) return fail(reader.error().message);
    import::Document doc;
    if (int rc = read_document(**reader, in, doc); rc >= 0) return rc;
    import::LottieExportStats st;
    auto text = import::export_lottie(doc, vector_only, st);
    if (!text) return fail(in + ": " + text.error().message);
    if (Status s = import::write_file_atomic(out, *text); !s) return fail(s.error().message);
    if (st.left_out_vector_only)
        std::fprintf(stderr, "spt export: --vector-only left out %llu stamp and affine strokes\n", (unsigned long long)st.left_out_vector_only);
    if (st.left_out_bitmaps)
        std::fprintf(stderr, "spt export: %llu strokes of bitmap templates have no vector form in Lottie: left out\n",
                     (unsigned long long)st.left_out_bitmaps);
    if (st.approximated)
        std::fprintf(stderr, "spt export: %llu curves of varying width drawn at their mean width (a Lottie stroke has one)\n",
                     (unsigned long long)st.approximated);
    return 0;
}

}  // namespace

int cmd_export(int argc, char** argv) {
    Args args("export", "write a .spt file as SVG (a file a frame), a JSON stroke list or a web page",
              "spt export IN.spt -o OUT.json|OUT.svg|OUT.####.svg [--frames RANGE]|OUT.html | -o DIR/ --web");
    args.positional("IN.spt", "the .spt file to export")
        .option("output", "OUT", "OUT.json: the JSON stroke list (importers/README.md), every frame as stored; "
                                 "OUT.svg: one SVG per frame, with #### (or %04d) in the name for several frames; "
                                 "OUT.html: one self-contained page that plays the clip (web/README.md)", 'o')
        .option("frames", "RANGE", "SVG only: the frames to export (\"0-10,20\"; 0-based)")
        .flag("lottie", "OUT.json as a Lottie animation (bodymovin JSON) that Lottie players play: one shape layer a "
                        "stroke over the frames it lives; polygons filled paths, curves round stroked paths, stamp and "
                        "affine strokes their template's outline (bitmap templates left out, counted)")
        .flag("vector-only", "SVG and --lottie only: leave out stamp and affine strokes, keeping the polygons and curves: a "
                             "--style cartoon painting's fills and lines as plain vector art, without the residual "
                             "stamps that add its last decibels (their count is said on stderr)")
        .flag("web", "write DIR/ for a web server: the player (web/README.md), its WebAssembly module, the clip and "
                     "index.html (OUT.html instead: one self-contained page that plays offline)")
        .epilog("The file is checked first as spt verify checks the frames it exports (each decoded and\n"
                "applied, within the limits); a bad or lost frame fails the export and nothing is written.\n"
                "The JSON output imports back (spt import) into the same .spt file. In the SVG, each stamp or\n"
                "affine stroke is its template (ellipse/rect/polygon, or a bitmap as a PNG mask) placed with\n"
                "transform=\"matrix(...)\"; curves are round-capped outlines; polygon strokes are <polygon>s\n"
                "(nonzero fill); the result renders in a browser\n"
                "close to spt render (browsers anti-alias edges; spt samples pixel centres).\n"
                "Format 1.3 files: an alpha canvas's SVG has no background rectangle (strokes keep their\n"
                "opacity); scene-linear colours are shown through the sRGB curve (above 1 clips). Their JSON\n"
                "is version 3: canvas.color_encoding, canvas.alpha and, when linear, colours as 16-bit half codes.");
    if (int rc = args.parse(argc, argv); rc >= 0) return rc;
    const std::string in = args.pos("IN.spt"), out = args.get("output");
    if (out.empty()) return args.usage_error("missing -o OUT.json or -o OUT.svg");
    if (is_web_export(out, args.has("web"))) {
        if (args.has("frames")) return args.usage_error("--frames applies to SVG output only (the player holds every frame)");
        if (args.has("vector-only")) return args.usage_error("--vector-only applies to SVG output only (the player draws every stroke)");
        return export_web(in, out, args.has("web"));
    }
    const bool json = ends_with(out, ".json"), svg = ends_with(out, ".svg");
    if (args.has("lottie")) {
        if (!json) return args.usage_error("--lottie writes a Lottie JSON file: the output must end in .json: " + out);
        if (args.has("frames")) return args.usage_error("--frames applies to SVG output only (the Lottie file holds every frame)");
        return export_lottie_file(in, out, args.has("vector-only"));
    }
    if (!json && !svg) return args.usage_error("the output must end in .json, .svg or .html (or give --web and a folder): " + out);
    if (json && args.has("frames")) return args.usage_error("--frames applies to SVG output only (JSON holds every frame as stored)");
    if (json && args.has("vector-only"))
        return args.usage_error("--vector-only applies to SVG and Lottie output only (JSON holds every stroke, to import back)");
    const bool vector_only = args.has("vector-only");
    io::FrameRange range;
    if (args.has("frames")) {
        auto r = io::parse_frame_range(args.get("frames"));
        if (!r) return args.usage_error(r.error().message);
        range = *r;
    }

    auto reader = io::open_spt(in);
    if (!reader) return fail(reader.error().message);
    Reader& r = **reader;
    const size_t n = r.frames().size();

    if (json) {
        import::Document doc;
        if (int rc = read_document(r, in, doc); rc >= 0) return rc;
        // JSON carries UTF-8 only (a file from another writer may hold other bytes), and what
        // export writes, import must read back.
        for (const auto& [k, v] : doc.info.metadata)
            if (!is_valid_utf8(k) || !is_valid_utf8(v))
                return fail(in + ": metadata key \"" + printable_text(k) + "\" holds bytes that are not UTF-8 (SPEC.md 3.3); JSON cannot carry them");
        for (size_t t = 0; t < doc.info.templates.size(); ++t)
            if (!is_valid_utf8(doc.info.templates[t].name))
                return fail(in + ": template " + std::to_string(t) + ": the name is not UTF-8 (SPEC.md 3.2); JSON cannot carry it");
        const std::string text = import::export_json(doc);
        const size_t limit = import::ImportOptions{}.max_file_bytes;
        if (text.size() > limit)
            return fail(out + ": the JSON would be " + std::to_string(text.size()) + " bytes, above the " +
                        std::to_string(limit) + " that spt import reads back; nothing written (keep the .spt, or export SVG frames)");
        if (Status s = import::write_file_atomic(out, text); !s) return fail(s.error().message);
        return 0;
    }

    std::vector<size_t> picked;
    for (size_t i = 0; i < n; ++i)
        if (range.empty() || range.contains(long(i))) picked.push_back(i);
    const bool pattern = io::is_sequence_pattern(out);
    if (picked.size() > 1 && !pattern)
        return args.usage_error(std::to_string(picked.size()) + " frames need a frame number placeholder in the output name (OUT.####.svg), or --frames N");
    // Lost frames matter when every frame is asked for, or one past the last found.
    bool past_end = range.empty();
    for (const auto& span : range.spans) past_end = past_end || span.second >= long(n);
    if (int rc = 0; !frames_sound(r, in, picked, past_end, rc)) return rc;
    if (picked.empty()) return fail(in + ": no frame in the requested range (the file has " + std::to_string(n) + ")");
    uint64_t left_out = 0;
    for (size_t i : picked) {
        auto live = r.strokes_at(i);
        if (!live) return fail(io::frame_place(r, i) + ": " + io::describe_error(in, live.error()));
        std::vector<Stroke> vector;
        if (vector_only)
            for (const Stroke& s : **live) {
                if (s.kind == StrokeKind::Polygon || s.kind == StrokeKind::Curve) vector.push_back(s);
                else ++left_out;
            }
        auto text = import::export_svg(r.info(), vector_only ? vector : **live);
        if (!text) return fail(in + ": " + text.error().message);
        const std::string path = pattern ? io::format_frame(out, long(i)) : out;
        if (Status s = import::write_file_atomic(path, *text); !s) return fail(s.error().message);
    }
    if (left_out > 0)
        std::fprintf(stderr, "spt export: --vector-only left out %llu stamp and affine strokes (%zu frame%s)\n",
                     (unsigned long long)left_out, picked.size(), picked.size() == 1 ? "" : "s");
    return 0;
}

}  // namespace spt::cli
