// Coding 0 frame bodies (SPEC.md 6): fixed-size little-endian records.
#include <bit>
#include <cstddef>
#include <cstring>

#include "byte_io.hpp"
#include "frame_coding.hpp"
#include "stamp_frame.hpp"
#include "validate.hpp"

namespace spt::detail {
namespace {

void put_stroke(ByteSink& s, const Stroke& st, const StreamShape& shape, FieldStats* stats) {
    const bool linear = shape.linear;
    auto add = [&](Field f, double bytes) { if (stats) (*stats)[f] += 8.0 * bytes; };
    s.u8(uint8_t(st.kind));
    add(Field::Kind, 1);
    auto rgba = [&](const Rgba8& c) {
        s.u8(c.r); s.u8(c.g); s.u8(c.b); s.u8(c.a);
        add(Field::Color, 3); add(Field::Alpha, 1);
        if (linear) { s.u8(c.r_lo); s.u8(c.g_lo); s.u8(c.b_lo); add(Field::Color, 3); }  // SPEC.md 6, encoding 1
    };
    switch (st.kind) {
        case StrokeKind::Stamp: {
            const auto& t = st.stamp;
            s.u8(t.set); s.u8(t.tmpl); s.u8(t.orient);
            s.i32(t.x); s.i32(t.y);
            rgba(t.color);
            add(Field::SetTemplate, 2); add(Field::Orientation, 1); add(Field::Position, 8);
            break;
        }
        case StrokeKind::Affine: {
            const auto& t = st.affine;
            s.u8(t.tmpl);
            s.i32(t.tx); s.i32(t.ty); s.i32(t.a); s.i32(t.b); s.i32(t.c); s.i32(t.d);
            rgba(t.color);
            add(Field::SetTemplate, 1); add(Field::Position, 8); add(Field::Geometry, 16);
            break;
        }
        case StrokeKind::Curve: {
            const auto& c = st.curve;
            rgba(c.color);
            if (shape.curve_grid) s.u8(c.supersample);  // format 1.4 (SPEC.md 6)
            s.u32(uint32_t(c.points.size()));
            for (const auto& p : c.points) { s.i32(p.x); s.i32(p.y); s.u32(p.width); }
            add(Field::Position, 8);
            add(Field::Geometry, (shape.curve_grid ? 5 : 4) + 12.0 * double(c.points.size()) - 8);
            break;
        }
        case StrokeKind::Polygon: {
            const auto& p = st.polygon;
            rgba(p.color);
            s.u8(p.supersample);
            s.u32(uint32_t(p.points.size()));
            for (const auto& v : p.points) { s.i32(v.x); s.i32(v.y); }
            add(Field::Position, 8);
            add(Field::Geometry, 5 + 8.0 * double(p.points.size()) - 8);
            break;
        }
    }
}

Status get_stroke(ByteCursor& c, Stroke& st, const DecodeContext& ctx, uint32_t i) {
    uint8_t kind;
    SPT_TRY(c.u8(kind, "stroke kind"));
    auto rgba = [&](Rgba8& col) -> Status {
        SPT_TRY(c.u8(col.r, "colour")); SPT_TRY(c.u8(col.g, "colour"));
        SPT_TRY(c.u8(col.b, "colour")); SPT_TRY(c.u8(col.a, "colour"));
        col.r_lo = col.g_lo = col.b_lo = 0;
        if (ctx.shape.linear) {
            SPT_TRY(c.u8(col.r_lo, "colour low byte")); SPT_TRY(c.u8(col.g_lo, "colour low byte"));
            SPT_TRY(c.u8(col.b_lo, "colour low byte"));
        }
        return {};
    };
    switch (kind) {
        case 0: {
            st.kind = StrokeKind::Stamp;
            auto& t = st.stamp;
            SPT_TRY(c.u8(t.set, "stamp set")); SPT_TRY(c.u8(t.tmpl, "template")); SPT_TRY(c.u8(t.orient, "orientation"));
            SPT_TRY(c.i32(t.x, "x")); SPT_TRY(c.i32(t.y, "y"));
            return rgba(t.color);
        }
        case 1: {
            st.kind = StrokeKind::Affine;
            auto& t = st.affine;
            SPT_TRY(c.u8(t.tmpl, "template"));
            SPT_TRY(c.i32(t.tx, "tx")); SPT_TRY(c.i32(t.ty, "ty"));
            SPT_TRY(c.i32(t.a, "a")); SPT_TRY(c.i32(t.b, "b")); SPT_TRY(c.i32(t.c, "c")); SPT_TRY(c.i32(t.d, "d"));
            return rgba(t.color);
        }
        case 2: {
            st.kind = StrokeKind::Curve;
            auto& cv = st.curve;
            SPT_TRY(rgba(cv.color));
            cv.supersample = 0;
            if (ctx.shape.curve_grid) {  // format 1.4: the record has a grid (SPEC.md 6)
                SPT_TRY(c.u8(cv.supersample, "curve supersampling"));
                if (cv.supersample == 1 || cv.supersample > 16)
                    return c.error(Code::Unsupported, "stroke " + std::to_string(i) + ": curve supersampling " +
                                                          std::to_string(cv.supersample) + " is reserved");
            }
            uint32_t n;
            SPT_TRY(c.u32(n, "curve point count"));
            if (n > ctx.limits.max_curve_points)
                return c.error(Code::LimitExceeded, "stroke " + std::to_string(i) + ": curve of " + std::to_string(n) + " points exceeds the limit");
            SPT_TRY(c.need(size_t(n) * 12, "curve points"));
            cv.points.resize(n);
            for (auto& p : cv.points) { SPT_TRY(c.i32(p.x, "x")); SPT_TRY(c.i32(p.y, "y")); SPT_TRY(c.u32(p.width, "width")); }
            return {};
        }
        case 3: {
            // Format 1.2. Stored records are unambiguous, so they decode whatever the header's
            // minor version says (SPEC.md 6).
            st.kind = StrokeKind::Polygon;
            auto& pg = st.polygon;
            SPT_TRY(rgba(pg.color));
            SPT_TRY(c.u8(pg.supersample, "polygon supersampling"));
            if (pg.supersample == 1 || pg.supersample > 16)
                return c.error(Code::Unsupported, "stroke " + std::to_string(i) + ": polygon supersampling " +
                                                      std::to_string(pg.supersample) + " is reserved");
            uint32_t n;
            SPT_TRY(c.u32(n, "polygon vertex count"));
            if (n < 3) return c.error(Code::Corrupt, "stroke " + std::to_string(i) + ": polygon of " + std::to_string(n) + " vertices");
            if (n > ctx.limits.max_polygon_vertices)
                return c.error(Code::LimitExceeded, "stroke " + std::to_string(i) + ": polygon of " + std::to_string(n) +
                                                        " vertices exceeds the limit");
            SPT_TRY(c.need(size_t(n) * 8, "polygon vertices"));
            pg.points.resize(n);
            for (auto& v : pg.points) { SPT_TRY(c.i32(v.x, "x")); SPT_TRY(c.i32(v.y, "y")); }
            return {};
        }
        default:
            return c.error(Code::Corrupt, "stroke " + std::to_string(i) + " has reserved kind " + std::to_string(kind));
    }
}

// Smallest possible stroke record: a curve with one point is 21 bytes, a stamp 16, so a count
// can be checked against the bytes left before anything is allocated.
constexpr size_t kMinStrokeBytes = 16;

// StampSource::fill over 16-byte records: a stamp is kind 0, set, template, orientation, x, y
// (little-endian), R, G, B, A.
bool fill_stamps(const void* ctx, size_t first, size_t n, StampStroke* out) {
    const uint8_t* q = static_cast<const uint8_t*>(ctx) + 16 * first;
    // Where StampStroke has the record's layout from byte 4 on (x, y, colour), as on every
    // little-endian host, a record is one 16-byte copy and a fix of its first word (kind, set,
    // template, orientation -> set, template, orientation): the player's path copies 30,000 of
    // them a frame.
    constexpr bool kSameTail = std::endian::native == std::endian::little && sizeof(StampStroke) >= 16 &&
                               offsetof(StampStroke, x) == 4 && offsetof(StampStroke, y) == 8 &&
                               offsetof(StampStroke, color) == 12 && offsetof(StampStroke, orient) == 2;
    for (size_t i = 0; i < n; ++i, q += 16) {
        if (q[0] != 0) return false;
        StampStroke& t = out[i];
        if constexpr (kSameTail) {
            std::memcpy(static_cast<void*>(&t), q, 16);
            t.color.r_lo = t.color.g_lo = t.color.b_lo = 0;
            t.set = q[1];
            t.tmpl = q[2];
            t.orient = q[3];
        } else {
            t.set = q[1];
            t.tmpl = q[2];
            t.orient = q[3];
            t.x = int32_t(load_u32(q + 4));
            t.y = int32_t(load_u32(q + 8));
            t.color = Rgba8{q[12], q[13], q[14], q[15]};
        }
    }
    return true;
}

}  // namespace

bool stored_key_stamps(const uint8_t* body, size_t n, const Limits& limits, StampSource& out) {
    if (n < 4) return false;
    const uint32_t added = load_u32(body);
    if (added > limits.max_strokes_per_frame || added > limits.max_live_strokes || uint64_t(n) - 4 != uint64_t(added) * 16)
        return false;
    out.count = added;
    out.ctx = body + 4;
    out.fill = fill_stamps;
    out.packed = body + 4;  // coding 0's records are packed stamps (SPEC 6)
    return true;
}

void encode_stored_body(const Frame& f, const StreamShape& shape, std::vector<uint8_t>& out, BodySplit* split,
                        FieldStats* stats) {
    ByteSink s;
    size_t motion_bytes = 0;
    if (f.type == FrameType::Inter) {
        s.u32(uint32_t(f.removed.size()));
        for (uint32_t r : f.removed) s.u32(r);
        s.u8(f.motion.empty() ? 0 : 1);
        if (stats) { (*stats)[Field::Count] += 8.0 * 5; (*stats)[Field::Removal] += 32.0 * double(f.removed.size()); }
        if (!f.motion.empty()) {
            s.u16(f.motion.block_size); s.u16(f.motion.cols); s.u16(f.motion.rows);
            for (const auto& [dx, dy] : f.motion.vectors) { s.i16(dx); s.i16(dy); }
            if (stats) (*stats)[Field::Motion] += 8.0 * (6 + 4.0 * double(f.motion.vectors.size()));
        }
        motion_bytes = s.size();
    }
    s.u32(uint32_t(f.added.size()));
    if (stats) (*stats)[Field::Count] += 32.0;
    for (const auto& st : f.added) put_stroke(s, st, shape, stats);
    if (split) *split = BodySplit::of(s.size(), motion_bytes, uint32_t(f.added.size()), uint32_t(f.removed.size()));
    out.insert(out.end(), s.bytes().begin(), s.bytes().end());
}

Status decode_stored_body(FrameType type, const uint8_t* p, size_t n, const DecodeContext& ctx, Frame& out,
                          BodySplit* split, size_t* checked) {
    if (checked) *checked = 0;
    ByteCursor c(p, n, ctx.offset, ctx.where);
    size_t motion_bytes = 0;
    if (type == FrameType::Inter) {
        uint32_t count;
        SPT_TRY(c.u32(count, "removed_count"));
        if (count > ctx.prev_live || count > ctx.limits.max_live_strokes)
            return c.error(Code::Corrupt, std::to_string(count) + " removals from a live list of " + std::to_string(ctx.prev_live));
        SPT_TRY(c.need(size_t(count) * 4, "removed indices"));
        out.removed.resize(count);
        for (auto& r : out.removed) SPT_TRY(c.u32(r, "removed index"));
        uint8_t motion;
        SPT_TRY(c.u8(motion, "motion_present"));
        if (motion > 1) return c.error(Code::Unsupported, "motion_present " + std::to_string(motion) + " is reserved");
        if (motion) {
            auto& m = out.motion;
            SPT_TRY(c.u16(m.block_size, "block_size")); SPT_TRY(c.u16(m.cols, "cols")); SPT_TRY(c.u16(m.rows, "rows"));
            if (m.block_size < 8 || m.block_size > 256)
                return c.error(Code::Corrupt, "motion block size " + std::to_string(m.block_size) + " is not 8..256");
            if (m.cols != blocks_for(ctx.shape.width, m.block_size) || m.rows != blocks_for(ctx.shape.height, m.block_size))
                return c.error(Code::Corrupt, "motion field of " + std::to_string(m.cols) + "x" + std::to_string(m.rows) +
                                                  " blocks does not match the canvas");
            const size_t count_v = size_t(m.cols) * m.rows;
            SPT_TRY(c.need(count_v * 4, "motion vectors"));
            m.vectors.resize(count_v);
            for (auto& [dx, dy] : m.vectors) { SPT_TRY(c.i16(dx, "dx")); SPT_TRY(c.i16(dy, "dy")); }
            if (count_v == 0) return c.error(Code::Corrupt, "motion field is empty");
        }
        motion_bytes = c.pos();
    }
    uint32_t added;
    SPT_TRY(c.u32(added, "added_count"));
    if (added > ctx.limits.max_strokes_per_frame)
        return c.error(Code::LimitExceeded, std::to_string(added) + " strokes exceed the stroke limit of " + std::to_string(ctx.limits.max_strokes_per_frame) + " per frame (max_strokes_per_frame)");
    if (uint64_t(added) * kMinStrokeBytes > c.left())
        return c.error(Code::Truncated, std::to_string(added) + " strokes cannot fit in " + std::to_string(c.left()) + " bytes");
    // The strokes of the Frame's previous contents are overwritten in place: destroying and
    // constructing 30,000 Strokes (3.6 MB) per frame streamed the list through the cache twice
    // more. (Members of a stroke's other kinds keep old values; only the kind's own are valid.)
    out.added.resize(added);
    bool valid_so_far = true;  // strokes [0, i) passed check_stroke's stamp test
    for (uint32_t i = 0; i < added; ++i) {
        Stroke& st = out.added[i];
        // The common record, a whole stamp, without a Status per field (most of a painting).
        if (!ctx.shape.linear && c.left() >= 16 && c.here()[0] == 0) {
            const uint8_t* q = c.here() + 1;
            st.kind = StrokeKind::Stamp;
            st.stamp.set = q[0]; st.stamp.tmpl = q[1]; st.stamp.orient = q[2];
            st.stamp.x = int32_t(load_u32(q + 3));
            st.stamp.y = int32_t(load_u32(q + 7));
            st.stamp.color = Rgba8{q[11], q[12], q[13], q[14]};
            if (!st.curve.points.empty()) st.curve.points.clear();
            if (!st.polygon.points.empty()) st.polygon.points.clear();
            c.advance(16);
            if (valid_so_far && stamp_ok(st.stamp, ctx.shape)) {
                if (checked) *checked = i + 1;
            } else {
                valid_so_far = false;
            }
            continue;
        }
        valid_so_far = false;
        st = Stroke();
        SPT_TRY(get_stroke(c, st, ctx, i));
    }
    if (c.left()) return c.error(Code::Corrupt, std::to_string(c.left()) + " bytes follow the last stroke");
    if (ctx.stats) {
        BodySplit dummy;
        std::vector<uint8_t> scratch;
        encode_stored_body(out, ctx.shape, scratch, &dummy, ctx.stats);  // exact byte accounting
    }
    if (split) *split = BodySplit::of(n, motion_bytes, added, uint32_t(out.removed.size()));
    return {};
}

Status measure_stored_body(FrameType type, uint64_t body_size, const BodyPeek& peek, const DecodeContext& ctx,
                           BodySplit& split) {
    uint8_t b[8];
    auto fail = [&](const char* what) {
        return make_error(Code::Corrupt, ctx.where + ": " + what + " lies outside the body (byte offset " +
                                             std::to_string(ctx.offset) + ")", ctx.offset);
    };
    uint64_t pos = 0;
    uint32_t removed = 0;
    if (type == FrameType::Inter) {
        if (body_size < 4 || !peek(0, 4, b)) return fail("removed_count");
        removed = load_u32(b);
        pos = 4 + uint64_t(removed) * 4;
        if (pos + 1 > body_size || !peek(pos, 1, b)) return fail("motion_present");
        const uint8_t motion = b[0];
        pos += 1;
        if (motion == 1) {
            if (pos + 6 > body_size || !peek(pos, 6, b)) return fail("motion header");
            pos += 6 + uint64_t(load_u16(b + 2)) * load_u16(b + 4) * 4;
        }
    }
    if (pos + 4 > body_size || !peek(pos, 4, b)) return fail("added_count");
    split = BodySplit::of(body_size, pos, load_u32(b), removed);
    return {};
}

}  // namespace spt::detail
