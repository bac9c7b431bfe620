// The counts and the edit stream that open every coding-1 and coding-2 body (SPEC.md 7.1,
// 7.5, 7.7.3): one reader of the counts for the decoders and for the frame table.
#include "byte_io.hpp"
#include "edit_stream.hpp"
#include "frame_coding.hpp"

namespace spt::detail {
namespace {

// The plain counts before the edit stream (SPEC.md 7.1).
struct BodyCounts {
    uint32_t removed = 0, added = 0, edit_len = 0;
    uint8_t motion = 0;
    uint16_t block = 0;
};

// Reads the counts and leaves `c` at the edit stream (inter frames) or the stroke stream.
Status read_counts(FrameType type, ByteCursor& c, BodyCounts& k) {
    if (type == FrameType::Key) return c.varint(k.added, "added_count");
    SPT_TRY(c.varint(k.removed, "removed_count"));
    SPT_TRY(c.varint(k.added, "added_count"));
    SPT_TRY(c.u8(k.motion, "motion_present"));
    if (k.motion > 1) return c.error(Code::Unsupported, "motion_present " + std::to_string(k.motion) + " is reserved");
    if (k.motion) SPT_TRY(c.u16(k.block, "block_size"));
    return c.varint(k.edit_len, "edit_length");
}

void encode_edits(const Frame& f, std::vector<uint8_t>& out, FieldStats* stats) {
    if (f.removed.empty() && f.motion.empty()) return;
    RangeEncoder enc(out, stats);
    EditCoderState st;
    Frame copy;
    copy.removed = f.removed;
    copy.motion = f.motion;
    SyntaxError err;
    code_edits(enc, st, copy, uint32_t(f.removed.size()), ~uint64_t(0), err);
    enc.finish();
}

}  // namespace

Error body_error(const DecodeContext& ctx, Code code, const std::string& msg, uint64_t rel) {
    return make_error(code, ctx.where + ": " + msg + " (body at byte offset " + std::to_string(ctx.offset + rel) + ")",
                      ctx.offset + rel);
}

size_t encode_body_prefix(const Frame& f, ByteSink& head, FieldStats* stats) {
    if (f.type == FrameType::Key) {
        head.varint(uint32_t(f.added.size()));
        if (stats) (*stats)[Field::Count] += 8.0 * double(head.size());
        return 0;
    }
    const size_t start = head.size();
    std::vector<uint8_t> edits;
    encode_edits(f, edits, stats);
    head.varint(uint32_t(f.removed.size()));
    head.varint(uint32_t(f.added.size()));
    head.u8(f.motion.empty() ? 0 : 1);
    if (!f.motion.empty()) head.u16(f.motion.block_size);
    head.varint(uint32_t(edits.size()));
    head.raw(edits.data(), edits.size());
    // The edit stream's bits were counted per field by its encoder; the rest are counts.
    if (stats) (*stats)[Field::Count] += 8.0 * double(head.size() - start - edits.size());
    return head.size() - start;
}

Status decode_edit_stream(const uint8_t* p, size_t n, uint32_t removed_count, bool motion, uint16_t block_size,
                          const DecodeContext& ctx, Frame& out) {
    out.removed.clear();
    out.motion = MotionField();
    if (removed_count > ctx.prev_live || removed_count > ctx.limits.max_live_strokes)
        return body_error(ctx, Code::Corrupt, std::to_string(removed_count) + " removals from a live list of " +
                                                  std::to_string(ctx.prev_live));
    if (motion) {
        if (block_size < 8 || block_size > 256)
            return body_error(ctx, Code::Corrupt, "motion block size " + std::to_string(block_size) + " is not 8..256");
        out.motion.block_size = block_size;
        out.motion.cols = blocks_for(ctx.shape.width, block_size);
        out.motion.rows = blocks_for(ctx.shape.height, block_size);
        out.motion.vectors.assign(size_t(out.motion.cols) * out.motion.rows, {0, 0});
    }
    if (removed_count == 0 && !motion) {
        if (n) return body_error(ctx, Code::Corrupt, "edit stream of a frame without edits is not empty");
        return {};
    }
    RangeDecoder dec(p, n, ctx.stats);
    EditCoderState st;
    SyntaxError err;
    if (!code_edits(dec, st, out, removed_count, ctx.prev_live, err)) return body_error(ctx, Code::Corrupt, err.msg);
    if (!dec.consumed_all()) return body_error(ctx, Code::Corrupt, "edit stream has bytes after its last value");
    return {};
}

Status decode_body_prefix(FrameType type, ByteCursor& c, const DecodeContext& ctx, Frame& out, BodyPrefix& pre) {
    BodyCounts k;
    SPT_TRY(read_counts(type, c, k));
    if (type == FrameType::Inter) SPT_TRY(c.need(k.edit_len, "edit stream"));
    if (ctx.stats) (*ctx.stats)[Field::Count] += 8.0 * double(c.pos());
    pre = BodyPrefix();
    pre.removed = k.removed;
    pre.added = k.added;
    if (type == FrameType::Key) return {};
    DecodeContext ec = ctx;
    ec.offset = c.offset();
    SPT_TRY(decode_edit_stream(c.here(), k.edit_len, k.removed, k.motion != 0, k.block, ec, out));
    SPT_TRY(c.skip(k.edit_len, "edit stream"));
    if (ctx.prev_live != kUnknownLive && ctx.prev_live - k.removed + k.added > ctx.limits.max_live_strokes)
        return c.error(Code::LimitExceeded, "live list would exceed the limit");
    pre.motion_bytes = c.pos();
    return {};
}

Status measure_body_prefix(FrameType type, uint64_t body_size, const BodyPeek& peek, const DecodeContext& ctx,
                           BodySplit& split) {
    uint8_t buf[32] = {};  // the counts take at most 18 bytes
    const size_t n = size_t(std::min<uint64_t>(body_size, sizeof buf));
    if (!peek(0, n, buf)) return body_error(ctx, Code::Truncated, "frame body cannot be read");
    ByteCursor c(buf, n, ctx.offset, ctx.where);
    BodyCounts k;
    SPT_TRY(read_counts(type, c, k));
    uint64_t motion_bytes = 0;
    if (type == FrameType::Inter) {
        if (c.pos() + uint64_t(k.edit_len) > body_size) return c.error(Code::Corrupt, "edit stream is longer than the body");
        motion_bytes = c.pos() + k.edit_len;
    }
    split = BodySplit::of(body_size, motion_bytes, k.added, k.removed);
    return {};
}

}  // namespace spt::detail
