// Internal: the coding-1 edit stream (SPEC.md 7.5), written once for both directions like
// stroke_stream.hpp. `C` is RangeEncoder or RangeDecoder.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "range_coder.hpp"
#include "spt/types.hpp"

namespace spt::detail {

// The edit stream (SPEC.md 7.5): removal gaps, then the motion field.
struct EditCoderState {
    UIntModel gap, run;
    SIntModel mvx, mvy;
};

inline std::pair<int32_t, int32_t> motion_prediction(const std::vector<std::pair<int16_t, int16_t>>& v,
                                                     size_t i, uint32_t cols) {
    const size_t c = i % cols, r = i / cols;
    auto at = [&](size_t cc, size_t rr) { return v[rr * cols + cc]; };
    if (r == 0) {
        if (c == 0) return {0, 0};
        return {at(c - 1, 0).first, at(c - 1, 0).second};
    }
    const auto t = at(c, r - 1);
    const auto l = c > 0 ? at(c - 1, r) : t;
    const auto tr = c + 1 < cols ? at(c + 1, r - 1) : t;
    auto med = [](int32_t a, int32_t b, int32_t d) { return std::max(std::min(a, b), std::min(std::max(a, b), d)); };
    return {med(l.first, t.first, tr.first), med(l.second, t.second, tr.second)};
}

template <class C>
bool code_edits(C& c, EditCoderState& st, Frame& f, uint32_t removed_count, uint64_t prev_live, SyntaxError& err) {
    c.set_field(Field::Removal);
    // The decoder grows the list as indices decode: a count is only a claim until then.
    if constexpr (C::kDecoding) f.removed.reserve(std::min<uint32_t>(removed_count, 1u << 16));
    int64_t prev = -1;
    for (uint32_t i = 0; i < removed_count; ++i) {
        const int64_t given = C::kDecoding ? prev + 1 : int64_t(f.removed[i]);
        const uint64_t gap = code_uint(c, st.gap, uint64_t(given - prev - 1));
        const int64_t v = prev + 1 + int64_t(gap);
        if (uint64_t(v) >= prev_live || v > 0xFFFFFFFFll) {
            err.set("removed index " + std::to_string(v) + " is not below the live count " + std::to_string(prev_live));
            return false;
        }
        if constexpr (C::kDecoding) f.removed.push_back(uint32_t(v));
        prev = v;
    }
    auto& m = f.motion;
    if (m.vectors.empty()) return true;
    c.set_field(Field::Motion);
    const size_t total = m.vectors.size();
    size_t i = 0;
    while (i < total) {
        // Length of the run of blocks whose vector equals its prediction (encoder side).
        uint64_t run = 0;
        if constexpr (!C::kDecoding) {
            size_t j = i;
            while (j < total) {
                const auto p = motion_prediction(m.vectors, j, m.cols);
                if (p.first != m.vectors[j].first || p.second != m.vectors[j].second) break;
                ++j;
            }
            run = j - i;
        }
        run = code_uint(c, st.run, run);
        if (run > total - i) { err.set("motion run of " + std::to_string(run) + " blocks passes the field's end"); return false; }
        for (uint64_t k = 0; k < run; ++k, ++i) {
            const auto p = motion_prediction(m.vectors, i, m.cols);
            m.vectors[i] = {int16_t(p.first), int16_t(p.second)};
        }
        if (i == total) break;
        const auto p = motion_prediction(m.vectors, i, m.cols);
        const int64_t rx = code_sint(c, st.mvx, int64_t(m.vectors[i].first) - p.first);
        const int64_t ry = code_sint(c, st.mvy, int64_t(m.vectors[i].second) - p.second);
        if (rx == 0 && ry == 0) { err.set("zero motion residual outside a run"); return false; }
        const int64_t x = p.first + rx, y = p.second + ry;
        if (x < -32768 || x > 32767 || y < -32768 || y > 32767) { err.set("motion vector outside i16"); return false; }
        m.vectors[i] = {int16_t(x), int16_t(y)};
        ++i;
    }
    return true;
}

}  // namespace spt::detail
