// Whole-frame rendering (Renderer::render). Drawing 30,000 strokes one after another at random
// places touches the whole canvas (2.7 MB at 1280x720) for every few strokes, so most time goes
// to cache misses. Instead every stroke is binned into the tiles its box touches; each tile is
// then rendered on its own in a small buffer that stays in L1 (background, then its strokes in
// drawing order, each clipped to the tile, less what later strokes hide), and copied out.
// A pixel sees exactly the strokes that cover it and stay visible, in the same order, with
// the same arithmetic: the bytes equal drawing stroke by stroke (render_tiles_test.cpp,
// render_cull_test.cpp). Tiles are independent, so threads can render
// different tiles of one frame without changing a byte.
#include <algorithm>
#include <atomic>
#include <cstring>
#include <string>
#include <thread>
#if defined(__x86_64__)
#include <immintrin.h>
#elif defined(__wasm_simd128__) && defined(__SSE2__)
#include <emmintrin.h>  // emscripten's SSE2 on WebAssembly SIMD (copy_rows; web/CMakeLists.txt)
#endif

#include "raster_cull.hpp"
#include "render_impl.hpp"
#include "stamp_frame.hpp"

namespace spt {

using namespace raster;

namespace {

// 128 x 64 px: 24 KB of pixels, half of L1; wide tiles split fewer of the (mostly wider than
// tall) brush strokes. Measured with bench/render_bench against 64x64 and 128x128.
constexpr int64_t kTileW = 128, kTileH = 64;
// Tile buffer rows have an apron of scratch pixels on both sides, so that a small stroke that
// crosses the tile's left or right edge is still blended a whole row at a time from its dense
// box (raster::blend_dense) instead of span by span with clipping; what lands in the apron is
// never copied out. (Rows are clipped to the tile: that costs nothing per row.) The right
// apron also holds the slack the span kernels may write past a clipped span. It is as wide as
// the widest dense box (kDenseMaxSteps * kDenseStep bytes, 42.7 px), so that every dense stroke
// that reaches into a tile is drawn dense there: with 24 px, the 34 px strokes that crossed a
// tile edge went span by span (frame about 1.5% slower).
constexpr int64_t kApronX = (int64_t(kDenseMaxSteps * kDenseStep) + 2) / 3;
constexpr size_t kTileStride = 3 * (kTileW + 2 * kApronX);
static_assert(3 * kApronX >= int64_t(kSpanPad), "clipped spans may run kSpanPad bytes into the right apron");
static_assert(kTileW == CullBits::kTileCols && kTileH == CullBits::kRows && kApronX <= CullBits::kBias,
              "the culling bits cover a tile and the part of its apron that narrow strokes reach");

// Occlusion culling (raster_cull.hpp). Before drawing, a tile walks its strokes backwards;
// each stroke drawn span by span (the big, coarse ones: painters put them first and cover
// most of their pixels) gets, per row, the columns from its first to its last pixel that no
// later stroke covers opaquely, and each stroke drawn from its dense box the range of its rows
// that hold such a pixel; every opaque stroke then marks its core. Only pixels that a later
// stroke overwrites completely are skipped, so the bytes are the same (SPEC 8.6 notes).

// Every stroke prepared for the tiles: a stamp with a cached footprint as a TileItem of its
// mask (masks: the frame's table of the footprints it uses), anything else as a TileItem
// without mask, drawn by draw_into(). Items are copied into every tile's list (16 bytes each),
// so that a tile reads its strokes sequentially, twice (culling, then drawing); lists of item
// numbers measured slower.
// What binning needs of a stamp's footprint, found once a frame per (set, template,
// orientation) triple: kinds[triple] (its mask kUnseen until then; reset through kind_triples
// after each frame), one load a stroke.
struct StampKind {
    static constexpr uint32_t kUnseen = ~0u;
    int32_t x0 = 0, y0 = 0;    // SpanMask::x0, y0
    int32_t w1 = 0, h1 = 0;    // columns - 1, rows - 1 (h1 < 0: an empty footprint)
    uint32_t mask = kUnseen;   // index into Bins::masks
    uint64_t work = 0;         // SpanMask::box_work
};
struct Bins {
    std::vector<TileItem> items;
    std::vector<uint16_t> range;  // per item: first and last tile column, first and last tile row
    std::vector<uint32_t> start;  // tiles + 1 offsets into list
    std::vector<TileItem> list;   // the items of each tile, in drawing order (and a scratch slot)
    std::vector<MaskRef> masks;
    std::vector<StampKind> kinds;        // per triple
    std::vector<uint32_t> kind_triples;  // the triples seen in this frame
};

// Copies `rows` rows of `bytes` bytes (src_stride 0: the same row every time). A whole tile
// row, the common case, is copied with vector moves in a loop of fixed count (64 bytes a move
// where AVX-512 is there, else 16): a library call per row cost about 1.5% of a frame, and the
// `rep movs` the compiler makes of a fixed-size memcpy about as much.
#if defined(__x86_64__)
__attribute__((target("avx512f"))) void copy_whole_rows_avx512(uint8_t* dst, size_t dst_stride, const uint8_t* src,
                                                               size_t src_stride, int64_t rows) {
    static_assert(3 * kTileW % 64 == 0, "a tile row is whole 64-byte moves");
    for (int64_t y = 0; y < rows; ++y, dst += dst_stride, src += src_stride)
        for (size_t k = 0; k < 3 * size_t(kTileW); k += 64) _mm512_storeu_si512(dst + k, _mm512_loadu_si512(src + k));
}
const bool kCopyAvx512 = __builtin_cpu_supports("avx512f");
#endif

void copy_rows(uint8_t* dst, size_t dst_stride, const uint8_t* src, size_t src_stride, int64_t rows, size_t bytes) {
    constexpr size_t kWhole = 3 * size_t(kTileW);
    if (bytes == kWhole) {
#if defined(__x86_64__)
        if (kCopyAvx512) return copy_whole_rows_avx512(dst, dst_stride, src, src_stride, rows);
#endif
        for (int64_t y = 0; y < rows; ++y, dst += dst_stride, src += src_stride) {
#if defined(__SSE2__)
            for (size_t k = 0; k < kWhole; k += 16)
                _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + k), _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + k)));
#else
            std::memcpy(dst, src, kWhole);
#endif
        }
    } else {
        for (int64_t y = 0; y < rows; ++y, dst += dst_stride, src += src_stride) std::memcpy(dst, src, bytes);
    }
}

Bins& scratch_bins() {
    thread_local Bins b;
    return b;
}

// Fills the tile lists of one frame: items are made stroke by stroke and counted per tile as
// they are (start[t + 1]: items of tile t so far), then sorted into one flat list by tile
// (counting sort; drawing order kept within a tile).
class Binner {
public:
    Binner(const RendererImpl& r, Bins& b, size_t strokes)
        : r_(r), b_(b), W_(r.header().width), H_(r.header().height), tiles_x_((W_ + kTileW - 1) / kTileW) {
        tiles_ = size_t(tiles_x_) * size_t((H_ + kTileH - 1) / kTileH);
        b_.masks.clear();
        // start[t + 1] counts tile t; past them a padding of tiles_x + 1 counters that add() and
        // finish() may add 0 to (see add()).
        b_.start.assign(tiles_ + 1 + size_t(tiles_x_) + 1, 0);
        if (b_.items.size() < strokes) {
            b_.items.resize(strokes);
            b_.range.resize(4 * strokes);
        }
        if (b_.kinds.size() < r.triples()) b_.kinds.resize(r.triples());
        templates_ = r.template_count();
        orientations_ = r.header().orientations.size();
    }
    // Clears the triple slots, ready for the next frame.
    ~Binner() {
        for (uint32_t t : b_.kind_triples) b_.kinds[t].mask = StampKind::kUnseen;
        b_.kind_triples.clear();
    }

    // What binning needs of a valid stamp triple's footprint; nullptr when it is not cached
    // (the stamp is then drawn from its inverse map).
    const StampKind* kind(uint32_t set, uint32_t tmpl, uint32_t orient) {
        const size_t t = (size_t(set) * templates_ + tmpl) * orientations_ + orient;  // RendererImpl::slot_index
        if (b_.kinds[t].mask != StampKind::kUnseen) return &b_.kinds[t];
        return add_kind(t, set, tmpl, orient);
    }
    // Adds a valid stamp at Q4 (x, y) of kind k.
    void add_stamp(const StampKind& k, int32_t x, int32_t y, Rgba4 c) {
        if (c.a == 0 || k.h1 < 0) return;
        TileItem it;
        it.c = c;
        it.ox = Renderer::stamp_pixel(x) + k.x0;
        it.oy = Renderer::stamp_pixel(y) + k.y0;
        it.mask = k.mask;
        add(it, it.ox, it.oy, int64_t(it.ox) + k.w1, int64_t(it.oy) + k.h1);
    }
    // Adds an item whose coverage lies in the inclusive canvas box.
    void add(const TileItem& it, int64_t x0, int64_t y0, int64_t x1, int64_t y1) {
        x0 = std::max<int64_t>(x0, 0); x1 = std::min<int64_t>(x1, W_ - 1);
        y0 = std::max<int64_t>(y0, 0); y1 = std::min<int64_t>(y1, H_ - 1);
        if (x0 > x1 || y0 > y1) return;
        // Non-negative now: unsigned division is a shift.
        const uint32_t tx0 = uint32_t(x0) / uint32_t(kTileW), tx1 = uint32_t(x1) / uint32_t(kTileW);
        const uint32_t ty0 = uint32_t(y0) / uint32_t(kTileH), ty1 = uint32_t(y1) / uint32_t(kTileH);
        b_.items[n_] = it;
        uint16_t* r = &b_.range[4 * n_++];
        r[0] = uint16_t(tx0); r[1] = uint16_t(tx1); r[2] = uint16_t(ty0); r[3] = uint16_t(ty1);
        const uint32_t right = tx1 - tx0, down = ty1 - ty0;
        if (right <= 1 && down <= 1) {
            // Up to 2 x 2 tiles (any stroke no bigger than a tile): counted without a branch on
            // how many (it mispredicted for the third of the strokes that cross a tile edge), by
            // adding 0 or 1 to each counter of the 2 x 2 block. The four addresses always differ:
            // adding 0 to c[0] again would make every count wait on the store before it.
            uint32_t* c = &b_.start[size_t(ty0) * size_t(tiles_x_) + tx0 + 1];
            const size_t w = size_t(tiles_x_);
            c[0] += 1;
            c[1] += right;
            c[w] += down;
            c[w + 1] += down & right;
            return;
        }
        for (uint32_t ty = ty0; ty <= ty1; ++ty)
            for (uint32_t tx = tx0; tx <= tx1; ++tx) ++b_.start[size_t(ty) * size_t(tiles_x_) + tx + 1];
    }
    // Sorts the items into the tile lists.
    void finish() {
        for (size_t t = 0; t < tiles_; ++t) b_.start[t + 1] += b_.start[t];
        const uint32_t scratch = b_.start[tiles_];  // a slot past the lists: the writes for no tile
        b_.list.resize(size_t(scratch) + 1);
        // fill[t]: where tile t's next item goes; padded like start.
        std::vector<uint32_t> fill(b_.start.begin(), b_.start.begin() + std::ptrdiff_t(tiles_));
        fill.resize(tiles_ + size_t(tiles_x_) + 1, scratch);
        TileItem* list = b_.list.data();
        const size_t w = size_t(tiles_x_);
        for (size_t k = 0; k < n_; ++k) {
            const uint16_t* r = &b_.range[4 * k];
            const TileItem item = b_.items[k];
            const uint32_t right = uint32_t(r[1] - r[0]), down = uint32_t(r[3] - r[2]);
            if (right <= 1 && down <= 1) {  // as in add(): the 2 x 2 block, four distinct counters
                uint32_t* f = &fill[size_t(r[2]) * w + r[0]];
                list[f[0]++] = item;
                if ((right | down) == 0) continue;  // most strokes: one tile, one store
                list[right ? f[1] : scratch] = item;
                f[1] += right;
                list[down ? f[w] : scratch] = item;
                f[w] += down;
                list[(down & right) ? f[w + 1] : scratch] = item;
                f[w + 1] += down & right;
                continue;
            }
            for (uint32_t ty = r[2]; ty <= r[3]; ++ty)
                for (uint32_t tx = r[0]; tx <= r[1]; ++tx) list[fill[size_t(ty) * size_t(tiles_x_) + tx]++] = item;
        }
    }

private:
    [[gnu::noinline]] const StampKind* add_kind(size_t t, uint32_t set, uint32_t tmpl, uint32_t orient) {
        const SpanMask* f = r_.spans(uint8_t(set), uint8_t(tmpl), uint8_t(orient));
        if (!f) return nullptr;
        StampKind k;
        k.x0 = f->x0;
        k.y0 = f->y0;
        k.w1 = int32_t(f->w) - 1;
        k.h1 = int32_t(f->rows.size()) - 1;
        k.mask = uint32_t(b_.masks.size());
        k.work = f->box_work;
        MaskRef m;
        m.rows = f->rows.data();
        m.cov3 = f->cov3.data();
        m.h = uint32_t(f->rows.size());
        if (!f->extent.empty()) {
            m.core = f->core.data();
            m.extent = f->extent.data();
            m.core_words = f->core_words;
            if (!f->foot.empty()) m.foot = f->foot.data();
        }
        if (f->dense_steps) {
            m.dense = f->dense.data();
            m.dense_steps = f->dense_steps;
        }
        b_.masks.push_back(m);
        b_.kind_triples.push_back(uint32_t(t));
        b_.kinds[t] = k;
        return &b_.kinds[t];
    }

    const RendererImpl& r_;
    Bins& b_;
    int64_t W_, H_, tiles_x_;
    size_t tiles_ = 0, n_ = 0;
    size_t templates_ = 0, orientations_ = 0;  // the triple index's strides, read once
};

// The tile pass: renders every tile of bins onto the canvas (already sized). Items without a
// mask are drawn from strokes[it.ox].
void draw_tiles(const RendererImpl& r, Canvas& canvas, const Bins& bins, const std::vector<Stroke>* strokes,
                unsigned threads) {
    const int64_t W = canvas.width, H = canvas.height;
    const int64_t tiles_x = (W + kTileW - 1) / kTileW, tiles_y = (H + kTileH - 1) / kTileH;
    const size_t tiles = size_t(tiles_x * tiles_y);
    const Rgb8 bg = r.header().background;
    uint8_t bg_row[3 * kTileW];
    for (int64_t i = 0; i < kTileW; ++i) {
        bg_row[3 * i] = bg.r;
        bg_row[3 * i + 1] = bg.g;
        bg_row[3 * i + 2] = bg.b;
    }

    const DenseOpsKernel dense_ops = dense_ops_kernel();  // Dense ops are planned only when there is one
    const bool dense = dense_ops != nullptr;
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    threads = unsigned(std::min<size_t>(threads, tiles));
    // Threads take tiles from a shared counter. Alone, a plain one: a locked add waits for the
    // tile copied out before it to reach the cache.
    std::atomic<size_t> next{0};
    const bool shared = threads > 1;
    auto worker = [&]() {
        thread_local std::vector<uint8_t> buf;  // zeroed once; the apron then holds leftovers
        thread_local CullBits cull;
        thread_local CullPlan plan;
        buf.resize(kTileStride * size_t(kTileH));
        uint8_t* const origin = buf.data() + 3 * size_t(kApronX);
        for (size_t own = 0;;) {
            const size_t tile = shared ? next.fetch_add(1, std::memory_order_relaxed) : own++;
            if (tile >= tiles) break;
            BlendTarget t;
            t.px = origin;
            t.stride = kTileStride;
            t.x0 = int64_t(tile % size_t(tiles_x)) * kTileW;
            t.y0 = int64_t(tile / size_t(tiles_x)) * kTileH;
            t.x1 = std::min(t.x0 + kTileW, W);
            t.y1 = std::min(t.y0 + kTileH, H);
            t.slack = true;
            const size_t row_bytes = size_t(t.x1 - t.x0) * 3;
            copy_rows(origin, kTileStride, bg_row, 0, t.y1 - t.y0, row_bytes);
            const uint32_t first = bins.start[tile], count = bins.start[tile + 1] - first;
            const TileItem* list = bins.list.data() + first;
            const MaskRef* masks = bins.masks.data();
            CullTile ct;
            ct.x0 = t.x0; ct.y0 = t.y0; ct.x1 = t.x1; ct.y1 = t.y1;
            ct.stride = int64_t(kTileStride);
            ct.dense = dense;
            ct.dense_lo = -kApronX;
            ct.dense_hi3 = 3 * (kTileW + kApronX);

            cull_tile(cull, list, count, masks, ct, plan);
            size_t slots = plan.slots;  // span-culled entries: their columns are in plan.cols, last first
            for (size_t k = plan.n; k-- > 0;) {
                const DrawOp& op = plan.ops[k];
                if (op.kind == DrawOp::Dense) {  // the run of dense ops from here, in one call
                    k = dense_ops(origin, kTileStride, plan.ops.data(), k + 1);  // the loop's k-- goes on
                    continue;
                }
                const TileItem& it = list[op.item];
                if (op.kind == DrawOp::SpanCols)
                    blend_spans_cols(t, placed(it, masks[it.mask]), &plan.cols[--slots * 2 * CullBits::kRows], op.vis);
                else if (it.mask == TileItem::kNoMask)
                    r.draw_into(t, (*strokes)[uint32_t(it.ox)]);
                else
                    blend_spans(t, placed(it, masks[it.mask]));
            }
            copy_rows(canvas.row(uint32_t(t.y0)) + 3 * t.x0, size_t(W) * 3, origin, kTileStride, t.y1 - t.y0, row_bytes);
        }
    };

    std::vector<std::thread> pool;
    for (unsigned k = 1; k < threads; ++k) {
        try {
            pool.emplace_back(worker);
        } catch (...) {
            break;  // fewer threads, same bytes
        }
    }
    worker();
    for (auto& th : pool) th.join();
}

void size_canvas(Canvas& canvas, const Header& h) {
    canvas.width = h.width;
    canvas.height = h.height;
    canvas.rgb.resize(size_t(h.width) * size_t(h.height) * 3);  // every byte is written by its tile
}

}  // namespace

Status RendererImpl::render(Canvas& canvas, const std::vector<Stroke>& strokes) const {
    return render(canvas, strokes, 1);
}

Status RendererImpl::render(Canvas& canvas, const std::vector<Stroke>& strokes, unsigned threads) const {
    if (!header_.plain_color()) return render_deep(canvas, strokes, threads);
    // Check and prepare every stroke (this also builds the footprints, so the tile pass only
    // reads shared state). On a bad stroke, the strokes before it are still drawn, as drawing
    // them one by one would have done, and the error names it.
    Bins& bins = scratch_bins();
    Binner binner(*this, bins, strokes.size());
    Status error;
    for (size_t i = 0; i < strokes.size(); ++i) {
        const Stroke& s = strokes[i];
        // The common case first: a valid stamp with a cached footprint.
        if (s.kind == StrokeKind::Stamp && stamp_valid(s.stamp)) {
            const StampStroke& st = s.stamp;
            if (const StampKind* k = binner.kind(st.set, st.tmpl, st.orient)) {
                binner.add_stamp(*k, st.x, st.y, st.color);
                continue;
            }
        }
        if (Status st = check(s); !st) {
            Error e = st.error();
            e.message = "stroke " + std::to_string(i) + ": " + e.message;
            error = e;
            break;
        }
        TileItem it;
        it.c = s.color();
        if (it.c.a == 0) continue;
        it.ox = int32_t(i);
        it.mask = TileItem::kNoMask;
        int64_t x0, y0, x1, y1;
        stroke_box(s, x0, y0, x1, y1);
        binner.add(it, x0, y0, x1, y1);
    }
    binner.finish();
    size_canvas(canvas, header_);
    draw_tiles(*this, canvas, bins, &strokes, threads);
    return error;
}

bool RendererImpl::render_stamps(Canvas& canvas, const detail::StampSource& src, unsigned threads,
                                 uint64_t work_limit, uint64_t* work_out) const {
    if (!header_.plain_color()) return false;
    Bins& bins = scratch_bins();
    Binner binner(*this, bins, src.count);
    const uint32_t S = uint32_t(header_.sets.size()), T = uint32_t(templates_.size());
    const uint32_t O = uint32_t(header_.orientations.size());
    uint64_t work = 0;  // at most 2^24 strokes of less than 2^36 each: no overflow
    // The checks of stamp_valid() in one branch (|x|, |y| <= 2^24 by unsigned wrap-around).
    constexpr uint32_t kMax = uint32_t(kMaxCoord);
    if (src.packed) {
        for (size_t i = 0; i < src.count; ++i) {
            const uint8_t* q = src.packed + detail::kPackedStampBytes * i;
            const uint32_t set = q[1], tmpl = q[2], orient = q[3];
            const uint32_t x = detail::packed_u32(q + 4), y = detail::packed_u32(q + 8);
            if ((q[0] != 0) | (set >= S) | (tmpl >= T) | (orient >= O) | (x + kMax > 2 * kMax) | (y + kMax > 2 * kMax))
                return false;
            const StampKind* k = binner.kind(uint8_t(set), uint8_t(tmpl), uint8_t(orient));
            if (!k) return false;
            work += k->work;
            Rgba4 c;
            c.r = q[12]; c.g = q[13]; c.b = q[14]; c.a = q[15];
            binner.add_stamp(*k, int32_t(x), int32_t(y), c);
        }
    }
    // Batches small enough to stay in L1 between the decoder's writes and the binning's reads.
    constexpr size_t kBatch = 256;
    StampStroke batch[kBatch];
    for (size_t first = 0; !src.packed && first < src.count; first += kBatch) {
        const size_t n = std::min(kBatch, src.count - first);
        if (!src.fill(src.ctx, first, n, batch)) return false;
        for (size_t i = 0; i < n; ++i) {
            const StampStroke& t = batch[i];
            const uint32_t x = uint32_t(t.x), y = uint32_t(t.y);
            if ((t.set >= S) | (t.tmpl >= T) | (t.orient >= O) | (x + kMax > 2 * kMax) | (y + kMax > 2 * kMax))
                return false;
            const StampKind* k = binner.kind(t.set, t.tmpl, t.orient);
            if (!k) return false;
            work += k->work;
            binner.add_stamp(*k, t.x, t.y, t.color);
        }
    }
    if (work > work_limit) return false;
    if (work_out) *work_out = work;
    binner.finish();
    size_canvas(canvas, header_);
    draw_tiles(*this, canvas, bins, nullptr, threads);
    return true;
}

namespace detail {

bool render_stamp_frame(const Renderer& renderer, Canvas& canvas, const StampSource& src, unsigned threads,
                        uint64_t work_limit, uint64_t* work) {
    // Renderer::create makes only RendererImpl.
    return static_cast<const RendererImpl&>(renderer).render_stamps(canvas, src, threads, work_limit, work);
}

}  // namespace detail

}  // namespace spt
