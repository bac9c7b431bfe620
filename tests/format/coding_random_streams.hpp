// Test helper: random but valid stroke streams (all stroke kinds, key and inter frames with
// removals and motion) and small file helpers, shared by the container and coding tests.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "spt/spt.hpp"

namespace spt::testing {

struct RandomStream {
    StreamInfo info;
    std::vector<Frame> frames;
};

struct StreamShapeOptions {
    uint32_t max_side = 300;
    int frames = 6;
    int max_strokes = 60;
    bool painter_like = false;  // stamps on pixel centres, coarse-to-fine sets
    // Polygon strokes too (format 1.2). Off by default, so that the streams of the golden files
    // (tests/format/make_golden.cpp) stay what they were.
    bool polygons = false;
    // Anti-aliased curves (format 1.4): the header gets the curve_grid flag and curves random
    // grids. Off by default for the same reason.
    bool curve_grid = false;
};

inline Stroke random_stroke(std::mt19937_64& rng, const StreamInfo& info, bool painter_like, int set_hint,
                            bool polygons = false) {
    auto uni = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
    const auto& h = info.header;
    const int64_t W = h.width, H = h.height;
    Rgba8 col{uint8_t(uni(0, 255)), uint8_t(uni(0, 255)), uint8_t(uni(0, 255)), uint8_t(uni(0, 3) ? 255 : uni(0, 254))};
    const int kind = painter_like ? 0 : int(uni(0, polygons ? 3 : 2));
    if (kind == 3) {
        PolygonStroke p;
        p.color = col;
        p.supersample = uint8_t(uni(0, 2) ? 0 : uni(2, 16));
        const int n = int(uni(3, 24));
        const int64_t unit = uni(0, 1) ? 8 : 1;  // half-pixel lattice (shift 3) or any Q4
        int32_t x = int32_t(unit * (uni(0, 16 * W) / unit)), y = int32_t(unit * (uni(0, 16 * H) / unit));
        for (int i = 0; i < n; ++i) {
            p.points.push_back({x, y});
            x += int32_t(unit * (uni(-300, 300) / unit));
            y += int32_t(unit * (uni(-300, 300) / unit));
        }
        return Stroke::make_polygon(std::move(p));
    }
    const auto T = int64_t(info.templates.size());
    if (kind == 0) {
        StampStroke s;
        s.set = uint8_t(painter_like ? set_hint : uni(0, int64_t(h.sets.size()) - 1));
        s.tmpl = uint8_t(uni(0, T - 1));
        s.orient = uint8_t(uni(0, int64_t(h.orientations.size()) - 1));
        if (painter_like) {
            s.x = int32_t(16 * uni(0, W - 1) + 8);
            s.y = int32_t(16 * uni(0, H - 1) + 8);
        } else {
            s.x = int32_t(uni(-16 * 40, 16 * (W + 40)));
            s.y = int32_t(uni(-16 * 40, 16 * (H + 40)));
        }
        s.color = col;
        return Stroke::make_stamp(s);
    }
    if (kind == 1) {
        AffineStroke a;
        a.tmpl = uint8_t(uni(0, T - 1));
        a.tx = int32_t(uni(-16 * 20, 16 * (W + 20)));
        a.ty = int32_t(uni(-16 * 20, 16 * (H + 20)));
        do {
            a.a = int32_t(uni(-4000, 4000)); a.b = int32_t(uni(-4000, 4000));
            a.c = int32_t(uni(-4000, 4000)); a.d = int32_t(uni(-4000, 4000));
        } while (int64_t(a.a) * a.d - int64_t(a.b) * a.c == 0);
        a.color = col;
        return Stroke::make_affine(a);
    }
    CurveStroke c;
    c.color = col;
    const int n = int(uni(1, 12));
    int32_t x = int32_t(uni(0, 16 * W)), y = int32_t(uni(0, 16 * H));
    uint32_t w = uint32_t(uni(0, 400));
    for (int i = 0; i < n; ++i) {
        c.points.push_back({x, y, w});
        x += int32_t(uni(-200, 200)); y += int32_t(uni(-200, 200));
        w = uint32_t(std::max<int64_t>(0, int64_t(w) + uni(-30, 30)));
    }
    if (h.curve_grid) c.supersample = uint8_t(uni(0, 2) ? 0 : uni(2, 16));  // drawn only then: other streams keep their values
    return Stroke::make_curve(std::move(c));
}

// One key frame of `strokes` on a w x h canvas with one 4x4 stroke set, `orientations`
// orientations and no templates: the smallest stream that shows one rule.
inline RandomStream one_frame_stream(uint32_t w, uint32_t h, std::vector<Stroke> strokes, uint32_t orientations = 1) {
    RandomStream rs;
    rs.info.header.width = w;
    rs.info.header.height = h;
    rs.info.header.sets = {{4, 4}};
    rs.info.header.orientations = default_orientations(orientations);
    Frame k;
    k.added = std::move(strokes);
    rs.frames = {k};
    return rs;
}

inline RandomStream make_random_stream(uint64_t seed, const StreamShapeOptions& o = {}) {
    std::mt19937_64 rng(seed);
    auto uni = [&](int64_t lo, int64_t hi) { return std::uniform_int_distribution<int64_t>(lo, hi)(rng); };
    RandomStream rs;
    auto& h = rs.info.header;
    h.width = uint32_t(uni(1, o.max_side));
    h.height = uint32_t(uni(1, o.max_side));
    h.fps = {24, 1};
    h.background = {uint8_t(uni(0, 255)), uint8_t(uni(0, 255)), uint8_t(uni(0, 255))};
    const int sets = int(uni(1, 16));
    for (int i = 0; i < sets; ++i) h.sets.push_back({uint16_t(uni(1, 64)), uint16_t(uni(1, 64))});
    h.orientations = default_orientations(int(uni(1, 64)));
    const int T = int(uni(1, 5));
    for (int i = 0; i < T; ++i) {
        Template t;
        t.kind = TemplateKind(uni(0, 3));
        if (t.kind == TemplateKind::Bitmap) {
            t.width = uint16_t(uni(1, 24));
            t.height = uint16_t(uni(1, 24));
            for (int k = 0; k < t.width * t.height; ++k) t.pixels.push_back(uint8_t(uni(0, 2) ? 255 * uni(0, 1) : uni(0, 255)));
        }
        t.name = "t" + std::to_string(i);
        rs.info.templates.push_back(t);
    }
    rs.info.metadata = {{"software", "spt tests"}, {"painter.seed", std::to_string(seed)}};
    if (o.curve_grid) {
        h.curve_grid = true;
        h.version_minor = kCurveGridMinorVersion;
    }
    size_t live = 0;
    for (int fi = 0; fi < o.frames; ++fi) {
        Frame f;
        f.index = uint32_t(fi);
        f.type = (fi == 0 || uni(0, 4) == 0) ? FrameType::Key : FrameType::Inter;
        if (f.type == FrameType::Inter) {
            for (uint32_t i = 0; i < live; ++i)
                if (uni(0, 5) == 0) f.removed.push_back(i);
            if (uni(0, 1)) {
                auto& m = f.motion;
                m.block_size = uint16_t(uni(8, 64));
                m.cols = uint16_t((h.width + m.block_size - 1) / m.block_size);
                m.rows = uint16_t((h.height + m.block_size - 1) / m.block_size);
                const int16_t gx = int16_t(uni(-40, 40)), gy = int16_t(uni(-40, 40));
                for (int k = 0; k < m.cols * m.rows; ++k)
                    m.vectors.push_back(uni(0, 2) ? std::pair<int16_t, int16_t>{gx, gy}
                                                  : std::pair<int16_t, int16_t>{int16_t(uni(-100, 100)), int16_t(uni(-100, 100))});
            }
        }
        const int n = int(uni(0, o.max_strokes));
        for (int i = 0; i < n; ++i) {
            const int set = int(std::min<int64_t>(int64_t(h.sets.size()) - 1, int64_t(i) * int64_t(h.sets.size()) / std::max(n, 1)));
            f.added.push_back(random_stroke(rng, rs.info, o.painter_like, set, o.polygons));
        }
        live = (f.type == FrameType::Key ? 0 : live - f.removed.size()) + f.added.size();
        rs.frames.push_back(std::move(f));
    }
    return rs;
}

// Per process: CTest runs every test case as its own process, several at once.
inline std::string temp_path(const std::string& name) {
    static const auto dir = std::filesystem::temp_directory_path() / ("spt-format-tests-" + std::to_string(::getpid()));
    static const struct RemoveAtExit {
        ~RemoveAtExit() { std::error_code ec; std::filesystem::remove_all(dir, ec); }
    } remove_at_exit;
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

inline std::vector<uint8_t> read_bytes(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(f), {});
}

inline Status write_stream(const std::string& path, const RandomStream& rs, Coding coding) {
    WriterOptions o;
    o.coding = coding;
    auto w = Writer::create(path, rs.info, o);
    if (!w) return w.error();
    for (const auto& f : rs.frames)
        if (auto st = (*w)->append(f); !st) return st;
    return (*w)->finish();
}

inline bool same_frame(const Frame& a, const Frame& b) {
    return a.index == b.index && a.type == b.type && a.removed == b.removed && a.added == b.added &&
           a.motion.vectors == b.motion.vectors &&
           (a.motion.empty() || (a.motion.block_size == b.motion.block_size && a.motion.cols == b.motion.cols &&
                                  a.motion.rows == b.motion.rows));
}

}  // namespace spt::testing
