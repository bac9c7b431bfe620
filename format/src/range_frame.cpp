// Coding 1 frame bodies (SPEC.md 7.1): the counts and edit stream of body_prefix.cpp, then the
// range-coded stroke stream.
#include <memory>

#include "byte_io.hpp"
#include "frame_coding.hpp"
#include "stroke_stream.hpp"

namespace spt::detail {
namespace {

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

}  // namespace

void encode_range_body(const Frame& f, const StreamShape& shape, std::vector<uint8_t>& out, BodySplit* split,
                       FieldStats* stats) {
    const size_t start = out.size();
    ByteSink head;
    const size_t motion_bytes = encode_body_prefix(f, head, stats);
    out.insert(out.end(), head.bytes().begin(), head.bytes().end());
    encode_strokes(f.added, shape, out, stats);
    if (split) *split = BodySplit::of(out.size() - start, motion_bytes, uint32_t(f.added.size()), uint32_t(f.removed.size()));
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

Status decode_range_body(FrameType type, const uint8_t* p, size_t n, const DecodeContext& ctx, Frame& out,
                         BodySplit* split) {
    ByteCursor c(p, n, ctx.offset, ctx.where);
    BodyPrefix pre;
    SPT_TRY(decode_body_prefix(type, c, ctx, out, pre));
    DecodeContext sc = ctx;
    sc.offset = c.offset();
    SPT_TRY(decode_stroke_stream(c.here(), c.left(), pre.added, sc, out.added));
    if (split) *split = BodySplit::of(n, pre.motion_bytes, pre.added, pre.removed);
    return {};
}

}  // namespace spt::detail
