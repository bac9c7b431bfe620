// Rendering alpha canvases and colour encoding 1 (format 1.3, SPEC.md 8.6): every stroke's
// coverage from the same rasterizers as plain canvases, composited one stroke after another
// with the per-channel rule of its encoding. Plain 8-bit sRGB canvases take the tiled kernels
// of render_tiles.cpp instead.
#include <algorithm>
#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "render_impl.hpp"
#include "spt/color.hpp"

namespace spt {

using namespace raster;

void Canvas::reset(const Header& h) {
    width = h.width;
    height = h.height;
    const size_t n = size_t(h.width) * h.height;
    if (h.color == ColorEncoding::LinearHalf) {
        rgb.clear();
        const uint16_t bg[3] = {uint16_t(h.background.r << 8 | h.background_lo.r),
                                uint16_t(h.background.g << 8 | h.background_lo.g),
                                uint16_t(h.background.b << 8 | h.background_lo.b)};
        rgb16.resize(n * 3);
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) rgb16[3 * i + c] = h.alpha ? 0 : bg[c];
    } else {
        rgb16.clear();
        if (h.alpha) rgb.assign(n * 3, 0);
        else fill(h.background);
    }
    if (h.alpha) alpha.assign(n, 0);
    else alpha.clear();
}

namespace {

// Composites `a` (the stroke's per-pixel alpha of 8.6, w x h at x0, y0) onto the canvas rows
// [ry0, ry1), clipped to the canvas.
void composite(Canvas& cv, const Header& h, int64_t x0, int64_t y0, uint32_t w, uint32_t hh,
               const uint8_t* a, bool coverage_only, uint32_t A, const Rgba8& c, int64_t ry0, int64_t ry1) {
    const int64_t cx0 = std::max<int64_t>(x0, 0), cy0 = std::max<int64_t>({y0, int64_t(0), ry0});
    const int64_t cx1 = std::min<int64_t>(x0 + w, cv.width), cy1 = std::min<int64_t>({y0 + hh, int64_t(cv.height), ry1});
    const bool linear = h.color == ColorEncoding::LinearHalf;
    const uint16_t src16[3] = {code16(c, 0), code16(c, 1), code16(c, 2)};
    for (int64_t y = cy0; y < cy1; ++y) {
        const uint8_t* row = a + size_t(y - y0) * w;
        for (int64_t x = cx0; x < cx1; ++x) {
            uint32_t al = row[x - x0];
            if (coverage_only) al = stroke_alpha(al, A);
            if (al == 0) continue;
            const size_t p = size_t(y) * cv.width + size_t(x);
            if (al == 255) {  // what 8.6 gives for full alpha: the stroke's colour exactly
                if (linear) for (int k = 0; k < 3; ++k) cv.rgb16[3 * p + k] = src16[k];
                else { cv.rgb[3 * p] = c.r; cv.rgb[3 * p + 1] = c.g; cv.rgb[3 * p + 2] = c.b; }
                if (h.alpha) cv.alpha[p] = 255;
                continue;
            }
            if (linear) {
                uint16_t* d = &cv.rgb16[3 * p];
                for (int k = 0; k < 3; ++k) d[k] = blend_half(d[k], src16[k], al);
            } else {
                uint8_t* d = &cv.rgb[3 * p];
                d[0] = blend8(d[0], c.r, al);
                d[1] = blend8(d[1], c.g, al);
                d[2] = blend8(d[2], c.b, al);
            }
            if (h.alpha) cv.alpha[p] = blend8(cv.alpha[p], 255, al);
        }
    }
}

bool canvas_matches(const Canvas& cv, const Header& h) {
    const size_t n = size_t(cv.width) * cv.height;
    if (cv.width != h.width || cv.height != h.height) return false;
    if (h.color == ColorEncoding::LinearHalf ? cv.rgb16.size() != 3 * n : cv.rgb.size() != 3 * n) return false;
    return !h.alpha || cv.alpha.size() == n;
}

}  // namespace

Status RendererImpl::draw_deep(Canvas& canvas, const Stroke& s) const {
    if (!canvas_matches(canvas, header_))
        return make_error(Code::InvalidArgument, "canvas: its planes do not match the header's colour encoding and alpha");
    return draw_deep_rows(canvas, s, 0, canvas.height);
}

Status RendererImpl::draw_deep_rows(Canvas& canvas, const Stroke& s, int64_t ry0, int64_t ry1) const {
    if (Status st = check(s); !st) return st;
    const Rgba8& c = s.color();
    if (c.a == 0) return {};
    if (s.kind == StrokeKind::Stamp) {
        const Mask& f = stamp_footprint(s.stamp.set, s.stamp.tmpl, s.stamp.orient);
        if (f.w == 0) return {};
        const int64_t y0 = int64_t(stamp_pixel(s.stamp.y)) + f.y0;
        if (y0 >= ry1 || y0 + f.h <= ry0) return {};
        composite(canvas, header_, int64_t(stamp_pixel(s.stamp.x)) + f.x0, y0, f.w, f.h, f.a.data(), true, c.a, c, ry0, ry1);
        return {};
    }
    int64_t bx0, by0, bx1, by1;
    stroke_box(s, bx0, by0, bx1, by1);
    if (bx1 < bx0 || by1 < by0 || by0 >= ry1 || by1 < ry0) return {};
    Mask m;
    if (Status st = stroke_mask(s, m); !st) return st;
    if (m.w) composite(canvas, header_, m.x0, m.y0, m.w, m.h, m.a.data(), false, 255, c, ry0, ry1);
    return {};
}

Status RendererImpl::render_deep(Canvas& canvas, const std::vector<Stroke>& strokes, unsigned threads) const {
    canvas.reset(header_);
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    threads = std::min<unsigned>(threads, std::max<uint32_t>(1, header_.height / 16));
    if (threads > 1) {
        // Bands of rows, each drawing every stroke clipped to it: a pixel sees the same strokes in
        // the same order, so the values are those of one thread. On an error the one-thread pass
        // below draws the strokes before it and names it.
        std::atomic<bool> failed{false};
        std::vector<std::thread> pool;
        for (unsigned t = 0; t < threads; ++t)
            pool.emplace_back([&, t] {
                const int64_t y0 = int64_t(header_.height) * t / threads, y1 = int64_t(header_.height) * (t + 1) / threads;
                for (const Stroke& s : strokes)
                    if (failed.load(std::memory_order_relaxed) || !draw_deep_rows(canvas, s, y0, y1)) {
                        failed = true;
                        return;
                    }
            });
        for (auto& th : pool) th.join();
        if (!failed) return {};
        canvas.reset(header_);
    }
    for (size_t i = 0; i < strokes.size(); ++i)
        if (Status st = draw_deep_rows(canvas, strokes[i], 0, canvas.height); !st) {
            Error e = st.error();
            e.message = "stroke " + std::to_string(i) + ": " + e.message;
            return e;
        }
    return {};
}

}  // namespace spt
