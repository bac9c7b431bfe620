// Refines a simplified outline: Douglas-Peucker keeps contour points, so a straight run between
// two kept points sits on one side of the points it replaces (up to the tolerance, all along a
// long edge). Here each side becomes the least-squares line of the contour points it replaces,
// moved out by half a sub-pixel (the contour runs through the centres of the boundary
// sub-pixels, the edge lies between them), and each vertex the meeting point of its two lines,
// or on a gentle bend (lines within 11.5 degrees, where the meeting point runs off) the middle of
// its feet on the two: a curve's chords all lie inside it, and refitted they run through it.
#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace spt::cartoon {

// `contour`: a closed outline of sub-pixel centres (cv::findContours); `simple`: its
// Douglas-Peucker vertices, each a point of `contour`, in the same order; `inside`: the binary
// image traced (to tell outward from inward). Returns one vertex per `simple` vertex.
std::vector<cv::Point2f> fit_outline(const std::vector<cv::Point>& contour, const std::vector<cv::Point>& simple,
                                     const cv::Mat& inside);

// The same for an open polyline (a line's centre points `pts`) and the indices `kept` of its
// Douglas-Peucker points (increasing, first and last included): each run between two kept
// points becomes the least-squares line of the points it spans, each inner vertex the meeting
// point of its two lines (kept where that is more than `reach` from it, or the lines nearly
// parallel), each end its projection on its run's line. One point per kept index.
std::vector<cv::Point2d> fit_polyline(const std::vector<cv::Point2d>& pts, const std::vector<size_t>& kept, double reach);

}  // namespace spt::cartoon
