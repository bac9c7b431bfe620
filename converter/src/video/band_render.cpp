#include "video/band_render.hpp"

#include <algorithm>
#include <cstring>

namespace spt::video {

Result<std::unique_ptr<BandRenderer>> BandRenderer::create(const Header& header, const std::vector<Template>& templates,
                                                           const Renderer& full) {
    std::unique_ptr<BandRenderer> b(new BandRenderer());
    b->header_ = header;
    b->full_ = &full;
    Header bh = header;
    bh.height = std::min<uint32_t>(kBand, header.height);
    Result<std::unique_ptr<Renderer>> r = Renderer::create(bh, templates);
    if (!r) return r.error();
    b->band_ = std::move(*r);
    return b;
}

bool BandRenderer::rows_of(const Stroke& s, int64_t& y0, int64_t& y1) const {
    if (s.kind != StrokeKind::Stamp) return false;
    const Mask& m = full_->stamp_footprint(s.stamp.set, s.stamp.tmpl, s.stamp.orient);
    y0 = int64_t(Renderer::stamp_pixel(s.stamp.y)) + m.y0;
    y1 = y0 + int64_t(m.h) - 1;
    return true;
}

Result<double> BandRenderer::update(Canvas& canvas, const std::vector<Stroke>& before, const Frame& f,
                                    const std::vector<Stroke>& after, unsigned threads) {
    const uint32_t H = header_.height, W = header_.width;
    const size_t bands = (H + kBand - 1) / kBand;
    auto full = [&]() -> Result<double> {
        Status st = full_->render(canvas, after, threads);
        if (!st) return st.error();
        return 1.0;
    };
    if (canvas.width != W || canvas.height != H || !f.added.empty()) return full();
    if (f.motion.empty()) return 0.0;  // removals of covered strokes change no pixel

    // Bands touched by a stroke that moves, at its old and its new place. `after` lists the
    // strokes of `before` that were not removed, in order.
    dirty_.assign(bands, 0);
    auto mark = [&](int64_t y0, int64_t y1) {
        y0 = std::max<int64_t>(y0, 0);
        y1 = std::min<int64_t>(y1, int64_t(H) - 1);
        for (int64_t b = y0 / kBand; y0 <= y1 && b <= y1 / int64_t(kBand); ++b) dirty_[size_t(b)] = 1;
    };
    size_t r = 0, k = 0;
    for (size_t i = 0; i < before.size(); ++i) {
        if (r < f.removed.size() && f.removed[r] == i) { ++r; continue; }
        if (k >= after.size()) return full();
        const Stroke& a = before[i];
        const Stroke& b = after[k++];
        if (a.kind != StrokeKind::Stamp || b.kind != StrokeKind::Stamp) return full();
        if (a.stamp.x == b.stamp.x && a.stamp.y == b.stamp.y) continue;
        int64_t y0, y1;
        rows_of(a, y0, y1);
        mark(y0, y1);
        rows_of(b, y0, y1);
        mark(y0, y1);
    }
    if (k != after.size()) return full();
    const size_t n_dirty = size_t(std::count(dirty_.begin(), dirty_.end(), uint8_t(1)));
    // Past about half the bands the per-band passes over the list cost more than one render.
    if (n_dirty * 2 > bands) return full();
    if (n_dirty == 0) return 0.0;

    uint64_t rows = 0;
    for (size_t b = 0; b < bands; ++b) {
        if (!dirty_[b]) continue;
        const int64_t top = int64_t(b) * kBand, bottom = std::min<int64_t>(top + kBand, H) - 1;
        shifted_.clear();
        for (const Stroke& s : after) {
            int64_t y0, y1;
            rows_of(s, y0, y1);
            if (y1 < top || y0 > bottom) continue;
            Stroke t = s;
            t.stamp.y -= int32_t(top * 16);  // whole pixels: same footprint, same pixels
            shifted_.push_back(t);
        }
        Status st = band_->render(band_canvas_, shifted_, threads);
        if (!st) return st.error();
        const size_t row_bytes = size_t(W) * 3;
        for (int64_t y = top; y <= bottom; ++y)
            std::memcpy(canvas.row(uint32_t(y)), band_canvas_.row(uint32_t(y - top)), row_bytes);
        rows += uint64_t(bottom - top + 1);
    }
    return double(rows) / double(H);
}

}  // namespace spt::video
