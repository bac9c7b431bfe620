// A paint job: everything `spt paint` and `spt plan` were asked to do, as one value the
// painters' drivers (job/*.cpp) take. The command line fills it (cli/paint_options.cpp); the
// drivers own every search a style makes (target PSNR and bytes, the cartoon trials), so that
// the command line only parses, reports and maps errors to exit codes.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "io/progress.hpp"
#include "paint/painter.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::job {

// The painters a job can use (--style).
enum class Style : uint8_t { Painterly, Cartoon };
const char* style_name(Style s);  // "painterly", "cartoon"
inline constexpr unsigned style_bit(Style s) { return 1u << unsigned(s); }
inline constexpr unsigned kAllStyles = 3;

// A region of interest as given on the command line or in a --roi-file (frames inclusive;
// a still uses frame 0).
struct RoiSpec {
    uint32_t first_frame = 0, last_frame = 0xFFFFFFFFu;
    paint::Rect rect;
};

struct PaintJob {
    std::string input;
    std::string output;
    Style style = Style::Painterly;       // --style painterly|cartoon
    double outline_tolerance = 0;         // --outline-tolerance PX (cartoon): 0 = the default
    double outline_smooth = -1;           // --outline-smooth PX (cartoon): -1 = the default
    int min_region = 0;                   // --min-region PX (cartoon): 0 = the default
    double min_color_share = 0;           // --min-color-share F (cartoon): 0 = the default
    bool lines = true;                    // cartoon: thin regions may be curves (--no-lines: not)
    paint::PaintOptions paint;            // seed, threads, limits, threshold, orient, lambda, ...
    int sets = 6;                         // --sets, when --set-sizes is not given
    std::vector<StrokeSet> set_sizes;     // --set-sizes WxH,WxH,... (coarse to fine)
    std::string templates_dir;            // --templates: empty = the built-in set
    std::vector<RoiSpec> rois;            // --roi and --roi-file together
    std::string roi_file;
    io::ProgressMode progress = io::ProgressMode::Auto;
    std::string preview;                  // --preview OUT.png
    std::string side_by_side;             // --side-by-side OUT.png
    Rgb8 background{255, 255, 255};
    bool stored = false;                  // --stored: coding 0 frames
    int coding = 2;                       // --coding 1|2: range coding, or replayed candidates
    uint64_t target_bytes = 0;            // --target-bytes N[/s]: 0 = none
    bool target_bytes_per_second = false; // N/s: per second of a clip
    size_t cli_roi_count = 0;             // rois[0..cli_roi_count) came from --roi (all frames)

    // Compositing-grade output (format 1.3, issue 17).
    std::string color_encoding = "auto";  // --color-encoding auto|srgb8|linear (auto: linear for float input)
    std::string alpha = "auto";           // --alpha auto|on|off (auto: on when the input's alpha is not all opaque)
    std::string colorspace;               // --colorspace NAME: the input's colour space (io::SceneReadOptions)
    std::string ocio_config;              // --ocio FILE: an OCIO config (default $OCIO)
    std::string layer;                    // --layer NAME: the EXR layer to paint

    // Sequences and video (ignored for a still image).
    std::string frames;                   // --frames A-B
    std::string fps;                      // --fps 24 | 30000/1001
    bool skip_bad_frames = false;         // --skip-bad-frames
    int keyframe_interval = 100;          // --keyframe-interval N
    double cut_threshold = 6.0;           // --cut-threshold X
    std::string flow = "dis-ultrafast";   // --flow
    uint64_t max_inter_strokes = 4000;    // --max-inter-strokes N
    int block_size = 16;                  // --motion-block N
    bool flow_orientation = false;        // --flow-orientation: new strokes along the motion
    long max_task_frames = 240;           // spt plan --max-task-frames N (0: split at cuts only)
    std::string cut_scan = "auto";        // spt plan --cut-scan auto|sampled|full|tasks
    int cut_step = 16;                    // spt plan --cut-step K
    int cut_history = 4;                  // spt plan --cut-history N

    // The options that shape the painting, canonically spelt (for the painter.options metadata):
    // no paths and no thread count, so that the file bytes do not depend on them. Written by
    // the option table's rows (option_table.hpp).
    std::string canonical() const;
};

// The --orient value's name ("edges", "gradient", "random").
const char* orient_name(paint::OrientMode m);

// A still painting's metadata: software, source (the input's file name), painter.seed and
// painter.options (PaintJob::canonical), printable.
std::vector<std::pair<std::string, std::string>> painting_metadata(const PaintJob& o);

// The templates a job paints with: those of --templates DIR, else the painter's defaults.
Result<std::vector<Template>> paint_templates(const std::string& templates_dir);

}  // namespace spt::job
