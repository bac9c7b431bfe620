// Round-trip properties: random valid streams written with either coding read back to the same
// frames and the same live stroke lists (sequential and random access).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <random>

#include "format/coding_random_streams.hpp"
#include "frame_coding.hpp"     // format/src: the stroke stream decoder on its own
#include "stroke_stream.hpp"    // format/src: the polygon syntax, to code hand-made plans

using namespace spt;
using namespace spt::testing;

namespace {

void check_stream(const RandomStream& rs, uint64_t seed, Coding coding) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " coding " + std::to_string(int(coding)));
    const std::string path = temp_path("rt-" + std::to_string(seed) + "-" + std::to_string(int(coding)) + ".spt");
    ASSERT_TRUE(write_stream(path, rs, coding).ok());
    auto r = Reader::open(path);
    ASSERT_TRUE(r.ok()) << r.error().message;
    Reader& rd = **r;
    EXPECT_TRUE(rd.complete());
    EXPECT_TRUE(rd.has_index());
    EXPECT_TRUE(rd.warnings().empty());
    EXPECT_EQ(rd.info().header.width, rs.info.header.width);
    EXPECT_EQ(rd.info().header.sets, rs.info.header.sets);
    EXPECT_EQ(rd.info().header.orientations, rs.info.header.orientations);
    EXPECT_EQ(rd.info().header.frame_count, rs.frames.size());
    EXPECT_EQ(rd.info().templates, rs.info.templates);
    EXPECT_EQ(rd.info().metadata, rs.info.metadata);
    ASSERT_EQ(rd.frames().size(), rs.frames.size());
    std::vector<Stroke> live;
    std::vector<std::vector<Stroke>> lives;
    for (size_t i = 0; i < rs.frames.size(); ++i) {
        auto f = rd.read_frame(i);
        ASSERT_TRUE(f.ok()) << f.error().message;
        EXPECT_TRUE(same_frame(*f, rs.frames[i])) << "frame " << i;
        EXPECT_EQ(rd.frames()[i].added, rs.frames[i].added.size());
        EXPECT_EQ(rd.frames()[i].removed, rs.frames[i].removed.size());
        EXPECT_EQ(rd.frames()[i].stroke_bytes + rd.frames()[i].motion_bytes + 8 + 12, rd.frames()[i].chunk_bytes);
        ASSERT_TRUE(apply_frame(live, rs.frames[i], rs.info.header).ok());
        lives.push_back(live);
        auto s = rd.strokes_at(i);
        ASSERT_TRUE(s.ok()) << s.error().message;
        EXPECT_EQ(**s, live) << "live list after frame " << i;
    }
    // Random access, backwards.
    for (size_t i = rs.frames.size(); i-- > 0;) {
        auto s = rd.strokes_at(i);
        ASSERT_TRUE(s.ok());
        EXPECT_EQ(**s, lives[i]);
    }
    // Decoding into one reused Frame, backwards (key frames after inter frames, whose removals
    // and motion must not linger), gives the same frames.
    Frame reused;
    for (size_t i = rs.frames.size(); i-- > 0;) {
        const Status st = rd.read_frame(i, reused);
        ASSERT_TRUE(st.ok()) << st.error().message;
        EXPECT_TRUE(same_frame(reused, rs.frames[i])) << "frame " << i << " into a reused Frame";
        // A stamp decoded where a curve or polygon was keeps none of its points.
        for (const Stroke& st : reused.added)
            if (st.kind == StrokeKind::Stamp) EXPECT_TRUE(st.curve.points.empty() && st.polygon.points.empty());
    }
    // Reading from memory gives the same.
    const auto bytes = read_bytes(path);
    auto m = Reader::open_memory(bytes.data(), bytes.size());
    ASSERT_TRUE(m.ok());
    auto s = (*m)->strokes_at(rs.frames.size() - 1);
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(**s, lives.back());
    std::remove(path.c_str());
}

void check_roundtrip(uint64_t seed, Coding coding, const StreamShapeOptions& o = {}) {
    check_stream(make_random_stream(seed, o), seed, coding);
}

}  // namespace

TEST(CodingRoundTrip, StoredRandomStreams) {
    for (uint64_t seed = 1; seed <= 40; ++seed) check_roundtrip(seed, Coding::Stored);
}

TEST(CodingRoundTrip, RangeRandomStreams) {
    for (uint64_t seed = 1; seed <= 40; ++seed) check_roundtrip(seed, Coding::Range);
}

// Polygon strokes (format 1.2) among every other kind, in both codings: the writer raises the
// header to 1.2 at the first polygon (or is asked for 1.2 when a range-coded curve came first).
TEST(CodingRoundTrip, PolygonStreams) {
    StreamShapeOptions o;
    o.polygons = true;
    for (uint64_t seed = 300; seed < 330; ++seed)
        for (Coding coding : {Coding::Stored, Coding::Range}) {
            RandomStream rs = make_random_stream(seed, o);
            rs.info.header.version_minor = 2;
            check_stream(rs, seed, coding);
        }
}

// Anti-aliased curves (format 1.4) among every other kind, in both codings: curves carry their
// grids through the stored record and the range-coded stream, and the file says 1.4.
TEST(CodingRoundTrip, CurveGridStreams) {
    StreamShapeOptions o;
    o.polygons = true;
    o.curve_grid = true;
    int gridded = 0;
    for (uint64_t seed = 500; seed < 530; ++seed) {
        RandomStream rs = make_random_stream(seed, o);
        for (const Frame& f : rs.frames)
            for (const Stroke& s : f.added) gridded += s.kind == StrokeKind::Curve && s.curve.supersample != 0;
        for (Coding coding : {Coding::Stored, Coding::Range}) check_stream(rs, seed, coding);
    }
    EXPECT_GT(gridded, 100);
}

// The writer refuses a curve with a grid in a file without the curve_grid flag (its record and
// stream would have no room for it), names the stroke, and raises a flagged header to 1.4.
TEST(CodingRoundTrip, CurveGridNeedsTheFlag) {
    CurveStroke c;
    c.supersample = 4;
    c.points = {{80, 80, 40}, {200, 90, 30}};
    RandomStream rs = one_frame_stream(20, 10, {Stroke::make_curve(c)});
    const std::string path = temp_path("curve-grid.spt");
    for (Coding coding : {Coding::Stored, Coding::Range}) {
        const Status st = write_stream(path, rs, coding);
        ASSERT_FALSE(st.ok());
        EXPECT_NE(st.error().message.find("curve_grid"), std::string::npos) << st.error().message;
    }
    rs.info.header.curve_grid = true;
    for (Coding coding : {Coding::Stored, Coding::Range}) {
        ASSERT_TRUE(write_stream(path, rs, coding).ok());
        auto r = Reader::open(path);
        ASSERT_TRUE(r.ok()) << r.error().message;
        EXPECT_EQ((*r)->info().header.version_minor, kCurveGridMinorVersion);
        EXPECT_TRUE((*r)->info().header.curve_grid);
        auto s = (*r)->strokes_at(0);
        ASSERT_TRUE(s.ok()) << s.error().message;
        EXPECT_EQ((**s)[0].curve.supersample, 4);
    }
}

// A stream that gets its first polygon after range-coded frames without curves is raised to 1.2
// in place; one that range-coded a curve first is refused, with a message saying why.
TEST(CodingRoundTrip, WriterRaisesVersionForPolygons) {
    AffineStroke a; a.a = a.d = 16; a.tx = a.ty = 40;
    RandomStream rs = one_frame_stream(20, 10, {Stroke::make_affine(a)}, 2);
    rs.info.templates = {Template{TemplateKind::Ellipse, 0, 0, {}, "e", 0}};
    Frame i; i.index = 1; i.type = FrameType::Inter;
    PolygonStroke p; p.points = {{0, 0}, {160, 8}, {40, 150}};
    i.added = {Stroke::make_polygon(p)};
    rs.frames.push_back(i);
    const std::string path = temp_path("poly-version.spt");
    ASSERT_TRUE(write_stream(path, rs, Coding::Range).ok());
    auto r = Reader::open(path);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ((*r)->info().header.version_minor, 2);
    auto s = (*r)->strokes_at(1);
    ASSERT_TRUE(s.ok()) << s.error().message;
    EXPECT_EQ((**s)[1], rs.frames[1].added[0]);
    // Without polygons the version stays as given.
    rs.frames.pop_back();
    ASSERT_TRUE(write_stream(path, rs, Coding::Range).ok());
    EXPECT_EQ((*Reader::open(path))->info().header.version_minor, 0);
    // A range-coded curve before the first polygon: refused.
    CurveStroke c; c.points = {{8, 8, 16}};
    rs.frames[0].added.push_back(Stroke::make_curve(c));
    rs.frames.push_back(i);
    const Status st = write_stream(path, rs, Coding::Range);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("version_minor = 2"), std::string::npos) << st.error().message;
    EXPECT_TRUE(write_stream(path, rs, Coding::Stored).ok());  // stored frames decode the same
    std::remove(path.c_str());
}

TEST(CodingRoundTrip, RangePainterLikeStreams) {
    StreamShapeOptions o;
    o.painter_like = true;
    o.max_strokes = 400;
    for (uint64_t seed = 100; seed < 110; ++seed) check_roundtrip(seed, Coding::Range, o);
}

TEST(CodingRoundTrip, RangeIsSmallerThanStoredForPainterStreams) {
    StreamShapeOptions o;
    o.painter_like = true;
    o.max_strokes = 2000;
    o.frames = 2;
    const RandomStream rs = make_random_stream(7, o);
    const std::string a = temp_path("size-stored.spt"), b = temp_path("size-range.spt");
    ASSERT_TRUE(write_stream(a, rs, Coding::Stored).ok());
    ASSERT_TRUE(write_stream(b, rs, Coding::Range).ok());
    const auto sa = read_bytes(a).size(), sb = read_bytes(b).size();
    EXPECT_LT(sb * 2, sa) << "stored " << sa << " range " << sb;
    std::remove(a.c_str());
    std::remove(b.c_str());
}

TEST(CodingRoundTrip, FieldStatsSumToBodySize) {
    StreamShapeOptions o;
    o.max_strokes = 300;
    const RandomStream rs = make_random_stream(11, o);
    for (Coding coding : {Coding::Stored, Coding::Range}) {
        const std::string path = temp_path("fields.spt");
        ASSERT_TRUE(write_stream(path, rs, coding).ok());
        auto r = Reader::open(path);
        ASSERT_TRUE(r.ok());
        for (size_t i = 0; i < (*r)->frames().size(); ++i) {
            auto fs = (*r)->field_stats(i);
            ASSERT_TRUE(fs.ok()) << fs.error().message;
            const auto& e = (*r)->frames()[i];
            const double body_bits = 8.0 * double(e.stroke_bytes + e.motion_bytes);
            // Range coding: information cost within a few bytes per stream of the real size.
            EXPECT_NEAR(fs->total_bits(), body_bits, coding == Coding::Stored ? 0.0 : 8.0 * 12) << "frame " << i;
        }
        std::remove(path.c_str());
    }
}

// ---- conic polygon prediction (SPEC.md 7.4, polygon 5, mode 2) ----

namespace {

// A regular n-gon under the affine map (rx, ry, rotation) about (cx, cy), in pixels, truncated
// to `step` Q4 units (geometrize truncates to whole pixels) plus `off`, optionally clockwise.
PolygonStroke affine_ngon(double cx, double cy, double rx, double ry, double deg, int n, int step, int off, bool cw,
                          double phase = 0) {
    PolygonStroke pg;
    pg.color = {90, 140, 200, 255};
    const double co = std::cos(deg * M_PI / 180), si = std::sin(deg * M_PI / 180);
    for (int i = 0; i < n; ++i) {
        const double a = phase + (cw ? -2 : 2) * M_PI * i / n;
        const double ex = rx * std::cos(a), ey = ry * std::sin(a);
        const double x = 16 * (cx + ex * co - ey * si), y = 16 * (cy + ex * si + ey * co);
        pg.points.push_back({int32_t(std::floor(x / step)) * step + off, int32_t(std::floor(y / step)) * step + off});
    }
    return pg;
}

RandomStream polygon_stream(std::vector<PolygonStroke> polys, uint32_t w = 200, uint32_t h = 150) {
    std::vector<Stroke> strokes;
    for (auto& p : polys) strokes.push_back(Stroke::make_polygon(std::move(p)));
    RandomStream rs = one_frame_stream(w, h, std::move(strokes));
    rs.info.header.version_minor = 2;
    return rs;
}

// One polygon stroke coded with a plan of the test's choosing (the syntax of code_polygon, but
// any rotation, matrix and shift), as a coding-1 stroke stream of a 1.2 file.
std::vector<uint8_t> encode_with_plan(const detail::StreamShape& sh, PolygonStroke pg, const detail::PolygonPlan& plan) {
    using namespace spt::detail;
    std::vector<uint8_t> out;
    RangeEncoder enc(out);
    auto st = std::make_unique<StrokeCoderState>(sh);
    enc.bit(st->kind0[0], 1); enc.bit(st->kind1[0], 1); enc.bit(st->kind2[0], 1);
    SyntaxError err;
    code_uint(enc, st->poly.points, pg.points.size() - 3);
    enc.bit(st->poly.same_aa, 0);
    code_position(enc, st->pos[3][0], pg.points[0].x, sh.width, err);
    code_position(enc, st->pos[3][1], pg.points[0].y, sh.height, err);
    code_polygon_outline(enc, st->poly, plan, pg.points, err);
    code_color(enc, *st, pg.color, pg.points[0].x, pg.points[0].y, 0, err);
    enc.finish();
    return out;
}

Result<std::vector<Stroke>> decode_one(const detail::StreamShape& sh, const std::vector<uint8_t>& bytes) {
    detail::DecodeContext ctx;
    ctx.shape = sh;
    std::vector<Stroke> out;
    if (auto s = detail::decode_stroke_stream(bytes.data(), bytes.size(), 1, ctx, out); !s) return s.error();
    return out;
}

}  // namespace

// Random near-regular polygons (truncated affine images of n-gons, either direction, on the
// 1/16, half- and whole-pixel lattices, with a few vertices moved) round-trip, and the encoder
// picks the conic mode for the exact ones.
TEST(CodingRoundTrip, ConicPolygonsRoundTrip) {
    std::mt19937 rng(5);
    auto uni = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    std::vector<PolygonStroke> polys;
    int conic = 0, exact = 0;
    for (int k = 0; k < 120; ++k) {
        const int n = 3 + int(rng() % 62);
        const int step = std::array<int, 3>{1, 8, 16}[rng() % 3];
        PolygonStroke pg = affine_ngon(uni(-20, 220), uni(-20, 170), uni(2, 90), uni(2, 90), uni(0, 360), n, step,
                                       step == 16 ? 8 : 0, rng() & 1, uni(0, 6.3));
        const bool moved = k % 4 == 3;
        if (moved) for (int j = 0; j < 3; ++j) pg.points[rng() % pg.points.size()].x += step * int(rng() % 9 - 4);
        if (!moved && n >= 8) {
            ++exact;
            const auto plan = detail::plan_polygon(detail::PolygonModels(), pg.points);
            conic += plan.mode == 2;
        }
        polys.push_back(pg);
    }
    EXPECT_GE(conic * 10, exact * 9) << conic << " of " << exact << " exact near-regular polygons coded conic";
    check_stream(polygon_stream(polys), 700, Coding::Range);
}

// The conic mode is what makes geometrize-like 20-gons cheap: their outline costs a few bytes,
// far below the differences of modes 0 and 1 (about 30 bytes each before the conic mode).
TEST(CodingRoundTrip, ConicPolygonsAreCompact) {
    std::mt19937 rng(9);
    std::vector<PolygonStroke> polys;
    for (int k = 0; k < 200; ++k)
        polys.push_back(affine_ngon(20 + rng() % 160, 20 + rng() % 110, 3 + rng() % 40, 3 + rng() % 40, double(rng() % 360),
                                    20, 16, 8, false));
    const RandomStream rs = polygon_stream(polys);
    const std::string path = temp_path("conic-size.spt");
    ASSERT_TRUE(write_stream(path, rs, Coding::Range).ok());
    auto r = Reader::open(path);
    ASSERT_TRUE(r.ok()) << r.error().message;
    auto f = (*r)->read_frame(0);
    ASSERT_TRUE(f.ok()) << f.error().message;
    EXPECT_TRUE(same_frame(*f, rs.frames[0]));
    auto fs = (*r)->field_stats(0);
    ASSERT_TRUE(fs.ok());
    const double geometry_bytes = (*fs)[Field::Geometry] / 8 / double(polys.size());
    EXPECT_LT(geometry_bytes, 11.0) << "geometry bytes per 20-gon";
    std::remove(path.c_str());
}

// Hostile rotations and matrices within the stated bounds decode without overflow to exactly
// the coded vertices; values beyond them are rejected as Corrupt with the stroke and offset.
TEST(CodingRoundTrip, ConicHostileValues) {
    using detail::kConicMaxCS;
    using detail::kConicMaxMatrix;
    detail::StreamShape sh;
    sh.width = 64; sh.height = 48; sh.sets = 1; sh.orientations = 1; sh.version_minor = 2;
    std::mt19937_64 rng(3);
    for (int k = 0; k < 200; ++k) {
        PolygonStroke pg;
        pg.color = {1, 2, 3, 255};
        const int n = 3 + int(rng() % 200);
        for (int i = 0; i < n; ++i)
            pg.points.push_back({(int32_t(int64_t(rng() % (2u << 23)) - (1 << 23)) & ~15) + 8, (int32_t(int64_t(rng() % (2u << 23)) - (1 << 23)) & ~15) + 8});
        pg.points[0] = {16 * 3 + 8, 16 * 4 + 8};
        detail::PolygonPlan plan;
        plan.mode = 2;
        plan.shift = 4;
        auto pick = [&](int64_t bound) {
            switch (rng() % 4) {
                case 0: return bound;
                case 1: return -bound;
                default: return int64_t(rng() % uint64_t(2 * bound + 1)) - bound;
            }
        };
        plan.cs[0] = pick(kConicMaxCS);
        plan.cs[1] = pick(kConicMaxCS);
        plan.matrix_shift = 0;
        for (auto& m : plan.m) m = pick(kConicMaxMatrix - 1) | 1;  // odd: shift 0 is canonical
        const auto bytes = encode_with_plan(sh, pg, plan);
        auto d = decode_one(sh, bytes);
        ASSERT_TRUE(d.ok()) << "case " << k << ": " << d.error().message;
        ASSERT_EQ(d->size(), 1u);
        EXPECT_EQ((*d)[0].polygon.points, pg.points) << "case " << k;
    }
    // Beyond the bounds, and non-canonical or reserved shifts.
    PolygonStroke pg = affine_ngon(30, 20, 10, 6, 15, 20, 16, 8, false);
    struct Bad { const char* what; detail::PolygonPlan plan; };
    detail::PolygonPlan base;
    base.mode = 2; base.shift = 4; base.matrix_shift = 0;
    detail::conic_rotation_for(20, base.cs);
    base.m[0] = 161; base.m[1] = 1; base.m[2] = 3; base.m[3] = 97;
    std::vector<Bad> bad;
    { auto p = base; p.cs[0] = -kConicMaxCS - 1; bad.push_back({"C below -2^30", p}); }
    { auto p = base; p.cs[1] = kConicMaxCS + 1; bad.push_back({"S outside", p}); }
    { auto p = base; p.m[2] = kConicMaxMatrix + 1; bad.push_back({"outside +-2^26", p}); }
    { auto p = base; p.m[0] = -kConicMaxMatrix - 1; bad.push_back({"outside +-2^26", p}); }
    { auto p = base; for (auto& m : p.m) m *= 2; bad.push_back({"matrix shift is not the largest", p}); }
    { auto p = base; p.matrix_shift = 5; for (auto& m : p.m) m *= 32; bad.push_back({"shift 5 is reserved", p}); }
    { auto p = base; p.shift = 3; bad.push_back({"polygon shift is not the largest", p}); }
    for (const auto& b : bad) {
        auto d = decode_one(sh, encode_with_plan(sh, pg, b.plan));
        ASSERT_FALSE(d.ok()) << b.what;
        EXPECT_EQ(d.error().code, Code::Corrupt) << b.what;
        EXPECT_NE(d.error().message.find(b.what), std::string::npos) << d.error().message;
        EXPECT_NE(d.error().message.find("stroke 0"), std::string::npos) << d.error().message;
        EXPECT_NE(d.error().message.find("byte offset"), std::string::npos) << d.error().message;
    }
    // A huge matrix that predicts vertices off the format's range: rejected, not wrapped.
    auto p = base;
    p.m[0] = kConicMaxMatrix - 1;
    PolygonStroke far = pg;
    for (auto& q : far.points) q = far.points[0];
    auto d = decode_one(sh, encode_with_plan(sh, far, p));
    ASSERT_TRUE(d.ok()) << d.error().message;  // residuals bring every vertex back to P_0
    EXPECT_EQ((*d)[0].polygon.points, far.points);
}
