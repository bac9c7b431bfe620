// Stroke orientation fields: for every pixel, the index into the header's orientation table
// along which a stroke centred there is laid (its long axis, template u).
#pragma once

#include <cstdint>
#include <vector>

#include "paint/painter.hpp"

namespace spt::paint {

// Lindeberg-style multiscale edges (scale-space edges with gamma-normalised derivatives,
// gamma = 1/2). Returns a width*height map, 255 on edge pixels, and, per pixel, the gradient
// angle (radians, image coordinates, y down) at the scale where the normalised gradient
// magnitude peaks.
struct EdgeMap {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> edge;      // 255 = edge
    std::vector<float> grad_angle;  // atan2(gy, gx) at the selected scale
};
EdgeMap multiscale_edges(const ImageView& img);

// The orientation index, for every pixel, of a stroke laid along the edge direction (the
// gradient turned by pi/2). Edges: the direction of the nearest multiscale edge pixel
// (distance transform with labels). Gradient: the local structure tensor's dominant direction.
// Random: empty (the painter draws orientations at random).
std::vector<uint8_t> orientation_field(const ImageView& img, const std::vector<Orientation>& table,
                                       OrientMode mode);

// The table entry closest to the (undirected) angle `theta` in image coordinates.
uint8_t nearest_orientation(const std::vector<Orientation>& table, double theta);

}  // namespace spt::paint
