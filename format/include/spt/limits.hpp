// Limits a reader checks before it allocates anything. Callers may tighten or loosen them.
#pragma once

#include <cstdint>

namespace spt {

struct Limits {
    uint32_t max_width = 16384;
    uint32_t max_height = 16384;
    uint64_t max_pixels = 1ull << 28;          // width * height
    uint32_t max_chunk_bytes = 1u << 30;       // one chunk's payload
    uint32_t max_templates = 255;
    uint32_t max_template_side = 1024;
    uint32_t max_strokes_per_frame = 1u << 24;
    uint32_t max_live_strokes = 1u << 24;      // strokes alive after applying a frame
    uint32_t max_curve_points = 1u << 16;      // points in one curve stroke
    uint32_t max_polygon_vertices = 1u << 16;  // vertices of one polygon stroke (format 1.2)
    uint32_t max_metadata_bytes = 1u << 24;
    uint32_t max_frames = 0xFFFFFFFEu;
};

}  // namespace spt
