// What coding a shape again costs in a range-coded frame, roughly, in bytes: the cost model the
// keep, motion and line rules share (measured with spt info --json on the cartoon clips:
// a polygon 8 + 2 a vertex, a line 6 + 2.5 a point). Stamps are 5.6-6 bytes; each rule says
// which it uses.
#pragma once

#include "spt/types.hpp"

namespace spt::cartoon {

// A polygon's or a curve's bytes; `stamp` for any other stroke.
inline double shape_bytes(const Stroke& s, double stamp) {
    if (s.kind == StrokeKind::Polygon) return 8.0 + 2.0 * double(s.polygon.points.size());
    if (s.kind == StrokeKind::Curve) return 6.0 + 2.5 * double(s.curve.points.size());
    return stamp;
}

}  // namespace spt::cartoon
