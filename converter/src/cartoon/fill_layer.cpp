#include "cartoon/fill_layer.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>

#include "cartoon/line_trace.hpp"
#include "cartoon/mask_pixels.hpp"
#include "cartoon/shape_cost.hpp"
#include "cartoon/regions.hpp"
#include "paint/worker_pool.hpp"

namespace spt::cartoon {

namespace {

// Squared error of a region's polygons (grid 8) drawn over the colour it lies on, against the
// source, on the pixels they cover or the region holds.
// With `below` (the fill layer drawn so far), the strokes are drawn on it instead of on the
// region's surrounding colour, and pixels of regions drawn later are left out (they will hide
// what is drawn there: a polygon reaches under them on purpose, a line does not).
double local_error(const cv::Mat& rgb, const Regions& regs, int index, const std::vector<Stroke>& strokes,
                   const Renderer& renderer, const Canvas* below = nullptr, uint8_t grid = 8) {
    const bool visible_only = below != nullptr;
    const Region& reg = regs.list[size_t(index)];
    const cv::Rect img(0, 0, rgb.cols, rgb.rows);
    const cv::Rect box = cv::Rect(reg.box.x - 4, reg.box.y - 4, reg.box.width + 8, reg.box.height + 8) & img;
    cv::Mat drawn(box.size(), CV_8UC3, cv::Scalar(reg.around[0], reg.around[1], reg.around[2]));
    if (below)
        for (int y = 0; y < box.height; ++y) std::memcpy(drawn.ptr(y), below->row(uint32_t(box.y + y)) + 3 * box.x, size_t(3 * box.width));
    cv::Mat touched(box.size(), CV_8U, cv::Scalar(0));
    Mask m;
    for (const Stroke& s : strokes) {
        Stroke q = s;
        (q.kind == StrokeKind::Polygon ? q.polygon.supersample : q.curve.supersample) = grid;
        if (!renderer.stroke_mask(q, m)) continue;
        const Rgba8 col = s.color();
        const uint8_t c[3] = {col.r, col.g, col.b};
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
            const int id = regs.id.at<int>(box.y + y, box.x + x);
            if (!touched.at<uint8_t>(y, x) && id != index) continue;
            if (visible_only && id > index) continue;
            const cv::Vec3b& a = drawn.at<cv::Vec3b>(y, x);
            const cv::Vec3b& b = rgb.at<cv::Vec3b>(box.y + y, box.x + x);
            for (int k = 0; k < 3; ++k) e += double(int(a[k]) - int(b[k])) * double(int(a[k]) - int(b[k]));
        }
    return e;
}

// The grid the layer so far is drawn with for the line rule, as the layer will be (8 is what the
// grid search picks on the clips). Coarser grids save little and decide worse: butterfly 12
// frames 57,598 B in 18.8 s at 8, 58,952 B in 16.7 s at 4, 58,978 B in 14.3 s at 2.
constexpr uint8_t kBuiltGrid = 8;
// The grid the line candidates are compared on among themselves (a quarter of grid 8's samples);
// the best is then judged against the polygons on grid 8.
constexpr uint8_t kSearchGrid = 4;

std::vector<Stroke> as_strokes(std::vector<PolygonStroke> polys) {
    std::vector<Stroke> v;
    for (PolygonStroke& p : polys) v.push_back(Stroke::make_polygon(std::move(p)));
    return v;
}

double strokes_bytes(const std::vector<Stroke>& v) {
    double b = 0;
    for (const Stroke& s : v) b += shape_bytes(s, 6);
    return b;
}

// Region `index` as lines, when it is thin and its best curves (two middles, seven widths each)
// are within opts.max_error_ratio of `polys`' error and cost fewer bytes. Empty otherwise.
std::vector<Stroke> lines_instead(const cv::Mat& rgb, const Regions& regs, int index, const std::vector<Stroke>& polys,
                                  const Renderer& renderer, const Canvas& below, const LineOptions& opts,
                                  paint::WorkerPool& pool) {
    if (!may_be_line(regs, index, opts)) return {};
    LineShape shape = centrelines(regs, index);
    if (!is_line(shape, opts)) return {};
    // Lines must cost fewer bytes: a branch is at least one point (two when it has two), so
    // outlines that cost no more than that stay without drawing a candidate.
    double least = 0;
    for (const Centreline& b : shape.paths) least += 6.0 + 2.5 * double(std::min<size_t>(b.pts.size(), 2));
    if (strokes_bytes(polys) <= least) return {};
    const cv::Vec3b c = regs.list[size_t(index)].color;
    const Rgba8 color{c[0], c[1], c[2], 255};
    const double poly_err = local_error(rgb, regs, index, polys, renderer, &below);
    // The skeleton's middle and width, and those measured on the source (exact on a line over a
    // flat ground, disturbed where other colours are near): each at seven widenings, judged in
    // parallel (each writes its own slot; the first of the least errors wins, as in order).
    static constexpr double kWiden[] = {-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0};
    constexpr size_t kWidenings = std::size(kWiden);
    std::vector<std::vector<Stroke>> cand(2 * kWidenings);
    std::vector<double> err(cand.size());
    LineShape measured = shape;
    fit_to_source(shape, rgb, c, false);
    fit_to_source(measured, rgb, c, true);
    pool.run(cand.size(), [&](size_t k) {
        const LineShape& sh = k < kWidenings ? shape : measured;
        for (CurveStroke& cv : line_curves(sh, color, kWiden[k % kWidenings], 8, opts)) cand[k].push_back(Stroke::make_curve(std::move(cv)));
        err[k] = local_error(rgb, regs, index, cand[k], renderer, &below, kSearchGrid);
    });
    const size_t pick = size_t(std::min_element(err.begin(), err.end()) - err.begin());
    std::vector<Stroke> best = std::move(cand[pick]);
    const double best_err = local_error(rgb, regs, index, best, renderer, &below);  // on the grid polygons are judged on
    // A line may be somewhat farther from the source than the outline (opts.max_error_ratio):
    // the stamps that follow correct the difference, and its bytes are fewer.
    if (best_err <= poly_err * opts.max_error_ratio + 1 && strokes_bytes(best) < strokes_bytes(polys)) return best;
    return {};
}

}  // namespace

FillLayer build_fill_layer(const cv::Mat& rgb, Rgb8 background, const Renderer& renderer, const FillOptions& opts,
                           const std::vector<cv::Vec3b>* given, const std::vector<Stroke>* previous) {
    FillLayer out;
    const std::vector<cv::Vec3b> palette = given ? *given : find_palette(rgb, opts.palette);
    out.palette = palette;
    out.colors = palette.size();
    out.min_region = opts.min_region_pixels;
    if (palette.empty()) return out;
    Regions regs = find_regions(rgb, label_pixels(rgb, palette), palette, opts.min_region_pixels);
    out.regions = regs.list.size();
    Canvas built(uint32_t(rgb.cols), uint32_t(rgb.rows), background);  // the layer so far, for the line test
    paint::WorkerPool pool(opts.threads);
    LineOptions line_opts = opts.line;  // lines as exact as the outlines (the target's tolerance)
    line_opts.epsilon = std::min(line_opts.epsilon, opts.trace.epsilon);
    // Lines the previous frame drew: their boxes (grown by 3 px) and colours.
    std::vector<std::pair<cv::Rect, Rgba8>> old_lines;
    if (previous)
        for (const Stroke& s : *previous)
            if (s.kind == StrokeKind::Curve && !s.curve.points.empty()) {
                int x0 = INT32_MAX, y0 = INT32_MAX, x1 = INT32_MIN, y1 = INT32_MIN;
                for (const CurvePoint& p : s.curve.points) {
                    x0 = std::min(x0, p.x >> 4); x1 = std::max(x1, p.x >> 4);
                    y0 = std::min(y0, p.y >> 4); y1 = std::max(y1, p.y >> 4);
                }
                old_lines.emplace_back(cv::Rect(cv::Point(x0 - 3, y0 - 3), cv::Point(x1 + 4, y1 + 4)), s.curve.color);
            }
    auto was_line = [&](const Region& r) {
        for (const auto& [box, col] : old_lines)
            if ((box & r.box).area() > 0 && std::abs(col.r - r.color[0]) <= 4 && std::abs(col.g - r.color[1]) <= 4 &&
                std::abs(col.b - r.color[2]) <= 4)
                return true;
        return false;
    };
    for (int i = 0; i < int(regs.list.size()); ++i) {
        Region& reg = regs.list[size_t(i)];
        const cv::Vec3b c = reg.color;
        // The first region in the background's colour is the canvas itself.
        if (i == 0 && std::max({std::abs(c[0] - background.r), std::abs(c[1] - background.g), std::abs(c[2] - background.b)}) <= 2)
            continue;
        std::vector<Stroke> polys = as_strokes(trace_region(rgb, regs, i, opts.trace));
        if (reg.ink_candidate && reg.ink != reg.color) {
            // Traced in its ink too; the closer wins (later regions trace against the winner).
            reg.color = reg.ink;
            std::vector<Stroke> inked = as_strokes(trace_region(rgb, regs, i, opts.trace));
            if (local_error(rgb, regs, i, inked, renderer) < local_error(rgb, regs, i, polys, renderer)) polys = std::move(inked);
            else reg.color = c;
        }
        LineOptions lo = line_opts;
        if (given && !was_line(reg)) lo.max_error_ratio = lo.max_error_ratio_inter;
        if (opts.lines)
            if (std::vector<Stroke> l = lines_instead(rgb, regs, i, polys, renderer, built, lo, pool); !l.empty()) {
                polys = std::move(l);
                ++out.lines;
            }
        for (Stroke& s : polys) {
            if (opts.lines) {
                Stroke d = s;
                (d.kind == StrokeKind::Curve ? d.curve.supersample : d.polygon.supersample) = kBuiltGrid;
                (void)renderer.draw(built, d);
            }
            out.strokes.push_back(std::move(s));
            out.region.push_back(i);
        }
    }

    // The grid whose rendering is closest to the source (smaller grids on ties: faster).
    const uint32_t W = uint32_t(rgb.cols), H = uint32_t(rgb.rows);
    uint64_t best_sse = std::numeric_limits<uint64_t>::max();
    Canvas canvas(W, H, background);
    for (uint8_t g : opts.grids) {
        uint64_t work = 0;
        for (Stroke& s : out.strokes) {
            if (s.kind == StrokeKind::Curve) { s.curve.supersample = g; continue; }
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
    for (Stroke& s : out.strokes) (s.kind == StrokeKind::Curve ? s.curve.supersample : s.polygon.supersample) = out.grid;
    return out;
}

}  // namespace spt::cartoon
