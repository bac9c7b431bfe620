// The default painter on a sequence or video, as a job: the video encoder's options from the
// paint job. `spt paint` and farm shots run it, and so does the cartoon style when it compares
// its painting with the default painter's (cartoon_job.hpp).
#pragma once

#include "job/paint_job.hpp"
#include "spt/result.hpp"
#include "video/video_paint.hpp"

namespace spt::job {

// Fails (naming the option) for what sequences do not take: --preview, --side-by-side,
// --set-sizes, an unknown --flow, templates that do not load.
Status painterly_video_options(const PaintJob& o, video::VideoPaintOptions& v);

}  // namespace spt::job
