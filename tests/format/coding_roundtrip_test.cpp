// Round-trip properties: random valid streams written with either coding read back to the same
// frames and the same live stroke lists (sequential and random access).
#include <gtest/gtest.h>

#include <algorithm>

#include "format/coding_random_streams.hpp"

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

// A stream that gets its first polygon after range-coded frames without curves is raised to 1.2
// in place; one that range-coded a curve first is refused, with a message saying why.
TEST(CodingRoundTrip, WriterRaisesVersionForPolygons) {
    RandomStream rs;
    rs.info.header.width = 20; rs.info.header.height = 10;
    rs.info.header.sets = {{4, 4}};
    rs.info.header.orientations = default_orientations(2);
    Frame k;
    AffineStroke a; a.a = a.d = 16; a.tx = a.ty = 40;
    rs.info.templates = {Template{TemplateKind::Ellipse, 0, 0, {}, "e", 0}};
    k.added = {Stroke::make_affine(a)};
    Frame i; i.index = 1; i.type = FrameType::Inter;
    PolygonStroke p; p.points = {{0, 0}, {160, 8}, {40, 150}};
    i.added = {Stroke::make_polygon(p)};
    rs.frames = {k, i};
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

// Polygon limits: a vertex count above the reader's limit and out-of-range vertices are rejected
// before anything is allocated or drawn, with errors that name the frame and the byte offset.
TEST(CodingRoundTrip, PolygonLimitsAndRanges) {
    RandomStream rs;
    rs.info.header.width = 16; rs.info.header.height = 16;
    rs.info.header.sets = {{4, 4}};
    rs.info.header.orientations = default_orientations(1);
    PolygonStroke p;
    for (int i = 0; i < 10; ++i) p.points.push_back({16 * i, 16 * ((i * 7) % 10)});
    Frame k;
    k.added = {Stroke::make_polygon(p)};
    rs.frames = {k};
    for (Coding coding : {Coding::Stored, Coding::Range}) {
        const std::string path = temp_path("poly-limits-" + std::to_string(int(coding)) + ".spt");
        ASSERT_TRUE(write_stream(path, rs, coding).ok());
        ReaderOptions ro;
        ro.limits.max_polygon_vertices = 9;
        auto r = Reader::open(path, ro);
        ASSERT_TRUE(r.ok()) << r.error().message;
        auto f = (*r)->read_frame(0);
        ASSERT_FALSE(f.ok());
        EXPECT_EQ(f.error().code, coding == Coding::Stored ? Code::LimitExceeded : Code::Corrupt);
        EXPECT_NE(f.error().message.find("frame 0"), std::string::npos) << f.error().message;
        EXPECT_NE(f.error().message.find("byte offset"), std::string::npos) << f.error().message;
        EXPECT_NE(f.error().message.find("10 vertices"), std::string::npos) << f.error().message;
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
