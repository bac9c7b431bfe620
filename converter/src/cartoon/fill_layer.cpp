#include "cartoon/fill_layer.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "cartoon/mask_pixels.hpp"
#include "cartoon/regions.hpp"

namespace spt::cartoon {

namespace {

// Squared error of a region's polygons (grid 8) drawn over the colour it lies on, against the
// source, on the pixels they cover or the region holds.
double local_error(const cv::Mat& rgb, const Regions& regs, int index, const std::vector<PolygonStroke>& polys,
                   const Renderer& renderer) {
    const Region& reg = regs.list[size_t(index)];
    const cv::Rect img(0, 0, rgb.cols, rgb.rows);
    const cv::Rect box = cv::Rect(reg.box.x - 4, reg.box.y - 4, reg.box.width + 8, reg.box.height + 8) & img;
    cv::Mat drawn(box.size(), CV_8UC3, cv::Scalar(reg.around[0], reg.around[1], reg.around[2]));
    cv::Mat touched(box.size(), CV_8U, cv::Scalar(0));
    Mask m;
    for (const PolygonStroke& p : polys) {
        PolygonStroke q = p;
        q.supersample = 8;
        if (!renderer.stroke_mask(Stroke::make_polygon(std::move(q)), m)) continue;
        const uint8_t c[3] = {p.color.r, p.color.g, p.color.b};
        visit_covered(m, box.x + box.width, box.y + box.height, [&](int32_t px, int32_t py, size_t, uint8_t a) {
            if (px < box.x || py < box.y) return;
            cv::Vec3b& d = drawn.at<cv::Vec3b>(py - box.y, px - box.x);
            for (int k = 0; k < 3; ++k) d[k] = blend8(d[k], c[k], a);
            touched.at<uint8_t>(py - box.y, px - box.x) = 1;
        });
    }
    double e = 0;
    for (int y = 0; y < box.height; ++y)
        for (int x = 0; x < box.width; ++x) {
            if (!touched.at<uint8_t>(y, x) && regs.id.at<int>(box.y + y, box.x + x) != index) continue;
            const cv::Vec3b& a = drawn.at<cv::Vec3b>(y, x);
            const cv::Vec3b& b = rgb.at<cv::Vec3b>(box.y + y, box.x + x);
            for (int k = 0; k < 3; ++k) e += double(int(a[k]) - int(b[k])) * double(int(a[k]) - int(b[k]));
        }
    return e;
}

}  // namespace

FillLayer build_fill_layer(const cv::Mat& rgb, Rgb8 background, const Renderer& renderer, const FillOptions& opts,
                           const std::vector<cv::Vec3b>* given) {
    FillLayer out;
    const std::vector<cv::Vec3b> palette = given ? *given : find_palette(rgb, opts.palette);
    out.palette = palette;
    out.colors = palette.size();
    if (palette.empty()) return out;
    Regions regs = find_regions(rgb, label_pixels(rgb, palette), palette, opts.min_region_pixels);
    out.regions = regs.list.size();
    for (int i = 0; i < int(regs.list.size()); ++i) {
        Region& reg = regs.list[size_t(i)];
        const cv::Vec3b c = reg.color;
        // The first region in the background's colour is the canvas itself.
        if (i == 0 && std::max({std::abs(c[0] - background.r), std::abs(c[1] - background.g), std::abs(c[2] - background.b)}) <= 2)
            continue;
        std::vector<PolygonStroke> polys = trace_region(rgb, regs, i, opts.trace);
        if (reg.ink_candidate && reg.ink != reg.color) {
            // Traced in its ink too; the closer wins (later regions trace against the winner).
            reg.color = reg.ink;
            std::vector<PolygonStroke> inked = trace_region(rgb, regs, i, opts.trace);
            if (local_error(rgb, regs, i, inked, renderer) < local_error(rgb, regs, i, polys, renderer)) polys = std::move(inked);
            else reg.color = c;
        }
        for (PolygonStroke& p : polys) out.strokes.push_back(Stroke::make_polygon(std::move(p)));
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
