// Frame body dispatch by coding, with the checks every decoded frame gets (SPEC.md 9).
#include "byte_io.hpp"
#include "frame_coding.hpp"

namespace spt::detail {

void encode_frame_body(const Frame& f, Coding coding, const StreamShape& shape, std::vector<uint8_t>& out,
                       BodySplit* split, FieldStats* stats) {
    // Coding 2 needs the writer's canvas state (encode_replay_body); without it, coding 1.
    if (coding == Coding::Stored) encode_stored_body(f, shape, out, split, stats);
    else encode_range_body(f, shape, out, split, stats);
}

Status decode_frame_body(FrameType type, Coding coding, const uint8_t* p, size_t n, const DecodeContext& ctx,
                         Frame& out, BodySplit* split) {
    out.type = type;
    out.removed.clear();
    out.motion = MotionField();
    size_t checked = 0;
    if (coding == Coding::Stored) {
        SPT_TRY(decode_stored_body(type, p, n, ctx, out, split, &checked));  // reuses out.added's strokes
    } else {
        out.added.clear();
        if (coding == Coding::Range) SPT_TRY(decode_range_body(type, p, n, ctx, out, split));
        else if (coding == Coding::Replay) {
            if (!ctx.shape.plain_color())
                return make_error(Code::Corrupt, ctx.where + ": frame coding 2 in a file with an alpha canvas or colour encoding 1", ctx.offset);
            SPT_TRY(decode_replay_body(type, p, n, ctx, out, split));
        }
        else return make_error(Code::Unsupported, ctx.where + ": coding " + std::to_string(int(coding)) + " is reserved", ctx.offset);
    }
    return check_frame(out, ctx.shape, ctx.limits, ctx.prev_live, Code::Corrupt, ctx.where, ctx.offset, checked);
}

Status measure_frame_body(FrameType type, Coding coding, uint64_t body_size, const BodyPeek& peek,
                          const DecodeContext& ctx, BodySplit& split) {
    if (coding == Coding::Stored) return measure_stored_body(type, body_size, peek, ctx, split);
    // Coding 2 starts with coding 1's counts and edit stream (SPEC.md 7.7.3).
    return measure_body_prefix(type, body_size, peek, ctx, split);
}

}  // namespace spt::detail
