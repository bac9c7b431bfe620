// The hash recorded in tests/format/golden/MANIFEST.txt: FNV-1a 64 over the canonical
// stored-mode bytes of a live stroke list, i.e. a coding-0 key frame body (SPEC.md 6):
// u32 stroke_count, then the stroke records. Written independently of libspt's stored coder.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "spt/types.hpp"

namespace spt::testing {

inline void put32(std::vector<uint8_t>& b, uint32_t v) {
    for (int i = 0; i < 4; ++i) b.push_back(uint8_t(v >> (8 * i)));
}

// `linear`: colour encoding 1, whose records carry the low bytes of each code (SPEC.md 6);
// `curve_grid`: the HEAD flag of format 1.4, whose curve records carry their grid.
inline std::vector<uint8_t> canonical_stored_bytes(const std::vector<Stroke>& live, bool linear = false,
                                                   bool curve_grid = false) {
    std::vector<uint8_t> b;
    put32(b, uint32_t(live.size()));
    auto rgba = [&](const Rgba8& c) {
        b.push_back(c.r); b.push_back(c.g); b.push_back(c.b); b.push_back(c.a);
        if (linear) { b.push_back(c.r_lo); b.push_back(c.g_lo); b.push_back(c.b_lo); }
    };
    for (const auto& s : live) {
        b.push_back(uint8_t(s.kind));
        if (s.kind == StrokeKind::Stamp) {
            b.push_back(s.stamp.set); b.push_back(s.stamp.tmpl); b.push_back(s.stamp.orient);
            put32(b, uint32_t(s.stamp.x)); put32(b, uint32_t(s.stamp.y));
            rgba(s.stamp.color);
        } else if (s.kind == StrokeKind::Affine) {
            const auto& a = s.affine;
            b.push_back(a.tmpl);
            for (int32_t v : {a.tx, a.ty, a.a, a.b, a.c, a.d}) put32(b, uint32_t(v));
            rgba(a.color);
        } else if (s.kind == StrokeKind::Polygon) {
            rgba(s.polygon.color);
            b.push_back(s.polygon.supersample);
            put32(b, uint32_t(s.polygon.points.size()));
            for (const auto& p : s.polygon.points) { put32(b, uint32_t(p.x)); put32(b, uint32_t(p.y)); }
        } else {
            rgba(s.curve.color);
            if (curve_grid) b.push_back(s.curve.supersample);
            put32(b, uint32_t(s.curve.points.size()));
            for (const auto& p : s.curve.points) { put32(b, uint32_t(p.x)); put32(b, uint32_t(p.y)); put32(b, p.width); }
        }
    }
    return b;
}

// The rendered frame as SPEC.md 9.4 hashes it: the colour plane (encoding 1: each code as a
// little-endian u16), then the alpha plane of an alpha canvas.
template <class CanvasT>
inline std::vector<uint8_t> render_bytes(const CanvasT& c) {
    std::vector<uint8_t> b(c.rgb.begin(), c.rgb.end());
    for (uint16_t v : c.rgb16) { b.push_back(uint8_t(v)); b.push_back(uint8_t(v >> 8)); }
    b.insert(b.end(), c.alpha.begin(), c.alpha.end());
    return b;
}

inline uint64_t fnv1a64(const std::vector<uint8_t>& b) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (uint8_t c : b) { h ^= c; h *= 0x100000001b3ull; }
    return h;
}

inline std::string hex64(uint64_t v) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
    return buf;
}

}  // namespace spt::testing
