// Writes the synthetic clips of tests/video/change_clips.hpp (still, nearly still, pan, fade,
// cut, flicker, held) as PNG sequences for bench/corpus_bench.py:
//   synthetic_clips OUT [FRAMES [WIDTH HEIGHT]]  ->  OUT/NAME/f.0000.png ...
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "io/image_io.hpp"
#include "video/change_clips.hpp"

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: synthetic_clips OUT [FRAMES [WIDTH HEIGHT]]\n");
        return 2;
    }
    const int frames = argc > 2 ? std::atoi(argv[2]) : 24;
    const uint32_t w = argc > 4 ? uint32_t(std::atoi(argv[3])) : 320, h = argc > 4 ? uint32_t(std::atoi(argv[4])) : 180;
    if (frames < 2 || w < 32 || h < 32) {
        std::fprintf(stderr, "synthetic_clips: need at least 2 frames of 32x32\n");
        return 2;
    }
    for (const spt_test::ChangeClip& c : spt_test::change_clips(w, h, frames)) {
        const std::filesystem::path d = std::filesystem::path(argv[1]) / c.name;
        std::filesystem::create_directories(d);
        for (size_t i = 0; i < c.frames.size(); ++i) {
            char name[32];
            std::snprintf(name, sizeof name, "f.%04zu.png", i);
            if (spt::Status s = spt::io::write_image((d / name).string(), c.width, c.height, c.frames[i].data()); !s) {
                std::fprintf(stderr, "synthetic_clips: %s\n", s.error().message.c_str());
                return 1;
            }
        }
    }
    return 0;
}
