// Stroke sets, default templates, header set-up and PSNR helpers.
#include <algorithm>
#include <cmath>

#include "paint/default_templates_data.hpp"
#include "paint/painter.hpp"

namespace spt::paint {

std::vector<StrokeSet> default_sets(uint32_t width, uint32_t height, int count) {
    count = std::clamp(count, 3, 10);
    const double side = std::max<uint32_t>(1, std::min(width, height));
    // Largest strokes: a fifth of the short side (a few dozen strokes lay in the whole picture,
    // as a painter blocks in masses); smallest: ~1/180 of it but at least 3 px, fine enough for
    // ~28 dB on photographs. Geometric steps between them, like the paper's coarse-to-fine sets.
    const double first = std::max(6.0, side / 5.0);
    const double last = std::max(3.0, side / 180.0);
    std::vector<StrokeSet> sets;
    for (int k = 0; k < count; ++k) {
        const double t = double(k) / (count - 1);
        const double len = first * std::pow(last / first, t);
        const int w = std::max(1, int(std::lround(len)));
        const int h = std::max(1, int(std::lround(len / 2)));
        sets.push_back(StrokeSet{uint16_t(std::min(w, 4096)), uint16_t(std::min(h, 4096))});
    }
    return sets;
}

std::vector<Template> default_templates() {
    std::vector<Template> out;
    for (int i = 0; i < detail::kDefaultTemplateCount; ++i) {
        const auto& d = detail::kDefaultTemplates[i];
        Template t;
        t.name = d.name;
        if (t.name == "rectangle") {
            // Analytic kinds are exact at every size and store no samples (their PNGs in
            // converter/templates/ show the same shape). The ellipse is 4x4 supersampled: its
            // anti-aliased rim paints like the bitmaps' soft edges.
            t.kind = TemplateKind::Rectangle;
        } else if (t.name == "ellipse") {
            t.kind = TemplateKind::Ellipse;
            t.supersample = 4;
        } else {
            t.kind = TemplateKind::Bitmap;
            t.width = uint16_t(d.width);
            t.height = uint16_t(d.height);
            t.pixels.assign(d.samples, d.samples + size_t(d.width) * d.height);
        }
        out.push_back(std::move(t));
    }
    return out;
}

PaintSetup make_setup(uint32_t width, uint32_t height, Rgb8 background, std::vector<StrokeSet> sets,
                      std::vector<Template> templates) {
    PaintSetup s;
    s.header.width = width;
    s.header.height = height;
    s.header.fps = Rational{24, 1};
    s.header.frame_count = 1;
    s.header.background = background;
    s.header.sets = std::move(sets);
    s.header.orientations = default_orientations(8);
    s.templates = std::move(templates);
    return s;
}

double psnr_rect(const ImageView& a, const uint8_t* b, const Rect& r) {
    const int64_t x0 = std::max<int64_t>(0, r.x), y0 = std::max<int64_t>(0, r.y);
    const int64_t x1 = std::min<int64_t>(a.width, int64_t(r.x) + r.w);
    const int64_t y1 = std::min<int64_t>(a.height, int64_t(r.y) + r.h);
    if (x0 >= x1 || y0 >= y1) return 0;
    uint64_t sse = 0;
    for (int64_t y = y0; y < y1; ++y)
        for (int64_t x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c) {
                const size_t i = (size_t(y) * a.width + size_t(x)) * 3 + c;
                const int d = int(a.rgb[i]) - int(b[i]);
                sse += uint64_t(d * d);
            }
    if (sse == 0) return 99;
    const double n = double(x1 - x0) * double(y1 - y0) * 3;
    return 10 * std::log10(255.0 * 255.0 * n / double(sse));
}

double psnr(const ImageView& a, const uint8_t* b) {
    return psnr_rect(a, b, Rect{0, 0, int32_t(a.width), int32_t(a.height)});
}

const char* stop_reason_name(StopReason r) {
    switch (r) {
        case StopReason::Converged: return "converged";
        case StopReason::MaxStrokes: return "max-strokes";
        case StopReason::TargetPsnr: return "target-psnr";
        case StopReason::Cancelled: return "cancelled";
    }
    return "?";
}

}  // namespace spt::paint
