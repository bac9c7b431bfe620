// Small synthetic clips for the video tests: textured scenes moving smoothly, several "shots"
// that differ in colour and layout so that the joins are true hard cuts.
#pragma once

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace spt_test {

// Shot `shot` at time `t` (frames): a smooth colour field plus hard-edged shapes, the whole
// scene translating by (vx, vy) pixels a frame.
inline std::vector<uint8_t> scene_frame(int shot, double t, uint32_t w, uint32_t h, double vx = 1.0,
                                        double vy = 0.5) {
    std::vector<uint8_t> rgb(size_t(w) * h * 3);
    const double fa = 0.05 + 0.02 * shot, fb = 0.08 - 0.015 * shot;
    const double ox = vx * t, oy = vy * t;
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const double u = x - ox, v = y - oy;
            double r = 128 + 70 * std::sin(fa * u + shot) * std::cos(fb * v);
            double g = 128 + 70 * std::cos(fb * u - 0.5 * shot) * std::sin(fa * v + 1);
            double b = 128 + 60 * std::sin(0.03 * (u + v) + 2.0 * shot);
            // A lattice of hard-edged discs: edges for the edge maps and for the flow.
            const double cx = std::fmod(std::fmod(u, 40.0) + 40.0, 40.0) - 20;
            const double cy = std::fmod(std::fmod(v, 40.0) + 40.0, 40.0) - 20;
            if (cx * cx + cy * cy < (8 + 3 * shot) * (8 + 3 * shot)) {
                r = shot == 1 ? 230 : 30 + 60 * shot;
                g = shot == 2 ? 220 : 40;
                b = shot == 0 ? 200 : 60;
            }
            uint8_t* p = &rgb[(size_t(y) * w + x) * 3];
            p[0] = uint8_t(std::clamp(r, 0.0, 255.0));
            p[1] = uint8_t(std::clamp(g, 0.0, 255.0));
            p[2] = uint8_t(std::clamp(b, 0.0, 255.0));
        }
    }
    return rgb;
}

// A fresh, empty temporary folder for one test, removed when the test process exits (pass or
// fail), so that repeated test runs do not fill the temp directory.
inline std::filesystem::path temp_dir(const std::string& name) {
    static struct RemoveAtExit {
        std::vector<std::filesystem::path> dirs;
        ~RemoveAtExit() {
            std::error_code ec;
            for (const auto& d : dirs) std::filesystem::remove_all(d, ec);
        }
    } made;
    auto d = std::filesystem::temp_directory_path() / ("spt_video_test_" + name + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(d);
    std::filesystem::create_directories(d);
    made.dirs.push_back(d);
    return d;
}

}  // namespace spt_test
