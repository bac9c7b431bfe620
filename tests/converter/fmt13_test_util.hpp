// Format 1.3 inputs for the CLI tests: a small alpha and/or scene-linear file made with
// spt::Writer, with opaque, half-transparent and soft-edged strokes and transparent corners.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "spt/spt.hpp"

namespace fmt13 {

using namespace spt;

constexpr uint32_t W = 16, H = 8;

inline Rgba8 codes(uint16_t r, uint16_t g, uint16_t b, uint8_t a) {
    Rgba8 c;
    c.a = a;
    set_code16(c, 0, r), set_code16(c, 1, g), set_code16(c, 2, b);
    return c;
}

// A 16 x 8 canvas: an opaque 4 x 4 square of (21.0, 0.18, 1.0) on the left, a half-transparent
// one of 2.0 in the middle, an ellipse with soft edges on the right; the rest transparent.
inline StreamInfo test_info(ColorEncoding enc, bool alpha) {
    StreamInfo info;
    Header& h = info.header;
    h.width = W, h.height = H, h.fps = {24, 1};
    h.color = enc, h.alpha = alpha;
    if (enc == ColorEncoding::LinearHalf) {
        h.background = {0x38, 0x00, 0x3C};  // 0.5, 0, 1.0
        h.background_lo = {0, 0, 0};
    } else {
        h.background = {10, 200, 30};
    }
    h.sets = {{4, 4}, {5, 5}};
    h.orientations = default_orientations(4);
    Template rect, ell;
    rect.kind = TemplateKind::Rectangle;
    ell.kind = TemplateKind::Ellipse;
    ell.supersample = 4;
    info.templates = {rect, ell};
    return info;
}

inline std::vector<Stroke> test_strokes(ColorEncoding enc) {
    auto stamp = [](uint8_t set, uint8_t tmpl, int x, int y, Rgba8 c) {
        StampStroke s;
        s.set = set, s.tmpl = tmpl, s.x = 16 * x + 8, s.y = 16 * y + 8, s.color = c;
        return Stroke::make_stamp(s);
    };
    if (enc == ColorEncoding::LinearHalf)
        return {stamp(0, 0, 2, 3, codes(0x4D40, 0x31C3, 0x3C00, 255)), stamp(0, 0, 7, 3, codes(0x4000, 0x4000, 0x4000, 128)),
                stamp(1, 1, 12, 4, codes(0x3555, 0x4900, 0x2E66, 200))};
    return {stamp(0, 0, 2, 3, {200, 100, 50, 255}), stamp(0, 0, 7, 3, {200, 100, 50, 128}), stamp(1, 1, 12, 4, {9, 250, 77, 200})};
}

// Writes the file and returns its rendered canvas.
inline Canvas make_file(const std::string& path, ColorEncoding enc, bool alpha) {
    StreamInfo info = test_info(enc, alpha);
    auto w = Writer::create(path, info);
    EXPECT_TRUE(w.ok()) << w.error().message;
    Frame f;
    f.added = test_strokes(enc);
    EXPECT_TRUE((*w)->append(f).ok());
    EXPECT_TRUE((*w)->finish().ok());
    auto r = Reader::open(path);
    EXPECT_TRUE(r.ok());
    Canvas c;
    EXPECT_TRUE((*r)->render_frame(0, c).ok());
    return c;
}

}  // namespace fmt13
