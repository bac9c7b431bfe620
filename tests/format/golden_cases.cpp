#include "format/golden_cases.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "spt/color.hpp"
#include "spt/replay.hpp"
#include "spt/spt.hpp"

namespace spt::testing::golden {
namespace {

Template ellipse() { Template t; t.kind = TemplateKind::Ellipse; t.name = "ellipse"; return t; }
Template rect() { Template t; t.kind = TemplateKind::Rectangle; return t; }
Template tri() { Template t; t.kind = TemplateKind::Triangle; t.name = "triangle"; return t; }
Template bitmap(uint16_t w, uint16_t h) {
    Template t;
    t.width = w; t.height = h; t.name = "brush";
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int dx = 2 * x + 1 - w, dy = 2 * y + 1 - h;
            const int r2 = dx * dx * h * h + dy * dy * w * w, R2 = w * w * h * h;
            t.pixels.push_back(uint8_t(r2 <= R2 / 2 ? 255 : r2 <= R2 ? 128 : 0));
        }
    return t;
}
Header header(uint32_t w, uint32_t h, int sets, int orients) {
    Header hd;
    hd.width = w; hd.height = h; hd.fps = {25, 1}; hd.background = {250, 245, 235};
    for (int i = 0; i < sets; ++i) hd.sets.push_back({uint16_t(32 >> std::min(i, 4)), uint16_t(std::max(1, 16 >> std::min(i, 4)))});
    hd.orientations = default_orientations(orients);
    return hd;
}
Stroke stamp(int set, int tmpl, int o, int32_t x, int32_t y, Rgba8 c) {
    StampStroke s; s.set = uint8_t(set); s.tmpl = uint8_t(tmpl); s.orient = uint8_t(o); s.x = x; s.y = y; s.color = c;
    return Stroke::make_stamp(s);
}

// ---- painter-like frames for frame coding 2 (SPEC.md 7.7) ----
// Candidates come from the generator; a fixed quarter of them is "accepted"; the colour is a
// synthetic model's colour at the pixel, put on the lattice of step q around the footprint mean
// of the canvas painted so far (computed here from SPEC.md 7.7.4, independently of libspt).
Rgb8 model_colour(uint32_t x, uint32_t y) {
    const int dx = int(x) - 20, dy = int(y) - 14;
    const bool disc = dx * dx + dy * dy < 100;
    return disc ? Rgb8{uint8_t(200 - 3 * x), 40, uint8_t(60 + 4 * y)} : Rgb8{uint8_t(30 + 4 * x), uint8_t(220 - 5 * y), 90};
}
int on_lattice(int base, int target, int q) {
    int r = (target - base) >= 0 ? (target - base + q / 2) / q : -((base - target + q / 2) / q);
    while (base + q * r > 255) --r;
    while (base + q * r < 0) ++r;
    return base + q * r;
}
Rgba8 lattice_colour(const Canvas& cv, const Mask& fp, int32_t px, int32_t py, Rgb8 bg, Rgb8 t, int q) {
    int64_t sa = 0, sk[3] = {0, 0, 0};
    for (uint32_t j = 0; j < fp.h; ++j)
        for (uint32_t i = 0; i < fp.w; ++i) {
            const int64_t x = px + fp.x0 + int64_t(i), y = py + fp.y0 + int64_t(j);
            const uint8_t a = fp.a[size_t(j) * fp.w + i];
            if (!a || x < 0 || y < 0 || x >= int64_t(cv.width) || y >= int64_t(cv.height)) continue;
            sa += a;
            for (int k = 0; k < 3; ++k) sk[k] += a * int64_t(cv.rgb[(size_t(y) * cv.width + size_t(x)) * 3 + k]);
        }
    int p[3] = {bg.r, bg.g, bg.b};
    if (sa > 0)
        for (int k = 0; k < 3; ++k) p[k] = int((sk[k] + sa / 2) / sa);
    const int g = on_lattice(p[1], t.g, q);
    const int r = on_lattice(std::clamp(g + p[0] - p[1], 0, 255), t.r, q);
    const int b = on_lattice(std::clamp(g + p[2] - p[1], 0, 255), t.b, q);
    return {uint8_t(r), uint8_t(g), uint8_t(b), 255};
}
// Appends `per_set` painter-like strokes of every set to f.added, drawing them on `cv`.
void paint_replayed(Frame& f, Canvas& cv, const Header& hd, const Renderer& rd, uint32_t templates, int per_set) {
    const ReplayInfo& ri = f.replay;
    for (uint32_t s = 0; s < hd.sets.size(); ++s) {
        const replay::CandidateDomain dom(hd.width, hd.height, ri.regions.empty() ? ReplayRegion{} : ri.regions[s]);
        if (dom.size() == 0) continue;
        int kept = 0;
        for (uint64_t n = 0; kept < per_set; ++n) {
            if ((replay::draw(ri.seed, s, n, replay::Stream::Accept) >> 62) != 0) continue;  // rejected
            const replay::Candidate c = replay::candidate(ri.seed, s, n, dom, templates, uint32_t(hd.orientations.size()));
            // Coded orientations follow a synthetic field, as the painter's edge field would.
            const uint8_t o = ri.random_orientation ? c.orient : uint8_t((c.x / 6 + c.y / 5) % hd.orientations.size());
            const Mask& fp = rd.stamp_footprint(uint8_t(s), c.tmpl, o);
            const Rgba8 col = lattice_colour(cv, fp, int32_t(c.x), int32_t(c.y), hd.background, model_colour(c.x, c.y), ri.color_step);
            const Stroke st = stamp(int(s), c.tmpl, o, int32_t(16 * c.x + 8), int32_t(16 * c.y + 8), col);
            (void)rd.draw(cv, st);
            f.added.push_back(st);
            ++kept;
        }
    }
}
Case replay_case() {
    Case c{"replay_paint", "frame coding 2 (format 1.1): a painter-like key frame (coded orientations, colour step 4, "
                           "rectangles for the finest set), then an inter frame with removals, motion and a block-mask "
                           "region (drawn orientations, colour step 8)", {}};
    c.replay = true;
    Header hd = header(48, 32, 3, 8);
    hd.sets = {{16, 8}, {8, 4}, {4, 2}};
    c.stream.info.header = hd;
    c.stream.info.templates = {bitmap(9, 7), ellipse()};
    auto rd = Renderer::create(hd, c.stream.info.templates);
    Canvas cv(hd.width, hd.height, hd.background);
    Frame k;
    k.replay.present = true;
    k.replay.seed = 0x5EED2024;
    k.replay.color_step = 4;
    k.replay.regions.assign(3, ReplayRegion{});
    k.replay.regions[2].use_rects = true;
    k.replay.regions[2].rects = {{4, 4, 20, 12}, {30, 10, 10, 20}};
    paint_replayed(k, cv, hd, **rd, 2, 12);
    Frame i;
    i.index = 1;
    i.type = FrameType::Inter;
    i.removed = {0, 5, 13, 30};
    i.motion.block_size = 16; i.motion.cols = 3; i.motion.rows = 2;
    i.motion.vectors = {{0, 0}, {16, -8}, {0, 0}, {-24, 0}, {0, 0}, {3, 5}};
    i.replay.present = true;
    i.replay.seed = 77;
    i.replay.random_orientation = true;
    i.replay.color_step = 8;
    ReplayRegion blocks;
    blocks.use_blocks = true;
    blocks.block_size = 8;
    blocks.blocks = {0, 1, 1, 0, 0, 0,
                     0, 1, 1, 1, 0, 0,
                     0, 0, 0, 1, 1, 0,
                     0, 0, 0, 0, 1, 0};
    i.replay.regions.assign(3, blocks);
    // The coding-2 starting canvas of an inter frame: the live list after removals and motion.
    std::vector<Stroke> live = k.added;
    Frame edits = i;
    (void)apply_frame(live, edits, hd);
    cv.fill(hd.background);
    for (const auto& s : live) (void)(*rd)->draw(cv, s);
    paint_replayed(i, cv, hd, **rd, 2, 5);
    c.stream.frames = {k, i};
    return c;
}

// Format 1.5 (SPEC.md 7.7.5): coding-2 frames whose polygons, curves and affine strokes lead,
// coded as in coding 1, and whose stamps replay on the canvas they leave.
Case replay_lead_case() {
    Case c{"replay_lead", "frame coding 2 with lead strokes (format 1.5): a key frame of a polygon, an anti-aliased "
                          "curve and an affine stroke, then replayed stamps predicted from the canvas they leave, "
                          "both sets drawing from one region (coded once); an inter frame with removals, motion, a "
                          "lead polygon and replayed stamps, each set with its own block mask", {}};
    c.replay = true;
    Header hd = header(48, 32, 2, 8);
    hd.sets = {{8, 4}, {4, 2}};
    hd.curve_grid = true;
    c.stream.info.header = hd;
    c.stream.info.templates = {bitmap(9, 7), ellipse()};
    auto rd = Renderer::create(hd, c.stream.info.templates);
    Canvas cv(hd.width, hd.height, hd.background);
    Frame k;
    PolygonStroke gon;
    gon.supersample = 4;
    gon.color = {30, 120, 200, 255};
    gon.points = {{16 * 3 + 5, 16 * 2}, {16 * 40, 16 * 4 + 9}, {16 * 30 + 2, 16 * 28}, {16 * 6, 16 * 22 + 12}};
    k.added.push_back(Stroke::make_polygon(gon));
    CurveStroke line;
    line.supersample = 4;
    line.color = {20, 20, 30, 255};
    line.points = {{16 * 2, 16 * 30, 40}, {16 * 24 + 3, 16 * 16, 24}, {16 * 46, 16 * 6 + 7, 32}};
    k.added.push_back(Stroke::make_curve(line));
    AffineStroke blob;
    blob.tmpl = 1; blob.tx = 16 * 36; blob.ty = 16 * 22; blob.a = 96; blob.d = 64; blob.color = {220, 60, 40, 255};
    k.added.push_back(Stroke::make_affine(blob));
    for (const Stroke& s : k.added) (void)(*rd)->draw(cv, s);
    k.replay.present = true;
    k.replay.seed = 0x1EAD;
    k.replay.color_step = 4;
    k.replay.regions.assign(2, ReplayRegion{});
    paint_replayed(k, cv, hd, **rd, 2, 16);
    Frame i;
    i.index = 1;
    i.type = FrameType::Inter;
    i.removed = {1, 4, 9};
    i.motion.block_size = 16; i.motion.cols = 3; i.motion.rows = 2;
    i.motion.vectors = {{0, 0}, {8, -8}, {0, 0}, {-16, 0}, {0, 0}, {2, 3}};
    PolygonStroke tri;
    tri.supersample = 8;
    tri.color = {250, 210, 40, 255};
    tri.points = {{16 * 10, 16 * 10}, {16 * 20 + 8, 16 * 12}, {16 * 14, 16 * 20 + 4}};
    i.added.push_back(Stroke::make_polygon(tri));
    i.replay.present = true;
    i.replay.seed = 99;
    i.replay.color_step = 6;
    ReplayRegion blocks;
    blocks.use_blocks = true;
    blocks.block_size = 8;
    blocks.blocks = {1, 1, 1, 0, 0, 0,
                     0, 1, 1, 1, 0, 0,
                     0, 0, 1, 1, 1, 0,
                     0, 0, 0, 0, 1, 1};
    i.replay.regions.assign(2, blocks);
    i.replay.regions[1].blocks = {1, 1, 1, 1, 0, 0,
                                  1, 1, 1, 1, 0, 0,
                                  0, 0, 1, 1, 1, 1,
                                  0, 0, 0, 1, 1, 1};
    std::vector<Stroke> live = k.added;
    Frame edits = i;
    edits.added.clear();
    (void)apply_frame(live, edits, hd);
    cv.fill(hd.background);
    for (const auto& s : live) (void)(*rd)->draw(cv, s);
    (void)(*rd)->draw(cv, i.added.front());
    paint_replayed(i, cv, hd, **rd, 2, 10);
    c.stream.frames = {k, i};
    return c;
}

}  // namespace

std::vector<Case> cases() {
    std::vector<Case> v;
    {   // 1x1 canvas, one stamp.
        Case c{"tiny_1x1", "1x1 canvas, one set, one orientation, one stamp on the only pixel", {}};
        c.stream.info.header = header(1, 1, 1, 1);
        c.stream.info.templates = {ellipse()};
        Frame f; f.added = {stamp(0, 0, 0, 8, 8, {200, 10, 20, 255})};
        c.stream.frames = {f};
        v.push_back(c);
    }
    {   // Empty key frames.
        Case c{"empty_key", "an empty key frame, a key frame with one stroke, an empty inter frame", {}};
        c.stream.info.header = header(16, 9, 2, 8);
        c.stream.info.templates = {ellipse()};
        Frame a; a.index = 0;
        Frame b; b.index = 1; b.added = {stamp(1, 0, 3, 40, 24, {1, 2, 3, 128})};
        Frame d; d.index = 2; d.type = FrameType::Inter;
        c.stream.frames = {a, b, d};
        v.push_back(c);
    }
    {   // Every kind, every template kind, negative and off-canvas coordinates, a 1-point curve.
        Case c{"all_kinds", "stamp, affine and curve strokes; bitmap and analytic templates; negative coordinates; "
                            "a curve with one point; translucent colours; metadata and rois", {}};
        c.stream.info.header = header(64, 48, 3, 8);
        c.stream.info.templates = {bitmap(9, 7), ellipse(), rect(), tri()};
        c.stream.info.metadata = {{"software", "spt make_golden"}, {"title", "all kinds"}};
        c.stream.info.rois = {{0, 0, 4, 4, 20, 10}};
        Frame f;
        f.added.push_back(stamp(0, 0, 2, 16 * 10 + 8, 16 * 12 + 8, {10, 200, 30, 255}));
        f.added.push_back(stamp(2, 1, 7, -5, -40, {255, 255, 0, 17}));
        AffineStroke a; a.tmpl = 3; a.tx = -33; a.ty = 16 * 20; a.a = 160; a.b = -40; a.c = 30; a.d = 200; a.color = {0, 0, 255, 200};
        f.added.push_back(Stroke::make_affine(a));
        AffineStroke r; r.tmpl = 2; r.tx = 16 * 70; r.ty = 16 * 30 + 3; r.a = -80; r.b = 0; r.c = 0; r.d = 48; r.color = {9, 8, 7, 255};
        f.added.push_back(Stroke::make_affine(r));
        CurveStroke one; one.color = {100, 50, 25, 255}; one.points = {{16 * 5, 16 * 40, 64}};
        f.added.push_back(Stroke::make_curve(one));
        CurveStroke cv; cv.color = {5, 80, 160, 90};
        cv.points = {{-16, -16, 0}, {16 * 30, 16 * 10, 48}, {16 * 60 + 5, 16 * 47 + 9, 96}, {16 * 80, 16 * 50, 8}};
        f.added.push_back(Stroke::make_curve(cv));
        c.stream.frames = {f};
        v.push_back(c);
    }
    {   // Motion and removals.
        Case c{"inter_motion", "key frame, then inter frames with removals, a block motion field (block 16) and additions; "
                               "a second key frame; 16 sets and 64 orientations", {}};
        c.stream.info.header = header(70, 40, 16, 64);
        c.stream.info.templates = {ellipse(), bitmap(5, 5)};
        Frame k;
        for (int i = 0; i < 40; ++i)
            k.added.push_back(stamp(i % 16, i % 2, (i * 7) % 64, 16 * ((i * 13) % 70) + 8, 16 * ((i * 7) % 40) + 8,
                                    {uint8_t(i * 6), uint8_t(255 - i * 5), uint8_t(i * 3), 255}));
        Frame i1; i1.index = 1; i1.type = FrameType::Inter;
        i1.removed = {0, 3, 4, 5, 39};
        i1.motion.block_size = 16; i1.motion.cols = 5; i1.motion.rows = 3;
        for (int b = 0; b < 15; ++b) i1.motion.vectors.push_back(b == 7 ? std::pair<int16_t, int16_t>{-40, 12} : std::pair<int16_t, int16_t>{5, -3});
        i1.added = {stamp(15, 1, 63, 16 * 69 + 8, 16 * 39 + 8, {0, 0, 0, 255})};
        Frame i2; i2.index = 2; i2.type = FrameType::Inter;
        i2.removed = {1};
        i2.motion.block_size = 256; i2.motion.cols = 1; i2.motion.rows = 1; i2.motion.vectors = {{-1, 1}};
        Frame k2; k2.index = 3; k2.added = {stamp(3, 0, 33, 100, 100, {1, 1, 1, 1})};
        Frame i3; i3.index = 4; i3.type = FrameType::Inter; i3.removed = {0};
        c.stream.frames = {k, i1, i2, k2, i3};
        v.push_back(c);
    }
    {
        Case c{"no_index", "a complete file without indx (IEND index_offset 0): readers scan", {}};
        c.stream = make_random_stream(5, {});
        c.drop_index = true;
        v.push_back(c);
    }
    {
        Case c{"unknown_ancillary", "an unknown ancillary chunk 'xtRa' after HEAD, which readers skip", {}};
        c.stream.info.header = header(20, 20, 1, 4);
        c.stream.info.templates = {rect()};
        Frame f; f.added = {stamp(0, 0, 1, 80, 80, {7, 7, 7, 255})};
        c.stream.frames = {f};
        c.unknown_ancillary = true;
        v.push_back(c);
    }
    {
        StreamShapeOptions o;
        o.max_side = 120;
        o.frames = 5;
        o.max_strokes = 40;
        Case c{"random_mix", "a random stream of every stroke kind with motion and removals (seed 42)", make_random_stream(42, o)};
        v.push_back(c);
    }
    v.push_back(replay_case());
    v.push_back(replay_lead_case());
    {   // Format 1.2: polygon strokes.
        Case c{"polygons", "format 1.2 polygon strokes: a 20-gon on the half-pixel lattice, a self-intersecting star, "
                           "a supersampled (N = 4) quadrilateral, repeated vertices and a horizontal edge, among a "
                           "curve and a stamp; then an inter frame whose motion moves a polygon rigidly", {}};
        c.stream.info.header = header(48, 40, 1, 4);
        c.stream.info.templates = {ellipse()};
        Frame k;
        PolygonStroke gon;
        gon.color = {200, 60, 30, 255};
        const int32_t ring[20][2] = {{15, 0}, {14, 5}, {12, 9}, {9, 12}, {5, 14}, {0, 15}, {-5, 14}, {-9, 12}, {-12, 9}, {-14, 5},
                                     {-15, 0}, {-14, -5}, {-12, -9}, {-9, -12}, {-5, -14}, {0, -15}, {5, -14}, {9, -12}, {12, -9}, {14, -5}};
        for (const auto& q : ring) gon.points.push_back({16 * 20 + 8 * q[0], 16 * 18 + 8 * q[1]});
        k.added.push_back(Stroke::make_polygon(gon));
        PolygonStroke star;
        star.color = {20, 90, 200, 160};
        star.points = {{16 * 40, 16 * 2}, {16 * 46, 16 * 30}, {16 * 26, 16 * 12}, {16 * 52, 16 * 12}, {16 * 32 + 3, 16 * 30 - 5}};
        k.added.push_back(Stroke::make_polygon(star));
        k.added.push_back(stamp(0, 0, 1, 16 * 5 + 8, 16 * 35 + 8, {0, 0, 0, 255}));
        CurveStroke cv; cv.color = {5, 80, 160, 90};
        cv.points = {{16, 16 * 39, 24}, {16 * 47, 16 * 20, 40}};
        k.added.push_back(Stroke::make_curve(cv));
        PolygonStroke quad;
        quad.color = {250, 250, 20, 200};
        quad.supersample = 4;
        quad.points = {{-40, -40}, {16 * 10 + 5, 3}, {16 * 10 + 5, 3}, {16 * 12, 16 * 9 + 7}, {7, 16 * 9 + 7}};
        k.added.push_back(Stroke::make_polygon(quad));
        Frame i; i.index = 1; i.type = FrameType::Inter;
        i.removed = {2};
        i.motion.block_size = 32; i.motion.cols = 2; i.motion.rows = 2;
        i.motion.vectors = {{-24, 8}, {0, 0}, {13, -7}, {0, 40}};
        PolygonStroke tri;
        tri.color = {0, 255, 0, 255};
        tri.points = {{16 * 30, 16 * 30}, {16 * 47, 16 * 39}, {16 * 30, 16 * 39}};
        i.added.push_back(Stroke::make_polygon(tri));
        c.stream.frames = {k, i};
        v.push_back(c);
    }
    {   // Format 1.2: polygons that the conic prediction codes (SPEC.md 7.4 polygon 5, mode 2).
        Case c{"polygons_conic", "format 1.2 polygons near affine images of regular polygons (conic prediction): three "
                                 "geometrize-like rotated-ellipse 20-gons on truncated whole pixels (one rotation, coded "
                                 "once), a clockwise 32-gon ellipse at 1/16 px, a half-pixel 12-gon circle, a 20-gon "
                                 "off the canvas", {}};
        c.stream.info.header = header(64, 48, 1, 1);
        c.stream.info.templates = {ellipse()};
        Frame k;
        // (centre x, centre y, rx, ry, angle in degrees, vertex count, Q4 step, clockwise)
        struct Ring { double cx, cy, rx, ry, deg; int n, step; bool cw; Rgba8 col; };
        const Ring rings[] = {{20, 15, 11, 6, 30, 20, 16, false, {200, 60, 30, 255}},
                              {40, 30, 7, 13, 105, 20, 16, false, {30, 160, 60, 128}},
                              {12, 36, 5, 4, 0, 20, 16, false, {250, 240, 10, 255}},
                              {44, 14, 14.3, 6.7, -20, 32, 1, true, {10, 20, 220, 200}},
                              {30, 24, 9.5, 9.5, 0, 12, 8, false, {120, 0, 120, 90}},
                              {-6, 50, 12, 8, 60, 20, 16, false, {0, 0, 0, 255}}};
        for (const Ring& r : rings) {
            PolygonStroke pg;
            pg.color = r.col;
            const double co = std::cos(r.deg * M_PI / 180), si = std::sin(r.deg * M_PI / 180);
            for (int i = 0; i < r.n; ++i) {
                const double a = (r.cw ? -2 : 2) * M_PI * i / r.n;
                const double ex = r.rx * std::cos(a), ey = r.ry * std::sin(a);
                const double x = 16 * (r.cx + ex * co - ey * si), y = 16 * (r.cy + ex * si + ey * co);
                // Truncated to the step (geometrize truncates to whole pixels), then on the
                // lattice through the first vertex: multiples of the step plus 8 for pixels.
                const int32_t off = r.step == 16 ? 8 : 0;
                pg.points.push_back({int32_t(std::floor(x / r.step)) * r.step + off, int32_t(std::floor(y / r.step)) * r.step + off});
            }
            k.added.push_back(Stroke::make_polygon(pg));
        }
        c.stream.frames = {k};
        v.push_back(c);
    }
    {   // Format 1.3: an alpha canvas (SPEC.md 8, 8.6): transparent start, premultiplied colour.
        Case c{"alpha_rgba", "format 1.3 alpha canvas in colour encoding 0: opaque and translucent stamps, a "
                             "supersampled affine ellipse, a curve and a polygon over a transparent canvas; then an "
                             "inter frame with a removal, motion and a stroke of partial opacity", {}};
        c.stream.info.header = header(64, 48, 2, 8);
        c.stream.info.header.alpha = true;
        Template aa = ellipse();
        aa.supersample = 4;
        c.stream.info.templates = {ellipse(), bitmap(8, 8), aa};
        Frame k;
        k.added.push_back(stamp(0, 0, 1, 16 * 20 + 8, 16 * 15 + 8, {220, 40, 30, 255}));
        k.added.push_back(stamp(1, 1, 3, 16 * 30 + 8, 16 * 20 + 8, {20, 90, 240, 128}));
        AffineStroke af;
        af.tmpl = 2; af.tx = 16 * 44; af.ty = 16 * 30; af.a = 16 * 9; af.b = 16 * 3; af.c = -16 * 2; af.d = 16 * 6;
        af.color = {250, 250, 250, 200};
        k.added.push_back(Stroke::make_affine(af));
        CurveStroke cv;
        cv.color = {0, 0, 0, 255};
        cv.points = {{16 * 5, 16 * 40, 40}, {16 * 25, 16 * 44, 16}, {16 * 60, 16 * 38, 64}};
        k.added.push_back(Stroke::make_curve(cv));
        PolygonStroke pg;
        pg.color = {40, 200, 60, 160};
        pg.supersample = 3;
        pg.points = {{16 * 2, 16 * 2}, {16 * 14, 16 * 4 + 5}, {16 * 9, 16 * 13}};
        k.added.push_back(Stroke::make_polygon(pg));
        Frame i; i.index = 1; i.type = FrameType::Inter;
        i.removed = {1};
        i.motion.block_size = 32; i.motion.cols = 2; i.motion.rows = 2;
        i.motion.vectors = {{16, 0}, {0, 0}, {-20, 12}, {0, 0}};
        i.added.push_back(stamp(0, 1, 5, 16 * 50 + 8, 16 * 10 + 8, {255, 200, 0, 90}));
        c.stream.frames = {k, i};
        v.push_back(c);
    }
    // Colour encoding 1 colours from linear values (exact half codes, SPEC.md 4 and 8.6).
    auto lin = [](float r, float g, float b, uint8_t a) {
        Rgba8 c; c.a = a;
        set_code16(c, 0, float_to_half_code(r)); set_code16(c, 1, float_to_half_code(g)); set_code16(c, 2, float_to_half_code(b));
        return c;
    };
    {   // Format 1.3: colour encoding 1, scene-linear half codes composited in linear light.
        Case c{"linear_hdr", "format 1.3 colour encoding 1 (scene-linear half floats): a mid-grey background, a glowing "
                             "stamp far above 1.0 (20), deep shadows in the half subnormals, translucent strokes of every kind "
                             "blended in linear light; then an inter frame with motion", {}};
        c.stream.info.header = header(48, 32, 2, 8);
        c.stream.info.header.color = ColorEncoding::LinearHalf;
        const Rgba8 bg = lin(0.18f, 0.18f, 0.18f, 255);
        c.stream.info.header.background = {bg.r, bg.g, bg.b};
        c.stream.info.header.background_lo = {bg.r_lo, bg.g_lo, bg.b_lo};
        c.stream.info.templates = {ellipse(), bitmap(6, 6)};
        Frame k;
        k.added.push_back(stamp(0, 0, 2, 16 * 16 + 8, 16 * 12 + 8, lin(20.0f, 12.5f, 3.0f, 255)));
        k.added.push_back(stamp(1, 1, 0, 16 * 30 + 8, 16 * 20 + 8, lin(0.00002f, 0.0000005f, 0.001f, 255)));
        k.added.push_back(stamp(1, 0, 6, 16 * 34 + 8, 16 * 22 + 8, lin(1.0f, 0.5f, 0.25f, 100)));
        AffineStroke af;
        af.tmpl = 1; af.tx = 16 * 10; af.ty = 16 * 25; af.a = 16 * 7; af.b = 0; af.c = 0; af.d = 16 * 4;
        af.color = lin(65504.0f, 0.0f, 0.75f, 30);
        k.added.push_back(Stroke::make_affine(af));
        CurveStroke cv;
        cv.color = lin(0.05f, 0.9f, 4.0f, 180);
        cv.points = {{16 * 2, 16 * 2, 24}, {16 * 46, 16 * 30, 48}};
        k.added.push_back(Stroke::make_curve(cv));
        PolygonStroke pg;
        pg.color = lin(0.3f, 0.3f, 2.5f, 255);
        pg.supersample = 4;
        pg.points = {{16 * 40, 16 * 1}, {16 * 47, 16 * 9}, {16 * 36, 16 * 7}};
        k.added.push_back(Stroke::make_polygon(pg));
        Frame i; i.index = 1; i.type = FrameType::Inter;
        i.removed = {2, 4};
        i.motion.block_size = 16; i.motion.cols = 3; i.motion.rows = 2;
        i.motion.vectors = {{8, 8}, {-16, 0}, {0, 0}, {0, 0}, {3, -5}, {0, 0}};
        i.added.push_back(stamp(0, 1, 4, 16 * 24 + 8, 16 * 16 + 8, lin(0.01f, 0.02f, 0.04f, 255)));
        c.stream.frames = {k, i};
        v.push_back(c);
    }
    {   // Format 1.3: both, as a render with transparent film gives them.
        Case c{"linear_alpha", "format 1.3 colour encoding 1 on an alpha canvas: premultiplied half codes over a "
                               "transparent start, HDR highlights with soft edges, a second key frame", {}};
        c.stream.info.header = header(40, 30, 2, 4);
        c.stream.info.header.color = ColorEncoding::LinearHalf;
        c.stream.info.header.alpha = true;
        c.stream.info.header.background = {0, 0, 0};
        c.stream.info.templates = {bitmap(10, 10), ellipse()};
        Frame k;
        k.added.push_back(stamp(0, 0, 1, 16 * 14 + 8, 16 * 12 + 8, lin(0.6f, 0.25f, 0.1f, 255)));
        k.added.push_back(stamp(1, 1, 2, 16 * 16 + 8, 16 * 10 + 8, lin(21.0f, 18.0f, 9.0f, 255)));
        k.added.push_back(stamp(1, 0, 3, 16 * 26 + 8, 16 * 20 + 8, lin(0.002f, 0.004f, 0.008f, 140)));
        Frame i; i.index = 1; i.type = FrameType::Inter;
        i.motion.block_size = 8; i.motion.cols = 5; i.motion.rows = 4;
        i.motion.vectors.assign(20, {4, -2});
        i.added.push_back(stamp(0, 1, 0, 16 * 30 + 8, 16 * 8 + 8, lin(3.0f, 3.0f, 3.0f, 64)));
        Frame k2; k2.index = 2;
        k2.added.push_back(stamp(0, 0, 2, 16 * 5 + 8, 16 * 25 + 8, lin(0.0f, 0.0f, 0.0f, 255)));
        c.stream.frames = {k, i, k2};
        v.push_back(c);
    }
    {   // Format 1.4: anti-aliased curves (HEAD flag curve_grid).
        Case c{"curves_aa", "format 1.4 anti-aliased curves (flag curve_grid): a cartoon-like line of varying width at "
                            "grid 4, a translucent hairline at grid 16, a grid-0 curve (the 1.3 rule) in the same "
                            "file, a one-point disc at grid 3, among a polygon and a stamp; then an inter frame whose "
                            "motion moves the curves' points and adds a grid-2 curve", {}};
        c.stream.info.header = header(56, 40, 1, 4);
        c.stream.info.header.curve_grid = true;
        c.stream.info.templates = {ellipse()};
        Frame k;
        PolygonStroke fill;
        fill.color = {250, 200, 40, 255};
        fill.supersample = 4;
        fill.points = {{16 * 6, 16 * 6}, {16 * 40, 16 * 4 + 5}, {16 * 44, 16 * 30}, {16 * 10, 16 * 34 + 9}};
        k.added.push_back(Stroke::make_polygon(fill));
        CurveStroke ink;
        ink.color = {20, 16, 12, 255};
        ink.supersample = 4;
        ink.points = {{16 * 6, 16 * 6, 40}, {16 * 40, 16 * 4 + 5, 56}, {16 * 44, 16 * 30, 28}, {16 * 10 + 3, 16 * 34 + 9, 40},
                      {16 * 6, 16 * 6, 40}};
        k.added.push_back(Stroke::make_curve(ink));
        CurveStroke hair;
        hair.color = {200, 30, 60, 170};
        hair.supersample = 16;
        hair.points = {{16 * 2 + 5, 16 * 38, 9}, {16 * 30 + 11, 16 * 20 + 2, 12}, {16 * 54, 16 * 37, 4}};
        k.added.push_back(Stroke::make_curve(hair));
        CurveStroke plain;
        plain.color = {0, 90, 200, 255};
        plain.points = {{16 * 48, 16 * 2, 24}, {16 * 52, 16 * 14, 24}};
        k.added.push_back(Stroke::make_curve(plain));
        CurveStroke dot;
        dot.color = {0, 160, 80, 255};
        dot.supersample = 3;
        dot.points = {{16 * 25 + 3, 16 * 18 + 11, 70}};
        k.added.push_back(Stroke::make_curve(dot));
        k.added.push_back(stamp(0, 0, 1, 16 * 50 + 8, 16 * 30 + 8, {90, 40, 160, 255}));
        Frame i; i.index = 1; i.type = FrameType::Inter;
        i.removed = {3};
        i.motion.block_size = 32; i.motion.cols = 2; i.motion.rows = 2;
        i.motion.vectors = {{-5, 3}, {11, 0}, {0, -9}, {6, 6}};
        CurveStroke late;
        late.color = {255, 255, 255, 255};
        late.supersample = 2;
        late.points = {{16 * 12, 16 * 20, 20}, {16 * 20 + 7, 16 * 21, 30}, {16 * 28, 16 * 19 + 4, 20}};
        i.added.push_back(Stroke::make_curve(late));
        c.stream.frames = {k, i};
        v.push_back(c);
    }
    return v;
}

}  // namespace spt::testing::golden
