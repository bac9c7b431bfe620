// Stamp footprints, computed once per (set, template, orientation) (SPEC 8.2: a stamp's
// coverage depends only on the triple and the pixel offset). Two caches:
//  - span footprints for drawing (raster::SpanMask, with a dense box when narrow), under the
//    budget of render_impl.hpp: one whose evaluation box could need more than
//    kMaxFootprintBytes, or that would take the cache past kFootprintCacheBytes, is not stored; such stamps are drawn
//    through their inverse map row by row (same pixels, more work per stroke);
//  - public Masks (stamp_footprint()), built only when a caller asks for one.
// Both are built under a lock and published through atomics; readers never lock.
#include <algorithm>
#include <cstdlib>

#include "render_impl.hpp"

namespace spt {

using namespace raster;

namespace {
// Marks a slot whose footprint is over budget: drawn uncached.
const SpanMask kUncached{};
}  // namespace

const SpanMask* RendererImpl::spans(uint8_t set, uint8_t tmpl, uint8_t orient) const {
    auto& slot = span_slots_[slot_index(set, tmpl, orient)];
    const SpanMask* f = slot.load(std::memory_order_acquire);
    if (!f) {
        std::lock_guard<std::mutex> lock(mutex_);
        f = slot.load(std::memory_order_acquire);
        if (!f) {
            const StrokeSet& ss = header_.sets[set];
            const InverseMap m = stamp_inverse(ss.width, ss.height, header_.orientations[orient], templates_[tmpl].supersample);
            const int64_t w = m.x1 - m.x0 + 1, h = m.y1 - m.y0 + 1;
            // Upper bound of the stored size, checked before anything is allocated.
            const uint64_t bound = uint64_t(w) * uint64_t(h) * 3 + uint64_t(h) * (kSpanPad + sizeof(SpanRow)) +
                                   (uint64_t(w) * 3 <= kDenseMaxSteps * kDenseStep ? uint64_t(h) * kDenseMaxSteps * 2 * kDenseStep : 0) +
                                   uint64_t(h) * (((uint64_t(w) + 63) / 64 + 1) * sizeof(uint64_t) + sizeof(uint32_t));
            const size_t used = cache_bytes_.load(std::memory_order_relaxed);
            if (bound > kMaxFootprintBytes || used + bound > kFootprintCacheBytes) {
                f = &kUncached;
            } else {
                auto sm = std::make_unique<SpanMask>();
                std::vector<uint8_t> row(size_t(w), 0);
                for (int64_t y = m.y0; y <= m.y1; ++y) {
                    int64_t a = m.x0, b = m.x1;
                    if (map_row_range(m, y, a, b)) {
                        rasterize_map_row(m, templates_[tmpl], y, a, b, row.data());
                        span_mask_add_row(*sm, row.data(), b - a + 1, a - m.x0);
                    } else {
                        span_mask_add_row(*sm, row.data(), 0, 0);
                    }
                }
                // Trim empty rows and columns so that tile binning sees the tight box.
                size_t first = 0, last = sm->rows.size();
                while (first < last && sm->rows[first].n == 0) ++first;
                while (last > first && sm->rows[last - 1].n == 0) --last;
                int32_t lo = INT32_MAX;
                for (size_t j = first; j < last; ++j)
                    if (sm->rows[j].n) lo = std::min(lo, sm->rows[j].lo);
                std::vector<SpanRow> rows(sm->rows.begin() + std::ptrdiff_t(first), sm->rows.begin() + std::ptrdiff_t(last));
                for (SpanRow& r : rows) {
                    if (r.n) r.lo -= lo;
                    sm->w = std::max<uint32_t>(sm->w, r.n ? uint32_t(r.lo) + r.n : 0);
                }
                sm->rows = std::move(rows);
                sm->rows.shrink_to_fit();
                sm->cov3.shrink_to_fit();
                sm->x0 = sm->rows.empty() ? 0 : int32_t(m.x0 + lo);
                sm->y0 = int32_t(m.y0 + int64_t(first));
                span_mask_make_dense(*sm);
                span_mask_make_core(*sm);
                {  // the bound of validate.cpp's fill_render_work for this triple
                    const int64_t C = std::abs(int64_t(header_.orientations[orient].cos_q14));
                    const int64_t S = std::abs(int64_t(header_.orientations[orient].sin_q14));
                    const int64_t rx = (int64_t(ss.width) * C + int64_t(ss.height) * S) / 32768 + 1;
                    const int64_t ry = (int64_t(ss.width) * S + int64_t(ss.height) * C) / 32768 + 1;
                    const Template& tp = templates_[tmpl];
                    const uint64_t k = tp.kind != TemplateKind::Bitmap && tp.supersample >= 2 ? tp.supersample : 1;
                    sm->box_work = uint64_t(2 * rx + 1) * uint64_t(2 * ry + 1) * k * k;
                }
                cache_bytes_.fetch_add(sm->bytes(), std::memory_order_relaxed);
                f = sm.get();
                owned_spans_.push_back(std::move(sm));
            }
            slot.store(f, std::memory_order_release);
        }
    }
    return f == &kUncached ? nullptr : f;
}

const Mask& RendererImpl::stamp_footprint(uint8_t set, uint8_t tmpl, uint8_t orient) const {
    // Out-of-range ids are a caller bug; answer with an empty footprint rather than crash.
    static const Mask kEmpty{};
    if (set >= header_.sets.size() || tmpl >= templates_.size() || orient >= header_.orientations.size()) return kEmpty;
    auto& slot = mask_slots_[slot_index(set, tmpl, orient)];
    if (const Mask* f = slot.load(std::memory_order_acquire)) return *f;

    std::lock_guard<std::mutex> lock(mutex_);
    if (const Mask* f = slot.load(std::memory_order_acquire)) return *f;
    const StrokeSet& ss = header_.sets[set];
    const InverseMap m = stamp_inverse(ss.width, ss.height, header_.orientations[orient], templates_[tmpl].supersample);
    const int64_t w = m.x1 - m.x0 + 1, h = m.y1 - m.y0 + 1;
    std::vector<uint8_t> full(size_t(w * h));
    rasterize_map(m, templates_[tmpl], m.x0, m.y0, m.x1, m.y1, full.data());
    // Trim to the non-zero box.
    int64_t lx = w, hx = -1, ly = h, hy = -1;
    for (int64_t j = 0; j < h; ++j)
        for (int64_t i = 0; i < w; ++i)
            if (full[size_t(j * w + i)]) {
                lx = std::min(lx, i); hx = std::max(hx, i);
                ly = std::min(ly, j); hy = std::max(hy, j);
            }
    auto mk = std::make_unique<Mask>();
    if (hx >= 0) {
        mk->x0 = int32_t(m.x0 + lx);
        mk->y0 = int32_t(m.y0 + ly);
        mk->w = uint32_t(hx - lx + 1);
        mk->h = uint32_t(hy - ly + 1);
        mk->a.resize(size_t(mk->w) * mk->h);
        for (uint32_t j = 0; j < mk->h; ++j)
            std::copy_n(&full[size_t((ly + j) * w + lx)], mk->w, &mk->a[size_t(j) * mk->w]);
    }
    // Counted, never refused: the caller asked for this mask (at most the evaluation box of a
    // 4096 x 4096 set, about 34 MB).
    cache_bytes_.fetch_add(mk->a.size() + sizeof(Mask), std::memory_order_relaxed);
    const Mask* p = mk.get();
    owned_masks_.push_back(std::move(mk));
    slot.store(p, std::memory_order_release);
    return *p;
}

}  // namespace spt
