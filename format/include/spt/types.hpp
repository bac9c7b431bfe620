// libspt data model: the values a .spt file holds, independent of how they are coded.
// See format/SPEC.md; field names here follow the spec's names.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace spt {

// Fixed-point positions and lengths are in 1/16 pixel ("Q4"). Pixel (x, y) covers
// [x, x+1) x [y, y+1); its centre is at (16x + 8, 16y + 8) in Q4.
constexpr int kQ4 = 16;

struct Rgb8 {
    uint8_t r = 0, g = 0, b = 0;
    friend bool operator==(const Rgb8&, const Rgb8&) = default;
};

// A stroke's colour and opacity `a`. In colour encoding 0 the channels are the 8-bit sRGB values
// r, g, b and the *_lo bytes are 0. In colour encoding 1 (scene-linear, format 1.3) each channel
// is a 16-bit half-float code, `(r << 8) | r_lo` (see code16() and SPEC.md 8.6); `a` stays 8-bit.
struct Rgba8 {
    uint8_t r = 0, g = 0, b = 0, a = 255;
    uint8_t r_lo = 0, g_lo = 0, b_lo = 0;
    friend bool operator==(const Rgba8&, const Rgba8&) = default;
};

// The 16-bit code of channel `ch` (0 R, 1 G, 2 B) of a colour in encoding 1.
inline uint16_t code16(const Rgba8& c, int ch) {
    return ch == 0 ? uint16_t(c.r << 8 | c.r_lo) : ch == 1 ? uint16_t(c.g << 8 | c.g_lo) : uint16_t(c.b << 8 | c.b_lo);
}
inline void set_code16(Rgba8& c, int ch, uint16_t v) {
    const auto hi = uint8_t(v >> 8), lo = uint8_t(v & 255);
    if (ch == 0) { c.r = hi; c.r_lo = lo; } else if (ch == 1) { c.g = hi; c.g_lo = lo; } else { c.b = hi; c.b_lo = lo; }
}
// The largest colour code of encoding 1: the largest finite half float, 65504.
constexpr uint16_t kMaxHalfCode = 0x7BFF;

// A stroke set: the size in pixels a stamp stroke of this set covers (before rotation).
struct StrokeSet {
    uint16_t width = 0;
    uint16_t height = 0;
    friend bool operator==(const StrokeSet&, const StrokeSet&) = default;
};

// One entry of the orientation table: cos and sin of the angle in Q14 (16384 = 1.0).
struct Orientation {
    int16_t cos_q14 = 16384;
    int16_t sin_q14 = 0;
    friend bool operator==(const Orientation&, const Orientation&) = default;
};

// Template shapes. Every stroke is the image of a template under an affine map.
enum class TemplateKind : uint8_t {
    Bitmap = 0,     // width x height 8-bit coverage samples, row-major, top row first
    Ellipse = 1,    // unit disc u^2 + v^2 <= 1
    Rectangle = 2,  // unit square |u| <= 1, |v| <= 1
    Triangle = 3,   // u >= -1, v >= -1, u + v <= 0: vertices (-1,-1), (1,-1), (-1,1)
};
// "bitmap", "ellipse", "rectangle", "triangle"; "unknown" for any other value.
const char* template_kind_name(TemplateKind k);

struct Template {
    TemplateKind kind = TemplateKind::Bitmap;
    uint16_t width = 0;    // Bitmap only
    uint16_t height = 0;   // Bitmap only
    std::vector<uint8_t> pixels;  // Bitmap only, width * height
    std::string name;      // informative (e.g. "bristle"); may be empty
    // Analytic kinds only: 0 samples the template once, at the pixel centre; N = 2..16 counts
    // an N x N grid of samples per pixel and gives coverage round(255 * inside / N^2)
    // (anti-aliased edges, SPEC.md 3.2 and 8.2). Stored in the TMPL coding byte.
    uint8_t supersample = 0;
    friend bool operator==(const Template&, const Template&) = default;
};

enum class StrokeKind : uint8_t { Stamp = 0, Affine = 1, Curve = 2, Polygon = 3 };

// The paper's SPT stroke: a template of a stroke set at one of the table's orientations.
struct StampStroke {
    uint8_t set = 0;
    uint8_t tmpl = 0;
    uint8_t orient = 0;
    int32_t x = 0, y = 0;  // Q4 centre; rendered centred on the pixel holding it
    Rgba8 color;
    friend bool operator==(const StampStroke&, const StampStroke&) = default;
};

// Any affine image of a template: template point (u, v) in [-1, 1]^2 maps to
// (tx + u*a + v*b, ty + u*c + v*d), all in Q4 pixels.
struct AffineStroke {
    uint8_t tmpl = 0;
    int32_t tx = 0, ty = 0;
    int32_t a = 0, b = 0, c = 0, d = 0;
    Rgba8 color;
    friend bool operator==(const AffineStroke&, const AffineStroke&) = default;
};

struct CurvePoint {
    int32_t x = 0, y = 0;  // Q4
    uint32_t width = 0;    // Q4 full width (diameter) at this point
    friend bool operator==(const CurvePoint&, const CurvePoint&) = default;
};

// A polyline with per-point width and one colour (hand-drawn or curved-stroke painters, a
// cartoon's drawn lines), sampled at pixel centres or, format 1.4, on an N x N grid per pixel
// (anti-aliased edges, SPEC.md 4 and 8.5). A grid needs Header::curve_grid.
struct CurveStroke {
    Rgba8 color;
    uint8_t supersample = 0;  // 0: pixel centres; 2..16: N x N samples per pixel (format 1.4)
    std::vector<CurvePoint> points;
    friend bool operator==(const CurveStroke&, const CurveStroke&) = default;
};

struct PolygonVertex {
    int32_t x = 0, y = 0;  // Q4
    friend bool operator==(const PolygonVertex&, const PolygonVertex&) = default;
};

// A filled polygon (format 1.2): n >= 3 vertices, closed, nonzero fill rule, sampled at pixel
// centres or on an N x N grid like analytic templates (SPEC.md 4 and 8.8). Shapes of painters
// whose pixels no affine image of a template reproduces (geometrize's 20-gon ellipses, SVG
// polygons) are stored with it exactly.
struct PolygonStroke {
    Rgba8 color;
    uint8_t supersample = 0;  // 0: pixel centres; 2..16: N x N samples per pixel
    std::vector<PolygonVertex> points;
    friend bool operator==(const PolygonStroke&, const PolygonStroke&) = default;
};

// One stroke: `kind` says which of the four members holds it. (Not a std::variant of the four,
// 40 bytes instead of 120: measured on a painted 1280 x 720 frame of 30,000 stamps, a variant
// list decodes 0.017 ms faster, is read 0.011 ms faster by the renderer and copies 0.08 ms
// faster, against 2.8 ms for decode + render of that frame (under 1%; Reader::render_frame
// builds no list for such frames at all), while every user of the API would change.)
struct Stroke {
    StrokeKind kind = StrokeKind::Stamp;
    StampStroke stamp;    // valid when kind == Stamp
    AffineStroke affine;  // valid when kind == Affine
    CurveStroke curve;    // valid when kind == Curve
    PolygonStroke polygon;  // valid when kind == Polygon

    static Stroke make_stamp(const StampStroke& s) { Stroke r; r.kind = StrokeKind::Stamp; r.stamp = s; return r; }
    static Stroke make_affine(const AffineStroke& s) { Stroke r; r.kind = StrokeKind::Affine; r.affine = s; return r; }
    static Stroke make_curve(CurveStroke s) { Stroke r; r.kind = StrokeKind::Curve; r.curve = std::move(s); return r; }
    static Stroke make_polygon(PolygonStroke s) { Stroke r; r.kind = StrokeKind::Polygon; r.polygon = std::move(s); return r; }
    // The stroke's colour, whatever its kind.
    const Rgba8& color() const {
        switch (kind) {
            case StrokeKind::Stamp: return stamp.color;
            case StrokeKind::Affine: return affine.color;
            case StrokeKind::Curve: return curve.color;
            case StrokeKind::Polygon: return polygon.color;
        }
        return stamp.color;
    }
    friend bool operator==(const Stroke& x, const Stroke& y) {
        if (x.kind != y.kind) return false;
        switch (x.kind) {
            case StrokeKind::Stamp: return x.stamp == y.stamp;
            case StrokeKind::Affine: return x.affine == y.affine;
            case StrokeKind::Curve: return x.curve == y.curve;
            case StrokeKind::Polygon: return x.polygon == y.polygon;
        }
        return false;
    }
};

// Block motion field: strokes move by the vector of the block holding their anchor.
struct MotionField {
    uint16_t block_size = 16;    // pixels
    uint16_t cols = 0, rows = 0; // ceil(width / block_size), ceil(height / block_size)
    std::vector<std::pair<int16_t, int16_t>> vectors;  // Q4 (dx, dy), row-major, cols*rows
    bool empty() const { return vectors.empty(); }
};

enum class FrameType : uint8_t { Key = 0, Inter = 1 };

// Where the candidates of one stroke set were drawn (SPEC.md 7.7.2): the canvas, intersected
// with the union of `rects` when `use_rects`, and with a block mask when `use_blocks`.
struct ReplayRegion {
    struct Rect {
        uint32_t x = 0, y = 0, w = 0, h = 0;
        friend bool operator==(const Rect&, const Rect&) = default;
    };
    bool use_rects = false;
    std::vector<Rect> rects;        // 1..4096 rectangles, each w, h >= 1
    bool use_blocks = false;
    uint16_t block_size = 8;        // 8..256 pixels
    std::vector<uint8_t> blocks;    // ceil(W/B) x ceil(H/B), row-major, 0 or 1
    friend bool operator==(const ReplayRegion&, const ReplayRegion&) = default;
};

// How a painter drew a frame's stamp strokes from the generator of SPEC.md 7.7 (spt/replay.hpp).
// A writer using frame coding 2 codes only which candidates were accepted when the frame's
// strokes match; otherwise it falls back to coding 1. Not stored as such in any file.
struct ReplayInfo {
    bool present = false;
    uint64_t seed = 0;
    bool random_orientation = false;     // orientations drawn by the generator, else coded
    // Colours lie on a lattice of this step around the canvas prediction (SPEC.md 7.7.5), 1..32.
    uint8_t color_step = 1;
    std::vector<ReplayRegion> regions;   // one per stroke set; empty = the canvas for every set
};

// One frame as stored: a key frame replaces the live stroke list; an inter frame edits it.
// Order of application for inter frames: remove, then move, then append `added`.
struct Frame {
    uint32_t index = 0;
    FrameType type = FrameType::Key;
    std::vector<uint32_t> removed;  // inter: indices into the previous list, strictly increasing
    MotionField motion;             // inter: optional
    std::vector<Stroke> added;      // key: the whole list; inter: appended on top
    ReplayInfo replay;              // optional: how a painter drew `added` (frame coding 2)
};

struct Rational {
    uint32_t num = 24, den = 1;
    friend bool operator==(const Rational&, const Rational&) = default;
};

// How colour values are coded (HEAD color_encoding, SPEC.md 3.1 and 8.6).
enum class ColorEncoding : uint8_t {
    Srgb8 = 0,       // 8-bit sRGB-encoded values, blended as they are
    LinearHalf = 1,  // scene-linear light, 16-bit half-float codes, blended in linear (format 1.3)
};
// "srgb8", "linear-half"; "unknown" for any other value.
const char* color_encoding_name(ColorEncoding e);
// First format minor version with alpha canvases and colour encoding 1.
constexpr uint16_t kAlphaLinearMinorVersion = 3;
// First format minor version with anti-aliased curves (HEAD flag curve_grid).
constexpr uint16_t kCurveGridMinorVersion = 4;
// First format minor version with lead strokes in frame coding 2 (curves and polygons coded
// before the replayed stamps).
constexpr uint16_t kLeadMinorVersion = 5;

constexpr uint32_t kUnknownFrameCount = 0xFFFFFFFFu;

struct Header {
    uint16_t version_major = 1;
    uint16_t version_minor = 0;
    uint32_t width = 0, height = 0;
    Rational fps;
    uint32_t frame_count = kUnknownFrameCount;  // may be unknown while streaming
    ColorEncoding color = ColorEncoding::Srgb8;
    // HEAD flags bit 0 (format 1.3): the canvas has an alpha channel. It then starts fully
    // transparent, colour channels premultiplied, and `background` is only the colour a viewer
    // shows behind it (SPEC.md 8).
    bool alpha = false;
    // HEAD flags bit 1 (format 1.4): every curve carries a supersampling grid (SPEC.md 4, 6,
    // 7.4). A writer needs it before the first curve with a grid; files without it keep the
    // curve records and streams of format 1.0 .. 1.3.
    bool curve_grid = false;
    Rgb8 background{255, 255, 255};
    // Colour encoding 1: the low bytes of the background's 16-bit codes (0 otherwise).
    Rgb8 background_lo{0, 0, 0};
    // True when this header needs nothing of format 1.3: 8-bit sRGB, no alpha.
    bool plain_color() const { return color == ColorEncoding::Srgb8 && !alpha; }
    std::vector<StrokeSet> sets;             // coarse to fine
    std::vector<Orientation> orientations;   // default: 8 entries, k*pi/8
    friend bool operator==(const Header&, const Header&) = default;
};

struct Roi {
    uint32_t first_frame = 0, last_frame = 0;  // inclusive
    uint32_t x = 0, y = 0, w = 0, h = 0;
};

// Everything a file holds besides its frames.
struct StreamInfo {
    Header header;
    std::vector<Template> templates;
    std::vector<std::pair<std::string, std::string>> metadata;  // UTF-8 key/value
    std::vector<Roi> rois;
};

// The default orientation table: n entries at k*pi/n (strokes are symmetric under pi).
std::vector<Orientation> default_orientations(int n = 8);

}  // namespace spt
