// The flat colours of a cartoon: the few colours that many pixels share exactly or nearly,
// found as the peaks of a colour histogram (anti-aliased and compressed pixels spread over
// many bins, flat fills pile into a few).
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace spt::cartoon {

struct PaletteOptions {
    int max_colors = 96;      // peaks taken at most
    double min_share = 1e-4;  // a peak needs at least this share of the pixels (and 8 pixels)
    int merge_distance = 20;  // colours closer than this (max over channels) are one peak
};

// Peaks of `rgb` (CV_8UC3, RGB order), each the mean of the pixels near it, most frequent first.
std::vector<cv::Vec3b> find_palette(const cv::Mat& rgb, const PaletteOptions& opts);

// Per pixel, the index of the nearest palette colour (CV_32S).
cv::Mat label_pixels(const cv::Mat& rgb, const std::vector<cv::Vec3b>& palette);

}  // namespace spt::cartoon
