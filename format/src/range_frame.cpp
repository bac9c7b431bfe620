// Coding 1 frame bodies (SPEC.md 7.1): plain counts, then the range-coded edit stream
// (inter frames) and the range-coded stroke stream.
#include <memory>

#include "byte_io.hpp"
#include "frame_coding.hpp"
#include "edit_stream.hpp"
#include "stroke_stream.hpp"

namespace spt::detail {
namespace {

Error body_error(const DecodeContext& ctx, Code code, const std::string& msg, uint64_t rel = 0) {
    return make_error(code, ctx.where + ": " + msg + " (body at byte offset " + std::to_string(ctx.offset + rel) + ")",
                      ctx.offset + rel);
}

void encode_strokes(const std::vector<Stroke>& strokes, const StreamShape& shape, std::vector<uint8_t>& out,
                    FieldStats* stats) {
    if (strokes.empty()) return;
    RangeEncoder enc(out, stats);
    auto st = std::make_unique<StrokeCoderState>(shape);
    Limits unlimited;
    unlimited.max_curve_points = 0xFFFFFFFFu;
    unlimited.max_polygon_vertices = 0xFFFFFFFFu;
    unlimited.max_polygon_work = unlimited.max_curve_work = ~uint64_t(0);
    SyntaxError err;
    for (const Stroke& s : strokes) {
        Stroke copy = s;  // code_stroke assigns coded values back
        code_stroke(enc, *st, copy, unlimited, err);
    }
    enc.finish();
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

void encode_range_body(const Frame& f, const StreamShape& shape, std::vector<uint8_t>& out, BodySplit* split,
                       FieldStats* stats) {
    const size_t start = out.size();
    ByteSink head;
    const size_t motion_bytes = encode_body_prefix(f, head, stats);
    out.insert(out.end(), head.bytes().begin(), head.bytes().end());
    encode_strokes(f.added, shape, out, stats);
    if (split) {
        split->motion_bytes = motion_bytes;
        split->stroke_bytes = out.size() - start - motion_bytes;
        split->added = uint32_t(f.added.size());
        split->removed = uint32_t(f.removed.size());
    }
}

Status decode_stroke_stream(const uint8_t* p, size_t n, uint32_t count, const DecodeContext& ctx,
                            std::vector<Stroke>& out) {
    out.clear();
    if (count > ctx.limits.max_strokes_per_frame)
        return body_error(ctx, Code::LimitExceeded, std::to_string(count) + " strokes exceed the per-frame limit");
    if (count == 0) {
        if (n) return body_error(ctx, Code::Corrupt, "stroke stream of a frame without strokes is not empty");
        return {};
    }
    RangeDecoder dec(p, n, ctx.stats);
    auto st = std::make_unique<StrokeCoderState>(ctx.shape);
    // Grow as strokes decode: a count is only a claim until its strokes are there.
    out.reserve(std::min<size_t>(count, 1u << 16));
    SyntaxError err;
    for (uint32_t i = 0; i < count; ++i) {
        // Decoded in place: no Stroke is built and moved per stroke.
        if (!code_stroke(dec, *st, out.emplace_back(), ctx.limits, err)) {
            out.pop_back();
            return body_error(ctx, Code::Corrupt, "stroke " + std::to_string(i) + ": " + err.msg);
        }
    }
    if (!dec.consumed_all()) return body_error(ctx, Code::Corrupt, "stroke stream has bytes after its last stroke");
    return {};
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
    uint32_t removed = 0, added = 0, edit_len = 0;
    uint8_t motion = 0;
    uint16_t block = 0;
    if (type == FrameType::Inter) {
        SPT_TRY(c.varint(removed, "removed_count"));
        SPT_TRY(c.varint(added, "added_count"));
        SPT_TRY(c.u8(motion, "motion_present"));
        if (motion > 1) return c.error(Code::Unsupported, "motion_present " + std::to_string(motion) + " is reserved");
        if (motion) SPT_TRY(c.u16(block, "block_size"));
        SPT_TRY(c.varint(edit_len, "edit_length"));
        SPT_TRY(c.need(edit_len, "edit stream"));
    } else {
        SPT_TRY(c.varint(added, "added_count"));
    }
    if (ctx.stats) (*ctx.stats)[Field::Count] += 8.0 * double(c.pos());
    if (type == FrameType::Inter) {
        DecodeContext ec = ctx;
        ec.offset = c.offset();
        SPT_TRY(decode_edit_stream(c.here(), edit_len, removed, motion != 0, block, ec, out));
        SPT_TRY(c.skip(edit_len, "edit stream"));
        if (ctx.prev_live != kUnknownLive && ctx.prev_live - removed + added > ctx.limits.max_live_strokes)
            return c.error(Code::LimitExceeded, "live list would exceed the limit");
    }
    pre.removed = removed;
    pre.added = added;
    pre.motion_bytes = c.pos();
    return {};
}

Status decode_range_body(FrameType type, const uint8_t* p, size_t n, const DecodeContext& ctx, Frame& out,
                         BodySplit* split) {
    ByteCursor c(p, n, ctx.offset, ctx.where);
    BodyPrefix pre;
    SPT_TRY(decode_body_prefix(type, c, ctx, out, pre));
    const uint32_t removed = pre.removed, added = pre.added;
    const size_t motion_bytes = pre.motion_bytes;
    DecodeContext sc = ctx;
    sc.offset = c.offset();
    SPT_TRY(decode_stroke_stream(c.here(), c.left(), added, sc, out.added));
    if (split) {
        split->motion_bytes = type == FrameType::Inter ? motion_bytes : 0;
        split->stroke_bytes = n - split->motion_bytes;
        split->added = added;
        split->removed = removed;
    }
    return {};
}

Status measure_range_body(FrameType type, uint64_t body_size, const BodyPeek& peek, const DecodeContext& ctx,
                          BodySplit& split) {
    uint8_t buf[32] = {};
    const size_t k = size_t(std::min<uint64_t>(body_size, sizeof buf));
    if (!peek(0, k, buf)) return body_error(ctx, Code::Truncated, "frame body cannot be read");
    ByteCursor c(buf, k, ctx.offset, ctx.where);
    uint32_t removed = 0, added = 0, edit_len = 0;
    uint8_t motion = 0;
    uint16_t block = 0;
    if (type == FrameType::Inter) {
        SPT_TRY(c.varint(removed, "removed_count"));
        SPT_TRY(c.varint(added, "added_count"));
        SPT_TRY(c.u8(motion, "motion_present"));
        if (motion) SPT_TRY(c.u16(block, "block_size"));
        SPT_TRY(c.varint(edit_len, "edit_length"));
        if (c.pos() + uint64_t(edit_len) > body_size) return c.error(Code::Corrupt, "edit stream is longer than the body");
        split.motion_bytes = c.pos() + edit_len;
    } else {
        SPT_TRY(c.varint(added, "added_count"));
        split.motion_bytes = 0;
    }
    split.stroke_bytes = body_size - split.motion_bytes;
    split.added = added;
    split.removed = removed;
    return {};
}

}  // namespace spt::detail
