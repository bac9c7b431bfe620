// spt::concatenate (spt cat) throughput: a 10,000-frame file made of 100 shots of 100 frames
// (a key frame of 8,000 stamps, then inter frames of 300 new stamps, removals and a motion
// field: about the bytes of painted 1080p video). Prints the median wall time of `runs` joins
// (page cache warm), MB/s of output, and a plain copy of the same bytes for scale.
//   build/bench/cat_bench [runs]
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "bench_timing.hpp"
#include "spt/concat.hpp"
#include "spt/spt.hpp"

namespace fs = std::filesystem;
using namespace spt;

namespace {

StreamInfo info() {
    StreamInfo i;
    i.header.width = 1920;
    i.header.height = 1080;
    i.header.fps = {24, 1};
    i.header.sets = {{216, 108}, {120, 60}, {68, 34}, {38, 19}, {21, 11}, {12, 6}};
    i.header.orientations = default_orientations(8);
    Template r, e;
    r.kind = TemplateKind::Rectangle;
    e.kind = TemplateKind::Ellipse;
    i.templates = {r, e};
    i.metadata = {{"software", "cat_bench"}};
    return i;
}

Stroke stamp(std::mt19937& rng) {
    auto u = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    StampStroke s;
    s.set = uint8_t(u(0, 5));
    s.tmpl = uint8_t(u(0, 1));
    s.orient = uint8_t(u(0, 7));
    s.x = u(0, 1919 * 16);
    s.y = u(0, 1079 * 16);
    s.color = {uint8_t(u(0, 255)), uint8_t(u(0, 255)), uint8_t(u(0, 255)), 255};
    return Stroke::make_stamp(s);
}

void write_shot(const std::string& path, uint32_t seed) {
    std::mt19937 rng(seed);
    auto w = Writer::create(path, info(), {Coding::Range});
    if (!w) { std::fprintf(stderr, "%s\n", w.error().message.c_str()); std::exit(1); }
    size_t live = 0;
    for (uint32_t i = 0; i < 100; ++i) {
        Frame f;
        f.index = i;
        f.type = i == 0 ? FrameType::Key : FrameType::Inter;
        if (i > 0) {
            for (uint32_t k = 0; k < live; k += 27) f.removed.push_back(k);
            f.motion.block_size = 16;
            f.motion.cols = 120;
            f.motion.rows = 68;
            for (int k = 0; k < 120 * 68; ++k) f.motion.vectors.push_back({int16_t(k % 7 - 3), int16_t(k % 5 - 2)});
        }
        for (int k = 0, n = i == 0 ? 8000 : 300; k < n; ++k) f.added.push_back(stamp(rng));
        live = i == 0 ? f.added.size() : live - f.removed.size() + f.added.size();
        if (auto st = (*w)->append(f); !st) { std::fprintf(stderr, "%s\n", st.error().message.c_str()); std::exit(1); }
    }
    if (auto st = (*w)->finish(); !st) { std::fprintf(stderr, "%s\n", st.error().message.c_str()); std::exit(1); }
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    const fs::path dir = fs::temp_directory_path() / ("spt_cat_bench_" + std::to_string(getpid()));
    fs::create_directories(dir);
    std::vector<std::string> parts;
    uint64_t in_bytes = 0;
    for (uint32_t k = 0; k < 100; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "shot-%03u.spt", k);
        parts.push_back((dir / name).string());
        write_shot(parts.back(), 100 + k);
        in_bytes += fs::file_size(parts.back());
    }
    const std::string out = (dir / "joined.spt").string();
    std::vector<double> cat_s, copy_s;
    uint64_t bytes = 0, frames = 0;
    for (int r = 0; r < runs; ++r) {
        double t0 = bench::wall_seconds();
        auto rep = concatenate(parts, out);
        cat_s.push_back(bench::wall_seconds() - t0);
        if (!rep) { std::fprintf(stderr, "%s\n", rep.error().message.c_str()); return 1; }
        bytes = rep->bytes;
        frames = rep->frames;
        // For scale: copying the same parts into one file without looking at them.
        t0 = bench::wall_seconds();
        {
            std::FILE* o = std::fopen((dir / "copy.bin").c_str(), "wb");
            std::vector<char> buf(1 << 20);
            for (const auto& p : parts) {
                std::FILE* i = std::fopen(p.c_str(), "rb");
                for (size_t n; (n = std::fread(buf.data(), 1, buf.size(), i)) > 0;) std::fwrite(buf.data(), 1, n, o);
                std::fclose(i);
            }
            std::fclose(o);
        }
        copy_s.push_back(bench::wall_seconds() - t0);
    }
    const double c = bench::median(cat_s), p = bench::median(copy_s);
    std::printf("cat_bench: 100 shots x 100 frames = %llu frames, %.1f MB in, %.1f MB out\n",
                (unsigned long long)frames, double(in_bytes) / 1e6, double(bytes) / 1e6);
    std::printf("spt cat (concatenate): median %.3f s of %d: %.0f MB/s, %.0f frames/s\n", c, runs,
                double(bytes) / 1e6 / c, double(frames) / c);
    std::printf("plain copy of the parts:  median %.3f s: %.0f MB/s (cat / copy time %.2f)\n", p,
                double(in_bytes) / 1e6 / p, c / p);
    fs::remove_all(dir);
    return 0;
}
