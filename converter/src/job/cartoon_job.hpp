// `--style cartoon` as a job: every search the style makes (the outline, smallest-region and
// palette trials of a still, the PSNR bisection of --target-bytes) for stills, sequences,
// videos and farm shots alike. The command line only reports what these return.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "cartoon/cartoon_paint.hpp"
#include "cartoon/cartoon_sequence.hpp"
#include "io/progress.hpp"
#include "job/paint_job.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"
#include "video/video_paint.hpp"

namespace spt::job {

using Metadata = std::vector<std::pair<std::string, std::string>>;

// With --target-psnr (and no --target-bytes) the cartoon style is never larger than the default
// painter at the same target: the default painter paints the same input too, and when its file
// is the smaller and no worse at the target (no_worse_at_target) it is written instead and
// `used_default` says so. (Region by region inside one file is not done yet.)
bool compares_with_default(const PaintJob& o);

// The video painter's inter frames repaint only where the error grew past a threshold, so its
// mean lands a little under the target (0.1 to 0.4 dB on the synthetic clips); far under it
// (taffy at 36 dB: 27.8) it has not painted the same picture, and its bytes do not compare.
constexpr double kDefaultPsnrSlackDb = 0.5;
// The default painter's PSNR is no worse when within the slack of the target, or of the
// cartoon's own PSNR where that is lower.
bool no_worse_at_target(double default_psnr, double cartoon_psnr, double target_psnr);

struct CartoonStill {
    bool used_default = false;  // the default painter's painting was written (default_*)
    uint64_t default_bytes = 0, cartoon_bytes = 0;
    double default_psnr = 0;
    cartoon::CartoonStats stats;
    Canvas canvas;          // the painting as a decoder shows it
    uint64_t bytes = 0;     // of the file written to o.output
    double target_psnr = 0; // the target painted to (the one --target-bytes chose)
    double seconds = 0;
};

// Paints the still o.input and writes o.output.
Result<CartoonStill> paint_cartoon_still(const PaintJob& o);

struct CartoonSequence {
    bool used_default = false;  // the default painter's painting was written (default_report)
    uint64_t cartoon_bytes = 0;
    video::VideoPaintReport default_report;
    cartoon::SequenceReport report;
    double target_psnr = 0;  // the target painted to (the one --target-bytes chose)
};

// Paints the sequence or video o.input to o.output, with the file's metadata plus `extra`
// (entries of the same key replaced); `progress` (may be null) is told each frame. On failure
// `out` still holds what was done (out.report.interrupted: stopped by a signal after a
// finished frame, the file valid).
Status paint_cartoon_sequence(const PaintJob& o, const Metadata& extra, io::Progress* progress, CartoonSequence& out);

}  // namespace spt::job
