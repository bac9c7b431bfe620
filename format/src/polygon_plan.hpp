// Internal: how the reference encoder codes a polygon's outline (SPEC.md 7.4, polygon 5), the
// plan that code_polygon (stroke_stream.hpp) codes; polygon_plan.cpp chooses it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "spt/types.hpp"

namespace spt::detail {

// How the encoder codes a polygon's outline (chosen by plan_polygon).
struct PolygonPlan {
    uint32_t shift = 4;          // lattice: vertex offsets are multiples of 2^shift (Q4)
    int mode = 0;                // 0 differences, 1 differences from the previous one, 2 conic
    int64_t cs[2] = {0, 0};      // conic: rotation (C, S), Q30
    uint32_t matrix_shift = 4;   // conic: M's entries are multiples of 2^matrix_shift
    int64_t m[4] = {0, 0, 0, 0}; // conic: M = (a b; c d), Q4
};

// The encoder's rotation for a regular n-gon: (round(2^30 cos 2pi/n), round(2^30 sin 2pi/n)).
// Floating point is fine here: (C, S) are coded, so the decoder never recomputes them.
void conic_rotation_for(size_t n, int64_t cs[2]);

struct PolygonModels;
// The encoder's choice of lattice shift and prediction mode for a polygon: the mode, and for the
// conic mode its matrix, that code the outline in the fewest bits given the contexts' current
// state.
PolygonPlan plan_polygon(const PolygonModels& pm, const std::vector<PolygonVertex>& pts);

}  // namespace spt::detail
