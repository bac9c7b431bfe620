// Format 1.4 (SPEC.md 3.1, 4, 6, 7.4, 8.5): the HEAD flag curve_grid and what readers, writers,
// joins and renderers do with curves that carry a grid. Round trips of random streams are in
// coding_roundtrip_test.cpp, the pixels against a literal reference in render_reference_test.cpp.
#include <gtest/gtest.h>

#include <cstring>

#include "format/test_dir.hpp"
#include "spt/concat.hpp"
#include "spt/spt.hpp"

using namespace spt;

namespace {

StreamInfo line_info(bool curve_grid) {
    StreamInfo info;
    info.header.width = 24;
    info.header.height = 16;
    info.header.fps = {24, 1};
    info.header.sets = {{4, 4}};
    info.header.orientations = default_orientations(1);
    info.header.curve_grid = curve_grid;
    return info;
}

Frame line_frame(uint8_t grid) {
    CurveStroke c;
    c.color = {10, 20, 30, 255};
    c.supersample = grid;
    c.points = {{16 * 2, 16 * 3 + 5, 40}, {16 * 20, 16 * 12, 24}};
    Frame f;
    f.added = {Stroke::make_curve(c)};
    return f;
}

std::string write(const std::string& path, const StreamInfo& info, const Frame& f, Coding coding) {
    WriterOptions o;
    o.coding = coding;
    auto w = Writer::create(path, info, o);
    EXPECT_TRUE(w.ok()) << w.error().message;
    EXPECT_TRUE((*w)->append(f).ok());
    EXPECT_TRUE((*w)->finish().ok());
    return path;
}

std::vector<uint8_t> bytes_of(const std::string& path) {
    const std::string s = spt::testing::slurp(path);
    return std::vector<uint8_t>(s.begin(), s.end());
}

ReaderOptions unchecked() {
    ReaderOptions o;
    o.verify_checksums = false;  // the tests patch bytes without fixing CRCs
    return o;
}

}  // namespace

// HEAD: bit 1 needs version_minor 4; bits above it are reserved.
TEST(CurveGrid, HeadFlagIsCheckedAndReservedBitsRejected) {
    spt::testing::TestDir dir;
    const auto bytes = bytes_of(write(dir / "aa.spt", line_info(true), line_frame(4), Coding::Stored));
    auto ok = Reader::open_memory(bytes.data(), bytes.size());
    ASSERT_TRUE(ok.ok()) << ok.error().message;
    EXPECT_TRUE((*ok)->info().header.curve_grid);
    EXPECT_EQ((*ok)->info().header.version_minor, kCurveGridMinorVersion);
    // HEAD's payload starts at byte 16: version_major u16, version_minor u16, flags u32.
    auto old = bytes;
    old[18] = 3;  // a 1.3 file cannot have the flag
    auto r3 = Reader::open_memory(old.data(), old.size(), unchecked());
    ASSERT_FALSE(r3.ok());
    EXPECT_EQ(r3.error().code, Code::Corrupt) << r3.error().message;
    EXPECT_NE(r3.error().message.find("format 1.4"), std::string::npos) << r3.error().message;
    auto reserved = bytes;
    reserved[20] |= 4;  // bit 2
    auto r4 = Reader::open_memory(reserved.data(), reserved.size(), unchecked());
    ASSERT_FALSE(r4.ok());
    EXPECT_EQ(r4.error().code, Code::Unsupported) << r4.error().message;
}

// Stored records: the grid byte follows the colour only in a flagged file, and a reserved grid
// is Unsupported, naming the stroke.
TEST(CurveGrid, StoredRecordCarriesTheGridAndRejectsReservedOnes) {
    spt::testing::TestDir dir;
    const auto plain = bytes_of(write(dir / "plain.spt", line_info(false), line_frame(0), Coding::Stored));
    const auto aa = bytes_of(write(dir / "aa.spt", line_info(true), line_frame(0), Coding::Stored));
    EXPECT_EQ(aa.size(), plain.size() + 1) << "one grid byte per curve record (the index moves, its size does not)";
    auto bytes = bytes_of(write(dir / "aa4.spt", line_info(true), line_frame(4), Coding::Stored));
    auto r = Reader::open_memory(bytes.data(), bytes.size());
    ASSERT_TRUE(r.ok());
    const size_t body = size_t((*r)->frames()[0].offset) + 16;  // chunk header 8, frame fields 8
    const size_t grid_at = body + 4 + 1 + 4;                     // stroke_count, kind, r g b a
    ASSERT_EQ(bytes[grid_at], 4);
    for (uint8_t bad : {uint8_t(1), uint8_t(17), uint8_t(255)}) {
        bytes[grid_at] = bad;
        auto d = Reader::open_memory(bytes.data(), bytes.size(), unchecked());
        ASSERT_TRUE(d.ok()) << d.error().message;
        auto f = (*d)->read_frame(0);
        ASSERT_FALSE(f.ok());
        EXPECT_EQ(f.error().code, Code::Unsupported) << f.error().message;
        EXPECT_NE(f.error().message.find("stroke 0: curve supersampling " + std::to_string(bad)), std::string::npos)
            << f.error().message;
    }
}

// A file's curves render as its grids say in both codings, and a grid-0 curve of a flagged file
// renders as the same curve of a 1.3 file.
TEST(CurveGrid, FilesRenderTheirGrids) {
    spt::testing::TestDir dir;
    Canvas plain, zero, aa;
    auto rp = Reader::open(write(dir / "p.spt", line_info(false), line_frame(0), Coding::Range));
    auto rz = Reader::open(write(dir / "z.spt", line_info(true), line_frame(0), Coding::Range));
    auto ra = Reader::open(write(dir / "a.spt", line_info(true), line_frame(8), Coding::Range));
    ASSERT_TRUE(rp.ok() && rz.ok() && ra.ok());
    ASSERT_TRUE((*rp)->render_frame(0, plain).ok());
    ASSERT_TRUE((*rz)->render_frame(0, zero).ok());
    ASSERT_TRUE((*ra)->render_frame(0, aa).ok());
    EXPECT_EQ(plain.rgb, zero.rgb);
    int partial = 0;
    for (size_t i = 0; i < aa.rgb.size(); i += 3) partial += aa.rgb[i] != 10 && aa.rgb[i] != 255;
    EXPECT_GT(partial, 20) << "the grid-8 line has anti-aliased edge pixels";
    for (size_t i = 0; i < plain.rgb.size(); i += 3) EXPECT_TRUE(plain.rgb[i] == 10 || plain.rgb[i] == 255);
}

// Joining: parts must agree on the flag (their curve records differ), named in the message.
TEST(CurveGrid, PartsOfDifferentCurveGridDoNotJoin) {
    spt::testing::TestDir dir;
    const std::string a = write(dir / "a.spt", line_info(false), line_frame(0), Coding::Range);
    const std::string b = write(dir / "b.spt", line_info(true), line_frame(4), Coding::Range);
    auto st = concatenate({a, b}, dir / "ab.spt");
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("curve_grid"), std::string::npos) << st.error().message;
    EXPECT_NE(st.error().message.find("b.spt"), std::string::npos) << st.error().message;
    ASSERT_TRUE(concatenate({b, b}, dir / "bb.spt").ok());
}
