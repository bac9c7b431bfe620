// Rendering and background fitting for imported documents.
#include "spt_import/evaluate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace spt::import {

Result<Canvas> render_frame(const Document& doc, size_t frame) {
    auto lists = live_lists(doc);
    if (!lists) return lists.error();
    if (frame >= lists->size()) return make_error(Code::InvalidArgument, "frame " + std::to_string(frame) + " does not exist");
    auto r = Renderer::create(doc.info.header, doc.info.templates);
    if (!r) return r.error();
    Canvas c(doc.info.header.width, doc.info.header.height, doc.info.header.background);
    if (Status s = (*r)->render(c, (*lists)[frame]); !s) return s.error();
    return c;
}

Result<Rgb8> fit_background(const Document& doc, const uint8_t* ref) {
    Document d = doc;
    const size_t last = d.frames.size() - 1;
    set_background(d, {0, 0, 0});
    auto black = render_frame(d, last);
    if (!black) return black.error();
    set_background(d, {255, 255, 255});
    auto white = render_frame(d, last);
    if (!white) return white.error();
    double num[3] = {0, 0, 0}, den[3] = {0, 0, 0};
    const size_t n = black->rgb.size();
    for (size_t i = 0; i < n; ++i) {
        const double w = (white->rgb[i] - black->rgb[i]) / 255.0;  // weight of the background
        num[i % 3] += w * (ref[i] - black->rgb[i]);
        den[i % 3] += w * w;
    }
    uint8_t c[3];
    for (int k = 0; k < 3; ++k) c[k] = den[k] > 0 ? uint8_t(std::clamp(std::lround(num[k] / den[k]), 0L, 255L)) : 255;
    return Rgb8{c[0], c[1], c[2]};
}

double psnr_rgb8(const uint8_t* a, const uint8_t* b, size_t pixels) {
    double se = 0;
    for (size_t i = 0; i < pixels * 3; ++i) {
        const double d = double(a[i]) - double(b[i]);
        se += d * d;
    }
    if (se == 0) return std::numeric_limits<double>::infinity();
    return 10 * std::log10(255.0 * 255.0 / (se / double(pixels * 3)));
}

}  // namespace spt::import
