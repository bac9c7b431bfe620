// Internal: the player's path for key frames of stamps (Reader::render_frame). The frame's
// decoder hands the renderer its stamps a batch at a time and the renderer bins them straight
// into its tiles: no Stroke list is built, the renderer reads no file bytes, and the reader
// knows nothing of the renderer's insides.
#pragma once

#include <cstddef>
#include <cstdint>

#include "spt/limits.hpp"
#include "spt/render.hpp"
#include "spt/types.hpp"

namespace spt::detail {

// The stamps of one frame, in drawing order: fill(ctx, first, n, out) writes stamps first ..
// first + n - 1 to out[0 .. n), or returns false when one of them is not a stamp.
struct StampSource {
    size_t count = 0;
    const void* ctx = nullptr;
    bool (*fill)(const void* ctx, size_t first, size_t n, StampStroke* out) = nullptr;
    // When not null: the same stamps as `count` records of kPackedStampBytes in the layout
    // below, which the renderer reads in place instead of through fill() (a copy of every
    // stamp costs the player's path about 5%).
    const uint8_t* packed = nullptr;
};

// A packed stamp record (SPEC 6's stored stamp record): kind (0), set, template, orientation,
// x, y (i32, little-endian), R, G, B, A.
constexpr size_t kPackedStampBytes = 16;
inline uint32_t packed_u32(const uint8_t* q) {
    return uint32_t(q[0]) | uint32_t(q[1]) << 8 | uint32_t(q[2]) << 16 | uint32_t(q[3]) << 24;
}

// Renders a key frame of src.count stamps onto `canvas`: the same bytes as Renderer::render of
// those stamps as Strokes (render_tiles.cpp). Returns false, having drawn nothing, when a stamp
// is not valid (SPEC 8.7), has no cached footprint, or the frame's fill work may exceed
// `work_limit` (SPEC 10); the caller then takes the general path, which reports what is wrong.
// With `work`, a rendered frame's fill work is stored there (the reader's per-file budget).
bool render_stamp_frame(const Renderer& renderer, Canvas& canvas, const StampSource& src, unsigned threads,
                        uint64_t work_limit, uint64_t* work = nullptr);

// The stamps of a coding-0 key frame body (SPEC 6; stored_frame.cpp): true, with `out` set,
// when the body is a stroke count within `limits` followed by that many 16-byte records (fill
// then declines any record that is not a stamp); false for any other body, which the general
// path decodes. `body` must outlive `out`.
bool stored_key_stamps(const uint8_t* body, size_t n, const Limits& limits, StampSource& out);

}  // namespace spt::detail
