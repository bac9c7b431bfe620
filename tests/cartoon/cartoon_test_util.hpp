// What the cartoon sequence tests share: a synthetic sequence written as f.####.png, and the
// PSNR of a rendered frame against its source.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <opencv2/core.hpp>

#include "converter/temp_dir.hpp"
#include "io/image_io.hpp"

namespace spt_test {

// Frames 0..n-1 of `art(i)` (8-bit RGB) as dir/f.0000.png ...
template <class Art>
void write_frames(const TempDir& dir, int n, Art art) {
    for (int i = 0; i < n; ++i) {
        const cv::Mat f = art(i);
        char name[32];
        std::snprintf(name, sizeof name, "f.%04d.png", i);
        ASSERT_TRUE(spt::io::write_image(dir.file(name), uint32_t(f.cols), uint32_t(f.rows), f.data));
    }
}

// PSNR (dB) of `rendered` against `source`, both interleaved 8-bit of rendered.size() bytes.
inline double psnr_of(const std::vector<uint8_t>& rendered, const uint8_t* source) {
    double sse = 0;
    for (size_t p = 0; p < rendered.size(); ++p) {
        const double d = double(rendered[p]) - double(source[p]);
        sse += d * d;
    }
    return 10 * std::log10(255.0 * 255.0 * double(rendered.size()) / std::max(sse, 1.0));
}

}  // namespace spt_test
