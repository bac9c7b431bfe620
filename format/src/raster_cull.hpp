// Internal to libspt: occlusion bits of one render tile (render_tiles.cpp).
//
// A pixel where a later stroke has coverage 255 and alpha 255 ends up that stroke's colour
// whatever was drawn there before (SPEC 8.6), so an exact renderer may skip earlier strokes
// there. A tile walks its strokes backwards keeping one bit a pixel, "hidden by what comes
// later": each stroke first asks which of its rows and columns (cull_visible), or for a narrow
// stroke which of its rows, are still visible, then adds its opaque core (cull_mark); cull_tile
// does the whole walk, and plans what the tile then draws (DrawOp). Both work on whole columns
// of rows at once, eight rows a vector with AVX-512: per stroke row they cost a fraction of
// blending it.
#pragma once

#include <cstdint>

#include "raster.hpp"

namespace spt::raster {

// Bits of a tile of up to kTileCols x kRows pixels, stored word-column-major so that the
// same word of consecutive rows is contiguous: bit b of w[k][r] is pixel (64 * k + b - kBias,
// r) of the tile. Columns kBias - 64.. and past the tile give narrow strokes that reach into
// the tile's apron somewhere to land; only tile columns are ever tested.
struct CullBits {
    static constexpr int64_t kBias = 64, kTileCols = 128;
    static constexpr uint32_t kWordCols = 5, kRows = 64;
    alignas(64) uint64_t w[kWordCols][kRows];
    void clear();
};

// ORs rows [j0, j1) of a mask's opaque core (SpanMask::core: `words` word columns of `rows`
// words each) into bits, the mask's column 0 at tile column dx and row j0 at tile row r0
// (0 <= r0, r0 + j1 - j0 <= kRows). Bits that fall outside the word columns are dropped.
void cull_mark(CullBits& bits, const uint64_t* core, uint32_t words, uint32_t rows, uint32_t j0, uint32_t j1,
               int64_t dx, int64_t r0);

// For rows [j0, j1) of a mask (SpanMask::extent: per row the span's columns [lo, hi) as
// lo | hi << 16), placed as in cull_mark: the columns of each row, within tile columns
// [0, width) (width <= kTileCols), from its first to its last pixel not yet hidden, as
// [cols[2i], cols[2i+1]) for row j0 + i; 0, 0 when none is visible.
void cull_visible(const CullBits& bits, const uint32_t* extent, uint32_t j0, uint32_t j1, int64_t dx, int64_t r0,
                  int64_t width, uint8_t* cols);

// One render tile and how its strokes are drawn (render_tiles.cpp).
struct CullTile {
    int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // canvas pixels [x0, x1) x [y0, y1)
    int64_t stride = 0;                      // bytes a row of the tile buffer
    bool dense = false;                      // blend_dense draws on this ISA
    // A dense box is drawn whole when its rows lie in the tile buffer: from dense_lo columns
    // left of x0 up to 3 * x0 + dense_hi3 bytes.
    int64_t dense_lo = 0, dense_hi3 = 0;
};

// True when the tile draws item `it` of mask m from its dense box (raster::blend_dense).
inline bool cull_dense(const TileItem& it, const MaskRef& m, const CullTile& t) {
    const int64_t dx = int64_t(it.ox) - t.x0;
    return t.dense && m.dense && dx >= t.dense_lo && 3 * dx + int64_t(m.dense_steps * kDenseStep) <= t.dense_hi3;
}

// One step of a tile's forward (drawing) pass, as its backwards pass planned it.
struct DrawOp {
    enum Kind : uint8_t {
        Dense,     // rows of a dense box (those holding a visible pixel), with blend_dense's arithmetic
        SpanCols,  // entry `item`, span by span: the rows of vis, clipped to their visible columns (cols)
        Whole,     // entry `item` as it is (no culling: no mask, or a mask without a core)
    };
    const uint8_t* pairs = nullptr;  // Dense: SpanMask::dense from the first row to blend
    int32_t dst = 0;                 // Dense: byte offset of that row's column 0 from the tile's pixel (x0, y0)
    // The rows to draw: Dense, bit i: the i-th row from the first one (which bit 0 always names);
    // SpanCols: the rows with visible columns, bit i: the i-th of the entry's rows inside the tile.
    uint64_t vis = 0;
    uint32_t item = 0;               // SpanCols, Whole: index in the tile's list
    uint8_t steps = 0;               // Dense: SpanMask::dense_steps
    Kind kind = Whole;
    Rgba4 c;                         // Dense: the colour
};

// Draws the run of Dense ops that ends at ops[k - 1] (ops[k - 1], ops[k - 2], ... down to the
// first op that is not Dense, or ops[0]) into the tile buffer at origin, rows stride bytes
// apart: each op's rows of vis, with blend_dense's arithmetic. Returns the index past the ops
// left (0, or the index + 1 of the op that stopped the run). nullptr when no dense kernel
// serves the current ISA.
struct DrawOp;
using DenseOpsKernel = size_t (*)(uint8_t* origin, size_t stride, const DrawOp* ops, size_t k);
DenseOpsKernel dense_ops_kernel();

// What a tile's backwards pass found, for its forward (drawing) pass.
struct CullPlan {
    // What to draw, the last step first (the forward pass reads ops[n - 1] .. ops[0]); entries
    // of which nothing is visible have none.
    std::vector<DrawOp> ops;
    size_t n = 0;
    // Per span-culled entry (SpanCols), the last one first: 2 * CullBits::kRows bytes of
    // visible columns (cull_visible) of its rows inside the tile (of the rows its op's vis
    // names; the others' are unspecified).
    std::vector<uint8_t> cols;
    size_t slots = 0;  // span-culled entries in cols
};

// The backwards pass over a tile's entries list[0..n) (masks: the frame's MaskRef table): bits
// are cleared, then for each entry, last to first: its drawing step into plan (for an entry
// whose mask has a core, MaskRef::extent set: only its visible rows (dense) or columns
// (otherwise)), then, when its alpha is 255, its core into bits.
void cull_tile(CullBits& bits, const TileItem* list, uint32_t n, const MaskRef* masks, const CullTile& t,
               CullPlan& plan);

}  // namespace spt::raster
