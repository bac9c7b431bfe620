// Painting render output (issue 17): per input, the same painting stored as 8-bit sRGB and as
// scene-linear half codes (full and coarser mantissas), with alpha when the input has it:
// bytes, paint time (thread CPU, 1 thread, median of --runs), error in a log domain
// (mean |log2((p + e) / (s + e))|, e = 1e-3, over R, G, B of premultiplied linear values), in
// sRGB after the view transform (PSNR of a * srgb(min(1, straight)), the painting over black)
// (over sRGB grey 128) and of the alpha (mean |A_p - A_s| overall, inside the source's matte (A_s > 0), outside).
//
// usage: scene_paint_bench [--runs N] [--lambda X] [--target-psnr DB] [--alpha-weight W] IMAGE...
// e.g.   build/bench/scene_paint_bench /work/shared/media/exr/orbit/orbit.0012.exr
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>
#include <vector>

#include "bench_timing.hpp"
#include "frames/scene_image.hpp"
#include "paint/scene_paint.hpp"
#include "spt/color.hpp"
#include "spt/writer.hpp"

using namespace spt;

namespace {

struct Variant {
    const char* name;
    bool linear;
    int mantissa;
    bool weighted = true;  // RefitOptions::highlight_weight
    int coding = 2;        // the writer codes coding 2 as 1 for format 1.3 canvases
};

// Premultiplied linear value of a painted pixel channel.
double painted_linear(const Canvas& c, size_t i, int k) {
    if (!c.rgb16.empty()) return half_to_float(c.rgb16[3 * i + k]);
    const double a = c.alpha.empty() ? 1.0 : c.alpha[i] / 255.0;
    if (a == 0) return 0;
    return a * paint::srgb_decode(std::min(1.0, c.rgb[3 * i + k] / 255.0 / a));
}

double painted_alpha(const Canvas& c, size_t i) { return c.alpha.empty() ? 1.0 : c.alpha[i] / 255.0; }

// The sRGB view over a mid-grey background (sRGB 128): over black, dark fringes a painting
// leaves outside the matte would not show.
double view(double v, double a) {
    static const double grey = paint::srgb_decode(128.0 / 255.0);
    return 255.0 * paint::srgb_encode(std::min(1.0, v + (1.0 - a) * grey));
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 3;
    double lambda = -1, target = 0;
    int alpha_weight = 0;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--runs" && i + 1 < argc) runs = std::atoi(argv[++i]);
        else if (a == "--lambda" && i + 1 < argc) lambda = std::atof(argv[++i]);
        else if (a == "--target-psnr" && i + 1 < argc) target = std::atof(argv[++i]);
        else if (a == "--alpha-weight" && i + 1 < argc) alpha_weight = std::atoi(argv[++i]);
        else files.push_back(a);
    }
    if (files.empty()) {
        std::fprintf(stderr, "usage: scene_paint_bench [--runs N] [--lambda X] [--target-psnr DB] IMAGE...\n");
        return 2;
    }
    const Variant variants[] = {{"srgb8", false, 10},          {"srgb8-c1", false, 10, true, 1},
                                {"linear-m10", true, 10},      {"linear", true, 7},
                                {"linear-m5", true, 5},        {"lin-unwtd", true, 7, false}};
    std::printf("%-22s %-10s %8s %8s %8s %9s %9s %8s %8s %8s %7s\n", "image", "encoding", "strokes", "bytes", "paint_s",
                "log2_err", "view_dB", "a_mae", "a_in", "a_out", "peak");
    for (const std::string& path : files) {
        auto img = io::read_scene_image(path);
        if (!img) {
            std::fprintf(stderr, "%s\n", img.error().message.c_str());
            return 1;
        }
        const uint32_t W = img->width, H = img->height;
        const size_t n = size_t(W) * H;
        const paint::LinearView view_in{W, H, img->rgba.data()};
        paint::PaintSetup setup = paint::make_setup(W, H, Rgb8{255, 255, 255}, paint::default_sets(W, H, 6), paint::default_templates());
        paint::PaintOptions po;
        po.threads = 1;
        po.color_step = 12;
        if (lambda >= 0) po.lambda = lambda;
        po.target_psnr = target;
        if (alpha_weight > 0) po.alpha_weight = alpha_weight;
        for (const Variant& v : variants) {
            paint::SceneTarget t;
            t.alpha = img->has_alpha && paint::has_transparency(view_in);  // as --alpha auto
            t.linear = v.linear;
            t.refit.mantissa_bits = v.mantissa;
            t.refit.highlight_weight = v.weighted;
            std::vector<double> secs;
            Result<paint::ScenePainting> sp = make_error(Code::BadState, "no run");
            for (int r = 0; r < runs; ++r) {
                const double t0 = bench::thread_seconds();
                sp = paint::paint_scene(view_in, setup, po, t);
                secs.push_back(bench::thread_seconds() - t0);
                if (!sp) break;
            }
            if (!sp) {
                std::fprintf(stderr, "%s: %s\n", path.c_str(), sp.error().message.c_str());
                return 1;
            }
            StreamInfo info;
            info.header = sp->header;
            info.templates = setup.templates;
            const std::string out = (std::filesystem::temp_directory_path() / ("scene_paint_bench." + std::to_string(::getpid()) + ".spt")).string();
            WriterOptions wo;
            wo.coding = v.coding == 2 ? Coding::Replay : Coding::Range;
            auto w = Writer::create(out, info, wo);
            uint64_t bytes = 0;
            if (w) {
                Frame f;
                f.added = sp->strokes;
                f.replay = paint::replay_info(setup, po, W, H);
                if ((*w)->append(f) && (*w)->finish()) bytes = (*w)->stats().total_bytes;
            }
            std::filesystem::remove(out);
            double log_err = 0, sse = 0, a_all = 0, a_in = 0, a_out = 0, peak = 0;
            size_t n_in = 0, n_out = 0;
            for (size_t i = 0; i < n; ++i) {
                const double as = img->rgba[4 * i + 3], ap = painted_alpha(sp->canvas, i);
                for (int k = 0; k < 3; ++k) {
                    const double s = img->rgba[4 * i + k], p = painted_linear(sp->canvas, i, k);
                    peak = std::max(peak, p);
                    log_err += std::abs(std::log2((p + 1e-3) / (s + 1e-3)));
                    const double d = view(p, ap) - view(s, as);
                    sse += d * d;
                }
                const double da = std::abs(ap - as);
                a_all += da;
                if (as > 0) { a_in += da; ++n_in; } else { a_out += da; ++n_out; }
            }
            const double view_db = sse > 0 ? 10 * std::log10(255.0 * 255.0 * 3.0 * double(n) / sse) : 99;
            std::printf("%-22s %-10s %8llu %8llu %8.3f %9.4f %9.2f %8.4f %8.4f %8.4f %7.2f\n",
                        std::filesystem::path(path).filename().string().c_str(), v.name,
                        (unsigned long long)sp->strokes.size(), (unsigned long long)bytes, bench::median(secs),
                        log_err / (3.0 * double(n)), view_db, a_all / double(n), n_in ? a_in / double(n_in) : 0.0,
                        n_out ? a_out / double(n_out) : 0.0, peak);
        }
    }
    return 0;
}
