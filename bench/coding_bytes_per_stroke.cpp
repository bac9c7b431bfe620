// Bytes per stroke of the stored and range codings, per-field bits, and encode/decode
// throughput, on synthetic painter-like streams (stamps on pixel centres, coarse-to-fine sets,
// colours sampled from a smooth synthetic image) and on uniformly random streams of all kinds.
//   coding_bytes_per_stroke [strokes_per_frame=20000] [frames=4]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "spt/spt.hpp"

using namespace spt;

namespace {

StreamInfo make_info(uint32_t w, uint32_t h) {
    StreamInfo info;
    info.header.width = w;
    info.header.height = h;
    info.header.sets = {{64, 16}, {32, 8}, {16, 4}, {8, 2}, {4, 2}};
    info.header.orientations = default_orientations(8);
    Template t;
    t.kind = TemplateKind::Ellipse;
    info.templates = {t};
    return info;
}

Rgba8 image_colour(double x, double y, std::mt19937_64& rng) {
    std::normal_distribution<double> noise(0, 6);
    auto ch = [&](double v) { return uint8_t(std::clamp(v + noise(rng), 0.0, 255.0)); };
    return {ch(128 + 100 * std::sin(x / 150) * std::cos(y / 90)), ch(120 + 80 * std::cos(x / 200 + y / 300)),
            ch(100 + 90 * std::sin((x + y) / 250)), 255};
}

std::vector<Frame> painter_frames(const StreamInfo& info, int n, int frames, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<Frame> out;
    const auto& h = info.header;
    for (int fi = 0; fi < frames; ++fi) {
        Frame f;
        f.index = uint32_t(fi);
        for (int i = 0; i < n; ++i) {
            StampStroke s;
            s.set = uint8_t(std::min<int>(4, i * 5 / n));
            s.orient = uint8_t(rng() % 8);
            const uint32_t px = uint32_t(rng() % h.width), py = uint32_t(rng() % h.height);
            s.x = int32_t(16 * px + 8);
            s.y = int32_t(16 * py + 8);
            s.color = image_colour(px, py, rng);
            f.added.push_back(Stroke::make_stamp(s));
        }
        out.push_back(std::move(f));
    }
    return out;
}

std::vector<Frame> random_frames(const StreamInfo& info, int n, int frames, uint64_t seed) {
    std::mt19937_64 rng(seed);
    auto uni = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
    std::vector<Frame> out;
    const int64_t W = info.header.width, H = info.header.height;
    for (int fi = 0; fi < frames; ++fi) {
        Frame f;
        f.index = uint32_t(fi);
        for (int i = 0; i < n; ++i) {
            const Rgba8 c{uint8_t(uni(0, 255)), uint8_t(uni(0, 255)), uint8_t(uni(0, 255)), uint8_t(uni(0, 1) ? 255 : 128)};
            const int k = int(uni(0, 2));
            if (k == 0) {
                StampStroke s{uint8_t(uni(0, 4)), 0, uint8_t(uni(0, 7)), int32_t(uni(0, 16 * W)), int32_t(uni(0, 16 * H)), c};
                f.added.push_back(Stroke::make_stamp(s));
            } else if (k == 1) {
                AffineStroke a{0, int32_t(uni(0, 16 * W)), int32_t(uni(0, 16 * H)), int32_t(uni(16, 800)), int32_t(uni(-100, 100)),
                               int32_t(uni(-100, 100)), int32_t(uni(16, 800)), c};
                f.added.push_back(Stroke::make_affine(a));
            } else {
                CurveStroke cv;
                cv.color = c;
                int32_t x = int32_t(uni(0, 16 * W)), y = int32_t(uni(0, 16 * H));
                for (int p = 0, np = int(uni(2, 8)); p < np; ++p) {
                    cv.points.push_back({x, y, uint32_t(uni(16, 80))});
                    x += int32_t(uni(-160, 160));
                    y += int32_t(uni(-160, 160));
                }
                f.added.push_back(Stroke::make_curve(cv));
            }
        }
        out.push_back(std::move(f));
    }
    return out;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void run(const char* label, const StreamInfo& info, const std::vector<Frame>& frames) {
    size_t strokes = 0;
    for (const auto& f : frames) strokes += f.added.size();
    std::printf("\n%s: %zu frames, %zu strokes, canvas %ux%u\n", label, frames.size(), strokes, info.header.width,
                info.header.height);
    std::printf("  %-8s %12s %10s %12s %12s\n", "coding", "body bytes", "B/stroke", "enc Mstk/s", "dec Mstk/s");
    for (Coding coding : {Coding::Stored, Coding::Range}) {
        const std::string path = (std::filesystem::temp_directory_path() / "spt-bench-coding.spt").string();
        WriterOptions o;
        o.coding = coding;
        auto t0 = std::chrono::steady_clock::now();
        auto w = Writer::create(path, info, o);
        if (!w) { std::fprintf(stderr, "%s\n", w.error().message.c_str()); std::exit(1); }
        for (const auto& f : frames)
            if (auto st = (*w)->append(f); !st) { std::fprintf(stderr, "%s\n", st.error().message.c_str()); std::exit(1); }
        if (auto st = (*w)->finish(); !st) { std::fprintf(stderr, "%s\n", st.error().message.c_str()); std::exit(1); }
        const double enc = seconds_since(t0);
        const WriteStats ws = (*w)->stats();
        auto r = Reader::open(path);
        t0 = std::chrono::steady_clock::now();
        for (size_t i = 0; i < frames.size(); ++i)
            if (!(*r)->read_frame(i)) { std::fprintf(stderr, "decode failed\n"); std::exit(1); }
        const double dec = seconds_since(t0);
        const uint64_t body = ws.stroke_bytes + ws.motion_bytes;
        std::printf("  %-8s %12llu %10.3f %12.2f %12.2f\n", coding == Coding::Stored ? "stored" : "range",
                    static_cast<unsigned long long>(body), double(body) / double(strokes), strokes / enc / 1e6,
                    strokes / dec / 1e6);
        if (coding == Coding::Range) {
            std::printf("  range-coded bits per stroke by field:");
            for (size_t fi = 0; fi < kFieldCount; ++fi)
                if (ws.fields.bits[fi] > 0) std::printf(" %s %.2f", field_name(Field(fi)), ws.fields.bits[fi] / double(strokes));
            std::printf("\n");
        }
        std::filesystem::remove(path);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const int n = argc > 1 ? std::atoi(argv[1]) : 20000;
    const int frames = argc > 2 ? std::atoi(argv[2]) : 4;
    const StreamInfo info = make_info(1280, 720);
    run("painter-like stamps (1280x720, 5 sets, 8 orientations)", info, painter_frames(info, n, frames, 1));
    run("random strokes of all kinds", info, random_frames(info, n, frames, 2));
    std::printf("\nlog2(1280*720) = %.2f bits: the floor for a uniformly random pixel position\n", std::log2(1280.0 * 720.0));
    return 0;
}
