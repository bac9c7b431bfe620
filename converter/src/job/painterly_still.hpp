// The default painter on an 8-bit still, as a job: its set-up, the --target-bytes search over
// lambda, the painting and the file. `spt paint` runs it, and so does the cartoon style when it
// compares its painting with the default painter's (cartoon_job.hpp).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "io/image_io.hpp"
#include "job/paint_job.hpp"
#include "paint/painter.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::job {

struct PainterlyStill {
    Canvas canvas;           // the painting as a decoder shows it
    paint::PaintStats stats;
    uint64_t bytes = 0;      // of the file written
};

struct StillTarget {
    std::string path;                 // where the file goes
    bool atomic_rename = true;        // false: `path` is a trial file (io/trial_output.hpp)
    std::vector<std::pair<std::string, std::string>> metadata;
    // Told each batch of the painting (strokes, set, dB); returning false stops it.
    std::function<bool(uint64_t, int, double)> progress;
};

// The number of stroke sets a still of `o` paints with at width x height.
size_t still_set_count(const PaintJob& o, uint32_t width, uint32_t height);

// Paints `img` for `o` and writes it to `to`. The file is created only after the painting.
Result<PainterlyStill> paint_painterly_still(const PaintJob& o, const io::Image& img, const StillTarget& to);

}  // namespace spt::job
