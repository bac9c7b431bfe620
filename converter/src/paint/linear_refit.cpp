#include "paint/linear_refit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "spt/color.hpp"

namespace spt::paint {

namespace {

// Linear values of every colour code (0..0x7BFF), for the canvas under a stroke.
const std::vector<float>& code_values() {
    static const std::vector<float> table = [] {
        std::vector<float> t(kMaxHalfCode + 1);
        for (uint32_t h = 0; h <= kMaxHalfCode; ++h) t[h] = half_to_float(uint16_t(h));
        return t;
    }();
    return table;
}

// Per-pixel weights of the refit's least squares (RefitOptions::highlight_weight).
std::vector<float> pixel_weights(const LinearView& model, bool highlight_weight) {
    const size_t n = size_t(model.width) * model.height;
    std::vector<float> w(n, 1.0f);
    if (highlight_weight)
        for (size_t p = 0; p < n; ++p) {
            const double m = std::max({model.rgba[4 * p], model.rgba[4 * p + 1], model.rgba[4 * p + 2]});
            w[p] = float(1.0 / ((1.0 + m) * (1.0 + m)));
        }
    return w;
}

double colour_error(const LinearView& model, const Canvas& c, const std::vector<float>& weight) {
    const std::vector<float>& lin = code_values();
    double e = 0;
    for (size_t p = 0; p < weight.size(); ++p)
        for (int k = 0; k < 3; ++k) {
            const double d = double(lin[c.rgb16[3 * p + k]]) - double(model.rgba[4 * p + k]);
            e += double(weight[p]) * d * d;
        }
    return e;
}

}  // namespace

double refit_error(const LinearView& model, const Canvas& canvas, bool highlight_weight) {
    return colour_error(model, canvas, pixel_weights(model, highlight_weight));
}

uint16_t linear_code(double value, int mantissa_bits) {
    const uint16_t h = float_to_half_code(float(value));
    const int drop = 10 - std::clamp(mantissa_bits, 1, 10);
    if (drop == 0) return h;
    // The two lattice codes around h (multiples of 2^drop; codes are monotone in value), the
    // nearer in linear value wins.
    const uint32_t step = 1u << drop;
    const uint32_t lo = h & ~(step - 1), hi = std::min<uint32_t>(lo + step, kMaxHalfCode & ~(step - 1));
    const double vlo = half_to_float(uint16_t(lo)), vhi = half_to_float(uint16_t(hi));
    return uint16_t(std::abs(value - vlo) <= std::abs(vhi - value) ? lo : hi);
}

Rgba8 proxy_to_linear(const Rgba8& proxy, const ProxyTransform& t, int mantissa_bits) {
    Rgba8 out;
    out.a = proxy.a;
    const uint8_t v[3] = {proxy.r, proxy.g, proxy.b};
    for (int c = 0; c < 3; ++c) set_code16(out, c, linear_code(t.decode(v[c] / 255.0), mantissa_bits));
    return out;
}

void set_linear_background(Header& h, Rgb8 srgb) {
    const uint8_t v[3] = {srgb.r, srgb.g, srgb.b};
    Rgba8 c;
    for (int k = 0; k < 3; ++k) set_code16(c, k, float_to_half_code(float(srgb_decode(v[k] / 255.0))));
    h.background = Rgb8{c.r, c.g, c.b};
    h.background_lo = Rgb8{c.r_lo, c.g_lo, c.b_lo};
}

Rgb8 proxy_background(Rgb8 srgb, const ProxyTransform& t) {
    auto p = [&](uint8_t v) { return uint8_t(std::lround(255.0 * t.encode(srgb_decode(v / 255.0)))); };
    return Rgb8{p(srgb.r), p(srgb.g), p(srgb.b)};
}

namespace {

// A stroke's coverage: the renderer's cached footprint for opaque stamps, else its mask.
// (ox, oy) is the canvas pixel of mask sample (0, 0).
Status coverage(const Renderer& r, const Stroke& s, Mask& scratch, const Mask*& m, int64_t& ox, int64_t& oy) {
    if (s.kind == StrokeKind::Stamp && s.stamp.color.a == 255) {
        m = &r.stamp_footprint(s.stamp.set, s.stamp.tmpl, s.stamp.orient);
        ox = int64_t(Renderer::stamp_pixel(s.stamp.x)) + m->x0;
        oy = int64_t(Renderer::stamp_pixel(s.stamp.y)) + m->y0;
        return {};
    }
    if (Status st = r.stroke_mask(s, scratch); !st) return st;
    m = &scratch;
    ox = scratch.x0;
    oy = scratch.y0;
    return {};
}

void set_colour(Stroke& s, const Rgba8& c) {
    switch (s.kind) {
        case StrokeKind::Stamp: s.stamp.color = c; break;
        case StrokeKind::Affine: s.affine.color = c; break;
        case StrokeKind::Curve: s.curve.color = c; break;
        case StrokeKind::Polygon: s.polygon.color = c; break;
    }
}

Status draw_all(const Renderer& r, Canvas& canvas, const std::vector<Stroke>& strokes) {
    for (size_t k = 0; k < strokes.size(); ++k)
        if (Status ds = r.draw(canvas, strokes[k]); !ds)
            return make_error(ds.error().code, "linear refit: stroke " + std::to_string(k) + ": " + ds.error().message);
    return {};
}

}  // namespace

Status refit_linear(const LinearView& model, const ProxyTransform& t, const Header& header,
                    const Renderer& renderer, Canvas& canvas, std::vector<Stroke>& strokes,
                    const RefitOptions& opts, RefitStats* stats) {
    const uint32_t W = header.width, H = header.height;
    if (header.color != ColorEncoding::LinearHalf || model.width != W || model.height != H ||
        canvas.width != W || canvas.height != H || canvas.rgb16.size() != size_t(W) * H * 3)
        return make_error(Code::InvalidArgument, "linear refit: the model, canvas and header do not match");
    const std::vector<float>& lin = code_values();
    RefitStats st;
    Mask scratch;
    const size_t n = size_t(W) * H;
    const std::vector<float> weight = pixel_weights(model, opts.highlight_weight);
    // The passes composite on double canvases (the exact rule rounds each blend to the nearest
    // half, within 2^-11 of these values); only the last replay is exact, onto `canvas`. Three
    // exact replays cost twice the paint on GoldenGate; these cost a fraction.
    std::vector<double> below(n * 3);
    for (size_t i = 0; i < n * 3; ++i) below[i] = lin[canvas.rgb16[i]];
    auto composite = [&](std::vector<double>& F, const Mask& m, int64_t ox, int64_t oy, const Rgba8& col) {
        const double c[3] = {lin[code16(col, 0)], lin[code16(col, 1)], lin[code16(col, 2)]};
        const int64_t x0 = std::max<int64_t>(0, ox), y0 = std::max<int64_t>(0, oy);
        const int64_t x1 = std::min<int64_t>(W, ox + int64_t(m.w)), y1 = std::min<int64_t>(H, oy + int64_t(m.h));
        for (int64_t y = y0; y < y1; ++y) {
            const uint8_t* ar = m.a.data() + size_t(y - oy) * m.w;
            for (int64_t x = x0; x < x1; ++x) {
                if (ar[x - ox] == 0) continue;
                const double a = ar[x - ox] / 255.0;
                double* f = &F[3 * (size_t(y) * W + size_t(x))];
                for (int k = 0; k < 3; ++k) f[k] += a * (c[k] - f[k]);
            }
        }
    };
    auto error_of = [&](const std::vector<double>& F) {
        double e = 0;
        for (size_t p = 0; p < n; ++p)
            for (int k = 0; k < 3; ++k) {
                const double d = F[3 * p + k] - double(model.rgba[4 * p + k]);
                e += double(weight[p]) * d * d;
            }
        return e;
    };
    std::vector<Stroke> converted = strokes;
    for (Stroke& s : converted) set_colour(s, proxy_to_linear(s.color(), t, opts.mantissa_bits));

    // Pass 1, forward: each stroke's least-squares colour given the linear canvas under it,
    // c = sum q a (255 M - (255 - a) C) / sum q a^2 per channel (M model, C canvas, linear,
    // premultiplied; q the pixel weight): the painter's 8-bit rule in linear light. Doubles
    // summed in a fixed order: the same result on every run.
    std::vector<double> F = below;
    for (size_t k = 0; k < strokes.size(); ++k) {
        Stroke& s = strokes[k];
        const Mask* m = nullptr;
        int64_t ox = 0, oy = 0;
        if (Status ms = coverage(renderer, s, scratch, m, ox, oy); !ms)
            return make_error(ms.error().code, "linear refit: stroke " + std::to_string(k) + ": " + ms.error().message);
        double saa = 0, num[3] = {0, 0, 0}, top[3] = {0, 0, 0};
        const int64_t x0 = std::max<int64_t>(0, ox), y0 = std::max<int64_t>(0, oy);
        const int64_t x1 = std::min<int64_t>(W, ox + int64_t(m->w)), y1 = std::min<int64_t>(H, oy + int64_t(m->h));
        for (int64_t y = y0; y < y1; ++y) {
            const uint8_t* ar = m->a.data() + size_t(y - oy) * m->w;
            for (int64_t x = x0; x < x1; ++x) {
                const double a = ar[x - ox];
                if (a == 0) continue;
                const size_t p = size_t(y) * W + size_t(x);
                const double q = weight[p];
                saa += q * a * a;
                for (int c = 0; c < 3; ++c) {
                    const double mv = model.rgba[4 * p + c];
                    top[c] = std::max(top[c], mv);
                    num[c] += q * a * (255.0 * mv - (255.0 - a) * F[3 * p + c]);
                }
            }
        }
        if (saa > 0) {
            // Clamped to the model's range under the stroke: a faint rim of coverage over a dark
            // canvas would otherwise ask for a huge colour that no pixel has.
            Rgba8 col;
            col.a = s.color().a;
            for (int c = 0; c < 3; ++c)
                set_code16(col, c, linear_code(std::clamp(num[c] / saa, 0.0, top[c]), opts.mantissa_bits));
            set_colour(s, col);
            ++st.refit;
        } else {
            set_colour(s, converted[k].color());
            ++st.converted;
        }
        composite(F, *m, ox, oy, s.color());
    }

    // Each forward choice is optimal for the canvas right after its stroke, not for the final
    // picture, where later strokes cover part of it; on hard images the converted proxy colours
    // can end up closer. Start from the better of the two, then one backward sweep of
    // coordinate descent on the final picture: stroke k shows through the transmittance T of
    // the strokes above it, final = rest + c_k a_k T / 255, so the colour that minimises the
    // final error is c_k + sum q w (M - F) / sum q w^2 with w = a_k T / 255. Every step lowers
    // the final error (up to the half rounding of the exact replay that follows).
    {
        std::vector<double> Fc = below;
        for (size_t k = 0; k < converted.size(); ++k) {
            const Mask* m = nullptr;
            int64_t ox = 0, oy = 0;
            if (Status ms = coverage(renderer, converted[k], scratch, m, ox, oy); !ms) return ms;
            composite(Fc, *m, ox, oy, converted[k].color());
        }
        if (error_of(Fc) < error_of(F)) {
            strokes = converted;
            F = std::move(Fc);
        }
    }
    std::vector<float> T(n, 1.0f);
    for (size_t k = strokes.size(); k-- > 0;) {
        Stroke& s = strokes[k];
        const Mask* m = nullptr;
        int64_t ox = 0, oy = 0;
        if (Status ms = coverage(renderer, s, scratch, m, ox, oy); !ms) return ms;
        const int64_t x0 = std::max<int64_t>(0, ox), y0 = std::max<int64_t>(0, oy);
        const int64_t x1 = std::min<int64_t>(W, ox + int64_t(m->w)), y1 = std::min<int64_t>(H, oy + int64_t(m->h));
        double sww = 0, saa = 0, num[3] = {0, 0, 0}, top[3] = {0, 0, 0};
        for (int64_t y = y0; y < y1; ++y) {
            const uint8_t* ar = m->a.data() + size_t(y - oy) * m->w;
            for (int64_t x = x0; x < x1; ++x) {
                if (ar[x - ox] == 0) continue;
                const size_t p = size_t(y) * W + size_t(x);
                const double a = ar[x - ox] / 255.0, w = a * double(T[p]), q = weight[p];
                sww += q * w * w;
                saa += q * a * a;
                for (int c = 0; c < 3; ++c) {
                    const double mv = model.rgba[4 * p + c];
                    top[c] = std::max(top[c], mv);
                    num[c] += q * w * (mv - F[3 * p + c]);
                }
            }
        }
        // A stroke that shows through less than ~20% (in w^2) is left as it is: its colour
        // would be fitted to a few faint pixels.
        if (sww > 0.04 * saa && sww > 1e-9) {
            Rgba8 col = s.color();
            double d[3];
            for (int c = 0; c < 3; ++c) {
                const double old = lin[code16(col, c)];
                const uint16_t code = linear_code(std::clamp(old + num[c] / sww, 0.0, std::max(old, top[c])), opts.mantissa_bits);
                d[c] = double(lin[code]) - old;
                set_code16(col, c, code);
            }
            set_colour(s, col);
            for (int64_t y = y0; y < y1; ++y) {
                const uint8_t* ar = m->a.data() + size_t(y - oy) * m->w;
                for (int64_t x = x0; x < x1; ++x) {
                    const size_t p = size_t(y) * W + size_t(x);
                    const double w = ar[x - ox] * double(T[p]) / 255.0;
                    for (int c = 0; c < 3; ++c) F[3 * p + c] += w * d[c];
                }
            }
        }
        for (int64_t y = y0; y < y1; ++y) {
            const uint8_t* ar = m->a.data() + size_t(y - oy) * m->w;
            for (int64_t x = x0; x < x1; ++x) T[size_t(y) * W + size_t(x)] *= float(255 - ar[x - ox]) / 255.0f;
        }
    }
    if (Status ds = draw_all(renderer, canvas, strokes); !ds) return ds;
    if (stats) *stats = st;
    return {};
}

double linear_sse(const LinearView& model, const Canvas& canvas) {
    const std::vector<float>& lin = code_values();
    const size_t n = size_t(model.width) * model.height;
    double e = 0;
    for (size_t i = 0; i < n; ++i) {
        for (int c = 0; c < 3; ++c) {
            const double d = double(lin[canvas.rgb16[3 * i + c]]) - double(model.rgba[4 * i + c]);
            e += d * d;
        }
        if (!canvas.alpha.empty()) {
            const double d = canvas.alpha[i] / 255.0 - double(model.rgba[4 * i + 3]);
            e += d * d;
        }
    }
    return e;
}

}  // namespace spt::paint
