// Native side of bench/web_bench.sh: a player's Reader::render_frame (one thread) on a .spt
// file, frames in order and random seeks, as the browser side (bench/web_bench.mjs) measures
// them with the same seek sequence.
//   play_bench FILE.spt [passes]   prints {"in_order_ms": M, "random_ms": M, "frames": N}
// Each figure is the median over passes of (wall time of the pass) / (frames drawn); wall
// time, as the browser has no thread clock.
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "bench_timing.hpp"
#include "spt/reader.hpp"

namespace {

// The seek sequence (also in web_bench.mjs): xorshift32 from 1, as many positions as frames.
std::vector<size_t> seeks(size_t frames) {
    std::vector<size_t> out;
    uint32_t x = 1;
    for (size_t i = 0; i < frames; ++i) {
        x ^= x << 13;
        x ^= x >> 17;
        x ^= x << 5;
        out.push_back(x % frames);
    }
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: play_bench FILE.spt [passes]\n");
        return 2;
    }
    const int passes = argc > 2 ? std::atoi(argv[2]) : 5;
    auto r = spt::Reader::open(argv[1]);
    if (!r) {
        std::fprintf(stderr, "play_bench: %s: %s\n", argv[1], r.error().message.c_str());
        return 1;
    }
    spt::Reader& reader = **r;
    const size_t n = reader.frames().size();
    spt::Canvas canvas(reader.info().header.width, reader.info().header.height);
    auto draw = [&](size_t pos) {
        if (spt::Status s = reader.render_frame(pos, canvas, 1); !s) {
            std::fprintf(stderr, "play_bench: %s: frame %zu: %s\n", argv[1], pos, s.error().message.c_str());
            std::exit(1);
        }
    };
    draw(0);  // warm: the footprint caches, as a player has them after its first frame
    const std::vector<size_t> order = seeks(n);
    std::vector<double> in_order, random;
    for (int p = 0; p < passes; ++p) {
        double t = bench::wall_seconds();
        for (size_t i = 0; i < n; ++i) draw(i);
        in_order.push_back((bench::wall_seconds() - t) * 1e3 / double(n));
        t = bench::wall_seconds();
        for (size_t i : order) draw(i);
        random.push_back((bench::wall_seconds() - t) * 1e3 / double(order.size()));
    }
    std::printf("{\"in_order_ms\": %.3f, \"random_ms\": %.3f, \"frames\": %zu}\n", bench::median(in_order),
                bench::median(random), n);
    return 0;
}
