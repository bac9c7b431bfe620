// Connected regions of one flat colour, ordered so that drawing each one's outer outline
// filled, first to last, rebuilds the picture: a region drawn later lies inside the filled
// outline of every region it is nested in, so holes need no outlines of their own.
#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace spt::cartoon {

struct Region {
    int label = 0;             // palette index
    cv::Vec3b color;           // mean of the region's pixels away from its edge
    // A thin region with no flat inside (small text, hairlines) may be ink rather than a fill:
    // `ink` is the far end of its blends with `around`, the colour it lies on; the fill layer
    // traces it in both colours and keeps the closer (fill_layer.cpp).
    bool ink_candidate = false;
    cv::Vec3b ink, around;
    int64_t pixels = 0;
    int64_t filled_area = 0;   // pixels inside its outer outline (holes included)
    cv::Rect box;
};

struct Regions {
    cv::Mat id;                 // CV_32S: per pixel, the index into `list` (drawing order)
    std::vector<Region> list;   // drawing order: larger filled outlines first
};

// Merges components smaller than `min_pixels` into their neighbours (by nearest colour), then
// splits the labels into 8-connected regions and orders them.
Regions find_regions(const cv::Mat& rgb, cv::Mat labels, const std::vector<cv::Vec3b>& palette, int min_pixels);

}  // namespace spt::cartoon
