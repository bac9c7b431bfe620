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
    // Rendering work of the polygons of one frame's live list (and of each one decoded):
    // non-horizontal edges x canvas rows of the box x samples per pixel, summed (SPEC.md 10,
    // polygon_render_work in render.hpp). Bounds what a small hostile file can make a renderer
    // do (every edge of a star polygon crosses every sample row): 2^28 is about ten seconds of
    // one core for the reference renderer at worst, and far above paintings (a geometrize
    // 20-gon needs a few thousand units; 30,000 of them a few 10^7).
    uint64_t max_polygon_work = 1ull << 28;
    // The same for curves: the canvas pixels of each segment's box, summed over the segments of
    // the curves of one frame's live list (SPEC.md 10, curve_render_work in render.hpp). 2^33
    // is about ten seconds of one core at worst; a hand-drawn stroke needs thousands.
    uint64_t max_curve_work = 1ull << 33;
    // The same for stamps and affine strokes: canvas pixels of each one's evaluation box times
    // its template's samples per pixel, summed over one frame's live list (SPEC.md 10,
    // fill_render_work in render.hpp): millions of canvas-sized strokes cost a few bytes each.
    // 2^36 is a few minutes of one core at worst; a 30,000-stroke 1280x720 painting needs ~2^28.
    uint64_t max_fill_work = 1ull << 36;
    uint32_t max_metadata_bytes = 1u << 24;
    uint32_t max_frames = 0xFFFFFFFEu;
};

}  // namespace spt
