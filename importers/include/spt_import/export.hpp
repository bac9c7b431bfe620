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

// Writes `data` to `path` through spt::AtomicFile (no half-written output, no symlink followed).
Status write_file_atomic(const std::string& path, const std::string& data);

}  // namespace spt::import
