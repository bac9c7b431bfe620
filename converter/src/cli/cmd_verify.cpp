// spt verify: every checksum, every frame decoded, applied and rendered; exit 0 only when the
// whole file is sound.
#include <cstdio>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "io/progress.hpp"
#include "io/spt_file.hpp"
#include "spt/spt.hpp"

namespace spt::cli {

namespace {

int bad(const std::string& path, const std::string& what) {
    // `what` names the file when it comes from an error description.
    if (what.rfind(path, 0) == 0)
        std::fprintf(stderr, "spt verify: FAILED: %s\n", what.c_str());
    else
        std::fprintf(stderr, "spt verify: FAILED: %s: %s\n", path.c_str(), what.c_str());
    return 1;
}

}  // namespace

int cmd_verify(int argc, char** argv) {
    Args args("verify", "check every checksum and decode every frame",
              "spt verify FILE.spt [--no-render] [--progress MODE]");
    args.positional("FILE.spt", "the file to check")
        .flag("no-render", "decode and apply every frame but do not render it")
        .option("progress", "MODE", io::kProgressHelp, 0, "auto")
        .flag("quiet", "print nothing on success", 'q')
        .epilog("Checks: the container (signature, chunk framing, every CRC), the index against "
                "the frames, the end chunk, the header's frame count, every frame's payload "
                "decoded, its edits applied to the live stroke list (removals in range, limits) "
                "and the list rendered. A failure names the frame and its byte offset.\n"
                "Exit 0 when the file is entirely sound, 1 otherwise.");
    if (int rc = args.parse(argc, argv); rc >= 0) return rc;
    io::ProgressMode mode;
    if (!args.get_progress(mode)) return 2;
    const std::string path = args.pos("FILE.spt");

    ReaderOptions ro;
    ro.verify_checksums = true;
    auto opened = io::open_spt(path, ro);
    if (!opened) return bad(path, opened.error().message);
    Reader& r = **opened;
    // Anything the reader had to work around is a defect of the file.
    if (!r.warnings().empty()) return bad(path, io::describe_error(path, r.warnings().front()));
    if (!r.complete()) return bad(path, "the file ends early (no end chunk)");
    if (!r.has_index()) return bad(path, "the frame index is missing");
    const auto& frames = r.frames();
    const Header& h = r.info().header;
    if (h.frame_count != kUnknownFrameCount && h.frame_count != frames.size())
        return bad(path, "the header says " + std::to_string(h.frame_count) + " frames, the file holds " +
                             std::to_string(frames.size()));

    const bool render = !args.has("no-render");
    Canvas canvas;
    if (render) {
        if (auto rc = Renderer::create(h, r.info().templates); !rc)
            return bad(path, "header/templates cannot be rendered: " + rc.error().message);
        canvas = Canvas(h);
    }

    io::Progress progress(mode, "verify", double(frames.size()));
    uint64_t strokes = 0;
    for (size_t i = 0; i < frames.size(); ++i) {
        const std::string where = io::frame_place(r, i);
        if (frames[i].index != i) return bad(path, path + ": " + where + ": frame number out of sequence (expected " + std::to_string(i) + ")");
        auto rec = r.read_frame(i);
        if (!rec) return bad(path, io::frame_error(r, i, path, rec.error()));
        auto live = r.strokes_at(i);
        if (!live) return bad(path, io::frame_error(r, i, path, live.error()));
        strokes += rec->added.size();
        // The reader's player path: a frame that leaves the live list as it was keeps the
        // picture drawn before it instead of rendering it again, and the reader bounds the
        // rendering work of the whole file.
        if (render) {
            Status s = r.render_frame(i, canvas);
            if (!s) return bad(path, io::frame_error(r, i, path, s.error()));
        }
        progress.update(double(i + 1));
    }
    progress.finish(true);
    if (!args.has("quiet"))
        std::printf("%s: OK, %zu frames, %llu strokes added, every checksum%s\n", path.c_str(), frames.size(),
                    (unsigned long long)strokes, render ? ", decode and render sound" : " and decode sound");
    return 0;
}

}  // namespace spt::cli
