#include "cartoon/fill_layer.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "cartoon/regions.hpp"

namespace spt::cartoon {

FillLayer build_fill_layer(const cv::Mat& rgb, Rgb8 background, const Renderer& renderer, const FillOptions& opts,
                           const std::vector<cv::Vec3b>* given) {
    FillLayer out;
    const std::vector<cv::Vec3b> palette = given ? *given : find_palette(rgb, opts.palette);
    out.palette = palette;
    out.colors = palette.size();
    if (palette.empty()) return out;
    const Regions regs = find_regions(rgb, label_pixels(rgb, palette), palette, opts.min_region_pixels);
    out.regions = regs.list.size();
    for (int i = 0; i < int(regs.list.size()); ++i) {
        const cv::Vec3b c = regs.list[size_t(i)].color;
        // The first region in the background's colour is the canvas itself.
        if (i == 0 && std::max({std::abs(c[0] - background.r), std::abs(c[1] - background.g), std::abs(c[2] - background.b)}) <= 2)
            continue;
        for (PolygonStroke& p : trace_region(rgb, regs, i, opts.trace)) out.strokes.push_back(Stroke::make_polygon(std::move(p)));
    }

    // The grid whose rendering is closest to the source (smaller grids on ties: faster).
    const uint32_t W = uint32_t(rgb.cols), H = uint32_t(rgb.rows);
    uint64_t best_sse = std::numeric_limits<uint64_t>::max();
    Canvas canvas(W, H, background);
    for (uint8_t g : opts.grids) {
        uint64_t work = 0;
        for (Stroke& s : out.strokes) {
            s.polygon.supersample = g;
            work += polygon_render_work(s.polygon, H);
        }
        if (work > opts.max_work && out.grid != 0) continue;
        if (!renderer.render(canvas, out.strokes)) continue;
        uint64_t sse = 0;
        for (uint32_t y = 0; y < H; ++y) {
            const uint8_t* a = canvas.row(y);
            const uint8_t* b = rgb.ptr<uint8_t>(int(y));
            for (uint32_t x = 0; x < 3 * W; ++x) sse += uint64_t((int(a[x]) - int(b[x])) * (int(a[x]) - int(b[x])));
        }
        if (sse < best_sse) {
            best_sse = sse;
            out.grid = g;
        }
    }
    for (Stroke& s : out.strokes) s.polygon.supersample = out.grid;
    return out;
}

}  // namespace spt::cartoon
