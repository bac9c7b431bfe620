// Round-trip properties: random valid streams written with either coding read back to the same
// frames and the same live stroke lists (sequential and random access).
#include <gtest/gtest.h>

#include "format/coding_random_streams.hpp"

using namespace spt;
using namespace spt::testing;

namespace {

void check_roundtrip(uint64_t seed, Coding coding, const StreamShapeOptions& o = {}) {
    SCOPED_TRACE("seed " + std::to_string(seed) + " coding " + std::to_string(int(coding)));
    const RandomStream rs = make_random_stream(seed, o);
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

}  // namespace

TEST(CodingRoundTrip, StoredRandomStreams) {
    for (uint64_t seed = 1; seed <= 40; ++seed) check_roundtrip(seed, Coding::Stored);
}

TEST(CodingRoundTrip, RangeRandomStreams) {
    for (uint64_t seed = 1; seed <= 40; ++seed) check_roundtrip(seed, Coding::Range);
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
