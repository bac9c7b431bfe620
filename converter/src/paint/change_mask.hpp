// What changed between two source frames, by the measure an inter frame's budget uses: a pixel
// changed when its colour moved by more than an RMS error (root mean square over the three
// channels), the target's. Both painters repaint only there (README.md, "Inter frames"), so an
// inter frame costs what changed and a held frame costs nothing.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

namespace spt::paint {

// The RMS error per channel of a PSNR (8-bit, peak 255).
inline double rms_of_psnr(double psnr_db) { return 255.0 / std::pow(10.0, psnr_db / 20.0); }

// How far strokes painted for a changed pixel may reach around it.
constexpr int kChangeGrow = 2;

struct ChangeMask {
    std::vector<uint8_t> mask;  // width * height, 1 where the pixel changed (widened by `grow`)
    std::vector<uint8_t> raw;   // the same before widening
    uint64_t changed = 0;       // pixels that changed, before widening
    bool empty() const { return changed == 0; }
};

// `a` and `b`: RGB8, width * height * 3. A pixel changed when the squared difference summed
// over the channels exceeds 3 rms^2, or (alpha canvases: `alpha_a`, `alpha_b` not null, width *
// height) when its alpha moved by more than rms; the mask is then widened by `grow` pixels (a
// square), so that strokes painted there reach the changed pixels' neighbours.
ChangeMask changed_pixels(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height, double rms, int grow,
                          const uint8_t* alpha_a = nullptr, const uint8_t* alpha_b = nullptr);

// Whether any pixel of the mask is set inside [x0, x1) x [y0, y1) (clipped to the canvas).
bool any_in(const ChangeMask& m, uint32_t width, uint32_t height, int64_t x0, int64_t y0, int64_t x1, int64_t y1);
// The share of the pixels inside [x0, x1) x [y0, y1) (clipped) that changed, before widening.
double changed_share_in(const ChangeMask& m, uint32_t width, uint32_t height, int64_t x0, int64_t y0, int64_t x1,
                        int64_t y1);

}  // namespace spt::paint
