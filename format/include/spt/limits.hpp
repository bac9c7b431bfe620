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
    // The same summed over the frames Reader::render_frame draws from one file (each distinct
    // live list once; a frame that leaves the list as it was is not drawn again): at most
    // max_file_fill_work + max_fill_work_per_byte x the file's size in bytes (SPEC.md B.7).
    // A per-frame bound alone lets 15 KB hold a frame of 20 s and every frame of a file cost
    // that; bounding work by the bytes that ask for it keeps it proportional to the file.
    // 2^30 is about 3 s of one core; 2^18 per byte is 6x the densest painting measured (a
    // 12-frame 480x270 video: 2^27 in 3.6 KB, 2^15.4 a byte; stills need at most 2^12.5).
    uint64_t max_file_fill_work = 1ull << 30;
    uint64_t max_fill_work_per_byte = 1ull << 18;
    // The same for polygons and curves (their units as max_polygon_work's and max_curve_work's):
    // 2^26 of polygon work and 2^31 of curve work are a few seconds of one core. The densest
    // cartoon paintings measured (the shared stills and the star's 12 frames, every frame's live
    // list counted) need at most 2^10.5 polygon units and 2^8.6 curve units a byte of their
    // file: 2^12 a byte is 3x and 10x above them.
    uint64_t max_file_polygon_work = 1ull << 26;
    uint64_t max_polygon_work_per_byte = 1ull << 12;
    uint64_t max_file_curve_work = 1ull << 31;
    uint64_t max_curve_work_per_byte = 1ull << 12;
    uint32_t max_metadata_bytes = 1u << 24;
    uint32_t max_frames = 0xFFFFFFFEu;
};

}  // namespace spt
