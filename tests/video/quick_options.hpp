// The options of the video tests' quick paints: four stroke sets, few strokes, a fixed seed and
// thread count, no signal handlers (the test process keeps its own).
#pragma once

#include <cstdint>
#include <string>

#include "video/video_paint.hpp"

namespace spt_test {

inline spt::video::VideoPaintOptions quick_options(const std::string& out, uint64_t seed, int threads,
                                                    uint64_t max_strokes, uint64_t max_inter_strokes) {
    spt::video::VideoPaintOptions o;
    o.output = out;
    o.sets = 4;
    o.paint.seed = seed;
    o.paint.threads = threads;
    o.paint.max_strokes = max_strokes;
    o.max_inter_strokes = max_inter_strokes;
    o.install_signal_handlers = false;
    return o;
}

}  // namespace spt_test
