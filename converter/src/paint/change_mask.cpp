#include "paint/change_mask.hpp"

#include <algorithm>
#include <cstdlib>

namespace spt::paint {

ChangeMask changed_pixels(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height, double rms, int grow,
                          const uint8_t* alpha_a, const uint8_t* alpha_b) {
    ChangeMask m;
    const size_t n = size_t(width) * height;
    std::vector<uint8_t> raw(n, 0);
    const double limit = 3 * rms * rms;
    for (size_t p = 0; p < n; ++p, a += 3, b += 3) {
        const int dr = a[0] - b[0], dg = a[1] - b[1], db = a[2] - b[2];
        const bool alpha_moved = alpha_a && alpha_b && std::abs(int(alpha_a[p]) - int(alpha_b[p])) > rms;
        if (double(dr * dr + dg * dg + db * db) > limit || alpha_moved) {
            raw[p] = 1;
            ++m.changed;
        }
    }
    if (m.changed == 0 || grow <= 0) {
        m.mask = raw;
        m.raw = std::move(raw);
        return m;
    }
    // Widened by a square of side 2 grow + 1: rows, then columns (separable, O(n grow)).
    const int W = int(width), H = int(height);
    std::vector<uint8_t> rows(n, 0);
    for (int y = 0; y < H; ++y) {
        const uint8_t* r = raw.data() + size_t(y) * W;
        uint8_t* o = rows.data() + size_t(y) * W;
        for (int x = 0; x < W; ++x) {
            if (!r[x]) continue;
            std::fill(o + std::max(0, x - grow), o + std::min(W, x + grow + 1), uint8_t(1));
        }
    }
    m.mask.assign(n, 0);
    for (int y = 0; y < H; ++y) {
        const uint8_t* r = rows.data() + size_t(y) * W;
        for (int x = 0; x < W; ++x) {
            if (!r[x]) continue;
            for (int yy = std::max(0, y - grow); yy < std::min(H, y + grow + 1); ++yy) m.mask[size_t(yy) * W + x] = 1;
        }
    }
    m.raw = std::move(raw);
    return m;
}

bool any_in(const ChangeMask& m, uint32_t width, uint32_t height, int64_t x0, int64_t y0, int64_t x1, int64_t y1) {
    if (m.empty()) return false;
    x0 = std::max<int64_t>(0, x0);
    y0 = std::max<int64_t>(0, y0);
    x1 = std::min<int64_t>(width, x1);
    y1 = std::min<int64_t>(height, y1);
    for (int64_t y = y0; y < y1; ++y) {
        const uint8_t* r = m.mask.data() + size_t(y) * width;
        for (int64_t x = x0; x < x1; ++x)
            if (r[x]) return true;
    }
    return false;
}

double changed_share_in(const ChangeMask& m, uint32_t width, uint32_t height, int64_t x0, int64_t y0, int64_t x1,
                        int64_t y1) {
    x0 = std::max<int64_t>(0, x0);
    y0 = std::max<int64_t>(0, y0);
    x1 = std::min<int64_t>(width, x1);
    y1 = std::min<int64_t>(height, y1);
    if (m.empty() || x1 <= x0 || y1 <= y0) return 0;
    uint64_t n = 0;
    for (int64_t y = y0; y < y1; ++y) {
        const uint8_t* r = m.raw.data() + size_t(y) * width;
        for (int64_t x = x0; x < x1; ++x) n += r[x];
    }
    return double(n) / double((x1 - x0) * (y1 - y0));
}

}  // namespace spt::paint
