// Incremental canvas update for inter frames: only the horizontal bands of the canvas that a
// moving stroke touches (before or after its move) are rendered again. A static shot with one
// moving character re-renders a few bands instead of the whole frame.
//
// Exactness: a band is rendered by a second Renderer whose canvas is one band tall, with every
// stamp shifted up by the band's first row (a whole number of pixels, i.e. a multiple of 16 in
// Q4), so each stamp lands on the same pixels with the same footprint and blends in the same
// order: the band's bytes equal those rows of a full render (tests/video/band_render_test.cpp).
// Non-stamp strokes are not shifted that way; a list holding any falls back to a full render.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "spt/render.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::video {

class BandRenderer {
public:
    static constexpr uint32_t kBand = 64;  // rows per band (the tile renderer's tile height)

    static Result<std::unique_ptr<BandRenderer>> create(const Header& header, const std::vector<Template>& templates,
                                                        const Renderer& full);

    // `canvas` holds the rendering of `before`; `after` is `before` with frame `f` applied
    // (spt::apply_frame: removals, then motion; `f.added` must be empty). Makes `canvas` the
    // rendering of `after`. Strokes the frame removes must be invisible in `before` (covered:
    // see hidden_strokes), which is how the encoder removes them. Returns the fraction of
    // rows rendered again (1 for a full render).
    Result<double> update(Canvas& canvas, const std::vector<Stroke>& before, const Frame& f,
                          const std::vector<Stroke>& after, unsigned threads);

private:
    BandRenderer() = default;
    // Inclusive pixel rows [y0, y1] a stroke can cover; false when it is not a stamp.
    bool rows_of(const Stroke& s, int64_t& y0, int64_t& y1) const;

    Header header_;
    const Renderer* full_ = nullptr;
    std::unique_ptr<Renderer> band_;
    Canvas band_canvas_;
    std::vector<uint8_t> dirty_;
    std::vector<Stroke> shifted_;
};

}  // namespace spt::video
