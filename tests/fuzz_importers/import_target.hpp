// The shared body of the importer fuzz targets (fuzz_<importer>.cpp): one import of arbitrary
// bytes under small limits. It must return a value or an error, never crash, hang or allocate hugely.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>

#include "spt_import/importer.hpp"

namespace spt_fuzz {

inline int import_bytes(const spt::import::Importer& imp, const uint8_t* data, size_t size) {
    spt::import::ImportOptions opts;
    // Small limits keep each run fast; the importer checks them before allocating.
    opts.limits.max_width = opts.limits.max_height = 4096;
    opts.limits.max_pixels = 1u << 20;
    opts.limits.max_strokes_per_frame = 1u << 16;
    opts.canvas_size = std::make_pair(64u, 48u);
    auto r = imp.load("fuzz-input", std::string(reinterpret_cast<const char*>(data), size), opts);
    (void)r;
    return 0;
}

}  // namespace spt_fuzz
