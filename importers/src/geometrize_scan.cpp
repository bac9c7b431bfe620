// geometrize's scan conversion, re-derived from its documented behaviour and checked against its
// own PNGs (see spt_import/geometrize.hpp): the pixel spans each shape paints.
#include "geometrize_internal.hpp"

#include <cmath>
#include <map>

namespace spt::import::geometrize {

namespace {

// Integer line from (x0, y0) to (x1, y1), one pixel per step of the major axis; on an exact
// tie the minor coordinate advances only when moving in the positive major direction (the
// rule that reproduces geometrize's outlines).
void line(int32_t x0, int32_t y0, int32_t x1, int32_t y1, std::map<int32_t, std::pair<int32_t, int32_t>>& rows) {
    auto put = [&rows](int32_t x, int32_t y) {
        auto it = rows.find(y);
        if (it == rows.end()) rows.emplace(y, std::make_pair(x, x));
        else { it->second.first = std::min(it->second.first, x); it->second.second = std::max(it->second.second, x); }
    };
    const int32_t sx = (x1 > x0) - (x1 < x0), sy = (y1 > y0) - (y1 < y0);
    const int64_t dx = 2 * int64_t(std::abs(x1 - x0)), dy = 2 * int64_t(std::abs(y1 - y0));
    put(x0, y0);
    if (dx >= dy) {
        int64_t e = dy - dx / 2;
        while (x0 != x1) {
            if (e > 0 || (e == 0 && sx > 0)) { e -= dx; y0 += sy; }
            e += dy; x0 += sx; put(x0, y0);
        }
    } else {
        int64_t e = dx - dy / 2;
        while (y0 != y1) {
            if (e > 0 || (e == 0 && sy > 0)) { e -= dy; x0 += sx; }
            e += dx; y0 += sy; put(x0, y0);
        }
    }
}

// geometrize computes with float and its own value of pi; the vertices are then truncated
// toward zero, so the same float arithmetic is needed to land on the same pixels.
constexpr float kGeoPi = 3.141f;
int32_t trunc_px(float v) { return int32_t(v); }

}  // namespace

// geometrize clips to [0, w-1) x [0, h-1): it passes the canvas size minus one as the bounds.
// A span is dropped when its row is outside or it starts right of the bound; then clamped.
std::vector<Span> trim(std::vector<Span> in, uint32_t w, uint32_t h) {
    const int32_t bw = int32_t(w) - 1, bh = int32_t(h) - 1;
    std::vector<Span> out;
    for (Span s : in) {
        if (s.y < 0 || s.y >= bh || s.x0 >= bw) continue;
        s.x0 = std::clamp(s.x0, 0, bw - 1);
        s.x1 = std::clamp(s.x1, 0, bw - 1);
        if (s.x0 > s.x1) continue;
        out.push_back(s);
    }
    return out;
}

std::vector<Span> polygon_spans(const std::vector<Pix>& p) {
    std::map<int32_t, std::pair<int32_t, int32_t>> rows;
    for (size_t i = 0; i < p.size(); ++i) {
        const Pix& a = p[i];
        const Pix& b = p[(i + 1) % p.size()];
        line(a.first, a.second, b.first, b.second, rows);
    }
    std::vector<Span> out;
    for (const auto& [y, r] : rows) out.push_back({y, r.first, r.second});
    return out;
}

std::vector<Pix> explicit_polygon(const std::vector<double>& d) {
    std::vector<Pix> p;
    for (size_t k = 0; k + 1 < d.size(); k += 2) p.push_back({int32_t(float(d[k])), int32_t(float(d[k + 1]))});
    return p;
}

std::vector<Pix> polygon(int type, const std::vector<double>& d) {
    std::vector<Pix> p;
    if (type == 4 && d.size() >= 6) {
        for (int k = 0; k < 3; ++k) p.push_back({int32_t(d[2 * k]), int32_t(d[2 * k + 1])});
    } else if (type == 2 && d.size() >= 5) {
        const float x1 = std::fmin(float(d[0]), float(d[2])), x2 = std::fmax(float(d[0]), float(d[2]));
        const float y1 = std::fmin(float(d[1]), float(d[3])), y2 = std::fmax(float(d[1]), float(d[3]));
        const float cx = (x2 + x1) / 2.0f, cy = (y2 + y1) / 2.0f;
        const float ox1 = x1 - cx, ox2 = x2 - cx, oy1 = y1 - cy, oy2 = y2 - cy;
        const float rad = float(d[4]) * kGeoPi / 180.0f;
        const float c = std::cos(rad), s = std::sin(rad);
        const float px[4][2] = {{ox1, oy1}, {ox2, oy1}, {ox2, oy2}, {ox1, oy2}};
        for (const auto& q : px) {
            const float xa = q[0] * c, xb = q[1] * s, ya = q[0] * s, yb = q[1] * c;
            p.push_back({trunc_px(xa - xb + cx), trunc_px(ya + yb + cy)});
        }
    } else if (type == 16 && d.size() >= 5) {
        const float rad = float(d[4]) * (kGeoPi / 180.0f);
        const float co = std::cos(rad), si = std::sin(rad);
        const float rx = float(d[2]), ry = float(d[3]), x = float(d[0]), y = float(d[1]);
        for (uint32_t i = 0; i < 20; ++i) {
            const float ang = ((360.0f / 20.0f) * float(i)) * (kGeoPi / 180.0f);
            const float crx = rx * std::cos(ang), cry = ry * std::sin(ang);
            const float a = crx * co, b = cry * si, e = crx * si, f = cry * co;
            p.push_back({trunc_px(a - b + x), trunc_px(e + f + y)});
        }
    }
    return p;
}

std::vector<Span> spans(int type, const std::vector<double>& d, uint32_t w, uint32_t h) {
    std::vector<Span> out;
    const int32_t bw = int32_t(w) - 1;
    switch (type) {
        case 1: {  // rows y1 .. y2 - 1, columns x1 .. x2
            const int32_t x1 = int32_t(std::min(d[0], d[2])), x2 = int32_t(std::max(d[0], d[2]));
            const int32_t y1 = int32_t(std::min(d[1], d[3])), y2 = int32_t(std::max(d[1], d[3]));
            for (int32_t y = y1; y < y2; ++y) out.push_back({y, x1, x2});
            break;
        }
        case 32: {  // x^2 + y^2 <= r^2 around pixel (x, y)
            const int32_t x = int32_t(d[0]), y = int32_t(d[1]), r = int32_t(d[2]);
            for (int32_t j = -r; j <= r; ++j) {
                int32_t s = int32_t(std::sqrt(double(r) * r - double(j) * j));
                while (int64_t(s + 1) * (s + 1) + int64_t(j) * j <= int64_t(r) * r) ++s;
                while (s >= 0 && int64_t(s) * s + int64_t(j) * j > int64_t(r) * r) --s;
                if (s < 0) continue;
                out.push_back({y + j, std::clamp(x - s, 0, bw - 1), std::clamp(x + s, 0, bw - 1)});
            }
            break;
        }
        case 8: {  // rows |dy| < ry, half width trunc(sqrt(ry^2 - dy^2) * rx / ry)
            const float aspect = float(d[2]) / float(d[3]);
            const int32_t x = int32_t(d[0]), y = int32_t(d[1]);
            const float ry = float(d[3]);
            for (int32_t dy = 0; dy < ry; ++dy) {
                const int32_t v = int32_t(std::sqrt(ry * ry - float(dy * dy)) * aspect);
                const int32_t x1 = std::max(x - v, 0), x2 = std::min(x + v, bw - 1);
                out.push_back({y - dy, x1, x2});
                if (dy > 0) out.push_back({y + dy, x1, x2});
            }
            break;
        }
        case 2: case 4: case 16: out = polygon_spans(polygon(type, d)); break;
        default: break;
    }
    return trim(std::move(out), w, h);
}

}  // namespace spt::import::geometrize
