// What every still paint sets up before painting, whatever its canvas: the stroke sets and
// templates (the header they give), and the regions of interest as the painter and the file see
// them. Shared by the 8-bit painting (cmd_paint.cpp) and the alpha / scene-linear one
// (paint_scene_still.cpp).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "job/paint_job.hpp"
#include "paint/painter.hpp"
#include "paint/rate_control.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::job {

struct StillSetup {
    paint::PaintSetup setup;    // header (sizes, background, sets, orientations) and templates
    paint::PaintOptions paint;  // o.paint with the still's ROIs (frame 0 only)
    std::vector<Roi> rois;      // the same ROIs clipped to the image, for the file
};

// Fails, with a message, when the templates cannot be loaded or a ROI lies outside the image.
Result<StillSetup> still_setup(const PaintJob& o, uint32_t width, uint32_t height);

// --target-bytes: the lambda whose painting (`trial`, one paint and code per call) comes
// closest to o.target_bytes, searched from `lambda` and reported on stderr.
double search_target_bytes(const PaintJob& o, const std::function<paint::RatePoint(double)>& trial,
                           double lambda);

}  // namespace spt::job
