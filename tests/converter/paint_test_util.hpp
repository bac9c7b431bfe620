// Helpers shared by the painter tests: small models from real media (or a synthetic picture
// when the media folder is absent).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "io/image_io.hpp"
#include "paint/painter.hpp"
#include "spt/render.hpp"

namespace spt::paint_test {

struct Model {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgb;
    paint::ImageView view() const { return paint::ImageView{width, height, rgb.data()}; }
};

inline std::string media(const std::string& rel) { return std::string(SPT_MEDIA_DIR) + "/" + rel; }

// A box-filtered reduction of a real still to at most max_w x max_h (keeping the aspect), then a
// centre crop to exactly w x h. Empty when the file is missing.
inline Model load_small(const std::string& rel, uint32_t w, uint32_t h) {
    Model m;
    const std::string path = media(rel);
    if (!std::filesystem::exists(path)) return m;
    auto img = io::read_image(path);
    if (!img) return m;
    const uint32_t f = std::max<uint32_t>(1, std::min(img->width / w, img->height / h));
    const uint32_t rw = img->width / f, rh = img->height / f;
    const uint32_t cx = (rw - w) / 2, cy = (rh - h) / 2;
    m.width = w;
    m.height = h;
    m.rgb.resize(size_t(w) * h * 3);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) {
                uint32_t s = 0;
                for (uint32_t j = 0; j < f; ++j)
                    for (uint32_t i = 0; i < f; ++i)
                        s += img->rgb[((size_t(cy + y) * f + j) * img->width + (cx + x) * f + i) * 3 + c];
                m.rgb[(size_t(y) * w + x) * 3 + c] = uint8_t((s + f * f / 2) / (f * f));
            }
    return m;
}

// A synthetic picture with edges, gradients and texture, for tests that must not depend on media.
inline Model synthetic(uint32_t w, uint32_t h) {
    Model m;
    m.width = w;
    m.height = h;
    m.rgb.resize(size_t(w) * h * 3);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            uint8_t* p = &m.rgb[(size_t(y) * w + x) * 3];
            const bool disc = (x - w / 3.0) * (x - w / 3.0) + (y - h / 2.0) * (y - h / 2.0) < (h / 3.0) * (h / 3.0);
            p[0] = uint8_t(disc ? 200 : 40 + 150 * x / w);
            p[1] = uint8_t(disc ? 60 : 90 + 100 * y / h);
            p[2] = uint8_t(x > 2 * w / 3 ? ((x / 4 + y / 4) % 2 ? 220 : 30) : 120);
        }
    return m;
}

// A real crop when the media is there, otherwise the synthetic picture.
inline Model model_or_synthetic(uint32_t w, uint32_t h) {
    Model m = load_small("stills/coffee.png", w, h);
    return m.width ? m : synthetic(w, h);
}

// A painting of a model on `setup` with `opts`, and the renderer that drew it.
struct Painting {
    paint::PaintSetup setup;
    std::unique_ptr<Renderer> renderer;
    Canvas canvas;
    std::vector<Stroke> strokes;
    paint::PaintStats stats;
};

inline Painting paint_model(const paint::ImageView& model, paint::PaintSetup setup, const paint::PaintOptions& opts) {
    Painting p;
    p.setup = std::move(setup);
    auto r = Renderer::create(p.setup.header, p.setup.templates);
    EXPECT_TRUE(r.ok()) << r.error().message;
    if (!r) return p;
    p.renderer = std::move(r.value());
    p.canvas = Canvas(p.setup.header);
    p.stats = paint::paint(model, p.canvas, *p.renderer, p.setup, opts, p.strokes);
    return p;
}

}  // namespace spt::paint_test
