// Synthetic clips for the cases the shared corpus lacks, each a rule's test: an inter frame
// must cost what changed (issue 34). Every clip is a flat-colour drawing (outlined shapes, the
// cartoon style's material) over textured paper (the default painter's), so both styles meet
// both kinds of region. Deterministic: the same frames on every platform.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace spt_test {

struct ChangeClip {
    std::string name;
    uint32_t width = 0, height = 0;
    std::vector<std::vector<uint8_t>> frames;  // RGB8, width * height * 3 each
};

namespace change_detail {

inline uint32_t hash(uint32_t x, uint32_t y, uint32_t seed) {
    uint32_t h = x * 0x8DA6B343u ^ y * 0xD8163841u ^ seed * 0xCB1AB31Fu;
    h ^= h >> 13;
    h *= 0x5BD1E995u;
    return h ^ (h >> 15);
}

// Paper: a smooth grain at a few pixels' scale plus a fine one, around a warm grey.
inline double paper(double x, double y) {
    const int ix = int(std::floor(x / 4)), iy = int(std::floor(y / 4));
    const double fx = x / 4 - ix, fy = y / 4 - iy;
    auto v = [&](int a, int b) { return double(hash(uint32_t(a), uint32_t(b), 7) & 255) / 255.0; };
    const double smooth = (v(ix, iy) * (1 - fx) + v(ix + 1, iy) * fx) * (1 - fy) +
                          (v(ix, iy + 1) * (1 - fx) + v(ix + 1, iy + 1) * fx) * fy;
    const double fine = double(hash(uint32_t(int(std::floor(x))), uint32_t(int(std::floor(y))), 11) & 255) / 255.0;
    return 200 + 24 * (smooth - 0.5) + 10 * (fine - 0.5);
}

// The drawing at offset (ox, oy) of the whole picture, with a small disc at (dx, dy), scene
// `scene` (0 or 1: two different pictures), brightness `gain`.
inline std::vector<uint8_t> draw(uint32_t w, uint32_t h, double ox, double oy, double dx, double dy, int scene,
                                 double gain) {
    std::vector<uint8_t> rgb(size_t(w) * h * 3);
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const double u = x + ox, v = y + oy;
            const double p = paper(u, v);
            double c[3] = {p, p * 0.97, p * 0.9};
            auto fill = [&](double r, double g, double b) { c[0] = r; c[1] = g; c[2] = b; };
            // An outlined body: a rectangle (scene 0) or a large disc (scene 1).
            if (scene == 0) {
                const double bx = std::abs(u - 0.5 * w), by = std::abs(v - 0.55 * h);
                const double ex = 0.22 * w, ey = 0.25 * h;
                if (bx < ex + 2 && by < ey + 2) fill(20, 20, 30);
                if (bx < ex && by < ey) fill(60, 110, 200);
            } else {
                const double r = std::hypot(u - 0.4 * w, v - 0.5 * h), R = 0.3 * h;
                if (r < R + 2) fill(25, 15, 10);
                if (r < R) fill(230, 170, 40);
            }
            // The small moving part: a red disc with an outline.
            const double d = std::hypot(u - dx, v - dy);
            if (d < 9) fill(15, 15, 15);
            if (d < 7) fill(210, 40, 40);
            for (int k = 0; k < 3; ++k) {
                rgb[(size_t(y) * w + x) * 3 + k] = uint8_t(std::clamp(std::lround(c[k] * gain), 0L, 255L));
            }
        }
    }
    return rgb;
}

}  // namespace change_detail

// The seven cases, `frames` frames each of w x h:
//   still         the same frame throughout
//   nearly-still  a small part moves a pixel a frame over still paper
//   pan           the whole picture moves 2 pixels a frame
//   fade          brightness falls 6% a frame
//   cut           a different picture from the middle on
//   flicker       brightness alternates by 4%
//   held          the small part moves 3 pixels a frame, then stops for the second half
inline std::vector<ChangeClip> change_clips(uint32_t w = 192, uint32_t h = 128, int frames = 8) {
    using change_detail::draw;
    std::vector<ChangeClip> clips;
    auto clip = [&](const std::string& name, auto frame_at) {
        ChangeClip c{name, w, h, {}};
        for (int t = 0; t < frames; ++t) c.frames.push_back(frame_at(t));
        clips.push_back(std::move(c));
    };
    const double dx = 0.75 * w, dy = 0.3 * h;
    const int half = frames / 2;
    clip("still", [&](int) { return draw(w, h, 0, 0, dx, dy, 0, 1.0); });
    clip("nearly-still", [&](int t) { return draw(w, h, 0, 0, dx + t, dy, 0, 1.0); });
    clip("pan", [&](int t) { return draw(w, h, 2.0 * t, 0, dx + 2.0 * t, dy, 0, 1.0); });
    clip("fade", [&](int t) { return draw(w, h, 0, 0, dx, dy, 0, 1.0 - 0.06 * t); });
    clip("cut", [&](int t) { return draw(w, h, 0, 0, dx, dy, t < half ? 0 : 1, 1.0); });
    clip("flicker", [&](int t) { return draw(w, h, 0, 0, dx, dy, 0, t % 2 ? 0.96 : 1.0); });
    clip("held", [&](int t) { return draw(w, h, 0, 0, dx + 3.0 * std::min(t, half), dy, 0, 1.0); });
    return clips;
}

// The share of pixels whose colour changed from `a` to `b` by more than the RMS error of
// `target_psnr` (root mean square over the three channels): the p of an inter frame's budget.
inline double changed_share(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b, double target_psnr) {
    const double rms = 255.0 / std::pow(10.0, target_psnr / 20.0);
    const double limit = 3 * rms * rms;
    size_t n = 0;
    for (size_t i = 0; i + 2 < a.size(); i += 3) {
        double s = 0;
        for (int k = 0; k < 3; ++k) {
            const double d = double(a[i + k]) - double(b[i + k]);
            s += d * d;
        }
        n += s > limit;
    }
    return a.empty() ? 0 : double(n) / double(a.size() / 3);
}

}  // namespace spt_test
