// Internal: the coding-1 stroke stream (SPEC.md 7.4), written once for both directions (the
// edit stream is edit_stream.hpp). `C` is RangeEncoder (codes the values it is given) or RangeDecoder (ignores them
// and returns decoded values); every function assigns what it coded back into its output.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "conic_prediction.hpp"
#include "polygon_plan.hpp"
#include "range_coder.hpp"
#include "spt/limits.hpp"
#include "spt/types.hpp"
#include "validate.hpp"

namespace spt::detail {

constexpr int kColorCellShift = 3;  // colour prediction cells are 8x8 pixels

// Position of one axis (SPEC.md 7.4, pos()).
struct PosModel {
    uint16_t inside = kProbInit;
    BitTree pix;
    SIntModel outside;
    uint16_t frac8 = kProbInit;
    uint16_t frac[16];
    void reset(uint32_t extent) {
        inside = frac8 = kProbInit;
        pix.reset(bit_length(extent - 1));
        outside = SIntModel();
        for (auto& q : frac) q = kProbInit;
    }
};

// Contexts and predictors of polygon strokes (format 1.2, SPEC.md 7.4 step 5). Fixed-size, so
// that the encoder can copy them cheaply to measure the bits of each prediction mode.
struct PolygonModels {
    UIntModel points;
    uint16_t same_aa = kProbInit;
    uint16_t aa[32];
    uint16_t shift[8];
    uint16_t conic = kProbInit, second = kProbInit;  // the prediction mode
    SIntModel dx[2], dy[2];                          // modes 0 and 1
    // mode 2, conic
    uint16_t conic_same = kProbInit;
    UIntModel conic_c;                               // 2^30 - C
    SIntModel conic_s;
    uint16_t conic_shift[8];
    SIntModel conic_m[4];                            // a, b, c, d
    SIntModel conic_rx, conic_ry;                    // residuals, in lattice steps
    // predictors
    uint32_t prev_aa = 0;
    int64_t prev_cs[2] = {0, 0};                     // (C, S) of the previous conic polygon
    PolygonModels() {
        for (auto& q : aa) q = kProbInit;
        for (auto& q : shift) q = kProbInit;
        for (auto& q : conic_shift) q = kProbInit;
    }
};

// Every context of the stroke stream and the state it predicts from; reset per frame body.
struct StrokeCoderState {
    StreamShape shape;
    // contexts
    // Indexed by the previous kind. Index 3 (after a polygon) and kind2 only occur in format
    // 1.2 streams, so 1.0/1.1 streams code exactly as before.
    uint16_t kind0[4], kind1[4], kind2[4];
    uint16_t same_set;
    BitTree set_tree;
    std::array<BitTree, 16> tmpl;     // stamp template, by set
    BitTree affine_tmpl;
    uint16_t same_orient[16];
    std::array<BitTree, 16> orient;   // by set
    PosModel pos[4][2];               // [stamp, affine, curve, polygon][x, y]
    Res8Model color[3][4];            // [G, R-G, B-G][class]
    uint16_t opaque;
    BitTree alpha;
    std::array<BitTree, 3> color_lo;  // [G, R, B] low bytes, colour encoding 1 (format 1.3)
    SIntModel matrix[4];
    uint16_t axis_aligned, same_scale, similarity;  // affine matrix form (SPEC.md 7.4)
    BitTree matrix_shift;
    UIntModel points;
    SIntModel width0, dx, dy, dw;
    uint16_t curve_same_aa;           // a curve's grid, format 1.4 with the curve_grid flag
    uint16_t curve_aa[32];
    PolygonModels poly;               // polygons (format 1.2, SPEC.md 7.4 step 5)
    // predictors
    int prev_kind = 0;
    int prev_set = 0;
    int prev_orient[16] = {};
    Rgb8 prev_color{128, 128, 128};
    int64_t prev_width0 = 0;
    uint32_t prev_curve_aa = 0;
    uint32_t grid_w = 0, grid_h = 0;
    std::vector<uint32_t> grid;       // 0 = empty, else 0x01RRGGBB

    explicit StrokeCoderState(const StreamShape& sh) : shape(sh) {
        for (int i = 0; i < 4; ++i) kind0[i] = kind1[i] = kind2[i] = kProbInit;
        same_set = opaque = curve_same_aa = kProbInit;
        for (auto& q : curve_aa) q = kProbInit;
        set_tree.reset(4);
        const int tb = sh.templates ? bit_length(sh.templates - 1) : 0;
        const int ob = sh.orientations ? bit_length(sh.orientations - 1) : 0;
        for (auto& t : tmpl) t.reset(tb);
        affine_tmpl.reset(tb);
        for (auto& q : same_orient) q = kProbInit;
        for (auto& t : orient) t.reset(ob);
        for (auto& g : pos) { g[0].reset(sh.width); g[1].reset(sh.height); }
        alpha.reset(8);
        for (auto& t : color_lo) t.reset(8);
        axis_aligned = same_scale = similarity = kProbInit;
        matrix_shift.reset(3);
        grid_w = (sh.width + 7) >> kColorCellShift;
        grid_h = (sh.height + 7) >> kColorCellShift;
    }

    size_t cell(int32_t x, int32_t y) const {
        const int64_t cx = std::clamp<int64_t>((int64_t(x) >> 4) >> kColorCellShift, 0, int64_t(grid_w) - 1);
        const int64_t cy = std::clamp<int64_t>((int64_t(y) >> 4) >> kColorCellShift, 0, int64_t(grid_h) - 1);
        return size_t(cy) * grid_w + size_t(cx);
    }
    Rgb8 predict(int32_t x, int32_t y) {
        if (grid.empty()) grid.assign(size_t(grid_w) * grid_h, 0);
        const uint32_t g = grid[cell(x, y)];
        if (!g) return prev_color;
        return Rgb8{uint8_t(g >> 16), uint8_t(g >> 8), uint8_t(g)};
    }
    void update(int32_t x, int32_t y, const Rgba8& c) {
        grid[cell(x, y)] = 0x01000000u | (uint32_t(c.r) << 16) | (uint32_t(c.g) << 8) | c.b;
        prev_color = Rgb8{c.r, c.g, c.b};
    }
};

template <class C>
SPT_CODER_INLINE int64_t code_position(C& c, PosModel& m, int32_t v, uint32_t extent, SyntaxError& err) {
    int64_t p = int64_t(v) >> 4;
    uint32_t f = uint32_t(v) & 15;
    const bool outside = c.bit(m.inside, (p >= 0 && p < int64_t(extent)) ? 0 : 1);
    if (!outside) {
        p = code_tree(c, m.pix, uint32_t(p));
        if (p >= int64_t(extent)) err.set("position " + std::to_string(p) + " coded inside is not below " + std::to_string(extent));
    } else {
        p = code_sint(c, m.outside, p);
        if (p >= 0 && p < int64_t(extent)) err.set("position " + std::to_string(p) + " coded outside lies inside the canvas");
    }
    if (!c.bit(m.frac8, f != 8 ? 1 : 0)) {
        f = 8;
    } else {
        f = code_tree(c, m.frac, 4, f);
        if (f == 8) err.set("fraction 8 coded without its flag");
    }
    const int64_t q = p * 16 + int64_t(f);
    if (q < -kMaxCoord || q > kMaxCoord) err.set("position " + std::to_string(q) + " is outside +-2^24");
    return q;
}

template <class C>
SPT_CODER_INLINE void code_color(C& c, StrokeCoderState& st, Rgba8& col, int32_t ax, int32_t ay, int cls, SyntaxError& err) {
    c.set_field(Field::Color);
    const Rgb8 p = st.predict(ax, ay);
    const int pg = p.g, pr = p.r - p.g, pb = p.b - p.g;
    const int g = code_res8(c, st.color[0][cls], wrap8(col.g - pg));
    const int gv = (pg + g) & 255;
    const int r = code_res8(c, st.color[1][cls], wrap8(col.r - gv - pr));
    const int b = code_res8(c, st.color[2][cls], wrap8(col.b - gv - pb));
    if (g > 127 || r > 127 || b > 127) err.set("colour residual +128");
    col.g = uint8_t(gv);
    col.r = uint8_t((gv + pr + r) & 255);
    col.b = uint8_t((gv + pb + b) & 255);
    c.set_field(Field::Alpha);
    if (!c.bit(st.opaque, col.a != 255 ? 1 : 0)) {
        col.a = 255;
    } else {
        col.a = uint8_t(code_tree(c, st.alpha, col.a));
        if (col.a == 255) err.set("alpha 255 coded without its flag");
    }
    if (st.shape.linear) {
        c.set_field(Field::Color);
        col.g_lo = uint8_t(code_tree(c, st.color_lo[0], col.g_lo));
        col.r_lo = uint8_t(code_tree(c, st.color_lo[1], col.r_lo));
        col.b_lo = uint8_t(code_tree(c, st.color_lo[2], col.b_lo));
    } else {
        col.r_lo = col.g_lo = col.b_lo = 0;
    }
    st.update(ax, ay, col);
}

// Affine matrix (SPEC.md 7.4, affine 3): its form (axis-aligned, and then a = d; else a
// similarity, d = a and b = -c), a shift s <= 4 that all coded entries are multiples of 2^s of
// (shape painters place on whole or half pixels), then the free entries >> s. Every form is
// canonical: a decoder rejects a form, or a shift, that the entries would have allowed to be
// smaller.
template <class C>
SPT_CODER_INLINE bool code_affine_matrix(C& c, StrokeCoderState& st, AffineStroke& t, SyntaxError& err) {
    const bool axis = c.bit(st.axis_aligned, (t.b == 0 && t.c == 0) ? 1 : 0);
    bool iso = false, sim = false;
    if (axis) iso = c.bit(st.same_scale, t.a == t.d ? 1 : 0);
    else sim = c.bit(st.similarity, (t.d == t.a && t.b == -t.c) ? 1 : 0);
    // The coded entries, by index into (a, b, c, d).
    int idx[4];
    int n = 0;
    if (axis) { idx[n++] = 0; if (!iso) idx[n++] = 3; }
    else if (sim) { idx[n++] = 0; idx[n++] = 2; }
    else { idx[0] = 0; idx[1] = 1; idx[2] = 2; idx[3] = 3; n = 4; }
    int32_t* m[4] = {&t.a, &t.b, &t.c, &t.d};
    uint32_t shift = 4;
    if constexpr (!C::kDecoding) {
        for (int k = 0; k < n; ++k)
            while (shift > 0 && (*m[idx[k]] & ((1 << shift) - 1)) != 0) --shift;
    }
    shift = code_tree(c, st.matrix_shift, shift);
    if (shift > 4) { err.set("affine matrix shift " + std::to_string(shift) + " is reserved"); return false; }
    bool could_shift_more = shift < 4;  // every entry a multiple of 2^(shift+1): not canonical
    for (int k = 0; k < n; ++k) {
        const int64_t v = code_sint(c, st.matrix[idx[k]], int64_t(*m[idx[k]]) >> shift);
        if (v < -(kMaxMatrix >> shift) || v > (kMaxMatrix >> shift)) { err.set("affine matrix entry outside +-2^16"); return false; }
        *m[idx[k]] = int32_t(v * (int64_t(1) << shift));
        if (v & 1) could_shift_more = false;
    }
    if (could_shift_more) { err.set("affine matrix shift is not the largest"); return false; }
    if (axis) { t.b = t.c = 0; if (iso) t.d = t.a; else if (t.a == t.d) { err.set("affine matrix form: a = d coded in full"); return false; } }
    else if (sim) {
        if (t.c == 0) { err.set("affine matrix form: an axis-aligned matrix coded as a similarity"); return false; }
        t.d = t.a;
        t.b = -t.c;
    }
    else if ((t.b == 0 && t.c == 0) || (t.d == t.a && t.b == -t.c)) { err.set("affine matrix form: a special form coded in full"); return false; }
    if (int64_t(t.a) * t.d - int64_t(t.b) * t.c == 0) { err.set("affine matrix is singular"); return false; }
    return true;
}

// Conic outline (SPEC.md 7.4, polygon 5, mode 2): the rotation (C, S) unless it repeats the
// previous conic polygon's, the matrix M with its shift, then per vertex the residual against
// P_0 + M (unit_i - unit_0) in lattice steps. The encoder codes `plan`; the decoder fills `pts`.
template <class C>
SPT_CODER_INLINE bool code_conic_outline(C& c, PolygonModels& pm, const PolygonPlan& plan, uint32_t shift,
                                         std::vector<PolygonVertex>& pts, SyntaxError& err) {
    int64_t rc = pm.prev_cs[0], rs = pm.prev_cs[1];
    if (c.bit(pm.conic_same, (plan.cs[0] != rc || plan.cs[1] != rs) ? 1 : 0)) {
        const uint64_t dc = code_uint(c, pm.conic_c, uint64_t(kConicOne - plan.cs[0]));
        if (dc > uint64_t(2 * kConicMaxCS)) { err.set("conic rotation C below -2^30"); return false; }
        const int64_t nc = kConicOne - int64_t(dc);
        const int64_t ns = code_sint(c, pm.conic_s, plan.cs[1]);
        if (ns < -kConicMaxCS || ns > kConicMaxCS) { err.set("conic rotation S outside +-2^30"); return false; }
        if (nc == rc && ns == rs) { err.set("conic rotation coded anew repeats the previous one"); return false; }
        rc = pm.prev_cs[0] = nc;
        rs = pm.prev_cs[1] = ns;
    }
    const uint32_t t = code_tree(c, pm.conic_shift, 3, plan.matrix_shift);
    if (t > 4) { err.set("conic matrix shift " + std::to_string(t) + " is reserved"); return false; }
    bool could_shift_more = t < 4;
    int64_t m[4];
    for (int k = 0; k < 4; ++k) {
        const int64_t v = code_sint(c, pm.conic_m[k], plan.m[k] >> t);
        if (v < -(kConicMaxMatrix >> t) || v > (kConicMaxMatrix >> t)) { err.set("conic matrix entry outside +-2^26"); return false; }
        if (v & 1) could_shift_more = false;
        m[k] = v * (int64_t(1) << t);
    }
    if (could_shift_more) { err.set("conic matrix shift is not the largest"); return false; }
    const int64_t x0 = pts[0].x, y0 = pts[0].y;
    bool lattice_more = shift < 4;  // every offset a multiple of 2^(shift+1): not canonical
    int64_t u = kConicOne, v = 0;
    for (size_t i = 1; i < pts.size(); ++i) {
        conic_rotate(rc, rs, u, v);
        const int64_t du = u - kConicOne;
        const int64_t pe = conic_steps(m[0], m[1], du, v, shift), pf = conic_steps(m[2], m[3], du, v, shift);
        const int64_t ex = C::kDecoding ? 0 : (int64_t(pts[i].x) - x0) >> shift;
        const int64_t ey = C::kDecoding ? 0 : (int64_t(pts[i].y) - y0) >> shift;
        const int64_t e = pe + code_sint(c, pm.conic_rx, ex - pe);
        const int64_t f = pf + code_sint(c, pm.conic_ry, ey - pf);
        if ((e | f) & 1) lattice_more = false;
        const int64_t x = x0 + e * (int64_t(1) << shift), y = y0 + f * (int64_t(1) << shift);
        if (x < -kMaxCoord || x > kMaxCoord || y < -kMaxCoord || y > kMaxCoord) { err.set("polygon vertex outside +-2^24"); return false; }
        if constexpr (C::kDecoding) { pts[i].x = int32_t(x); pts[i].y = int32_t(y); }
    }
    if (lattice_more) { err.set("polygon shift is not the largest"); return false; }
    return true;
}

// A polygon's outline after its first vertex (SPEC.md 7.4, polygon 5): the lattice shift, the
// prediction mode, then the vertices. Modes 0 and 1 code the differences between consecutive
// vertices predicted as zero or as the previous difference; mode 2 is the conic prediction.
template <class C>
SPT_CODER_INLINE bool code_polygon_outline(C& c, PolygonModels& pm, const PolygonPlan& plan,
                                           std::vector<PolygonVertex>& pts, SyntaxError& err) {
    const uint32_t shift = code_tree(c, pm.shift, 3, plan.shift);
    if (shift > 4) { err.set("polygon shift " + std::to_string(shift) + " is reserved"); return false; }
    if (c.bit(pm.conic, plan.mode == 2 ? 1 : 0)) return code_conic_outline(c, pm, plan, shift, pts, err);
    const int mode = c.bit(pm.second, plan.mode == 1 ? 1 : 0);
    bool lattice_more = shift < 4;
    int64_t px = 0, py = 0;  // previous difference, in units of 2^shift
    for (size_t i = 1; i < pts.size(); ++i) {
        const auto& a = pts[i - 1];
        const int64_t ex = C::kDecoding ? 0 : (int64_t(pts[i].x) - a.x) >> shift;
        const int64_t ey = C::kDecoding ? 0 : (int64_t(pts[i].y) - a.y) >> shift;
        const int64_t qx = mode ? px : 0, qy = mode ? py : 0;
        const int64_t vx = qx + code_sint(c, pm.dx[mode], ex - qx);
        const int64_t vy = qy + code_sint(c, pm.dy[mode], ey - qy);
        if ((vx | vy) & 1) lattice_more = false;
        const int64_t x = a.x + vx * (int64_t(1) << shift), y = a.y + vy * (int64_t(1) << shift);
        if (x < -kMaxCoord || x > kMaxCoord || y < -kMaxCoord || y > kMaxCoord) { err.set("polygon vertex outside +-2^24"); return false; }
        if constexpr (C::kDecoding) { pts[i].x = int32_t(x); pts[i].y = int32_t(y); }
        px = vx; py = vy;
    }
    if (lattice_more) { err.set("polygon shift is not the largest"); return false; }
    return true;
}

// A polygon's or a curve's supersampling grid (SPEC.md 7.4): the same as `prev` (one flag), or a
// 5-bit tree that MUST differ from it and be 0 or 2..16; `prev` becomes the grid.
template <class C>
SPT_CODER_INLINE bool code_grid(C& c, uint16_t& same, uint16_t* tree, uint32_t& prev, uint8_t& grid, const char* kind,
                                SyntaxError& err) {
    uint32_t g = prev;
    if (c.bit(same, grid != prev ? 1 : 0)) {
        g = code_tree(c, tree, 5, grid);
        if (g == prev || g == 1 || g > 16) { err.set(std::string(kind) + " supersampling " + std::to_string(g) + " is invalid"); return false; }
    }
    grid = uint8_t(g);
    prev = g;
    return true;
}

// Polygon stroke geometry (SPEC.md 7.4, polygon 5): vertex count, supersampling, first vertex,
// then the outline.
template <class C>
SPT_CODER_INLINE bool code_polygon(C& c, StrokeCoderState& st, PolygonStroke& pg, const Limits& lim, SyntaxError& err) {
    const StreamShape& sh = st.shape;
    PolygonModels& pm = st.poly;
    c.set_field(Field::Geometry);
    const uint64_t n = code_uint(c, pm.points, pg.points.size() >= 3 ? pg.points.size() - 3 : 0) + 3;
    if (n > lim.max_polygon_vertices) { err.set("polygon of " + std::to_string(n) + " vertices exceeds the limit"); return false; }
    if (!code_grid(c, pm.same_aa, pm.aa, pm.prev_aa, pg.supersample, "polygon", err)) return false;
    pg.points.resize(size_t(n));  // the encoder's size already; the decoder's new
    auto& p0 = pg.points[0];
    c.set_field(Field::Position);
    p0.x = int32_t(code_position(c, st.pos[3][0], p0.x, sh.width, err));
    p0.y = int32_t(code_position(c, st.pos[3][1], p0.y, sh.height, err));
    if (err.bad) return false;
    c.set_field(Field::Geometry);
    PolygonPlan plan;
    if constexpr (!C::kDecoding) plan = plan_polygon(pm, pg.points);
    return code_polygon_outline(c, pm, plan, pg.points, err);
}

// One stroke (SPEC.md 7.4.2). Returns false and fills `err` on an invalid coded value.
template <class C>
SPT_CODER_INLINE bool code_stroke(C& c, StrokeCoderState& st, Stroke& s, const Limits& lim, SyntaxError& err) {
    const StreamShape& sh = st.shape;
    c.set_field(Field::Kind);
    int kind = 0;
    if (c.bit(st.kind0[st.prev_kind], s.kind != StrokeKind::Stamp ? 1 : 0)) {
        kind = c.bit(st.kind1[st.prev_kind], s.kind == StrokeKind::Curve || s.kind == StrokeKind::Polygon ? 1 : 0) ? 2 : 1;
        if (kind == 2 && sh.has_polygons()) kind = c.bit(st.kind2[st.prev_kind], s.kind == StrokeKind::Polygon ? 1 : 0) ? 3 : 2;
    }
    st.prev_kind = kind;
    s.kind = StrokeKind(kind);

    if (kind == 3) {
        auto& pg = s.polygon;
        if (!code_polygon(c, st, pg, lim, err)) return false;
        code_color(c, st, pg.color, pg.points[0].x, pg.points[0].y, 0, err);
        return !err.bad;
    }

    if (kind == 0) {
        auto& t = s.stamp;
        c.set_field(Field::SetTemplate);
        int set = st.prev_set;
        if (sh.sets > 1 && c.bit(st.same_set, t.set != st.prev_set ? 1 : 0)) {
            set = int(code_tree(c, st.set_tree, t.set));
            if (set == st.prev_set || uint32_t(set) >= sh.sets) {
                err.set("stamp set " + std::to_string(set) + " is invalid");
                return false;
            }
        }
        t.set = uint8_t(set);
        st.prev_set = set;
        if (sh.templates == 0) { err.set("stamp stroke in a file without templates"); return false; }
        t.tmpl = uint8_t(code_tree(c, st.tmpl[set], t.tmpl));
        if (t.tmpl >= sh.templates) { err.set("template " + std::to_string(t.tmpl) + " is not below the template count"); return false; }
        c.set_field(Field::Orientation);
        int o = st.prev_orient[set];
        if (sh.orientations > 1 && c.bit(st.same_orient[set], t.orient != o ? 1 : 0)) {
            const int v = int(code_tree(c, st.orient[set], t.orient));
            if (v == o || uint32_t(v) >= sh.orientations) { err.set("orientation " + std::to_string(v) + " is invalid"); return false; }
            o = v;
        }
        t.orient = uint8_t(o);
        st.prev_orient[set] = o;
        c.set_field(Field::Position);
        t.x = int32_t(code_position(c, st.pos[0][0], t.x, sh.width, err));
        t.y = int32_t(code_position(c, st.pos[0][1], t.y, sh.height, err));
        if (err.bad) return false;
        code_color(c, st, t.color, t.x, t.y, std::min(set, 3), err);
        return !err.bad;
    }
    if (kind == 1) {
        auto& t = s.affine;
        c.set_field(Field::SetTemplate);
        if (sh.templates == 0) { err.set("affine stroke in a file without templates"); return false; }
        t.tmpl = uint8_t(code_tree(c, st.affine_tmpl, t.tmpl));
        if (t.tmpl >= sh.templates) { err.set("template " + std::to_string(t.tmpl) + " is not below the template count"); return false; }
        c.set_field(Field::Position);
        t.tx = int32_t(code_position(c, st.pos[1][0], t.tx, sh.width, err));
        t.ty = int32_t(code_position(c, st.pos[1][1], t.ty, sh.height, err));
        if (err.bad) return false;
        c.set_field(Field::Geometry);
        if (!code_affine_matrix(c, st, t, err)) return false;
        code_color(c, st, t.color, t.tx, t.ty, 0, err);
        return !err.bad;
    }
    auto& cv = s.curve;
    c.set_field(Field::Geometry);
    const uint64_t n = code_uint(c, st.points, cv.points.empty() ? 0 : cv.points.size() - 1) + 1;
    if (n > lim.max_curve_points) { err.set("curve of " + std::to_string(n) + " points exceeds the limit"); return false; }
    if (sh.curve_grid) {  // format 1.4 (SPEC.md 7.4 step 4)
        if (!code_grid(c, st.curve_same_aa, st.curve_aa, st.prev_curve_aa, cv.supersample, "curve", err)) return false;
    } else {
        cv.supersample = 0;
    }
    cv.points.resize(size_t(n));  // the encoder's size already; the decoder's new
    auto& p0 = cv.points[0];
    c.set_field(Field::Position);
    p0.x = int32_t(code_position(c, st.pos[2][0], p0.x, sh.width, err));
    p0.y = int32_t(code_position(c, st.pos[2][1], p0.y, sh.height, err));
    if (err.bad) return false;
    c.set_field(Field::Geometry);
    const int64_t w0 = code_sint(c, st.width0, int64_t(p0.width) - st.prev_width0) + st.prev_width0;
    if (w0 < 0 || w0 > kMaxWidthQ4) { err.set("curve width outside 0..2^16"); return false; }
    p0.width = uint32_t(w0);
    st.prev_width0 = w0;
    for (size_t i = 1; i < cv.points.size(); ++i) {
        const auto& a = cv.points[i - 1];
        auto& b = cv.points[i];
        const int64_t x = a.x + code_sint(c, st.dx, int64_t(b.x) - a.x);
        const int64_t y = a.y + code_sint(c, st.dy, int64_t(b.y) - a.y);
        const int64_t w = int64_t(a.width) + code_sint(c, st.dw, int64_t(b.width) - int64_t(a.width));
        if (x < -kMaxCoord || x > kMaxCoord || y < -kMaxCoord || y > kMaxCoord) { err.set("curve point outside +-2^24"); return false; }
        if (w < 0 || w > kMaxWidthQ4) { err.set("curve width outside 0..2^16"); return false; }
        b.x = int32_t(x); b.y = int32_t(y); b.width = uint32_t(w);
    }
    code_color(c, st, cv.color, p0.x, p0.y, 0, err);
    return !err.bad;
}

}  // namespace spt::detail
