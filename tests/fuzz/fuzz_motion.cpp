// Fuzz target: the coding-1 edit stream decoder (removal gaps, motion field) on its own.
// Input: u16 width, u16 height, u16 live count, u16 removed count, u8 motion_present,
// u16 block_size, then the range-coded edit stream.
#include <cstddef>
#include <cstdint>

#include "byte_io.hpp"
#include "frame_coding.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using spt::detail::load_u16;
    if (size < 11) return 0;
    spt::detail::DecodeContext ctx;
    ctx.shape.width = 1u + (load_u16(data) & 4095);
    ctx.shape.height = 1u + (load_u16(data + 2) & 4095);
    ctx.shape.sets = ctx.shape.orientations = ctx.shape.templates = 1;
    ctx.prev_live = load_u16(data + 4);
    const uint32_t removed = load_u16(data + 6);
    spt::Frame f;
    f.type = spt::FrameType::Inter;
    (void)spt::detail::decode_edit_stream(data + 11, size - 11, removed, data[8] & 1, load_u16(data + 9), ctx, f);
    return 0;
}
