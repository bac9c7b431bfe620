// The rendering work a reader bounds (SPEC.md 10): fill work of stamps and affine strokes, curve
// work, polygon work and vertex counts, per stroke and over the live list, in both codings, with
// errors that say which limit and where.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "format/coding_random_streams.hpp"

using namespace spt;
using namespace spt::testing;

namespace {

// Frame 0's live list of `path`, read under `limits`: whether it fits. A refusal must be a
// LimitExceeded that speaks of rendering work.
bool live_list_fits(const std::string& path, const Limits& limits) {
    ReaderOptions ro;
    ro.limits = limits;
    auto r = Reader::open(path, ro);
    EXPECT_TRUE(r.ok()) << r.error().message;
    if (!r.ok()) return false;
    auto live = (*r)->strokes_at(0);
    if (!live.ok()) {
        EXPECT_EQ(live.error().code, Code::LimitExceeded);
        EXPECT_NE(live.error().message.find("rendering work"), std::string::npos) << live.error().message;
    }
    return live.ok();
}

// Frame 0 of `path`, read under `limits` (the file itself opens).
Result<Frame> read_frame0(const std::string& path, const Limits& limits) {
    ReaderOptions ro;
    ro.limits = limits;
    auto r = Reader::open(path, ro);
    EXPECT_TRUE(r.ok()) << r.error().message;
    if (!r.ok()) return r.error();
    return (*r)->read_frame(0);
}

}  // namespace

// Stamps and affine strokes: box pixels x template samples per pixel (SPEC 10).
TEST(RenderWorkLimits, FillRenderingWorkIsBounded) {
    StreamInfo info;
    info.header.width = 64; info.header.height = 48;
    info.header.sets = {{8, 4}};
    info.header.orientations = default_orientations(1);  // 0 degrees: cos 16384, sin 0
    info.templates.resize(2);
    info.templates[0].kind = TemplateKind::Ellipse;
    info.templates[1].kind = TemplateKind::Ellipse;
    info.templates[1].supersample = 4;
    StampStroke st;
    st.x = 10 * 16 + 8; st.y = 10 * 16 + 8; st.color = {1, 2, 3, 255};
    // rx = 8 * 16384 / 32768 + 1 = 5, ry = 4 * 16384 / 32768 + 1 = 3: 11 x 7 pixels.
    EXPECT_EQ(fill_render_work(Stroke::make_stamp(st), info.header, info.templates), 77u);
    st.tmpl = 1;
    EXPECT_EQ(fill_render_work(Stroke::make_stamp(st), info.header, info.templates), 77u * 16);
    AffineStroke a;
    a.tx = 0; a.ty = 0; a.a = 16 * 100; a.d = 16 * 100; a.color = {1, 2, 3, 255};
    // Reaches 102 px around (0, 0): the whole 64 x 48 canvas.
    EXPECT_EQ(fill_render_work(Stroke::make_affine(a), info.header, info.templates), 64u * 48);

    RandomStream rs;
    rs.info = info;
    Frame k;
    for (int i = 0; i < 10; ++i) k.added.push_back(Stroke::make_affine(a));
    rs.frames = {k};
    const std::string path = temp_path("fill-work.spt");
    ASSERT_TRUE(write_stream(path, rs, Coding::Range).ok());
    for (uint64_t limit : {uint64_t(64 * 48 * 10 - 1), uint64_t(64 * 48 * 10)}) {
        Limits limits;
        limits.max_fill_work = limit;
        EXPECT_EQ(live_list_fits(path, limits), limit == 64 * 48 * 10) << limit;
    }
    std::remove(path.c_str());
}

// Curves: the work a reader bounds (SPEC 10) is the canvas pixels of each segment's box.
TEST(RenderWorkLimits, CurveRenderingWorkIsBounded) {
    CurveStroke c;
    c.color = {1, 2, 3, 255};
    // One segment from pixel centre (2, 3) to (9, 3), 2 px wide: the box reaches 1 px + 1 Q4
    // unit around it, so columns 1..10 and rows 2..4 (SPEC 8.5): 10 x 3 pixels.
    c.points = {{2 * 16 + 8, 3 * 16 + 8, 32}, {9 * 16 + 8, 3 * 16 + 8, 32}};
    EXPECT_EQ(curve_render_work(c, 64, 64), 30u);
    EXPECT_EQ(curve_render_work(c, 6, 64), 15u);  // clipped to the canvas: columns 1..5
    CurveStroke dot = c;
    dot.points.resize(1);  // a one-point curve is one disc: columns 1..3, rows 2..4
    EXPECT_EQ(curve_render_work(dot, 64, 64), 9u);

    const RandomStream rs = one_frame_stream(64, 64, {Stroke::make_curve(c), Stroke::make_curve(c)});
    for (Coding coding : {Coding::Stored, Coding::Range}) {
        const std::string path = temp_path("curve-work-" + std::to_string(int(coding)) + ".spt");
        ASSERT_TRUE(write_stream(path, rs, coding).ok());
        for (uint64_t limit : {uint64_t(29), uint64_t(59), uint64_t(60)}) {
            Limits limits;
            limits.max_curve_work = limit;
            EXPECT_EQ(live_list_fits(path, limits), limit == 60) << limit;  // each curve 30, the live list 60
        }
        std::remove(path.c_str());
    }
}

// Polygon limits: a vertex count above the reader's limit and out-of-range vertices are rejected
// before anything is allocated or drawn, with errors that name the frame and the byte offset;
// the polygon rendering work is bounded per stroke and over the live list.
TEST(RenderWorkLimits, PolygonLimitsAndRanges) {
    PolygonStroke p;
    for (int i = 0; i < 10; ++i) p.points.push_back({16 * i, 16 * ((i * 7) % 10)});
    const RandomStream rs = one_frame_stream(16, 16, {Stroke::make_polygon(p)});
    // Rendering work (SPEC 10): 10 non-horizontal edges x 10 rows x 1 sample = 100 units here.
    EXPECT_EQ(polygon_render_work(p, 16), 100u);
    PolygonStroke aa = p;
    aa.supersample = 4;
    EXPECT_EQ(polygon_render_work(aa, 16), 100u * 16);
    EXPECT_EQ(polygon_render_work(p, 5), 10u * 5);  // rows clipped to the canvas
    for (Coding coding : {Coding::Stored, Coding::Range}) {
        const std::string path = temp_path("poly-limits-" + std::to_string(int(coding)) + ".spt");
        ASSERT_TRUE(write_stream(path, rs, coding).ok());
        Limits vertices;
        vertices.max_polygon_vertices = 9;
        auto f = read_frame0(path, vertices);
        ASSERT_FALSE(f.ok());
        EXPECT_EQ(f.error().code, coding == Coding::Stored ? Code::LimitExceeded : Code::Corrupt);
        EXPECT_NE(f.error().message.find("frame 0"), std::string::npos) << f.error().message;
        EXPECT_NE(f.error().message.find("byte offset"), std::string::npos) << f.error().message;
        EXPECT_NE(f.error().message.find("10 vertices"), std::string::npos) << f.error().message;
        Limits work;
        work.max_polygon_work = 99;
        f = read_frame0(path, work);
        ASSERT_FALSE(f.ok());
        EXPECT_EQ(f.error().code, Code::LimitExceeded);
        EXPECT_NE(f.error().message.find("rendering work"), std::string::npos) << f.error().message;
        EXPECT_NE(f.error().message.find("frame 0"), std::string::npos) << f.error().message;
        work.max_polygon_work = 100;
        EXPECT_TRUE(live_list_fits(path, work));
        std::remove(path.c_str());
    }
    // The live list's sum is bounded too: two frames of one polygon each, 100 units apiece.
    {
        RandomStream two = rs;
        Frame inter;
        inter.type = FrameType::Inter;
        inter.index = 1;
        inter.added = {Stroke::make_polygon(p)};
        two.frames.push_back(inter);
        const std::string path = temp_path("poly-live-work.spt");
        ASSERT_TRUE(write_stream(path, two, Coding::Stored).ok());
        ReaderOptions ro;
        ro.limits.max_polygon_work = 199;
        auto r = Reader::open(path, ro);
        ASSERT_TRUE(r.ok());
        EXPECT_TRUE((*r)->strokes_at(0).ok());
        auto live = (*r)->strokes_at(1);
        ASSERT_FALSE(live.ok());
        EXPECT_EQ(live.error().code, Code::LimitExceeded);
        EXPECT_NE(live.error().message.find("live list"), std::string::npos) << live.error().message;
        std::remove(path.c_str());
    }
    // A vertex outside +-2^24: the writer refuses it; a stored file carrying one is Corrupt.
    RandomStream bad = rs;
    bad.frames[0].added[0].polygon.points[3].x = (1 << 24) + 1;
    const std::string path = temp_path("poly-range.spt");
    const Status w = write_stream(path, bad, Coding::Stored);
    ASSERT_FALSE(w.ok());
    EXPECT_EQ(w.error().code, Code::InvalidArgument);
    EXPECT_NE(w.error().message.find("polygon vertex 3"), std::string::npos) << w.error().message;
    ASSERT_TRUE(write_stream(path, rs, Coding::Stored).ok());
    auto bytes = read_bytes(path);
    // Vertex 3's x in the only polygon record: find the record by its vertex values.
    const uint8_t want[8] = {48, 0, 0, 0, 16 * 1, 0, 0, 0};  // (16*3, 16*((3*7)%10)) = (48, 16)
    auto at = std::search(bytes.begin(), bytes.end(), want, want + 8);
    ASSERT_NE(at, bytes.end());
    at[0] = 1; at[1] = 0; at[2] = 0; at[3] = 1;  // 2^24 + 1
    ReaderOptions ro;
    ro.verify_checksums = false;
    auto r = Reader::open_memory(bytes.data(), bytes.size(), ro);
    ASSERT_TRUE(r.ok()) << r.error().message;
    auto f = (*r)->read_frame(0);
    ASSERT_FALSE(f.ok());
    EXPECT_EQ(f.error().code, Code::Corrupt);
    EXPECT_NE(f.error().message.find("frame 0"), std::string::npos) << f.error().message;
    EXPECT_NE(f.error().message.find("outside +-2^24"), std::string::npos) << f.error().message;
    std::remove(path.c_str());
}

// The file's fill budget (Limits::max_file_fill_work + max_fill_work_per_byte per byte): the
// live lists render_frame draws are counted, each once; still frames draw nothing and cost
// nothing; the frame that would pass the budget is refused before it is drawn, named.
TEST(RenderWorkLimits, FillWorkIsBoundedPerFile) {
    AffineStroke a;
    a.a = 16 * 100; a.d = 16 * 100; a.color = {1, 2, 3, 128};  // the whole 64 x 48 canvas: 3072
    RandomStream rs = one_frame_stream(64, 48, std::vector<Stroke>(10, Stroke::make_affine(a)));
    rs.info.templates.resize(1);
    rs.info.templates[0].kind = TemplateKind::Ellipse;
    for (uint32_t i = 1; i <= 6; ++i) {
        Frame f;
        f.index = i;
        f.type = FrameType::Inter;
        if (i == 4) f.added = {Stroke::make_affine(a)};  // 11 strokes from here: 33792
        rs.frames.push_back(f);
    }
    const std::string path = temp_path("file-fill-work.spt");
    ASSERT_TRUE(write_stream(path, rs, Coding::Range).ok());
    const uint64_t key = 64 * 48 * 10, later = 64 * 48 * 11;
    const auto draw_all = [&](const Limits& limits, size_t* refused) {
        ReaderOptions ro;
        ro.limits = limits;
        auto r = Reader::open(path, ro);
        EXPECT_TRUE(r.ok());
        Canvas c;
        for (size_t i = 0; i < 7; ++i) {
            const Status st = (*r)->render_frame(i, c);
            if (st) continue;
            *refused = i;
            EXPECT_EQ(st.error().code, Code::LimitExceeded);
            EXPECT_NE(st.error().message.find("frame 4 (FRAM chunk at byte offset"), std::string::npos) << st.error().message;
            EXPECT_NE(st.error().message.find("rendering work"), std::string::npos) << st.error().message;
            EXPECT_NE(st.error().message.find("the limit for a file of"), std::string::npos) << st.error().message;
            // Frames already paid for still draw, on any canvas.
            Canvas other;
            EXPECT_TRUE((*r)->render_frame(2, other).ok());
            return false;
        }
        return true;
    };
    Limits limits;
    limits.max_fill_work_per_byte = 0;
    size_t refused = 99;
    limits.max_file_fill_work = key + later;
    EXPECT_TRUE(draw_all(limits, &refused));
    limits.max_file_fill_work = key + later - 1;
    EXPECT_FALSE(draw_all(limits, &refused));
    EXPECT_EQ(refused, 4u);
    // The per-byte part: the same budget from the file's size.
    const uint64_t size = std::filesystem::file_size(path);
    limits.max_file_fill_work = 0;
    limits.max_fill_work_per_byte = (key + later) / size + 1;
    EXPECT_TRUE(draw_all(limits, &refused));
    limits.max_fill_work_per_byte = (key + later) / size - 1;
    if (limits.max_fill_work_per_byte * size >= key) {
        EXPECT_FALSE(draw_all(limits, &refused));
        EXPECT_EQ(refused, 4u);
    }
    // The default budget: far above a small file's needs.
    EXPECT_TRUE(draw_all(Limits(), &refused));
    std::remove(path.c_str());
}
