// Source frame numbers (SPEC.md 3.3 source.first_frame): a sequence painted from frame 3
// keeps 3 as its first number; render names files and takes --frames by it; info shows it;
// files without it number from 0.
#include "converter/cli_test_util.hpp"

#include "spt/concat.hpp"

namespace {

using namespace spt_test;

const std::string kEarth = std::string(SPT_MEDIA_DIR) + "/exr/earth/earth.####.exr";

TEST(FrameNumbersCli, ASequenceKeepsItsFrameNumbers) {
    REQUIRE_TOOL();
    ASSERT_TRUE(fs::exists(std::string(SPT_MEDIA_DIR) + "/exr/earth/earth.0003.exr"))
        << "the shared media are needed: " << SPT_MEDIA_DIR;
    TempDir d;
    RunResult r = run_spt(d, {"paint", kEarth, "--frames", "3-6", "-o", d.file("e.spt"), "--max-strokes", "300",
                              "--keyframe-interval", "2", "--progress", "none"});
    ASSERT_EQ(r.code, 0) << r.err;
    auto rd = spt::Reader::open(d.file("e.spt"));
    ASSERT_TRUE(rd.ok());
    EXPECT_EQ(spt::first_frame_number((*rd)->info()), 3u);

    r = run_spt(d, {"info", d.file("e.spt"), "--json", "--no-fields", "--frames"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("\"first_frame_number\": 3"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\"number\": 6"), std::string::npos) << r.out;
    r = run_spt(d, {"info", d.file("e.spt"), "--no-fields"});
    EXPECT_NE(r.out.find("numbered 3-6 (source frames)"), std::string::npos) << r.out;

    // Default names follow the source; --frames and --frame take source numbers.
    ASSERT_EQ(run_spt(d, {"render", d.file("e.spt"), "-o", d.file("o.####.png")}).code, 0);
    for (int n = 3; n <= 6; ++n) EXPECT_TRUE(fs::exists(d.file("o.000" + std::to_string(n) + ".png"))) << n;
    EXPECT_FALSE(fs::exists(d.file("o.0000.png")));
    ASSERT_EQ(run_spt(d, {"render", d.file("e.spt"), "--frames", "5-6", "-o", d.file("p.####.png")}).code, 0);
    EXPECT_TRUE(fs::exists(d.file("p.0005.png")) && fs::exists(d.file("p.0006.png")));
    EXPECT_FALSE(fs::exists(d.file("p.0004.png")));
    EXPECT_EQ(slurp(d.file("p.0005.png")), slurp(d.file("o.0005.png")));
    ASSERT_EQ(run_spt(d, {"render", d.file("e.spt"), "--frame", "4", "-o", d.file("one.png")}).code, 0);
    EXPECT_EQ(slurp(d.file("one.png")), slurp(d.file("o.0004.png")));
    // A number the file does not have is refused, saying which it has.
    r = run_spt(d, {"render", d.file("e.spt"), "--frames", "1-4", "-o", d.file("q.####.png")});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("has frames 3-6"), std::string::npos) << r.err;
    r = run_spt(d, {"render", d.file("e.spt"), "--frame", "0", "-o", d.file("q.png")});
    EXPECT_EQ(r.code, 1);
    // --start still renumbers: the file's i-th frame as i + N.
    ASSERT_EQ(run_spt(d, {"render", d.file("e.spt"), "--start", "100", "-o", d.file("s.####.png")}).code, 0);
    EXPECT_TRUE(fs::exists(d.file("s.0100.png")) && fs::exists(d.file("s.0103.png")));
    EXPECT_EQ(slurp(d.file("s.0101.png")), slurp(d.file("o.0004.png")));
}

TEST(FrameNumbersCli, FilesWithoutNumbersCountFromZero) {
    REQUIRE_TOOL();
    TempDir d;
    write_test_spt(d.file("t.spt"), 4, 2);
    ASSERT_EQ(run_spt(d, {"render", d.file("t.spt"), "-o", d.file("o.####.png")}).code, 0);
    EXPECT_TRUE(fs::exists(d.file("o.0000.png")) && fs::exists(d.file("o.0003.png")));
    ASSERT_EQ(run_spt(d, {"render", d.file("t.spt"), "--frames", "2", "-o", d.file("p.####.png")}).code, 0);
    EXPECT_TRUE(fs::exists(d.file("p.0002.png")));
    RunResult r = run_spt(d, {"info", d.file("t.spt"), "--json", "--no-fields"});
    EXPECT_NE(r.out.find("\"first_frame_number\": 0"), std::string::npos) << r.out;
}

}  // namespace
