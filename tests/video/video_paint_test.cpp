// run_video_paint / video_paint on real files: PNG sequences written by the test, the shared
// media clips, missing frames, --skip-bad-frames, ROI files and the stop flag.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <fstream>

#include "io/image_io.hpp"
#include "io/progress.hpp"
#include "quick_options.hpp"
#include "spt/reader.hpp"
#include "synthetic.hpp"
#include "video/video_paint.hpp"

using namespace spt;
using namespace spt::video;

namespace {

VideoPaintOptions options(const std::string& in, const std::string& out) {
    VideoPaintOptions o = spt_test::quick_options(out, 3, 1, 300, 100);
    o.input = in;
    return o;
}

// video_paint with a silent progress line.
Status paint_quietly(const VideoPaintOptions& o, VideoPaintReport* rep = nullptr) {
    io::Progress progress(io::ProgressMode::None, "paint", 0);
    return video_paint(o, progress, rep);
}

// Writes frames first..last of a moving scene as dir/seq.####.png, leaving out `missing`.
void write_sequence(const std::filesystem::path& dir, int first, int last, int missing = -1) {
    const uint32_t w = 64, h = 48;
    for (int f = first; f <= last; ++f) {
        if (f == missing) continue;
        const auto rgb = spt_test::scene_frame(0, f, w, h);
        char name[64];
        std::snprintf(name, sizeof name, "seq.%04d.png", f);
        ASSERT_TRUE(io::write_image((dir / name).string(), w, h, rgb.data()).ok());
    }
}

}  // namespace

TEST(VideoPaint, PaintsAPngSequence) {
    const auto dir = spt_test::temp_dir("seq");
    write_sequence(dir, 1, 8);
    auto o = options((dir / "seq.####.png").string(), (dir / "out.spt").string());
    o.fps = "30000/1001";
    VideoPaintReport rep;
    Status st = paint_quietly(o, &rep);
    ASSERT_TRUE(st.ok()) << st.error().message;
    EXPECT_EQ(rep.frames, 8u);
    auto r = Reader::open(o.output);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ((*r)->frames().size(), 8u);
    EXPECT_EQ((*r)->info().header.fps, (Rational{30000, 1001}));
    EXPECT_TRUE((*r)->has_index());
    std::filesystem::remove_all(dir);
}

TEST(VideoPaint, MissingFrameIsAnErrorNamingIt) {
    const auto dir = spt_test::temp_dir("missing");
    write_sequence(dir, 1, 6, 4);
    auto o = options((dir / "seq.####.png").string(), (dir / "out.spt").string());
    Status st = paint_quietly(o);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("seq.0004.png"), std::string::npos) << st.error().message;
    EXPECT_FALSE(std::filesystem::exists(o.output)) << "no output after a failure";
    EXPECT_FALSE(std::filesystem::exists(o.output + ".partial"));

    // --skip-bad-frames: frame 4 repeats frame 3, and the encode goes on.
    o.skip_bad_frames = true;
    VideoPaintReport rep;
    st = paint_quietly(o, &rep);
    ASSERT_TRUE(st.ok()) << st.error().message;
    EXPECT_EQ(rep.frames, 6u);
    EXPECT_EQ(rep.skipped_frames, 1u);
    std::filesystem::remove_all(dir);
}

// A frame of another size stops the paint, naming it, on the 8-bit and the scene-linear reading
// paths; --skip-bad-frames repeats the previous frame instead.
TEST(VideoPaint, AFrameOfAnotherSizeIsAnErrorNamingIt) {
    const auto dir = spt_test::temp_dir("size");
    write_sequence(dir, 1, 3);
    const auto rgb = spt_test::scene_frame(0, 2, 40, 24);
    ASSERT_TRUE(io::write_image((dir / "seq.0002.png").string(), 40, 24, rgb.data()).ok());
    for (const char* encoding : {"srgb8", "linear"}) {
        auto o = options((dir / "seq.####.png").string(), (dir / "out.spt").string());
        o.color_encoding = encoding;
        Status st = paint_quietly(o);
        ASSERT_FALSE(st.ok()) << encoding;
        EXPECT_NE(st.error().message.find("seq.0002.png: frame 2 is 40x24, the sequence is 64x48"), std::string::npos)
            << encoding << ": " << st.error().message;
        o.skip_bad_frames = true;
        VideoPaintReport rep;
        ASSERT_TRUE(paint_quietly(o, &rep).ok()) << encoding;
        EXPECT_EQ(rep.skipped_frames, 1u) << encoding;
    }
    std::filesystem::remove_all(dir);
}

TEST(VideoPaint, UnreadableFrameIsSkippedWhenAsked) {
    const auto dir = spt_test::temp_dir("unreadable");
    write_sequence(dir, 1, 5);
    std::ofstream(dir / "seq.0003.png") << "not a png";
    auto o = options((dir / "seq.####.png").string(), (dir / "out.spt").string());
    Status st = paint_quietly(o);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("seq.0003.png"), std::string::npos) << st.error().message;
    o.skip_bad_frames = true;
    VideoPaintReport rep;
    ASSERT_TRUE(paint_quietly(o, &rep).ok());
    EXPECT_EQ(rep.skipped_frames, 1u);
    std::filesystem::remove_all(dir);
}

TEST(VideoPaint, StopFlagLeavesAValidFileWithTheFinishedFrames) {
    const auto dir = spt_test::temp_dir("stop");
    write_sequence(dir, 0, 11);
    auto o = options((dir / "seq.%04d.png").string(), (dir / "out.spt").string());
    std::atomic<bool> stop{false};
    o.stop = &stop;
    o.on_frame = [&](uint64_t done) {
        if (done == 5) stop = true;
    };
    VideoPaintReport rep;
    Status st = paint_quietly(o, &rep);
    EXPECT_FALSE(st.ok()) << "an interrupted encode reports it";
    EXPECT_TRUE(rep.interrupted);
    EXPECT_FALSE(std::filesystem::exists(o.output + ".partial"));
    auto r = Reader::open(o.output);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_TRUE((*r)->complete());
    ASSERT_EQ((*r)->frames().size(), 5u);
    EXPECT_TRUE((*r)->strokes_at(4).ok());
    std::filesystem::remove_all(dir);
}

TEST(VideoPaint, RoiFileBecomesRoiRecords) {
    const auto dir = spt_test::temp_dir("roi");
    write_sequence(dir, 10, 17);
    std::ofstream(dir / "rois.json") << R"({"rois":[{"frames":"12-14","x":8,"y":8,"w":20,"h":16}]})";
    auto o = options((dir / "seq.####.png").string(), (dir / "out.spt").string());
    o.roi_file = (dir / "rois.json").string();
    ASSERT_TRUE(paint_quietly(o).ok());
    auto r = Reader::open(o.output);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ((*r)->info().rois.size(), 1u);
    const Roi& roi = (*r)->info().rois[0];
    EXPECT_EQ(roi.first_frame, 2u) << "input frame 12 is output frame 2";
    EXPECT_EQ(roi.last_frame, 4u);
    EXPECT_EQ(roi.w, 20u);
    std::filesystem::remove_all(dir);
}

TEST(VideoPaint, ReadsAVideoFileWithItsFrameRate) {
    const std::string clip = std::string(SPT_MEDIA_DIR) + "/video/butterfly-cartoon.avi";
    if (!std::filesystem::exists(clip)) GTEST_FAIL() << "no shared media at " << clip;
    const auto dir = spt_test::temp_dir("avi");
    auto o = options(clip, (dir / "b.spt").string());
    o.frames = "0-3";
    o.paint.max_strokes = 200;
    VideoPaintReport rep;
    Status st = paint_quietly(o, &rep);
    ASSERT_TRUE(st.ok()) << st.error().message;
    EXPECT_EQ(rep.frames, 4u);
    auto r = Reader::open(o.output);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ((*r)->info().header.fps, (Rational{18, 1}));
    EXPECT_EQ((*r)->info().header.width, 520u);
    std::filesystem::remove_all(dir);
}
