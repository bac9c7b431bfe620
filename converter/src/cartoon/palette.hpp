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

// Sparser palettes a painting short of its PSNR target also tries (PaletteOptions::min_share):
// compressed video's ringing and blends pile into colours of their own that take pixels from
// the flat fills around them, and the residual stamps paint what they stood for in fewer bytes.
// Still at 36 dB, bytes with a share of 1e-4 / 3e-4 / 1e-3 / 1e-2: butterfly frame 40 13,344
// (9 colours) / 16,176 / 8,973 (6) / 8,564 (4), its 12 frames 31,764 at 1e-4, 22,881 at 1e-3,
// 83,999 at 1e-2 (its key frame short of the target); taffy frame 30 20,347 (2 colours) /
// - / 20,748 (2) / short of the target; the star's thin black outline is a colour under 1e-2.
// Tried in turn, each only while the one before won: 1e-2 takes the butterfly frame 40 to 8,585
// bytes (4 colours) after 8,995 at 1e-3.
constexpr double kSparsePaletteShares[] = {1e-3, 1e-2};

// Whether find_palette with min_share `share` (and `opts` otherwise) finds fewer colours than
// with `opts`: a painting with the same colours is not tried again.
bool sparser_palette_has_fewer_colours(const cv::Mat& rgb, const PaletteOptions& opts, double share);

// Per pixel, the index of the nearest palette colour (CV_32S).
cv::Mat label_pixels(const cv::Mat& rgb, const std::vector<cv::Vec3b>& palette);

}  // namespace spt::cartoon
