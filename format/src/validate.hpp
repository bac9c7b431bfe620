// Internal: the value rules of SPEC.md sections 3-5, shared by the writer (which rejects what
// it is asked to write, InvalidArgument) and the decoders (which reject what they read, Corrupt).
#pragma once

#include <string>

#include "spt/limits.hpp"
#include "spt/reader.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::detail {

constexpr int32_t kMaxCoord = 1 << 24;     // |x|, |y|, |tx|, |ty|
constexpr int32_t kMaxMatrix = 1 << 16;    // |a|, |b|, |c|, |d|
constexpr uint32_t kMaxWidthQ4 = 1u << 16; // curve width
constexpr uint32_t kMaxSets = 16, kMaxOrientations = 64, kMaxSetSide = 4096;
constexpr uint32_t kMaxTemplateSide = 1024;

// What decoding a stroke needs to know about the stream.
struct StreamShape {
    uint32_t width = 0, height = 0;
    uint32_t sets = 0, orientations = 0, templates = 0;
    // HEAD's version_minor: coding 1 codes the polygon kind flag only from 1.2 on (SPEC.md 7.4).
    uint32_t version_minor = 0;
    // Colour encoding 1: every stroke colour carries 16-bit codes (SPEC.md 6, 7.4).
    bool linear = false;
    bool alpha = false;  // HEAD flag: frame coding 2 is not defined for such canvases (SPEC.md 7.7)
    bool curve_grid = false;  // HEAD flag: every curve record and coded curve has a grid (format 1.4)
    static StreamShape of(const Header& h, size_t templates) {
        return {h.width, h.height, uint32_t(h.sets.size()), uint32_t(h.orientations.size()), uint32_t(templates),
                h.version_minor, h.color == ColorEncoding::LinearHalf, h.alpha, h.curve_grid};
    }
    bool plain_color() const { return !linear && !alpha; }
    bool has_polygons() const { return version_minor >= 2; }
};
// First format minor version with polygon strokes.
constexpr uint16_t kPolygonMinorVersion = 2;

// `code` is the error code to report (InvalidArgument when writing, Corrupt when reading);
// `where` prefixes the message; `offset` is the byte offset to report.
Status check_header(const Header& h, const Limits& lim, Code code, const std::string& where, uint64_t offset);
Status check_template(const Template& t, const Limits& lim, Code code, const std::string& where, uint64_t offset);
Status check_stroke(const Stroke& s, const StreamShape& shape, const Limits& lim, Code code,
                    const std::string& where, uint64_t offset);
// A live list length not known to the decoder (a frame decoded on its own): removals are then
// checked when the frame is applied.
constexpr uint64_t kUnknownLive = ~uint64_t(0);

// Checks a frame's removal list and motion field against the previous live list length and
// the canvas, and its strokes from index `checked` on (the caller vouches for the ones before).
// `prev_live` is ignored for key frames.
Status check_frame(const Frame& f, const StreamShape& shape, const Limits& lim, uint64_t prev_live,
                   Code code, const std::string& where, uint64_t offset, size_t checked = 0);
// check_stroke(s, ...) of a stamp passes (the test alone, no message).
// Colour encoding 0 has no low bytes; encoding 1 codes are finite half floats >= 0 (SPEC.md 4).
inline bool color_ok(const Rgba8& c, const StreamShape& sh) {
    if (!sh.linear) return (c.r_lo | c.g_lo | c.b_lo) == 0;
    return code16(c, 0) <= kMaxHalfCode && code16(c, 1) <= kMaxHalfCode && code16(c, 2) <= kMaxHalfCode;
}

inline bool stamp_ok(const StampStroke& t, const StreamShape& sh) {
    return color_ok(t.color, sh) && t.set < sh.sets && t.tmpl < sh.templates && t.orient < sh.orientations && t.x >= -kMaxCoord &&
           t.x <= kMaxCoord && t.y >= -kMaxCoord && t.y <= kMaxCoord;
}

inline uint16_t blocks_for(uint32_t extent, uint32_t block) { return uint16_t((extent + block - 1) / block); }

}  // namespace spt::detail
