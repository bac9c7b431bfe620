// What the geometrize emulation's three parts share (importers/src/geometrize_*.cpp; the
// interface is spt_import/geometrize.hpp): pixel indices, the span helpers the fits start
// from, the pixel-difference objective both fits minimise, and the polygon fit's entry point.
#pragma once

#include <algorithm>
#include <climits>
#include <cstdint>
#include <utility>
#include <vector>

#include "spt/render.hpp"
#include "spt_import/geometrize.hpp"

namespace spt::import::geometrize {

using Pix = std::pair<int32_t, int32_t>;

// Spans clipped as geometrize clips them (to [0, w-1) x [0, h-1)).
std::vector<Span> trim(std::vector<Span> in, uint32_t w, uint32_t h);
// geometrize's outline-and-fill of a polygon of pixel vertices (Bresenham outline, each row
// filled from its leftmost to its rightmost outline pixel).
std::vector<Span> polygon_spans(const std::vector<Pix>& p);

// Pixels of the target and of a candidate stroke that differ, counted where geometrize paints.
class Objective {
public:
    Objective(const Renderer& r, const std::vector<Span>& t, uint32_t w, uint32_t h) : r_(r), w_(w), h_(h) {
        for (const Span& s : t) {
            x0_ = std::min(x0_, s.x0); x1_ = std::max(x1_, s.x1);
            y0_ = std::min(y0_, s.y); y1_ = std::max(y1_, s.y);
        }
        if (x1_ < x0_) { x0_ = x1_ = y0_ = y1_ = 0; }
        bw_ = uint32_t(x1_ - x0_ + 1);
        in_.assign(size_t(bw_) * uint32_t(y1_ - y0_ + 1), 0);
        for (const Span& s : t)
            for (int32_t x = s.x0; x <= s.x1; ++x) {
                uint8_t& v = in_[size_t(s.y - y0_) * bw_ + size_t(x - x0_)];
                if (!v) { v = 1; ++count_; }
            }
    }
    uint64_t operator()(const AffineStroke& s) const {
        Stroke st = Stroke::make_affine(s);
        st.affine.color = {0, 0, 0, 255};
        return (*this)(st);
    }
    // Any stroke kind, drawn opaque.
    uint64_t operator()(const Stroke& st) const {
        Mask m;
        if (!r_.stroke_mask(st, m)) return ~uint64_t(0);
        uint64_t hit = 0, extra = 0;
        const int32_t cw = int32_t(w_) - 1, ch = int32_t(h_) - 1;
        for (uint32_t j = 0; j < m.h; ++j) {
            const int32_t y = m.y0 + int32_t(j);
            if (y < 0 || y >= ch) continue;
            const uint8_t* row = &m.a[size_t(j) * m.w];
            for (uint32_t i = 0; i < m.w; ++i) {
                if (!row[i]) continue;
                const int32_t x = m.x0 + int32_t(i);
                if (x < 0 || x >= cw) continue;
                if (x >= x0_ && x <= x1_ && y >= y0_ && y <= y1_ && in_[size_t(y - y0_) * bw_ + size_t(x - x0_)]) ++hit;
                else ++extra;
            }
        }
        return (count_ - hit) + extra;
    }
private:
    const Renderer& r_;
    uint32_t w_, h_, bw_ = 0;
    int32_t x0_ = INT32_MAX, x1_ = INT32_MIN, y0_ = INT32_MAX, y1_ = INT32_MIN;
    std::vector<uint8_t> in_;
    uint64_t count_ = 0;
};

// Appends the polygon stroke closest to geometrize's pixels `target` of the outline `vertices`;
// false when no polygon could be fitted (the caller then fits an affine stroke).
bool append_polygon(const Renderer& r, const std::vector<Pix>& vertices, const std::vector<Span>& target, Rgba8 colour,
                    uint32_t w, uint32_t h, std::vector<Stroke>& out, ImportReport& rep, uint64_t& differing);

}  // namespace spt::import::geometrize
