// Image similarity: PSNR and SSIM of two 8-bit RGB images, as `spt compare` and benches use.
#pragma once

#include <cstdint>

#include "spt/result.hpp"

namespace spt::io {

struct ImageMetrics {
    double mse = 0;   // mean squared error over all R, G, B samples (8-bit scale)
    double psnr = 0;  // 10*log10(255^2 / mse) dB; +infinity when the images are identical
    double ssim = 1;  // mean SSIM of the luma planes (see below)
};

// PSNR over the R, G and B samples together (8-bit). SSIM (Wang et al. 2004: 11x11 Gaussian
// window, sigma 1.5, K1 = 0.01, K2 = 0.03, L = 255) on luma Y = 0.299 R + 0.587 G + 0.114 B of
// the sRGB-coded values, averaged over every pixel (windows clamp at the borders).
// Both images are width x height RGB8, row-major.
ImageMetrics compare_rgb8(const uint8_t* a, const uint8_t* b, uint32_t width, uint32_t height);

}  // namespace spt::io
