// Internal: the coding-2 stroke stream (SPEC.md 7.7.3-7.7.5), written once for both directions
// like stroke_stream.hpp. The caller keeps the canvas; every stroke is drawn on it as soon as it
// is coded, so encoder and decoder predict from the same pixels.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "canvas_prediction.hpp"
#include "range_coder.hpp"
#include "stroke_stream.hpp"
#include "spt/render.hpp"
#include "spt/replay.hpp"

namespace spt::detail {

constexpr uint64_t kMaxReplayCounter = uint64_t(1) << 48;  // candidate numbers stay below this

struct ReplayCoderState {
    uint16_t use_rects = kProbInit, use_blocks = kProbInit;
    UIntModel rect_count, rect_xy, rect_wh, block_size;
    uint16_t mask[4];
    UIntModel count;
    UIntModel lead_count;                               // format 1.5: strokes coded as in coding 1
    std::array<std::array<UIntModel, 6>, 4> gap;        // [set class][previous gap class]
    std::array<std::array<BitTree, 4>, 4> orient;       // [set class][edge strength]
    Res8Model color[3][4][4];                           // [G, R-G, B-G][set class][activity]
    FootprintTable footprints;                          // colour predictions' stamp coverage
    ReplayCoderState(uint32_t orientations, const Renderer& renderer) : footprints(renderer) {
        for (auto& m : mask) m = kProbInit;
        const int ob = orientations ? bit_length(orientations - 1) : 0;
        for (auto& row : orient)
            for (auto& t : row) t.reset(ob);
    }
};

// What one set codes: its region and its accepted candidates (encoder: given; decoder: filled).
struct ReplaySet {
    ReplayRegion region;
    std::vector<uint64_t> counters;   // accepted candidate numbers, increasing
    std::vector<Stroke> strokes;      // the stamps, in the same order
};

inline int gap_class(uint64_t gap) { return std::min(5, bit_length(gap)); }

template <class C>
bool code_region(C& c, ReplayCoderState& st, ReplayRegion& r, uint32_t W, uint32_t H, SyntaxError& err) {
    r.use_rects = c.bit(st.use_rects, r.use_rects ? 1 : 0) != 0;
    if (r.use_rects) {
        const uint64_t n = code_uint(c, st.rect_count, r.rects.empty() ? 0 : r.rects.size() - 1) + 1;
        if (n > 4096) { err.set(std::to_string(n) + " candidate rectangles, at most 4096"); return false; }
        r.rects.resize(size_t(n));
        for (auto& q : r.rects) {
            const uint64_t x = code_uint(c, st.rect_xy, q.x), y = code_uint(c, st.rect_xy, q.y);
            const uint64_t w = code_uint(c, st.rect_wh, q.w - 1) + 1, h = code_uint(c, st.rect_wh, q.h - 1) + 1;
            if (x >= W || y >= H || w > W - x || h > H - y) { err.set("candidate rectangle leaves the canvas"); return false; }
            q = {uint32_t(x), uint32_t(y), uint32_t(w), uint32_t(h)};
        }
    }
    r.use_blocks = c.bit(st.use_blocks, r.use_blocks ? 1 : 0) != 0;
    if (r.use_blocks) {
        const uint64_t b = code_uint(c, st.block_size, r.block_size - 8u) + 8;
        if (b > 256) { err.set("candidate block size " + std::to_string(b) + " is not 8..256"); return false; }
        r.block_size = uint16_t(b);
        const uint32_t cols = blocks_for(W, r.block_size), rows = blocks_for(H, r.block_size);
        if constexpr (C::kDecoding) r.blocks.assign(size_t(cols) * rows, 0);
        for (uint32_t y = 0; y < rows; ++y)
            for (uint32_t x = 0; x < cols; ++x) {
                const int left = x ? r.blocks[size_t(y) * cols + x - 1] : 0;
                const int up = y ? r.blocks[size_t(y - 1) * cols + x] : 0;
                uint8_t& v = r.blocks[size_t(y) * cols + x];
                v = uint8_t(c.bit(st.mask[left + 2 * up], v));
            }
    }
    return true;
}

// One set's accepted candidates: the count, then per stroke the gap since the previous accepted
// candidate, the orientation when it is not drawn, the colour. Draws every stroke on `canvas`.
template <class C>
bool code_replay_set(C& c, ReplayCoderState& st, ReplaySet& set, uint32_t s, uint64_t seed, bool random_orient,
                     int step, uint64_t max_strokes, const Header& hd, uint32_t templates, const Renderer& renderer,
                     Canvas& canvas, SyntaxError& err) {
    c.set_field(Field::Candidates);
    const uint64_t k = code_uint(c, st.count, set.counters.size());
    if (k > max_strokes) { err.set("set " + std::to_string(s) + " claims " + std::to_string(k) + " strokes, more than the frame's"); return false; }
    if (k == 0) return true;
    const replay::CandidateDomain domain(hd.width, hd.height, set.region);
    if (domain.size() == 0) { err.set("set " + std::to_string(s) + " has strokes but an empty candidate region"); return false; }
    if (templates == 0) { err.set("stamp strokes in a file without templates"); return false; }
    const int q = int(std::min<uint32_t>(s, 3));
    const uint32_t N = uint32_t(hd.orientations.size());
    if constexpr (C::kDecoding) {
        set.counters.clear();
        set.strokes.clear();
        // A count is only a claim until its strokes decode: reserve a bounded amount.
        set.counters.reserve(size_t(std::min<uint64_t>(k, 1u << 16)));
        set.strokes.reserve(size_t(std::min<uint64_t>(k, 1u << 16)));
    }
    int64_t prev = -1;
    uint64_t prev_gap = 0;
    for (uint64_t i = 0; i < k; ++i) {
        c.set_field(Field::Candidates);
        const uint64_t given_gap = C::kDecoding ? 0 : set.counters[i] - uint64_t(prev + 1);
        const uint64_t gap = code_uint(c, st.gap[q][gap_class(prev_gap)], given_gap);
        const uint64_t n = uint64_t(prev + 1) + gap;
        if (n >= kMaxReplayCounter) { err.set("candidate number passes 2^48"); return false; }
        prev = int64_t(n);
        prev_gap = gap;
        const replay::Candidate cand = replay::candidate(seed, s, n, domain, templates, N);
        StampStroke t;
        if constexpr (!C::kDecoding) t = set.strokes[i].stamp;
        t.set = uint8_t(s);
        t.tmpl = cand.tmpl;
        t.x = int32_t(cand.x) * 16 + 8;
        t.y = int32_t(cand.y) * 16 + 8;
        if (random_orient) {
            t.orient = cand.orient;
        } else {
            c.set_field(Field::Orientation);
            const OrientGuess g = gradient_orientation(canvas, cand.x, cand.y, hd.orientations);
            const uint32_t d = code_tree(c, st.orient[q][g.strength], (t.orient + N - g.orient) % N);
            if (d >= N) { err.set("orientation residual " + std::to_string(d) + " is not below the table size"); return false; }
            t.orient = uint8_t((g.orient + d) % N);
        }
        c.set_field(Field::Color);
        const FootprintMean m = footprint_mean(canvas, st.footprints.get(t.set, t.tmpl, t.orient), int32_t(cand.x), int32_t(cand.y));
        const Rgb8 p = m.covered ? m.mean : hd.background;
        // Residuals on the colour lattice of step q around the prediction: G, then R and B
        // predicted from G plus the prediction's R-G and B-G (SPEC.md 7.7.5).
        Res8Model* ctx[3] = {&st.color[0][q][m.activity], &st.color[1][q][m.activity], &st.color[2][q][m.activity]};
        const int pg = p.g;
        const int vg = int(code_res8(c, *ctx[0], (int(t.color.g) - pg) / step));
        const int gv = pg + step * vg;
        const int pr = std::clamp(gv + int(p.r) - int(p.g), 0, 255), pb = std::clamp(gv + int(p.b) - int(p.g), 0, 255);
        const int vr = int(code_res8(c, *ctx[1], (int(t.color.r) - pr) / step));
        const int vb = int(code_res8(c, *ctx[2], (int(t.color.b) - pb) / step));
        const int rv = pr + step * vr, bv = pb + step * vb;
        if constexpr (!C::kDecoding) {
            if (gv != t.color.g || rv != t.color.r || bv != t.color.b || t.color.a != 255) {
                err.set("colour is not on the lattice of step " + std::to_string(step));
                return false;
            }
        }
        if (gv < 0 || gv > 255 || rv < 0 || rv > 255 || bv < 0 || bv > 255) { err.set("colour outside 0..255"); return false; }
        t.color = Rgba8{uint8_t(rv), uint8_t(gv), uint8_t(bv), 255};
        const Stroke stroke = Stroke::make_stamp(t);
        if (auto ds = renderer.draw(canvas, stroke); !ds) { err.set(ds.error().message); return false; }
        if constexpr (C::kDecoding) {
            set.counters.push_back(n);
            set.strokes.push_back(stroke);
        }
    }
    return true;
}

}  // namespace spt::detail
