#include "video/stroke_cull.hpp"

#include <algorithm>
#include <string>

namespace spt::video {

Result<std::vector<uint32_t>> hidden_strokes(const std::vector<Stroke>& live, const Renderer& renderer,
                                             uint32_t width, uint32_t height,
                                             std::vector<uint8_t>& opaque) {
    opaque.assign(size_t(width) * height, 0);
    std::vector<uint32_t> hidden;
    Mask mask;
    // Walk from the top of the stack down: `opaque` marks pixels that some stroke above has
    // replaced outright, so anything below that shows nowhere else is invisible.
    for (size_t k = live.size(); k-- > 0;) {
        const Stroke& s = live[k];
        const Mask* m = &mask;
        if (s.kind == StrokeKind::Stamp && s.stamp.color.a == 255) {
            // The cached footprint (template coverage of an opaque stamp) avoids an allocation
            // per stroke; it is offset to the stamp's pixel.
            m = &renderer.stamp_footprint(s.stamp.set, s.stamp.tmpl, s.stamp.orient);
        } else {
            Status st = renderer.stroke_mask(s, mask);
            if (!st) {
                Error e = st.error();
                e.message = "live stroke " + std::to_string(k) + ": " + e.message;
                return e;
            }
        }
        int32_t ox = m->x0, oy = m->y0;
        if (m != &mask) {
            ox += Renderer::stamp_pixel(s.stamp.x);
            oy += Renderer::stamp_pixel(s.stamp.y);
        }
        const int64_t x_begin = std::max<int64_t>(0, ox), y_begin = std::max<int64_t>(0, oy);
        const int64_t x_end = std::min<int64_t>(width, int64_t(ox) + m->w);
        const int64_t y_end = std::min<int64_t>(height, int64_t(oy) + m->h);
        bool visible = false;
        for (int64_t y = y_begin; y < y_end && !visible; ++y) {
            const uint8_t* a = m->a.data() + size_t(y - oy) * m->w;
            const uint8_t* o = opaque.data() + size_t(y) * width;
            for (int64_t x = x_begin; x < x_end; ++x) {
                if (a[x - ox] != 0 && o[x] == 0) {
                    visible = true;
                    break;
                }
            }
        }
        if (!visible) {
            hidden.push_back(uint32_t(k));
            continue;
        }
        for (int64_t y = y_begin; y < y_end; ++y) {
            const uint8_t* a = m->a.data() + size_t(y - oy) * m->w;
            uint8_t* o = opaque.data() + size_t(y) * width;
            for (int64_t x = x_begin; x < x_end; ++x) o[x] |= uint8_t(a[x - ox] == 255);
        }
    }
    std::reverse(hidden.begin(), hidden.end());
    return hidden;
}

}  // namespace spt::video
