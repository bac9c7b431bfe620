// Zhang-Suen thinning of a binary mask to a one-pixel skeleton, as OpenCV's
// cv::ximgproc::thinning(THINNING_ZHANGSUEN) computes it, pixel for pixel (tested against it).
// Here rather than through opencv_contrib's ximgproc because that module links OpenCV's image
// codecs, and through them GDAL and some 130 libraries (185 MB) into spt, for this one function.
#pragma once

#include <opencv2/core.hpp>

namespace spt::cartoon {

// `mask`: CV_8UC1, 0 or 255 (other values: >= 128 is set, as OpenCV's division by 255 rounds).
// `out`: CV_8UC1 0/255 skeleton. The outermost rows and columns are never removed.
void thin_zhang_suen(const cv::Mat& mask, cv::Mat& out);

}  // namespace spt::cartoon
