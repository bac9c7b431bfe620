// The canvas pixels a stroke's coverage mask covers: the walk the cartoon painter's keep and
// order rules make over masks, clipped to the canvas, in one place.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "spt/render.hpp"

namespace spt::cartoon {

// Calls f(px, py, i, a) for every pixel of a W x H canvas that `m` covers (a > 0), i being the
// pixel's index in the mask, row by row. An f that returns bool stops the walk by returning
// true, and visit_covered then returns true; an f that returns nothing sees every pixel.
template <class F>
bool visit_covered(const Mask& m, int32_t W, int32_t H, F f) {
    for (uint32_t y = 0; y < m.h; ++y) {
        const int32_t py = m.y0 + int32_t(y);
        if (py < 0 || py >= H) continue;
        for (uint32_t x = 0; x < m.w; ++x) {
            const int32_t px = m.x0 + int32_t(x);
            const size_t i = size_t(y) * m.w + x;
            if (m.a[i] == 0 || px < 0 || px >= W) continue;
            if constexpr (std::is_void_v<std::invoke_result_t<F, int32_t, int32_t, size_t, uint8_t>>)
                f(px, py, i, m.a[i]);
            else if (f(px, py, i, m.a[i]))
                return true;
        }
    }
    return false;
}

}  // namespace spt::cartoon
