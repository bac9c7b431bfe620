// Internal to libspt: the integer rasterisation rules of SPEC.md section 8 (draft text in
// format/SPEC.md section 8). Every function here is exact integer arithmetic; the
// comments name the spec paragraph each one implements.
#pragma once

#include <cstdint>
#include <vector>

#include "spt/types.hpp"

namespace spt::raster {

// Template coordinates are Q16: 65536 = 1.0 (SPEC 8.3).
constexpr int64_t kOne = 65536;

// Largest canvas side the renderer accepts: Q4 pixel centres stay below 2^24, which keeps
// every product of section 8 inside int64 (SPEC 8.1).
constexpr uint32_t kMaxCanvasSide = 1u << 20;

// floor(n / d) for d > 0 (C++ '/' truncates toward zero).
inline int64_t floor_div(int64_t n, int64_t d) {
    int64_t q = n / d;
    if ((n % d != 0) && ((n < 0) != (d < 0))) --q;
    return q;
}

// x / 255 for 0 <= x <= 65152 (= 255*255 + 127) without a division. Exact on that range;
// tests/format/render_math_test.cpp checks every input.
inline uint32_t div255(uint32_t x) { return (x + 1u + (x >> 8)) >> 8; }

// alpha = (coverage * A + 127) / 255 (SPEC 8.6).
inline uint32_t stroke_alpha(uint32_t coverage, uint32_t a) { return div255(coverage * a + 127u); }

// Coverage 0..255 of template `t` at template point (U, V), Q16 (SPEC 8.4).
uint8_t template_coverage(const Template& t, int64_t U, int64_t V);

// A linear function of the pixel position divided by a positive denominator:
//   value(x, y) = floor((ax * x + ay * y + c) / den)
// Stamps and affine strokes both map pixel centres back to template space this way.
struct LinearMap {
    int64_t ax = 0, ay = 0, c = 0, den = 1;
    int64_t at(int64_t x, int64_t y) const { return floor_div(ax * x + ay * y + c, den); }
};

// Walks value(x, y), value(x+1, y), ... exactly without dividing per pixel: keeps
// numerator = q * den + r with 0 <= r < den.
class LinearWalker {
public:
    LinearWalker(const LinearMap& m, int64_t x, int64_t y) : den_(m.den) {
        const int64_t n = m.ax * x + m.ay * y + m.c;
        q_ = floor_div(n, den_);
        r_ = n - q_ * den_;
        step_q_ = floor_div(m.ax, den_);
        step_r_ = m.ax - step_q_ * den_;
    }
    int64_t value() const { return q_; }
    void next() {
        q_ += step_q_;
        r_ += step_r_;
        if (r_ >= den_) { r_ -= den_; ++q_; }
    }
private:
    int64_t den_, q_, r_, step_q_, step_r_;
};

// The inverse map of one stamp or affine stroke and the pixel box it is evaluated on.
struct InverseMap {
    LinearMap u, v;                    // pixel (x, y) -> template (U, V), Q16
    int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // inclusive pixel box; empty when x1 < x0
    uint32_t aa = 1;  // samples per axis and pixel (SPEC 8.2): 1 = the pixel centre only
};

// SPEC 8.3: stamp of set size (w, h) at orientation (cos, sin) Q14, centred on pixel (0, 0).
// `supersample` is the template's TMPL value (0 or 2..16, SPEC 3.2).
InverseMap stamp_inverse(uint32_t w, uint32_t h, Orientation o, uint8_t supersample = 0);
// SPEC 8.2: affine stroke; returns false for a singular matrix (draws nothing). A supersampled
// template widens the evaluation box by half a pixel.
bool affine_inverse(const AffineStroke& s, InverseMap& out, uint8_t supersample = 0);

// Coverage of the map over the pixel rows [y0, y1] and columns [x0, x1] (already clipped by
// the caller to a sub-box of m's box): row-major into `out` (size (x1-x0+1)*(y1-y0+1)).
void rasterize_map(const InverseMap& m, const Template& t, int64_t x0, int64_t y0, int64_t x1,
                   int64_t y1, uint8_t* out);
// The columns of row y where |U| <= 65536 and |V| <= 65536, intersected with [x0, x1]: every
// template kind has coverage 0 outside that square (SPEC 8.4), so only these columns need
// evaluating. Exact (solves the floor divisions for x); false when the range is empty.
bool map_row_range(const InverseMap& m, int64_t y, int64_t& x0, int64_t& x1);
// One row of rasterize_map restricted to [x0, x1] (inside map_row_range), with the template
// kind dispatched once per row instead of per pixel.
void rasterize_map_row(const InverseMap& m, const Template& t, int64_t y, int64_t x0, int64_t x1,
                       uint8_t* out);
// The inverse map of a stamp whose centre pixel is (cx, cy), in canvas coordinates.
InverseMap stamp_inverse_at(uint32_t w, uint32_t h, Orientation o, int64_t cx, int64_t cy, uint8_t supersample = 0);

// SPEC 8.5: coverage of a curve over the pixel box [x0, x1] x [y0, y1], row-major
// into `out` (zeroed by the callee). Pixels of the box outside the curve get 0.
void rasterize_curve(const CurveStroke& s, int64_t x0, int64_t y0, int64_t x1, int64_t y1,
                     uint8_t* out);
// The same for a curve with a grid (supersample >= 2): coverage (255 k + g^2/2) / g^2 of the k
// of its g x g samples that some segment covers (format 1.4). raster_curve_aa.cpp.
void rasterize_curve_aa(const CurveStroke& s, int64_t x0, int64_t y0, int64_t x1, int64_t y1,
                        uint8_t* out);
// Conservative pixel box of a curve (every covered pixel is inside it).
void curve_box(const CurveStroke& s, int64_t& x0, int64_t& y0, int64_t& x1, int64_t& y1);

// A coverage mask stored as one span of non-zero columns per row, three bytes a pixel (one
// per channel), every span followed by kSpanPad zero bytes so that a short span may be
// blended with one vector that runs past its end (where coverage 0 leaves pixels
// unchanged). Stamp footprints are kept this way: no zero runs at row ends are stored or
// visited.
constexpr uint32_t kSpanPad = 32;
struct SpanRow {
    int32_t lo = 0;    // first column of the span, relative to SpanMask::x0
    uint32_t n = 0;    // pixels; 0: empty row
    uint32_t off = 0;  // byte offset of the span's coverage in SpanMask::cov3
};
// Narrow masks (w <= kDenseMaxSteps * 64 / 3 pixels) are also kept as a dense box: every row
// the same number of 64-byte steps of three-byte coverage, zero outside the spans, so that a
// stroke whose box fits a tile buffer with its apron is blended one full step a row with no
// span bookkeeping (blend_dense). Most painter strokes are this small; per-row work, not
// per-pixel work, is what their spans cost. Each step is stored as 128 bytes of (c, 255 - c)
// pairs in the lane order of the kernel (raster_span.cpp: span_mask_make_dense).
constexpr uint32_t kDenseStep = 64, kDenseMaxSteps = 2;
struct SpanMask {
    int32_t x0 = 0, y0 = 0;     // offset of column 0 / row 0 (from the stamp's centre pixel)
    uint32_t w = 0;             // columns: every span lies in [0, w)
    std::vector<SpanRow> rows;  // row j is y0 + j
    std::vector<uint8_t> cov3;
    uint32_t dense_steps = 0;    // 64-byte steps a dense row; 0: no dense box
    std::vector<uint8_t> dense;  // rows.size() rows of dense_steps * 128 bytes
    // For occlusion culling in whole-frame rendering (raster_cull.hpp):
    // the opaque core, where a stroke of alpha 255 leaves exactly its colour whatever lay below
    // (SPEC 8.6): bit i of core[k * rows.size() + j] is set when column 64 * k + i of row j has
    // coverage 255 (word-column-major, so that one word of consecutive rows is contiguous);
    uint32_t core_words = 0;     // (w + 63) / 64
    std::vector<uint64_t> core;  // core_words * rows.size()
    // and each row's span as lo | (lo + n) << 16 (w < 65536 for masks that keep a core);
    std::vector<uint32_t> extent;
    // for masks of one core word a row (w <= 64), the footprint: bit i of foot[j] is set when
    // column i of row j has coverage above 0.
    std::vector<uint64_t> foot;
    // SPEC 10's fill work of a stamp with this footprint before its box is clipped to the
    // canvas (evaluation box pixels x template samples): a bound of any such stamp's work.
    uint64_t box_work = 0;
    size_t bytes() const {
        return rows.size() * sizeof(SpanRow) + cov3.size() + dense.size() +
               (core.size() + foot.size()) * sizeof(uint64_t) + extent.size() * sizeof(uint32_t);
    }
};
// Fills m.core, m.extent and m.foot from m's spans (after its rows and w are final); leaves
// them empty when w >= 65536 (foot: when w > 64).
void span_mask_make_core(SpanMask& m);
// Fills m.dense from m's spans when m is narrow enough (after its rows and w are final).
void span_mask_make_dense(SpanMask& m);
// Appends one row to a SpanMask from one byte of coverage a pixel (n pixels, column 0 at
// mask column `first`): trims zero ends, stores the span with its padding.
void span_mask_add_row(SpanMask& m, const uint8_t* cov, int64_t n, int64_t first);

// The colour the 8-bit kernels blend: an encoding-0 stroke colour without the low bytes of
// encoding 1 (those canvases are drawn by render_deep.cpp), so that a TileItem stays 16 bytes.
struct Rgba4 {
    uint8_t r = 0, g = 0, b = 0, a = 255;
    Rgba4() = default;
    Rgba4(const Rgba8& c) : r(c.r), g(c.g), b(c.b), a(c.a) {}  // NOLINT: implicit by design
};

// Where spans are composited: canvas pixels [x0, x1) x [y0, y1) stored at px (pixel (x0, y0))
// with `stride` bytes a row. `slack`: every row has kSpanPad writable bytes past column x1
// that nobody else reads (a tile buffer), which lets short spans run past their end; without
// it (a caller's canvas, possibly shared by threads drawing disjoint regions) nothing outside
// the written spans is touched.
struct BlendTarget {
    uint8_t* px = nullptr;
    size_t stride = 0;
    int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool slack = false;
};
// A SpanMask placed on the canvas for one stroke, as the span kernels take it (whole-frame
// rendering builds one from a TileItem and its MaskRef, placed()).
struct PlacedSpans {
    const SpanRow* rows = nullptr;
    const uint8_t* cov3 = nullptr;
    const uint8_t* dense = nullptr;    // the mask's dense box, if it has one
    const uint64_t* core = nullptr;    // the mask's opaque core (SpanMask::core), or nullptr
    const uint32_t* extent = nullptr;  // SpanMask::extent
    int32_t ox = 0, oy = 0;  // canvas position of column 0 / row 0
    uint32_t h = 0;          // rows
    Rgba4 c;
    uint32_t dense_steps = 0;
    uint32_t core_words = 0;
};
// Whole-frame rendering keeps what it needs of each distinct footprint of a frame once, in a
// small table that stays in cache (MaskRef), and lists the strokes of every tile as 16-byte
// TileItems that refer to it: the per-tile lists are written once and read twice per frame.
struct MaskRef {
    const SpanRow* rows = nullptr;
    const uint8_t* cov3 = nullptr;
    const uint8_t* dense = nullptr;    // SpanMask::dense, or nullptr
    const uint64_t* core = nullptr;    // SpanMask::core, or nullptr (then extent is too)
    const uint32_t* extent = nullptr;  // SpanMask::extent, or nullptr
    const uint64_t* foot = nullptr;    // SpanMask::foot, or nullptr
    uint32_t h = 0, dense_steps = 0, core_words = 0;
};
struct TileItem {
    static constexpr uint32_t kNoMask = ~0u;
    int32_t ox = 0, oy = 0;  // canvas position of the mask's column 0 / row 0
    uint32_t mask = 0;       // index into the frame's MaskRef table; kNoMask: the stroke whose
                             // index is ox is drawn from its own geometry
    Rgba4 c;
};
static_assert(sizeof(TileItem) == 16);
inline PlacedSpans placed(const TileItem& it, const MaskRef& m) {
    PlacedSpans p;
    p.rows = m.rows;
    p.cov3 = m.cov3;
    p.dense = m.dense;
    p.core = m.core;
    p.extent = m.extent;
    p.ox = it.ox;
    p.oy = it.oy;
    p.h = m.h;
    p.c = it.c;
    p.dense_steps = m.dense_steps;
    p.core_words = m.core_words;
    return p;
}
// Composites p (SPEC 8.6), clipped to t.
void blend_spans(const BlendTarget& t, const PlacedSpans& p);
// Composites mask m with its column 0 / row 0 at canvas (ox, oy), clipped to t.
void blend_spans(const BlendTarget& t, const SpanMask& m, int64_t ox, int64_t oy, Rgba4 c);
// Composites rows [j0, j1) of p's dense box, row j0 at `origin` (p's canvas pixel
// (ox, oy + j0)), rows `stride` bytes apart: every byte of those rows' dense_steps * 64 bytes
// is read and written (bytes outside the spans keep their value). The caller guarantees the
// rows lie in its buffer and that the pixels outside its target are scratch. False, with
// nothing drawn, when no dense kernel serves the current ISA (the caller then uses
// blend_spans).
bool blend_dense(uint8_t* origin, size_t stride, const PlacedSpans& p, uint32_t j0, uint32_t j1);
// Composites the rows of p that `rows` names (bit i: the i-th of p's rows inside t, at most
// 64 of them) like blend_spans, each clipped to the columns [cols[2 * i], cols[2 * i + 1])
// relative to t.x0, a non-empty range inside the row's span and t (occlusion culling: only
// the rows and columns that later strokes leave visible).
void blend_spans_cols(const BlendTarget& t, const PlacedSpans& p, const uint8_t* cols, uint64_t rows);
// True when blend_dense draws on this ISA.
bool dense_available();
// Composites one row of one-byte coverage: n pixels starting at canvas (x, y), clipped to t.
void blend_cov_row(const BlendTarget& t, int64_t x, int64_t y, const uint8_t* cov, int64_t n, Rgba4 c);

enum class BlendIsa { Best, Scalar, Sse2, Avx2, Avx512 };
// Test hook: forces the span kernels of blend_spans/blend_cov_row and the culling kernels
// (raster_cull.hpp) onto one ISA (Best: the fastest available). Not thread-safe; tests only.
void force_span_isa(BlendIsa isa);
BlendIsa forced_span_isa();
bool blend_isa_available(BlendIsa isa);

}  // namespace spt::raster
