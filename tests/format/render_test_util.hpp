// Shared helpers of the renderer tests (tests/format/render_*_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "spt/render.hpp"
#include "spt/types.hpp"

namespace spt_test {

inline spt::Header make_header(uint32_t w, uint32_t h, std::vector<spt::StrokeSet> sets, int orientations = 8) {
    spt::Header hd;
    hd.width = w;
    hd.height = h;
    hd.background = {255, 255, 255};
    hd.sets = std::move(sets);
    hd.orientations = spt::default_orientations(orientations);
    return hd;
}

inline spt::Template bitmap(uint16_t w, uint16_t h, std::vector<uint8_t> px) {
    spt::Template t;
    t.kind = spt::TemplateKind::Bitmap;
    t.width = w;
    t.height = h;
    t.pixels = std::move(px);
    return t;
}

inline spt::Template analytic(spt::TemplateKind k) {
    spt::Template t;
    t.kind = k;
    return t;
}

inline std::unique_ptr<spt::Renderer> make_renderer(const spt::Header& h, const std::vector<spt::Template>& t) {
    auto r = spt::Renderer::create(h, t);
    EXPECT_TRUE(r.ok()) << r.error().message;
    return r.ok() ? std::move(r.value()) : nullptr;
}

inline uint64_t fnv1a64(const std::vector<uint8_t>& b) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (uint8_t c : b) { h ^= c; h *= 0x100000001b3ull; }
    return h;
}

// Q4 coordinate of the centre of pixel p.
inline int32_t centre(int32_t p) { return 16 * p + 8; }

inline spt::Stroke stamp(uint8_t set, uint8_t tmpl, uint8_t orient, int32_t x, int32_t y, spt::Rgba8 c) {
    spt::StampStroke s;
    s.set = set; s.tmpl = tmpl; s.orient = orient; s.x = x; s.y = y; s.color = c;
    return spt::Stroke::make_stamp(s);
}

inline spt::Stroke affine(uint8_t tmpl, int32_t tx, int32_t ty, int32_t a, int32_t b, int32_t c, int32_t d, spt::Rgba8 col) {
    spt::AffineStroke s;
    s.tmpl = tmpl; s.tx = tx; s.ty = ty; s.a = a; s.b = b; s.c = c; s.d = d; s.color = col;
    return spt::Stroke::make_affine(s);
}

inline spt::Stroke curve(std::vector<spt::CurvePoint> pts, spt::Rgba8 col) {
    spt::CurveStroke s;
    s.points = std::move(pts);
    s.color = col;
    return spt::Stroke::make_curve(std::move(s));
}

}  // namespace spt_test
