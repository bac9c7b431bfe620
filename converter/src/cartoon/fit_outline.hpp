// Refines a simplified outline: Douglas-Peucker keeps contour points, so a straight run between
// two kept points sits on one side of the points it replaces (up to the tolerance, all along a
// long edge). Here each side becomes the least-squares line of the contour points it replaces,
// moved out by half a sub-pixel (the contour runs through the centres of the boundary
// sub-pixels, the edge lies between them), and each vertex the meeting point of its two lines.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace spt::cartoon {

// `contour`: a closed outline of sub-pixel centres (cv::findContours); `simple`: its
// Douglas-Peucker vertices, each a point of `contour`, in the same order; `inside`: the binary
// image traced (to tell outward from inward). Returns one vertex per `simple` vertex.
std::vector<cv::Point2f> fit_outline(const std::vector<cv::Point>& contour, const std::vector<cv::Point>& simple,
                                     const cv::Mat& inside);

}  // namespace spt::cartoon
