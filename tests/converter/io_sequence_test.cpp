// Frame ranges, sequence patterns and listing sequences on disk.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "io/sequence.hpp"

namespace fs = std::filesystem;
using namespace spt::io;

TEST(IoSequence, ParsesRanges) {
    auto r = parse_frame_range("1-10,20, 30-40x5");
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_TRUE(r->contains(1));
    EXPECT_TRUE(r->contains(10));
    EXPECT_FALSE(r->contains(11));
    EXPECT_TRUE(r->contains(20));
    EXPECT_TRUE(r->contains(35));
    EXPECT_FALSE(r->contains(36));
    EXPECT_EQ(r->frames_within(0, 100),
              (std::vector<long>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 20, 30, 35, 40}));
    EXPECT_EQ(r->frames_within(8, 32), (std::vector<long>{8, 9, 10, 20, 30}));
    auto single = parse_frame_range("7");
    ASSERT_TRUE(single.ok());
    EXPECT_EQ(single->spans.size(), 1u);
    EXPECT_EQ(single->spans[0], (std::pair<long, long>{7, 7}));
    auto all = parse_frame_range("");
    ASSERT_TRUE(all.ok());
    EXPECT_TRUE(all->empty());
    EXPECT_TRUE(all->contains(12345));
    EXPECT_EQ(parse_frame_range("0-3")->frames_within(0, 100).size(), 4u);
}

TEST(IoSequence, RejectsBadRanges) {
    for (const char* bad : {"a", "5-2", "1-", "-3", "1,,2", "1-10x0", "1-10xq", "99999999999"}) {
        auto r = parse_frame_range(bad);
        ASSERT_FALSE(r.ok()) << bad;
        EXPECT_NE(r.error().message.find(bad), std::string::npos) << r.error().message;
    }
}

TEST(IoSequence, Patterns) {
    EXPECT_TRUE(is_sequence_pattern("out.####.png"));
    EXPECT_TRUE(is_sequence_pattern("out.#.png"));
    EXPECT_TRUE(is_sequence_pattern("out_@@@.exr"));
    EXPECT_TRUE(is_sequence_pattern("out_%04d.tif"));
    EXPECT_TRUE(is_sequence_pattern("out_%d.tif"));
    EXPECT_TRUE(is_sequence_pattern("shot.1-120#.png"));
    EXPECT_FALSE(is_sequence_pattern("out.png"));
    EXPECT_FALSE(is_sequence_pattern("dir#1/out.png"));  // only the file name counts
    EXPECT_FALSE(is_sequence_pattern("100%.png"));

    EXPECT_EQ(format_frame("out.####.png", 7), "out.0007.png");
    EXPECT_EQ(format_frame("out.####.png", 12345), "out.12345.png");
    EXPECT_EQ(format_frame("out.#.png", 7), "out.0007.png");
    EXPECT_EQ(format_frame("out.##.png", 7), "out.07.png");
    EXPECT_EQ(format_frame("out_@@@.exr", 7), "out_007.exr");
    EXPECT_EQ(format_frame("out_@.exr", 7), "out_7.exr");
    EXPECT_EQ(format_frame("out_%04d.tif", 42), "out_0042.tif");
    EXPECT_EQ(format_frame("out_%d.tif", 42), "out_42.tif");
    EXPECT_EQ(format_frame("a/b/shot.1-120#.png", 3), "a/b/shot.0003.png");
    EXPECT_EQ(format_frame("shot_2024-1-3#.png", 2), "shot_2024-0002.png");
    EXPECT_EQ(format_frame("plain.png", 3), "plain.png");
}

TEST(IoSequence, VideoNames) {
    EXPECT_TRUE(is_video_file("a/clip.MP4"));
    EXPECT_TRUE(is_video_file("city.mpg"));
    EXPECT_TRUE(is_video_file("x.avi"));
    EXPECT_FALSE(is_video_file("x.png"));
    EXPECT_FALSE(is_video_file("mp4"));
}

class IoSequenceDisk : public ::testing::Test {
protected:
    fs::path dir;
    void SetUp() override {
        dir = fs::temp_directory_path() / ("spt_io_seq_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        for (const char* n : {"f.0001.png", "f.0002.png", "f.0003.png", "f.0010.png", "f.10000.png",
                              "f.00001.png", "f.0004.jpg", "g.0001.png", "notes.txt"})
            std::ofstream(dir / n) << "x";
    }
    void TearDown() override { fs::remove_all(dir); }
};

TEST_F(IoSequenceDisk, ListsPatternFramesFound) {
    auto s = list_sequence((dir / "f.####.png").string());
    ASSERT_TRUE(s.ok()) << s.error().message;
    std::vector<long> frames;
    for (auto& f : *s) frames.push_back(f.frame);
    EXPECT_EQ(frames, (std::vector<long>{1, 2, 3, 10, 10000}));
    EXPECT_EQ((*s)[0].path, (dir / "f.0001.png").string());

    auto ranged = list_sequence((dir / "f.%04d.png").string(), *parse_frame_range("2-10"));
    ASSERT_TRUE(ranged.ok());
    EXPECT_EQ(ranged->size(), 3u);
}

TEST_F(IoSequenceDisk, ListsOiiotoolRangeAndReportsMissing) {
    auto s = list_sequence((dir / "f.1-3#.png").string());
    ASSERT_TRUE(s.ok()) << s.error().message;
    ASSERT_EQ(s->size(), 3u);
    EXPECT_EQ((*s)[2].path, (dir / "f.0003.png").string());
    auto missing = list_sequence((dir / "f.1-5#.png").string());
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("f.0004.png"), std::string::npos) << missing.error().message;
}

TEST_F(IoSequenceDisk, ListsFolderInNameOrder) {
    auto s = list_sequence(dir.string());
    ASSERT_TRUE(s.ok()) << s.error().message;
    ASSERT_EQ(s->size(), 8u);  // notes.txt is not an image
    EXPECT_EQ((*s)[0].frame, 0);
    EXPECT_EQ(fs::path((*s)[0].path).filename(), "f.00001.png");
    EXPECT_EQ(fs::path((*s)[7].path).filename(), "g.0001.png");
}

TEST_F(IoSequenceDisk, ErrorsNameThePattern) {
    const std::string pat = (dir / "nothing.####.png").string();
    auto s = list_sequence(pat);
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find(pat), std::string::npos);
    auto none = list_sequence((dir / "f.####.png").string(), *parse_frame_range("500-600"));
    EXPECT_FALSE(none.ok());
    auto nodir = list_sequence("/no/such/dir/f.####.png");
    ASSERT_FALSE(nodir.ok());
    EXPECT_NE(nodir.error().message.find("/no/such/dir/f.####.png"), std::string::npos);
}

// The cases where OpenImageIO's sequence functions differ from what spt promises (see the
// comments in sequence.cpp): they must keep working.
TEST(IoSequence, NamesOpenImageIOWouldMisread) {
    EXPECT_EQ(format_frame("100%_####.png", 3), "100%_0003.png");  // printf would eat the '%'
    EXPECT_EQ(format_frame("out.####.png", 3), "out.0003.png");      // not 16 digits
    EXPECT_EQ(format_frame("out.1-10x2@@.png", 3), "out.03.png");
    EXPECT_FALSE(is_sequence_pattern("out.%4d.png"));                // space padding: not a name
    auto r = parse_frame_range("0-999999999");                      // kept as a span, not expanded
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->frames_within(999999990, 2000000000).size(), 10u);
}

TEST_F(IoSequenceDisk, ListsNamesWithRegexCharacters) {
    for (const char* n : {"take+1.0001.png", "take+1.0002.png", "takee1.0003.png", "(a)$.01.png"})
        std::ofstream(dir / n) << "x";
    auto s = list_sequence((dir / "take+1.####.png").string());
    ASSERT_TRUE(s.ok()) << s.error().message;
    ASSERT_EQ(s->size(), 2u);
    EXPECT_EQ(fs::path((*s)[1].path).filename(), "take+1.0002.png");
    auto t = list_sequence((dir / "(a)$.@@.png").string());
    ASSERT_TRUE(t.ok()) << t.error().message;
    EXPECT_EQ(t->size(), 1u);
}
