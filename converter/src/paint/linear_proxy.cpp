#include "paint/linear_proxy.hpp"

#include <algorithm>
#include <cmath>

namespace spt::paint {

namespace {

// The slope of the sRGB curve at 1: the log segment above 1 continues it smoothly.
constexpr double kLogSlope = 1.055 / 2.4;

// Above 1: 1 + k ln(1 + b (x - 1)) / b, slope k at 1 for every b >= 1 (b = 1: 1 + k ln x).
double v_of(double x, double b) {
    return x <= 1.0 ? srgb_encode(x) : 1.0 + kLogSlope * std::log1p(b * (x - 1.0)) / b;
}

double v_inverse(double v, double b) {
    return v <= 1.0 ? srgb_decode(v) : 1.0 + std::expm1((v - 1.0) * b / kLogSlope) / b;
}

}  // namespace

ProxyTransform ProxyTransform::with_peak(double peak, double unit) {
    ProxyTransform t;
    t.peak = std::max(1.0, peak);
    t.bend = 1.0;
    // The bend that puts 1.0 at `unit` of the range: v(peak, b) = 1 / unit, v falling in b.
    const double want = 1.0 / std::clamp(unit, 0.05, 1.0);
    if (v_of(t.peak, 1.0) > want) {
        double lo = 1.0, hi = 2.0;
        while (v_of(t.peak, hi) > want && hi < 1e12) hi *= 2;
        for (int i = 0; i < 200; ++i) {
            const double mid = 0.5 * (lo + hi);
            (v_of(t.peak, mid) > want ? lo : hi) = mid;
        }
        t.bend = hi;
    }
    return t;
}

double srgb_encode(double x) {
    if (x <= 0) return 0;
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

double srgb_decode(double v) {
    if (v <= 0) return 0;
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

double ProxyTransform::encode(double x) const {
    return std::clamp(v_of(std::min(x, peak), bend) / v_of(peak, bend), 0.0, 1.0);
}

double ProxyTransform::decode(double p) const { return v_inverse(std::clamp(p, 0.0, 1.0) * v_of(peak, bend), bend); }

ProxyTransform proxy_for(const LinearView& img) {
    float m = 1.0f;
    const size_t n = size_t(img.width) * img.height;
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) m = std::max(m, img.rgba[4 * i + c]);
    return ProxyTransform::with_peak(double(m));
}

void make_proxy(const LinearView& img, const ProxyTransform& t, std::vector<uint8_t>& rgb,
                std::vector<uint8_t>* alpha) {
    const size_t n = size_t(img.width) * img.height;
    rgb.assign(n * 3, 0);
    if (alpha) alpha->assign(n, 0);
    for (size_t i = 0; i < n; ++i) {
        const float* p = img.rgba + 4 * i;
        double a = 1.0;
        if (alpha) {
            const long a8 = std::lround(std::clamp(double(p[3]), 0.0, 1.0) * 255.0);
            (*alpha)[i] = uint8_t(a8);
            a = double(a8) / 255.0;
            if (a8 == 0) continue;  // premultiplied: no colour where nothing is
        }
        for (int c = 0; c < 3; ++c) {
            // Straight colour from the premultiplied source (its own alpha, not the rounded one).
            const double straight = alpha && p[3] > 0 ? double(p[c]) / double(p[3]) : double(p[c]);
            rgb[3 * i + c] = uint8_t(std::lround(255.0 * a * t.encode(straight)));
        }
    }
}

}  // namespace spt::paint
