// spt import: strokes of other painters (spt JSON stroke list, primitive/geometrize SVG,
// geometrize JSON; single files or numbered sequences) into a .spt file.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "io/image_io.hpp"
#include "spt_import/evaluate.hpp"
#include "spt_import/importer.hpp"
#include "spt/utf8.hpp"

namespace spt::cli {

namespace {

bool parse_size(const std::string& s, uint32_t& w, uint32_t& h) {
    unsigned long a = 0, b = 0;
    char x = 0, extra = 0;
    if (std::sscanf(s.c_str(), "%lu%c%lu%c", &a, &x, &b, &extra) != 3 || (x != 'x' && x != 'X') || a < 1 || b < 1 || a > 65535 || b > 65535)
        return false;
    w = uint32_t(a);
    h = uint32_t(b);
    return true;
}

bool parse_rgb(std::string s, Rgb8& c) {
    if (!s.empty() && s[0] == '#') s.erase(0, 1);
    if (s.size() != 6) return false;
    unsigned v = 0;
    for (char ch : s) {
        int d = ch >= '0' && ch <= '9' ? ch - '0' : ch >= 'a' && ch <= 'f' ? ch - 'a' + 10 : ch >= 'A' && ch <= 'F' ? ch - 'A' + 10 : -1;
        if (d < 0) return false;
        v = v * 16 + unsigned(d);
    }
    c = {uint8_t(v >> 16), uint8_t(v >> 8), uint8_t(v)};
    return true;
}

}  // namespace

int cmd_import(int argc, char** argv) {
    std::string importers_help = "Importers (--from):\n";
    for (const auto* i : import::importers()) importers_help += std::string("  ") + i->name + ": " + i->description + "\n";
    Args args("import", "bring strokes from other painters (JSON, SVG, geometrize, Lottie) into .spt",
              "spt import IN -o OUT.spt [--from NAME] [--reference PNG] [options]");
    args.positional("IN", "a file, a numbered sequence (shapes.####.svg, frame_%04d.json) or a folder of .svg/.json files")
        .option("output", "OUT.spt", "the .spt file to write", 'o')
        .option("from", "NAME", "force an importer instead of detecting it from the extension and content")
        .option("reference", "IMAGE", "the painting tool's own rendering: print the PSNR of the imported rendering against it")
        .option("size", "WxH", "canvas size, for sources that do not state it (geometrize JSON); default: the reference's size")
        .option("background", "RRGGBB", "canvas colour (overrides the source)")
        .option("fps", "N", "frame rate of a sequence (default 24)")
        .flag("stored", "write stored frames (coding 0) instead of range-coded")
        .flag("quiet", "print nothing but errors", 'q')
        .epilog(importers_help +
                "\nA sequence becomes one frame per file; a file that repeats the previous file's first shapes\n"
                "becomes an inter frame that keeps them. With --reference and a source that does not state its\n"
                "background colour, the colour is fitted to the reference (least squares) and printed.\n"
                "Shapes the stroke model holds only approximately are counted and described.");
    if (int rc = args.parse(argc, argv); rc >= 0) return rc;
    const std::string in = args.pos("IN"), out = args.get("output");
    if (out.empty()) return args.usage_error("missing -o OUT.spt");
    const bool quiet = args.has("quiet");

    import::ImportOptions opts;
    if (args.has("background")) {
        Rgb8 c;
        if (!parse_rgb(args.get("background"), c)) return args.usage_error("--background wants RRGGBB, got '" + args.get("background") + "'");
        opts.background = c;
    }
    if (args.has("fps")) {
        long f = 24;
        if (!args.get_long("fps", f, 1, 100000)) return 2;
        opts.fps = Rational{uint32_t(f), 1};
    }
    if (args.has("size")) {
        uint32_t w, h;
        if (!parse_size(args.get("size"), w, h)) return args.usage_error("--size wants WxH, got '" + args.get("size") + "'");
        opts.canvas_size = std::make_pair(w, h);
    }
    std::optional<io::Image> ref;
    if (args.has("reference")) {
        auto r = io::read_image(args.get("reference"));
        if (!r) { std::fprintf(stderr, "spt import: %s\n", r.error().message.c_str()); return 1; }
        ref = std::move(*r);
        if (!opts.canvas_size) opts.canvas_size = std::make_pair(ref->width, ref->height);
    }
    auto doc = import::import_path(in, args.get("from"), opts);
    if (!doc) { std::fprintf(stderr, "spt import: %s\n", doc.error().message.c_str()); return 1; }
    const Header& h = doc->info.header;
    if (ref && (ref->width != h.width || ref->height != h.height)) {
        std::fprintf(stderr, "spt import: the reference is %ux%u but the canvas is %ux%u\n", ref->width, ref->height, h.width, h.height);
        return 1;
    }
    bool fitted = false;
    // The fit is of 8-bit sRGB backgrounds on opaque canvases.
    if (ref && !doc->report.background_stated && !opts.background && doc->info.header.plain_color()) {
        auto bg = import::fit_background(*doc, ref->rgb.data());
        if (!bg) { std::fprintf(stderr, "spt import: %s\n", bg.error().message.c_str()); return 1; }
        import::set_background(*doc, *bg);
        fitted = true;
    }
    // Provenance for foreign sources (the file name, not the path: the path says where the file
    // was on one machine); a JSON stroke list keeps its own metadata and tables, so that
    // export -> import reproduces the .spt byte for byte.
    if (doc->info.metadata.empty()) {
        doc->info.metadata.emplace_back("software", "spt import");
        doc->info.metadata.emplace_back("source", printable_text(std::filesystem::path(in).filename().string()));
        import::drop_unused_tables(*doc);
    }

    WriterOptions wo;
    wo.coding = args.has("stored") ? Coding::Stored : Coding::Range;
    auto stats = import::write_document(*doc, out, wo);
    if (!stats) { std::fprintf(stderr, "spt import: %s\n", stats.error().message.c_str()); return 1; }

    const auto& rep = doc->report;
    if (!quiet) {
        std::printf("%s: %zu frame(s), %llu shapes -> %llu strokes, %llu bytes\n", out.c_str(), doc->frames.size(),
                    (unsigned long long)rep.shapes, (unsigned long long)rep.strokes, (unsigned long long)stats->total_bytes);
        std::printf("  rounding to the 1/16 px grid: at most %.4f px per vertex\n", rep.max_q4_error_px);
        if (rep.approximated) std::printf("  approximated shapes: %llu\n", (unsigned long long)rep.approximated);
        if (rep.dropped) std::printf("  dropped shapes (cover nothing or out of range): %llu\n", (unsigned long long)rep.dropped);
        for (const auto& n : rep.notes) std::printf("  note: %s\n", n.c_str());
        if (fitted)
            std::printf("  background fitted to the reference: %02x%02x%02x\n", doc->info.header.background.r,
                        doc->info.header.background.g, doc->info.header.background.b);
    }
    if (ref) {
        auto canvas = import::render_frame(*doc, doc->frames.size() - 1);
        if (!canvas) { std::fprintf(stderr, "spt import: rendering failed: %s\n", canvas.error().message.c_str()); return 1; }
        const double p = import::psnr_rgb8(canvas->rgb.data(), ref->rgb.data(), size_t(h.width) * h.height);
        if (!quiet) {
            if (std::isinf(p)) std::printf("  PSNR against %s: inf (identical)\n", args.get("reference").c_str());
            else std::printf("  PSNR against %s: %.2f dB\n", args.get("reference").c_str(), p);
        }
    }
    return 0;
}

}  // namespace spt::cli
