// The 8-bit perceptual proxy a scene-linear (HDR) image is painted on (README.md "Linear HDR"):
// the painter places strokes where they matter to the eye, then linear_refit.hpp gives them
// their linear colours. The proxy of a linear value x (straight, not premultiplied) is
//     v(x) = srgb(x)                          for x <= 1  (the sRGB transfer curve)
//     v(x) = 1 + k ln(1 + b (x - 1)) / b      for x > 1,  k = 1.055 / 2.4
// (v and v' continuous at 1 for every bend b >= 1; b = 1 is 1 + k ln x), scaled so that the
// image's peak maps to 255: proxy = round(255 * v(x) / v(peak)). b is the smallest that puts
// 1.0 at 0.7 of the range or above: highlights up to the peak keep their gradations on a log
// scale in the top codes instead of clipping, and neither dominate the error nor squeeze the
// picture below 1 into a few codes.
#pragma once

#include <cstdint>
#include <vector>

namespace spt::paint {

// A scene-linear RGBA image: width * height * 4 floats, premultiplied, finite and >= 0
// (io::SceneImage holds one).
struct LinearView {
    uint32_t width = 0, height = 0;
    const float* rgba = nullptr;
};

struct ProxyTransform {
    double peak = 1.0;  // the linear value that maps to 255 (>= 1)
    double bend = 1.0;  // b of the log segment (>= 1), see with_peak()
    // The transform of a peak, the log segment bent (b) so that 1.0 maps to at least `unit` of
    // the range: highlights then share the top codes, and the picture below 1 keeps most.
    static ProxyTransform with_peak(double peak, double unit = kDefaultUnit);
    static constexpr double kDefaultUnit = 0.7;  // measured, README.md "Linear HDR"
    // v(x) / v(peak) in 0..1 for a straight linear value x (clamped at the peak).
    double encode(double x) const;
    // The straight linear value whose proxy is p (0..1 of v(peak)).
    double decode(double p) const;
};

// The proxy of an image: peak = the largest colour value (premultiplied values: an opaque
// pixel's own value; 1 when the image stays at or below 1).
ProxyTransform proxy_for(const LinearView& img);

// The 8-bit premultiplied proxy image: rgb (width * height * 3) = round(255 * alpha8/255 *
// encode(straight)), alpha (width * height, when `alpha` is not null) = round(255 * A).
// Without an alpha plane the colour is taken as it is (alpha 1).
void make_proxy(const LinearView& img, const ProxyTransform& t, std::vector<uint8_t>& rgb,
                std::vector<uint8_t>* alpha);

// sRGB transfer curve and its inverse on 0..1.
double srgb_encode(double linear);
double srgb_decode(double encoded);

}  // namespace spt::paint
