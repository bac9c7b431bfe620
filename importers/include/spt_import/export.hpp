// Exporters: a .spt document as the JSON stroke list (importers/README.md) or as SVG.
#pragma once

#include <string>
#include <vector>

#include "spt/result.hpp"
#include "spt_import/document.hpp"

namespace spt::import {

// The JSON stroke list of a document, frames as stored (key and inter frames), positions in
// pixels written exactly (Q4 values are multiples of 1/16, whose decimals are finite).
std::string export_json(const Document& doc);

// One frame (its live stroke list) as a standalone SVG a browser renders like spt::Renderer:
// stamp and affine strokes are their template (analytic shape, or bitmap as a PNG mask) under
// transform="matrix(...)"; curves are round-capped outlines. Only the bitmap templates some
// stroke draws are written as masks.
Result<std::string> export_svg(const StreamInfo& info, const std::vector<Stroke>& strokes);

// What a Lottie export left out or approximated.
struct LottieExportStats {
    uint64_t layers = 0;                // shape layers written (one a stroke, over its frames)
    uint64_t left_out_vector_only = 0;  // stamp and affine strokes left out by --vector-only
    uint64_t left_out_bitmaps = 0;      // strokes of bitmap templates (no vector form)
    uint64_t approximated = 0;          // curves of varying width drawn at their mean width
};

// The document as a Lottie animation (bodymovin JSON): one shape layer a stroke, shown over the
// frames it is alive; polygons as filled paths, curves as round stroked paths, stamp and affine
// strokes of analytic templates as their mapped outline. Refuses scene-linear colours.
Result<std::string> export_lottie(const Document& doc, bool vector_only, LottieExportStats& stats);

// Writes `data` to `path` through spt::AtomicFile (no half-written output, no symlink followed).
Status write_file_atomic(const std::string& path, const std::string& data);

}  // namespace spt::import
