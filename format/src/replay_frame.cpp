// Coding 2 frame bodies (SPEC.md 7.7): the coding-1 layout up to the stroke stream, then the
// frame's generator seed and flags, then one range-coded stream: the lead strokes coded as in
// coding 1 (format 1.5), then candidate regions, accepted candidate gaps, orientations and
// colours predicted from the canvas painted so far.
#include <algorithm>
#include <memory>

#include "byte_io.hpp"
#include "frame_coding.hpp"
#include "replay_strokes.hpp"

namespace spt::detail {
namespace {

constexpr uint8_t kRandomOrientation = 1;     // flags bit 0
constexpr uint8_t kLeadStrokes = 2;           // flags bit 1 (format 1.5)
constexpr uint8_t kOneRegion = 4;             // flags bit 2 (format 1.5): one region for every set
constexpr uint8_t kMaxColorStep = 32;
constexpr uint64_t kMaxEncoderScan = 1u << 24;  // candidates searched for one stroke

// Matches the frame's strokes to the generator's candidates, set by set: each stroke takes the
// first candidate after the previous one with its position, template (and orientation when
// drawn). An earlier identical candidate gives the same stroke, so first match is exact.
// The strokes before the first stamp are the lead (`lead`, coded as in coding 1) when
// `allow_lead`; at least one stroke must be replayed.
bool plan(const Frame& f, const Header& hd, uint32_t templates, bool allow_lead, size_t& lead,
          std::vector<ReplaySet>& sets) {
    const ReplayInfo& ri = f.replay;
    const uint32_t S = uint32_t(hd.sets.size()), N = uint32_t(hd.orientations.size());
    if (!ri.present || f.added.empty() || templates == 0 || ri.color_step < 1 || ri.color_step > kMaxColorStep) return false;
    if (!ri.regions.empty() && ri.regions.size() != S) return false;
    sets.assign(S, ReplaySet{});
    for (uint32_t s = 0; s < S; ++s) {
        if (!ri.regions.empty()) sets[s].region = ri.regions[s];
        if (!replay::check_region(sets[s].region, hd.width, hd.height).empty()) return false;
    }
    lead = 0;
    while (lead < f.added.size() && f.added[lead].kind != StrokeKind::Stamp) ++lead;
    if (lead == f.added.size() || (lead > 0 && !allow_lead)) return false;
    int last_set = 0;
    for (size_t i = lead; i < f.added.size(); ++i) {
        const Stroke& st = f.added[i];
        if (st.kind != StrokeKind::Stamp) return false;
        const StampStroke& t = st.stamp;
        if (t.set < last_set || t.set >= S || t.color.a != 255 || (t.x & 15) != 8 || (t.y & 15) != 8) return false;
        if (t.x < 0 || t.y < 0 || uint32_t(t.x >> 4) >= hd.width || uint32_t(t.y >> 4) >= hd.height) return false;
        last_set = t.set;
        sets[t.set].strokes.push_back(st);
    }
    for (uint32_t s = 0; s < S; ++s) {
        ReplaySet& rs = sets[s];
        if (rs.strokes.empty()) {
            rs.region = ReplayRegion{};  // no candidate of it is used: the region in two flags
            continue;
        }
        const replay::CandidateDomain dom(hd.width, hd.height, rs.region);
        if (dom.size() == 0) return false;
        uint64_t next = 0;
        for (const Stroke& st : rs.strokes) {
            const StampStroke& t = st.stamp;
            const uint32_t x = uint32_t(t.x >> 4), y = uint32_t(t.y >> 4);
            if (!dom.contains(x, y)) return false;
            const uint64_t end = std::min(next + kMaxEncoderScan, kMaxReplayCounter);
            bool found = false;
            for (uint64_t n = next; n < end; ++n) {
                uint32_t cx, cy;
                dom.pixel(replay::below(replay::draw(ri.seed, s, n, replay::Stream::Position), dom.size()), cx, cy);
                if (cx != x || cy != y) continue;
                if (replay::below(replay::draw(ri.seed, s, n, replay::Stream::Template), templates) != t.tmpl) continue;
                if (ri.random_orientation &&
                    replay::below(replay::draw(ri.seed, s, n, replay::Stream::Orientation), N) != t.orient)
                    continue;
                rs.counters.push_back(n);
                next = n + 1;
                found = true;
                break;
            }
            if (!found) return false;
        }
    }
    return true;
}

// The canvas a coding-2 frame starts from: the background, with the live list after the
// frame's removals and motion drawn on it (inter frames).
Status start_canvas(const Frame& edits, FrameType type, const Header& hd, const Renderer& renderer,
                    const std::vector<Stroke>* live, Canvas& canvas) {
    canvas = Canvas(hd.width, hd.height, hd.background);
    if (type == FrameType::Key) return {};
    if (!live) return make_error(Code::InvalidArgument, "a coding-2 inter frame needs the previous live list");
    std::vector<Stroke> moved = *live;
    Frame e;
    e.index = edits.index;
    e.type = FrameType::Inter;
    e.removed = edits.removed;
    e.motion = edits.motion;
    Limits unlimited;
    unlimited.max_live_strokes = 0xFFFFFFFFu;
    unlimited.max_polygon_work = unlimited.max_curve_work = ~uint64_t(0);  // the reader checked this live list
    SPT_TRY(apply_frame(moved, e, hd, unlimited));
    return renderer.render(canvas, moved);
}

// The lead strokes (SPEC.md 7.7.5, format 1.5): their count, then each as in coding 1 (7.4),
// with that stream's contexts and predictors, drawn on `canvas` as soon as it is coded. Every
// stroke is checked before it is drawn, and the lead's polygons and curves together stay within
// the rendering work the limits allow the whole live list.
template <class C>
bool code_lead(C& c, ReplayCoderState& rs, std::vector<Stroke>& lead, uint64_t added, const StreamShape& shape,
               const Limits& lim, const Renderer& renderer, Canvas& canvas, SyntaxError& err) {
    c.set_field(Field::Count);
    const uint64_t n = code_uint(c, rs.lead_count, lead.empty() ? 0 : lead.size() - 1) + 1;
    if (n >= added) {
        err.set(std::to_string(n) + " lead strokes leave none of the frame's " + std::to_string(added) + " to replay");
        return false;
    }
    // A count is only a claim until its strokes decode: the decoder grows the list stroke by stroke.
    if constexpr (C::kDecoding) lead.reserve(size_t(std::min<uint64_t>(n, 1u << 16)));
    auto st = std::make_unique<StrokeCoderState>(shape);
    uint64_t polygon_work = 0, curve_work = 0;
    for (size_t i = 0; i < n; ++i) {
        if constexpr (C::kDecoding) lead.emplace_back();
        Stroke& s = lead[i];
        if (!code_stroke(c, *st, s, lim, err)) {
            err.msg = "lead stroke " + std::to_string(i) + ": " + err.msg;
            return false;
        }
        if (auto ok = check_stroke(s, shape, lim, Code::Corrupt, "lead stroke " + std::to_string(i), 0); !ok) {
            err.set(ok.error().message);
            err.code = ok.error().code;
            return false;
        }
        if (s.kind == StrokeKind::Polygon) polygon_work += polygon_render_work(s.polygon, shape.height);
        if (s.kind == StrokeKind::Curve) curve_work += curve_render_work(s.curve, shape.width, shape.height);
        if (polygon_work > lim.max_polygon_work || curve_work > lim.max_curve_work) {
            err.set("the lead strokes need more rendering work than the limits allow");
            err.code = Code::LimitExceeded;
            return false;
        }
        if (auto ds = renderer.draw(canvas, s); !ds) { err.set(ds.error().message); return false; }
    }
    return true;
}

// The region every set that has strokes draws from (then coded once, flags bit 2); null when
// they draw from different ones, or no set has strokes.
const ReplayRegion* one_region(const std::vector<ReplaySet>& sets) {
    const ReplayRegion* first = nullptr;
    for (const ReplaySet& s : sets) {
        if (s.strokes.empty()) continue;
        if (!first) first = &s.region;
        else if (!(s.region == *first)) return nullptr;
    }
    return first;
}

template <class C>
bool code_sets(C& c, std::vector<ReplaySet>& sets, uint64_t seed, bool random_orient, int step, uint64_t added,
               const Header& hd, uint32_t templates, const Renderer& renderer, Canvas& canvas, SyntaxError& err,
               std::vector<Stroke>* lead = nullptr, const StreamShape* shape = nullptr, const Limits* lim = nullptr,
               bool shared_region = false) {
    ReplayCoderState st(uint32_t(hd.orientations.size()), renderer);
    uint64_t left = added;
    if (lead) {
        if (!code_lead(c, st, *lead, added, *shape, *lim, renderer, canvas, err)) return false;
        left -= lead->size();
    }
    for (uint32_t s = 0; s < sets.size(); ++s) {
        c.set_field(Field::Candidates);
        if (shared_region && s > 0) sets[s].region = sets[0].region;
        else if (!code_region(c, st, sets[s].region, hd.width, hd.height, err)) return false;
        if (!code_replay_set(c, st, sets[s], s, seed, random_orient, step, left, hd, templates, renderer, canvas, err))
            return false;
        left -= sets[s].strokes.size();
    }
    if (left != 0) { err.set(std::to_string(left) + " of the frame's strokes are missing from its sets"); return false; }
    return true;
}

}  // namespace

bool encode_replay_body(const Frame& f, const ReplayEnv& env, std::vector<uint8_t>& out, BodySplit* split,
                        FieldStats* stats, bool* needs_lead_version) {
    const Header& hd = *env.header;
    std::vector<ReplaySet> sets;
    size_t lead = 0;
    if (!plan(f, hd, env.shape.templates, env.allow_lead, lead, sets)) return false;
    // One region for all sets in a file that is (or this frame makes) 1.5; files that are not
    // keep their bytes.
    const ReplayRegion* common = one_region(sets);
    const bool shared = env.allow_lead && (lead > 0 || env.shape.version_minor >= kLeadMinorVersion) && common;
    if (shared) {
        const ReplayRegion region = *common;
        for (ReplaySet& s : sets) s.region = region;
    }
    Canvas canvas;
    if (!start_canvas(f, f.type, hd, *env.renderer, env.live, canvas)) return false;

    FieldStats fs;
    ByteSink head;
    const size_t motion_bytes = encode_body_prefix(f, head, &fs);
    head.u64(f.replay.seed);
    head.u8(uint8_t((f.replay.random_orientation ? kRandomOrientation : 0) | (lead ? kLeadStrokes : 0) |
                    (shared ? kOneRegion : 0)));
    head.u8(f.replay.color_step);
    fs[Field::Candidates] += 8.0 * 10;
    std::vector<uint8_t> stream;
    {
        RangeEncoder enc(stream, &fs);
        SyntaxError err;
        std::vector<Stroke> lead_strokes(f.added.begin(), f.added.begin() + std::ptrdiff_t(lead));
        // The lead is coded under format 1.5 (its kinds as a 1.2+ stream codes them).
        StreamShape shape = env.shape;
        shape.version_minor = std::max<uint32_t>(shape.version_minor, kLeadMinorVersion);
        Limits unlimited;
        unlimited.max_curve_points = unlimited.max_polygon_vertices = 0xFFFFFFFFu;
        unlimited.max_polygon_work = unlimited.max_curve_work = ~uint64_t(0);
        if (!code_sets(enc, sets, f.replay.seed, f.replay.random_orientation, f.replay.color_step, f.added.size(), hd,
                       env.shape.templates, *env.renderer, canvas, err, lead ? &lead_strokes : nullptr, &shape, &unlimited,
                       shared))
            return false;
        enc.finish();
    }
    const size_t start = out.size();
    out.insert(out.end(), head.bytes().begin(), head.bytes().end());
    out.insert(out.end(), stream.begin(), stream.end());
    if (stats) stats->add(fs);
    if (split) *split = BodySplit::of(out.size() - start, motion_bytes, uint32_t(f.added.size()), uint32_t(f.removed.size()));
    if (needs_lead_version) *needs_lead_version = lead > 0 || shared;
    return true;
}

Status decode_replay_body(FrameType type, const uint8_t* p, size_t n, const DecodeContext& ctx, Frame& out,
                          BodySplit* split) {
    if (!ctx.header || !ctx.renderer)
        return body_error(ctx, Code::InvalidArgument, "coding 2 needs the stream header and a renderer to decode");
    ByteCursor c(p, n, ctx.offset, ctx.where);
    BodyPrefix pre;
    SPT_TRY(decode_body_prefix(type, c, ctx, out, pre));
    const uint32_t added = pre.added;
    if (added == 0) return c.error(Code::Corrupt, "a coding-2 frame without strokes (such frames use coding 1)");
    if (added > ctx.limits.max_strokes_per_frame)
        return c.error(Code::LimitExceeded, std::to_string(added) + " strokes exceed the stroke limit of " + std::to_string(ctx.limits.max_strokes_per_frame) + " per frame (max_strokes_per_frame)");
    uint64_t seed = 0;
    uint8_t flags = 0;
    SPT_TRY(c.u64(seed, "seed"));
    SPT_TRY(c.u8(flags, "replay flags"));
    if (flags & ~(kRandomOrientation | kLeadStrokes | kOneRegion))
        return c.error(Code::Unsupported, "reserved replay flags " + std::to_string(flags));
    const bool has_lead = (flags & kLeadStrokes) != 0, shared = (flags & kOneRegion) != 0;
    if ((has_lead || shared) && ctx.shape.version_minor < kLeadMinorVersion)
        return c.error(Code::Corrupt, std::string(has_lead ? "lead strokes (coding-2 flags bit 1)" : "one region for every set (coding-2 flags bit 2)") +
                                          " need format 1.5, the file is 1." + std::to_string(ctx.shape.version_minor));
    uint8_t step = 0;
    SPT_TRY(c.u8(step, "colour step"));
    if (step < 1 || step > kMaxColorStep) return c.error(Code::Corrupt, "colour step " + std::to_string(step) + " is not 1..32");
    if (ctx.stats) (*ctx.stats)[Field::Candidates] += 8.0 * 10;
    Canvas canvas;
    if (auto st = start_canvas(out, type, *ctx.header, *ctx.renderer, ctx.base, canvas); !st)
        return body_error(ctx, st.error().code, st.error().message);
    std::vector<ReplaySet> sets(ctx.header->sets.size());
    std::vector<Stroke> lead;
    RangeDecoder dec(c.here(), c.left(), ctx.stats);
    SyntaxError err;
    if (!code_sets(dec, sets, seed, (flags & kRandomOrientation) != 0, step, added, *ctx.header, ctx.shape.templates,
                   *ctx.renderer, canvas, err, has_lead ? &lead : nullptr, &ctx.shape, &ctx.limits, shared))
        return body_error(ctx, err.code, "replayed stroke stream: " + err.msg, c.pos());
    if (!dec.consumed_all()) return body_error(ctx, Code::Corrupt, "stroke stream has bytes after its last value", c.pos());
    out.added = std::move(lead);
    out.added.reserve(added);
    for (auto& s : sets) out.added.insert(out.added.end(), s.strokes.begin(), s.strokes.end());
    out.replay.present = true;
    out.replay.seed = seed;
    out.replay.random_orientation = (flags & kRandomOrientation) != 0;
    out.replay.color_step = step;
    out.replay.regions.clear();
    for (auto& s : sets) out.replay.regions.push_back(std::move(s.region));
    if (split) *split = BodySplit::of(n, pre.motion_bytes, added, pre.removed);
    return {};
}

}  // namespace spt::detail
