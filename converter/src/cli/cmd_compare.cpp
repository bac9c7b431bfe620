// spt compare: PSNR and SSIM of two images, or of two sequences frame by frame.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "io/image_io.hpp"
#include "spt_json/write.hpp"
#include "io/metrics.hpp"
#include "io/sequence.hpp"

namespace spt::cli {

namespace {

bool is_sequence_arg(const std::string& s) {
    std::error_code ec;
    return io::is_sequence_pattern(s) || std::filesystem::is_directory(s, ec);
}

std::string psnr_text(double p) {
    if (std::isinf(p)) return "inf";
    char b[32];
    std::snprintf(b, sizeof b, "%.3f", p);
    return b;
}

// PSNR as JSON: identical images have no finite PSNR; null says so.
json::Doc json_psnr(double p) { return std::isinf(p) ? json::Doc(nullptr) : json::number(p); }

struct Pair {
    long frame;
    std::string a, b;
};

}  // namespace

int cmd_compare(int argc, char** argv) {
    Args args("compare", "PSNR and SSIM of one image (or sequence) against another",
              "spt compare A B [--json] [--frames RANGE] [--min-psnr DB] [--min-ssim S]");
    args.positional("A", "an image, a sequence pattern (####, %04d, @) or a folder of frames")
        .positional("B", "the image (or sequence) to compare with, same size as A")
        .flag("json", "print one JSON document on stdout")
        .option("frames", "RANGE", "sequences only: compare these frame numbers (\"1-10,20\")")
        .option("min-psnr", "DB", "exit 1 when PSNR (the lowest, for sequences) is below DB")
        .option("min-ssim", "S", "exit 1 when SSIM (the lowest, for sequences) is below S")
        .epilog(std::string(
                    "PSNR is over the R, G and B samples together (8-bit, peak 255); identical "
                    "images print 'inf' (JSON: null). SSIM is the mean SSIM of the luma planes "
                    "(Y = 0.299 R + 0.587 G + 0.114 B of the sRGB values; 11x11 Gaussian window, "
                    "sigma 1.5). Images are read as 8-bit sRGB: alpha over white; ") +
                io::kLinearToSrgbText +
                ".\n\nSequences are paired by frame number; a frame of A missing from B is an "
                "error.\n\nJSON keys, images: a, b, width, height, mse, psnr, ssim, identical.\n"
                "Sequences: a, b, count, frames [{frame, mse, psnr, ssim}], mean_psnr (from the "
                "mean MSE), min_psnr, mean_ssim, min_ssim.");
    if (int rc = args.parse(argc, argv); rc >= 0) return rc;
    double min_psnr = -1, min_ssim = -2;
    if (!args.get_double("min-psnr", min_psnr) || !args.get_double("min-ssim", min_ssim)) return 2;
    const std::string a = args.pos("A"), b = args.pos("B");
    const bool json = args.has("json");

    const bool seq = is_sequence_arg(a);
    if (seq != is_sequence_arg(b)) return args.usage_error("A and B must both be images or both be sequences");
    if (!seq && args.has("frames")) return args.usage_error("--frames applies to sequences only");

    std::vector<Pair> pairs;
    if (seq) {
        auto range = io::parse_frame_range(args.get("frames"));
        if (!range) return args.usage_error(range.error().message);
        auto la = io::list_sequence(a, *range);
        if (!la) { std::fprintf(stderr, "spt compare: %s\n", la.error().message.c_str()); return 1; }
        auto lb = io::list_sequence(b, *range);
        if (!lb) { std::fprintf(stderr, "spt compare: %s\n", lb.error().message.c_str()); return 1; }
        std::map<long, std::string> bmap;
        for (auto& f : *lb) bmap[f.frame] = f.path;
        for (auto& f : *la) {
            auto it = bmap.find(f.frame);
            if (it == bmap.end()) {
                std::fprintf(stderr, "spt compare: frame %ld (%s) has no counterpart in %s\n", f.frame,
                             f.path.c_str(), b.c_str());
                return 1;
            }
            pairs.push_back({f.frame, f.path, it->second});
        }
    } else {
        pairs.push_back({0, a, b});
    }

    struct Row { long frame; io::ImageMetrics m; };
    std::vector<Row> rows;
    uint32_t w = 0, h = 0;
    for (const auto& p : pairs) {
        auto ia = io::read_image(p.a);
        if (!ia) { std::fprintf(stderr, "spt compare: %s\n", ia.error().message.c_str()); return 1; }
        auto ib = io::read_image(p.b);
        if (!ib) { std::fprintf(stderr, "spt compare: %s\n", ib.error().message.c_str()); return 1; }
        if (ia->width != ib->width || ia->height != ib->height) {
            std::fprintf(stderr, "spt compare: sizes differ: %s is %ux%u, %s is %ux%u\n", p.a.c_str(),
                         ia->width, ia->height, p.b.c_str(), ib->width, ib->height);
            return 1;
        }
        w = ia->width, h = ia->height;
        rows.push_back({p.frame, io::compare_rgb8(ia->rgb.data(), ib->rgb.data(), w, h)});
    }

    double lowest_psnr = std::numeric_limits<double>::infinity(), lowest_ssim = 1, mse_sum = 0, ssim_sum = 0;
    for (const auto& r : rows) {
        lowest_psnr = std::min(lowest_psnr, r.m.psnr);
        lowest_ssim = std::min(lowest_ssim, r.m.ssim);
        mse_sum += r.m.mse;
        ssim_sum += r.m.ssim;
    }
    const double mean_mse = mse_sum / double(rows.size());
    const double mean_psnr = mean_mse == 0 ? std::numeric_limits<double>::infinity()
                                           : 10.0 * std::log10(255.0 * 255.0 / mean_mse);
    const double mean_ssim = ssim_sum / double(rows.size());

    if (json) {
        json::Doc j = {{"a", a}, {"b", b}};
        if (!seq) {
            const auto& m = rows[0].m;
            j["width"] = w;
            j["height"] = h;
            j["mse"] = json::number(m.mse);
            j["psnr"] = json_psnr(m.psnr);
            j["ssim"] = json::number(m.ssim);
            j["identical"] = m.mse == 0;
        } else {
            j["count"] = uint64_t(rows.size());
            json::Doc& frames = j["frames"] = json::Doc::array();
            for (const auto& r : rows)
                frames.push_back({{"frame", int64_t(r.frame)}, {"mse", json::number(r.m.mse)}, {"psnr", json_psnr(r.m.psnr)},
                                  {"ssim", json::number(r.m.ssim)}});
            j["mean_psnr"] = json_psnr(mean_psnr);
            j["min_psnr"] = json_psnr(lowest_psnr);
            j["mean_ssim"] = json::number(mean_ssim);
            j["min_ssim"] = json::number(lowest_ssim);
        }
        std::printf("%s\n", json::dump(j, 2).c_str());
    } else if (!seq) {
        std::printf("PSNR %s dB  SSIM %.5f  (%ux%u, MSE %.4f)\n", psnr_text(rows[0].m.psnr).c_str(),
                    rows[0].m.ssim, w, h, rows[0].m.mse);
    } else {
        for (const auto& r : rows)
            std::printf("frame %ld: PSNR %s dB  SSIM %.5f\n", r.frame, psnr_text(r.m.psnr).c_str(), r.m.ssim);
        std::printf("%zu frames: PSNR mean %s dB (from mean MSE), min %s dB; SSIM mean %.5f, min %.5f\n",
                    rows.size(), psnr_text(mean_psnr).c_str(), psnr_text(lowest_psnr).c_str(), mean_ssim,
                    lowest_ssim);
    }
    if (args.has("min-psnr") && lowest_psnr < min_psnr) {
        std::fprintf(stderr, "spt compare: PSNR %s dB is below --min-psnr %g\n", psnr_text(lowest_psnr).c_str(), min_psnr);
        return 1;
    }
    if (args.has("min-ssim") && lowest_ssim < min_ssim) {
        std::fprintf(stderr, "spt compare: SSIM %.5f is below --min-ssim %g\n", lowest_ssim, min_ssim);
        return 1;
    }
    return 0;
}

}  // namespace spt::cli
