// Fuzz target: the coding-1 stroke stream decoder on its own.
// Input: u8 sets-1 (bit 7: a format 1.2 stream, with polygon strokes; bit 6: a format 1.3
// stream in colour encoding 1, with colour low bytes; bit 5: a format 1.4 stream whose curves
// carry a grid), u8 orientations-1,
// u8 templates, u16 width, u16 height, then a coding-1 key frame body (varint stroke count,
// range-coded stroke stream).
#include <cstddef>
#include <cstdint>

#include "byte_io.hpp"
#include "frame_coding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 7) return 0;
    spt::detail::DecodeContext ctx;
    ctx.shape.sets = 1u + (data[0] & 15);
    ctx.shape.orientations = 1u + (data[1] & 63);
    ctx.shape.templates = data[2];
    ctx.shape.version_minor = (data[0] & 0x20) ? 4 : (data[0] & 0x40) ? 3 : (data[0] & 0x80) ? 2 : 0;
    ctx.shape.linear = (data[0] & 0x40) != 0;
    ctx.shape.curve_grid = (data[0] & 0x20) != 0;
    ctx.shape.width = 1u + (spt::detail::load_u16(data + 3) & 4095);
    ctx.shape.height = 1u + (spt::detail::load_u16(data + 5) & 4095);
    ctx.limits.max_strokes_per_frame = ctx.limits.max_live_strokes = 1u << 14;
    ctx.limits.max_curve_points = 1u << 10;
    ctx.limits.max_polygon_vertices = 1u << 10;
    spt::FieldStats fs;
    ctx.stats = &fs;
    spt::Frame f;
    (void)spt::detail::decode_range_body(spt::FrameType::Key, data + 7, size - 7, ctx, f, nullptr);
    return 0;
}
