#include "cli/paint_cartoon.hpp"

#include <cstdio>
#include <filesystem>
#include <string>

#include "cli/commands.hpp"
#include "io/image_io.hpp"
#include "io/progress.hpp"
#include "io/sequence.hpp"
#include "job/cartoon_job.hpp"
#include "paint/rate_control.hpp"
#include "video/video_paint.hpp"

namespace spt::cli {

namespace {

int fail(const std::string& msg) { return command_failed("paint", msg); }

void warn_frames_short(uint64_t frames_short, uint64_t frames, double target, double lowest, uint32_t at, const char* why) {
    if (frames_short == 0) return;
    std::fprintf(stderr, "spt paint: warning: %llu of %llu frames short of --target-psnr %.2f (lowest %.2f dB, frame %u "
                         "of the file)%s\n",
                 (unsigned long long)frames_short, (unsigned long long)frames, target, lowest, at, why);
}

int report_cartoon_still(const PaintCommandOptions& o) {
    auto r = job::paint_cartoon_still(o);
    if (!r) return fail(r.error().message);
    if (!o.preview.empty())
        if (Status p = io::write_image(o.preview, r->canvas); !p) return extra_output_failed("--preview", o.output, p.error().message);
    if (r->used_default) {
        // Said whatever the progress mode: the file is not what the user asked for.
        std::fprintf(stderr, "spt paint: --style cartoon: the default painter paints %s in fewer bytes at --target-psnr %.2f "
                             "(%llu against the cartoon's %llu): %s holds its painting, %.2f dB\n",
                     o.input.c_str(), r->target_psnr, (unsigned long long)r->default_bytes,
                     (unsigned long long)r->cartoon_bytes, o.output.c_str(), r->default_psnr);
        if (!paint::reaches_target(r->default_psnr, r->target_psnr))
            std::fprintf(stderr, "spt paint: warning: %s is %.2f dB, short of --target-psnr %.2f\n", o.output.c_str(),
                         r->default_psnr, r->target_psnr);
        return 0;
    }
    const cartoon::CartoonStats& st = r->stats;
    if (o.progress != io::ProgressMode::None)
        std::fprintf(stderr,
                     "spt paint: %s: %zu colours, %zu regions, %zu polygons (%zu vertices), %zu lines (%zu points), "
                     "grid %d, %.2f dB; %llu stamps; %.2f dB PSNR, %llu bytes, %.2f s\n",
                     o.output.c_str(), st.colors, st.regions, st.polygons, st.vertices, st.lines, st.line_points,
                     int(st.grid), st.fill_psnr, (unsigned long long)st.stamps.strokes, st.stamps.psnr,
                     (unsigned long long)r->bytes, r->seconds);
    if (!paint::reaches_target(st.stamps.psnr, r->target_psnr))
        std::fprintf(stderr, "spt paint: warning: %s is %.2f dB, short of --target-psnr %.2f: the residual stamps stopped "
                             "improving it\n", o.output.c_str(), st.stamps.psnr, r->target_psnr);
    return 0;
}

// Paints the sequence of `o` with the file's metadata plus `extra`; returns the exit code.
int report_cartoon_sequence(const PaintCommandOptions& o, const Metadata& extra, uint64_t* frames) {
    if (!o.preview.empty()) return fail("--preview is for still images; render a sequence with 'spt render'");
    io::Progress progress(o.progress, "paint", 0);
    job::CartoonSequence out;
    const Status st = job::paint_cartoon_sequence(o, extra, &progress, out);
    const cartoon::SequenceReport& r = out.report;
    if (frames) *frames = r.frames;
    progress.finish(bool(st), st ? o.output : st.error().message);
    if (!st && r.interrupted) {  // stopped by a signal after a finished frame: the output is valid
        std::fprintf(stderr, "spt paint: %s\n", st.error().message.c_str());
        return video::kExitInterrupted;
    }
    if (!st) return fail(st.error().message);
    if (out.used_default) {
        const video::VideoPaintReport& d = out.default_report;
        std::fprintf(stderr, "spt paint: --style cartoon: the default painter paints %s in fewer bytes at --target-psnr %.2f "
                             "(%llu against the cartoon's %llu): %s holds its painting, %llu frames, PSNR mean %.2f dB\n",
                     o.input.c_str(), out.target_psnr, (unsigned long long)d.bytes, (unsigned long long)out.cartoon_bytes,
                     o.output.c_str(), (unsigned long long)d.frames, d.mean_psnr);
        warn_frames_short(d.frames_short, d.frames, out.target_psnr, d.min_psnr, d.min_psnr_frame, "");
        return 0;
    }
    if (o.progress != io::ProgressMode::None)
        std::fprintf(stderr,
                     "spt paint: %s: %llu frames (%llu key, %llu with motion), polygons %llu added %llu kept, %llu stamps, %llu removed; "
                     "PSNR mean %.2f dB min %.2f; %llu bytes, %.2f s (%.3f s a frame)\n",
                     o.output.c_str(), (unsigned long long)r.frames, (unsigned long long)r.key_frames,
                     (unsigned long long)r.motion_frames,
                     (unsigned long long)r.polygons_added, (unsigned long long)r.polygons_kept,
                     (unsigned long long)r.stamps_added, (unsigned long long)r.removed, r.mean_psnr, r.min_psnr,
                     (unsigned long long)r.bytes, r.seconds, r.frames ? r.seconds / double(r.frames) : 0.0);
    warn_frames_short(r.frames_short, r.frames, out.target_psnr, r.min_psnr, r.min_psnr_frame,
                      ": the residual stamps stopped improving them");
    return 0;
}

}  // namespace

int paint_cartoon(const PaintCommandOptions& o) {
    std::error_code ec;
    if (io::is_sequence_pattern(o.input) || io::is_video_file(o.input) || std::filesystem::is_directory(o.input, ec))
        return report_cartoon_sequence(o, {}, nullptr);
    if (!o.side_by_side.empty()) return fail("--style cartoon: --side-by-side is not supported; use --preview");
    return report_cartoon_still(o);
}

int paint_cartoon_shot(const PaintCommandOptions& o, const Metadata& metadata, uint64_t& frames) {
    frames = 0;
    return report_cartoon_sequence(o, metadata, &frames);
}

}  // namespace spt::cli
