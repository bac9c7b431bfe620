// spt pack: re-code every frame (range coding, or stored with --stored) and prove the output
// holds exactly the same frames.
#include <cstdio>
#include <filesystem>
#include <system_error>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "io/progress.hpp"
#include "io/spt_file.hpp"
#include "spt/spt.hpp"

namespace spt::cli {

namespace fs = std::filesystem;

namespace {

int fail(const std::string& msg) { return command_failed("pack", msg); }

// Frame records equal field by field (Frame has no operator==: motion fields are compared
// by value, the frame index by position).
bool same_frame(const Frame& a, const Frame& b) {
    return a.index == b.index && a.type == b.type && a.removed == b.removed && a.added == b.added &&
           a.motion.vectors == b.motion.vectors &&
           (a.motion.empty() || (a.motion.block_size == b.motion.block_size &&
                                 a.motion.cols == b.motion.cols && a.motion.rows == b.motion.rows));
}

}  // namespace

int cmd_pack(int argc, char** argv) {
    Args args("pack", "re-code a .spt file: stored to range-coded, or back with --stored",
              "spt pack IN.spt -o OUT.spt [--stored] [--progress MODE]");
    args.positional("IN.spt", "the file to re-code")
        .option("output", "OUT.spt", "the re-coded file (must differ from IN)", 'o')
        .flag("stored", "write stored frames (fixed-size fields, no entropy coding) instead of range coding")
        .option("progress", "MODE", io::kProgressHelp, 0, "auto")
        .epilog("Header, templates, metadata and ROIs are kept; every frame keeps its type, "
                "removals, motion and strokes. The output is then decoded and compared with the "
                "input frame by frame; on any difference it is deleted and the exit code is 1.");
    if (int rc = args.parse(argc, argv); rc >= 0) return rc;
    io::ProgressMode mode;
    if (!args.get_progress(mode)) return 2;
    const std::string in = args.pos("IN.spt"), out = args.get("output");
    if (out.empty()) return args.usage_error("missing -o OUT.spt");
    std::error_code ec;
    if (out == in || (fs::exists(out, ec) && fs::equivalent(in, out, ec)))
        return args.usage_error("-o must name another file than the input");

    auto opened = io::open_spt(in);
    if (!opened) return fail(opened.error().message);
    Reader& r = **opened;
    const size_t n = r.frames().size();

    WriterOptions wo;
    wo.coding = args.has("stored") ? Coding::Stored : Coding::Range;
    wo.template_coding = wo.coding;
    auto created = Writer::create(out, r.info(), wo);
    if (!created) return fail(io::describe_error(out, created.error()));
    Writer& w = **created;

    io::Progress progress(mode, "pack", double(2 * n));
    for (size_t i = 0; i < n; ++i) {
        auto f = r.read_frame(i);
        if (!f) {
            w.abort();
            return fail(io::frame_error(r, i, in, f.error()));
        }
        Status s = w.append(*f);
        if (!s) {
            w.abort();
            return fail(out + ": frame " + std::to_string(i) + ": " + s.error().message);
        }
        progress.update(double(i + 1), "writing");
    }
    // ROIs travel in r.info(): Writer::create already took them.
    if (Status s = w.finish(); !s) {
        w.abort();
        return fail(io::describe_error(out, s.error()));
    }
    const WriteStats stats = w.stats();

    // Verify: decode the output and compare every frame record with the input's.
    auto removed_out = [&](const std::string& why) {
        fs::remove(out, ec);
        return fail(out + ": verification failed, output deleted: " + why);
    };
    auto check = io::open_spt(out);
    if (!check) return removed_out(check.error().message);
    Reader& c = **check;
    if (c.frames().size() != n) return removed_out("frame count " + std::to_string(c.frames().size()) + " != " + std::to_string(n));
    if (!(c.info().header.sets == r.info().header.sets) || !(c.info().templates == r.info().templates) ||
        c.info().metadata != r.info().metadata || c.info().rois.size() != r.info().rois.size())
        return removed_out("header, templates, metadata or ROIs differ");
    for (size_t i = 0; i < n; ++i) {
        auto a = r.read_frame(i);
        auto b = c.read_frame(i);
        if (!a || !b) return removed_out("frame " + std::to_string(i) + " cannot be decoded again");
        if (!same_frame(*a, *b)) return removed_out("frame " + std::to_string(i) + " differs");
        progress.update(double(n + i + 1), "verifying");
    }
    progress.finish(true);
    const uint64_t in_bytes = r.file_size();
    std::printf("%s: %zu frames, %llu -> %llu bytes (%.1f%%), %s coding, verified\n", out.c_str(), n,
                (unsigned long long)in_bytes, (unsigned long long)stats.total_bytes,
                in_bytes ? 100.0 * double(stats.total_bytes) / double(in_bytes) : 0.0,
                wo.coding == Coding::Range ? "range" : "stored");
    return 0;
}

}  // namespace spt::cli
