// Renderer throughput: a 1280x720 key frame of 30,000 stamp strokes, as a painter makes them.
// Prints the median frames per second and nanoseconds per stroke over several runs for a
// "painting" distribution (most strokes small) and a "mid-size" one, plus affine and curve
// frames, each for the old path (clear + draw() per stroke) and render() (tiled), measured
// alternately in the same run (thread CPU time), and render() with 1 and 2 threads (wall
// time, so only meaningful on an idle machine). Checks that all paths give identical bytes.
// Usage: render_bench [runs] [painting|mid|affine|curve]   (deterministic content)
#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "spt/render.hpp"

namespace {

constexpr uint32_t kW = 1280, kH = 720;
constexpr int kStrokes = 30000;

// A soft bristle blob: an elliptical falloff with streaks along u, like a brush dab.
spt::Template bristle(std::mt19937& rng) {
    spt::Template t;
    t.kind = spt::TemplateKind::Bitmap;
    t.width = t.height = 60;
    t.pixels.resize(3600);
    std::uniform_real_distribution<double> streak(0.6, 1.0);
    std::vector<double> rows(60);
    for (double& r : rows) r = streak(rng);
    for (int y = 0; y < 60; ++y)
        for (int x = 0; x < 60; ++x) {
            const double u = (x + 0.5) / 30.0 - 1.0, v = (y + 0.5) / 30.0 - 1.0;
            const double d = u * u + v * v;
            const double a = d >= 1.0 ? 0.0 : std::min(1.0, (1.0 - d) * 3.0) * rows[size_t(y)];
            t.pixels[size_t(y) * 60 + size_t(x)] = uint8_t(std::lround(255.0 * a));
        }
    return t;
}

spt::Header header() {
    spt::Header h;
    h.width = kW;
    h.height = kH;
    // From about 1/8 of the canvas width down to 4 px, elongated like brush strokes.
    h.sets = {{160, 64}, {96, 40}, {48, 20}, {24, 10}, {12, 6}, {4, 4}};
    h.orientations = spt::default_orientations(8);
    return h;
}

std::vector<spt::Stroke> stamp_frame(const std::vector<double>& set_weights, uint32_t seed) {
    std::mt19937 rng(seed);
    std::discrete_distribution<int> set(set_weights.begin(), set_weights.end());
    std::uniform_int_distribution<int> x(0, int(kW) * 16 - 1), y(0, int(kH) * 16 - 1), byte(0, 255),
        tmpl(0, 3), orient(0, 7), translucent(0, 3);
    std::vector<spt::Stroke> v;
    for (int i = 0; i < kStrokes; ++i) {
        spt::StampStroke s;
        s.set = uint8_t(set(rng));
        s.tmpl = uint8_t(tmpl(rng));
        s.orient = uint8_t(orient(rng));
        s.x = x(rng);
        s.y = y(rng);
        s.color = {uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng)),
                   uint8_t(translucent(rng) == 0 ? 128 + byte(rng) / 2 : 255)};
        v.push_back(spt::Stroke::make_stamp(s));
    }
    return v;
}

std::vector<spt::Stroke> affine_frame(int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> x(0, int(kW) * 16 - 1), y(0, int(kH) * 16 - 1), byte(0, 255),
        m(-160, 160), tmpl(0, 6);
    std::vector<spt::Stroke> v;
    for (int i = 0; i < n; ++i) {
        spt::AffineStroke s;
        s.tmpl = uint8_t(tmpl(rng));
        s.tx = x(rng); s.ty = y(rng);
        do { s.a = m(rng); s.b = m(rng); s.c = m(rng); s.d = m(rng); } while (int64_t(s.a) * s.d == int64_t(s.b) * s.c);
        s.color = {uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng)), 200};
        v.push_back(spt::Stroke::make_affine(s));
    }
    return v;
}

std::vector<spt::Stroke> curve_frame(int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> x(0, int(kW) * 16 - 1), y(0, int(kH) * 16 - 1), byte(0, 255),
        step(-200, 200), w(16, 120);
    std::vector<spt::Stroke> v;
    for (int i = 0; i < n; ++i) {
        spt::CurveStroke s;
        int32_t px = x(rng), py = y(rng);
        for (int k = 0; k < 8; ++k) {
            s.points.push_back({px, py, uint32_t(w(rng))});
            px += step(rng);
            py += step(rng);
        }
        s.color = {uint8_t(byte(rng)), uint8_t(byte(rng)), uint8_t(byte(rng)), 230};
        v.push_back(spt::Stroke::make_curve(std::move(s)));
    }
    return v;
}

using bench::median;
using bench::thread_seconds;
using bench::wall_seconds;

// The old path: clear, then draw() stroke after stroke onto the whole canvas.
void draw_loop(const spt::Renderer& r, spt::Canvas& c, const std::vector<spt::Stroke>& strokes) {
    c.fill(spt::Rgb8{255, 255, 255});
    for (const auto& s : strokes) (void)r.draw(c, s);
}

// Runs alternate between the paths so that both see the same machine load.
void measure(const char* name, const spt::Renderer& r, const std::vector<spt::Stroke>& strokes, int runs) {
    spt::Canvas a(kW, kH), b(kW, kH), c2(kW, kH);
    if (!r.render(b, strokes).ok()) { std::printf("%s: render failed\n", name); std::exit(1); }  // warm the cache
    draw_loop(r, a, strokes);
    if (!r.render(c2, strokes, 2).ok() || a.rgb != b.rgb || c2.rgb != b.rgb) {
        std::printf("%s: render() and the draw() loop disagree\n", name);
        std::exit(1);
    }
    std::vector<double> old_s, new_s, thr_wall, one_wall;
    for (int i = 0; i < runs; ++i) {
        double t0 = thread_seconds();
        draw_loop(r, a, strokes);
        old_s.push_back(thread_seconds() - t0);
        t0 = thread_seconds();
        (void)r.render(b, strokes);
        new_s.push_back(thread_seconds() - t0);
        t0 = wall_seconds();
        (void)r.render(b, strokes, 1);
        one_wall.push_back(wall_seconds() - t0);
        t0 = wall_seconds();
        (void)r.render(c2, strokes, 2);
        thr_wall.push_back(wall_seconds() - t0);
    }
    uint64_t px = 0;
    for (const auto& s : strokes) {
        spt::Mask m;
        if (r.stroke_mask(s, m).ok())
            for (uint8_t v : m.a) px += v != 0;
    }
    const double o = median(old_s), n = median(new_s);
    std::printf("%-34s %6zu strokes %5.0f px/stroke overdraw %4.1f\n", name, strokes.size(),
                double(px) / double(strokes.size()), double(px) / (double(kW) * kH));
    std::printf("    draw() loop (old)   %8.1f fps %9.1f ns/stroke   [thread CPU]\n", 1.0 / o, o * 1e9 / double(strokes.size()));
    std::printf("    render() 1 thread   %8.1f fps %9.1f ns/stroke   [thread CPU]  x%.2f vs old\n", 1.0 / n,
                n * 1e9 / double(strokes.size()), o / n);
    std::printf("    render() 1 thread   %8.1f fps   [wall]   2 threads %8.1f fps [wall]  x%.2f\n", 1.0 / median(one_wall),
                1.0 / median(thr_wall), median(one_wall) / median(thr_wall));
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 15;
    const std::string only = argc > 2 ? argv[2] : "";  // painting | mid | affine | curve
    std::mt19937 rng(1234);
    std::vector<spt::Template> templates;
    for (int i = 0; i < 4; ++i) templates.push_back(bristle(rng));
    for (auto k : {spt::TemplateKind::Ellipse, spt::TemplateKind::Rectangle, spt::TemplateKind::Triangle}) {
        spt::Template t;
        t.kind = k;
        templates.push_back(t);
    }
    auto made = spt::Renderer::create(header(), templates);
    if (!made.ok()) { std::printf("create: %s\n", made.error().message.c_str()); return 1; }
    const spt::Renderer& r = **made;
    std::printf("render_bench: %ux%u, median of %d runs\n", kW, kH, runs);
    // Painting: coarse to fine, each set covering the canvas about once where it is used, so
    // strokes get more numerous as they get smaller (per set, coarse to fine, in per mille).
    if (only.empty() || only == "painting")
        measure("stamps, painting distribution", r, stamp_frame({3, 10, 30, 100, 300, 557}, 1), runs);
    // Heavier: most strokes mid-size, about 20x overdraw.
    if (only.empty() || only == "mid")
        measure("stamps, mid-size distribution", r, stamp_frame({0, 10, 40, 40, 10, 0}, 2), runs);
    if (only.empty() || only == "affine") measure("affine (bitmap+analytic, ~20 px)", r, affine_frame(10000, 3), runs);
    if (only.empty() || only == "curve") measure("curves (8 points, 1-7 px wide)", r, curve_frame(2000, 4), runs);
    return 0;
}
