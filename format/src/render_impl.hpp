// Internal to libspt: the Renderer implementation shared by render.cpp (validation, draw,
// masks), render_cache.cpp (footprint cache with its memory budget) and render_tiles.cpp
// (whole-frame tile rendering).
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "raster.hpp"
#include "spt/render.hpp"

namespace spt {

namespace detail {
struct StampSource;
}

class RendererImpl final : public Renderer {
public:
    RendererImpl(const Header& h, const std::vector<Template>& t);

    Status stroke_mask(const Stroke& s, Mask& out) const override;
    const Mask& stamp_footprint(uint8_t set, uint8_t tmpl, uint8_t orient) const override;
    Status draw(Canvas& canvas, const Stroke& s) const override;
    Status render(Canvas& canvas, const std::vector<Stroke>& strokes) const override;
    Status render(Canvas& canvas, const std::vector<Stroke>& strokes, unsigned threads) const override;
    size_t footprint_cache_bytes() const override { return cache_bytes_.load(std::memory_order_relaxed); }

    // Memory budget of the span footprints draw() and render() cache (one per set, template and
    // orientation used, stored as per-row spans of non-zero coverage, 3 bytes a pixel). A
    // footprint whose evaluation box could need more than kMaxFootprintBytes, or that would
    // take the cache past kFootprintCacheBytes, is not stored: such stamps are evaluated per
    // stroke through their inverse map (same pixels, slower). A 4096 x 4096 set at 45 degrees
    // (about 100 MB) is drawn that way; sets up to about 1400 x 1400 are cached. A Mask that
    // stamp_footprint() is asked for is always built, whatever its size (at most the
    // evaluation box of a 4096 x 4096 set, about 34 MB), and counted in footprint_cache_bytes().
    static constexpr size_t kFootprintCacheBytes = size_t(256) << 20;
    static constexpr size_t kMaxFootprintBytes = size_t(16) << 20;

    // detail::render_stamp_frame (stamp_frame.hpp): a key frame of stamps binned straight from
    // their source, without a Stroke list.
    bool render_stamps(Canvas& canvas, const detail::StampSource& src, unsigned threads, uint64_t work_limit,
                       uint64_t* work_out = nullptr) const;
    // Alpha canvases and colour encoding 1 (render_deep.cpp): stroke by stroke, exact.
    Status draw_deep(Canvas& canvas, const Stroke& s) const;
    Status draw_deep_rows(Canvas& canvas, const Stroke& s, int64_t ry0, int64_t ry1) const;  // rows [ry0, ry1) only
    Status render_deep(Canvas& canvas, const std::vector<Stroke>& strokes, unsigned threads) const;
    // Range and reference checks of one stroke (SPEC 8.7).
    Status check(const Stroke& s) const;
    // check(s) of a stamp, without the message: true when it passes.
    bool stamp_valid(const StampStroke& t) const {
        return t.set < header_.sets.size() && t.tmpl < templates_.size() && t.orient < header_.orientations.size() &&
               t.x >= -kMaxCoord && t.x <= kMaxCoord && t.y >= -kMaxCoord && t.y <= kMaxCoord;
    }
    static constexpr int64_t kMaxCoord = int64_t(1) << 24;  // SPEC 4 value ranges of positions
    // The span footprint of a stamp for drawing, built on first use; nullptr when it does not
    // fit the cache budget (the stamp is then drawn through its inverse map, same pixels).
    const raster::SpanMask* spans(uint8_t set, uint8_t tmpl, uint8_t orient) const;
    // Composites a checked stroke onto t, clipped to t.
    void draw_into(const raster::BlendTarget& t, const Stroke& s) const;
    // Inclusive canvas pixel box outside which the checked stroke has no coverage (may be
    // empty: x1 < x0).
    void stroke_box(const Stroke& s, int64_t& x0, int64_t& y0, int64_t& x1, int64_t& y1) const;

    const Header& header() const { return header_; }

    size_t template_count() const { return templates_.size(); }
    // The header's (set, template, orientation) triples; a stamp's footprint slot is
    // slot_index(set, tmpl, orient) < triples() (render_tiles.cpp's binning computes the same
    // index with the strides read once a frame).
    size_t triples() const { return header_.sets.size() * templates_.size() * header_.orientations.size(); }
    size_t slot_index(uint8_t set, uint8_t tmpl, uint8_t orient) const {
        return (size_t(set) * templates_.size() + tmpl) * header_.orientations.size() + orient;
    }

private:
    void draw_map(const raster::BlendTarget& t, const raster::InverseMap& m, const Template& tp, Rgba8 c) const;
    void draw_curve(const raster::BlendTarget& t, const CurveStroke& s) const;

    Header header_;
    std::vector<Template> templates_;
    mutable std::vector<std::atomic<const raster::SpanMask*>> span_slots_;
    mutable std::vector<std::atomic<const Mask*>> mask_slots_;
    mutable std::mutex mutex_;
    mutable std::vector<std::unique_ptr<raster::SpanMask>> owned_spans_;
    mutable std::vector<std::unique_ptr<Mask>> owned_masks_;
    mutable std::atomic<size_t> cache_bytes_{0};
};

}  // namespace spt
