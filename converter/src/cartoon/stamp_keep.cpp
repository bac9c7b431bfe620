#include "cartoon/stamp_keep.hpp"

#include <algorithm>
#include <iterator>

#include "cartoon/mask_pixels.hpp"

namespace spt::cartoon {

// Passes of the keep rule: 3 measured (butterfly 12 frames: 106,023 bytes with 2, 104,694 with
// 3, 104,562 with 6; taffy 526,674, 526,026, 525,860).
constexpr int kPasses = 3;

namespace {

// One pass: the kept old stamps (not in `removed`) that make the frame worse, increasing.
std::vector<uint32_t> hurting_stamps(const std::vector<Stroke>& moved, const std::vector<uint32_t>& removed,
                                     const std::vector<Stroke>& added, const paint::ImageView& model,
                                     const Renderer& renderer, const Header& header) {
    // The frame as a decoder draws it before the new stamps: what the old list keeps, then
    // what the frame adds. cand[k]: the old index of stroke k when it is a kept old stamp.
    std::vector<Stroke> with;
    std::vector<int64_t> cand;
    size_t r = 0;
    for (uint32_t i = 0; i < moved.size(); ++i) {
        if (r < removed.size() && removed[r] == i) {
            ++r;
            continue;
        }
        with.push_back(moved[i]);
        cand.push_back(moved[i].kind == StrokeKind::Stamp ? int64_t(i) : -1);
    }
    if (std::none_of(cand.begin(), cand.end(), [](int64_t c) { return c >= 0; })) return {};
    with.insert(with.end(), added.begin(), added.end());
    cand.resize(with.size(), -1);

    // What each kept stamp changes in the final frame, exactly up to rounding: drawn over
    // `below` (the canvas just before it) with coverage a, it moves a pixel by
    // a (colour - below), and the strokes drawn after it pass a fraction T of that on.
    // So without it the pixel would be final - a T (colour - below).
    const int32_t W = int32_t(model.width), H = int32_t(model.height);
    struct Effect {
        Mask mask;
        std::vector<float> delta;  // per covered pixel and channel: a T (colour - below)
    };
    std::vector<Effect> fx(with.size());
    Canvas canvas(header);
    for (size_t k = 0; k < with.size(); ++k) {
        if (cand[k] >= 0 && renderer.stroke_mask(with[k], fx[k].mask)) {
            const Mask& m = fx[k].mask;
            const Rgba8 c = with[k].stamp.color;
            fx[k].delta.assign(size_t(m.w) * m.h * 3, 0.0f);
            visit_covered(m, W, H, [&](int32_t px, int32_t py, size_t i, uint8_t a) {
                const uint8_t* b = canvas.rgb.data() + (size_t(py) * W + px) * 3;
                float* d = &fx[k].delta[i * 3];
                d[0] = float(a) / 255.0f * float(int(c.r) - int(b[0]));
                d[1] = float(a) / 255.0f * float(int(c.g) - int(b[1]));
                d[2] = float(a) / 255.0f * float(int(c.b) - int(b[2]));
            });
        }
        if (!renderer.draw(canvas, with[k])) return {};
    }
    // T, from the last stroke back: the fraction of a pixel the strokes after each one leave.
    std::vector<float> through(size_t(W) * H, 1.0f);
    Mask m;
    for (size_t k = with.size(); k-- > 0;) {
        const bool is_cand = cand[k] >= 0 && !fx[k].delta.empty();
        if (!is_cand && !renderer.stroke_mask(with[k], m)) continue;
        const Mask& mk = is_cand ? fx[k].mask : m;
        visit_covered(mk, W, H, [&](int32_t px, int32_t py, size_t i, uint8_t a) {
            float& t = through[size_t(py) * W + px];
            if (is_cand) {
                float* d = &fx[k].delta[i * 3];
                d[0] *= t;
                d[1] *= t;
                d[2] *= t;
            }
            t *= 1.0f - float(a) / 255.0f;
        });
    }
    // A stamp goes when the frame is closer to the source without it. (Removing one costs a
    // fraction of a byte; keeping one that hurts costs the stamps that paint over it.)
    std::vector<uint32_t> drop;
    for (size_t k = 0; k < with.size(); ++k) {
        if (cand[k] < 0 || fx[k].delta.empty()) continue;
        const Mask& mk = fx[k].mask;
        double gain = 0;  // squared error the stamp removes
        visit_covered(mk, W, H, [&](int32_t px, int32_t py, size_t i, uint8_t) {
            const size_t p = (size_t(py) * W + px) * 3;
            const float* d = &fx[k].delta[i * 3];
            for (int ch = 0; ch < 3; ++ch) {
                const float e = float(model.rgb[p + ch]) - float(canvas.rgb[p + ch]);
                gain += double((e + d[ch]) * (e + d[ch]) - e * e);
            }
        });
        if (gain < 0) drop.push_back(uint32_t(cand[k]));
    }
    return drop;
}

}  // namespace

std::vector<uint32_t> drop_unhelpful_stamps(const std::vector<Stroke>& moved, const std::vector<uint32_t>& removed,
                                            const std::vector<Stroke>& added, const paint::ImageView& model,
                                            const Renderer& renderer, const Header& header) {
    // Each stamp is judged with all the others kept; a wrong stamp under another wrong one
    // shows only once that one is gone, so a few passes.
    std::vector<uint32_t> out = removed;
    for (int pass = 0; pass < kPasses; ++pass) {
        const std::vector<uint32_t> drop = hurting_stamps(moved, out, added, model, renderer, header);
        if (drop.empty()) break;
        std::vector<uint32_t> merged;
        merged.reserve(out.size() + drop.size());
        std::merge(out.begin(), out.end(), drop.begin(), drop.end(), std::back_inserter(merged));
        out = std::move(merged);
    }
    return out;
}

}  // namespace spt::cartoon
