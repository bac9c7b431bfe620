// spt plan's cut pass reads 8-bit sequences as bytes (plan/gray_frames.hpp): its gray frames
// must be exactly those of the painter's reader (video::FrameSource, then RGB -> gray), or the
// plan would place cuts the painter's detector does not see. Also for the files it leaves to
// the painter's reader (EXR), for video files, and for missing frames.
#include "converter/cli_test_util.hpp"

#include <algorithm>

#include <OpenImageIO/imageio.h>
#include <opencv2/imgproc.hpp>

#include "io/image_io.hpp"
#include "io/sequence.hpp"
#include "plan/gray_frames.hpp"
#include "frames/frame_source.hpp"

namespace {

using namespace spt_test;

void expect_same_gray(const std::string& pattern, int frames, int threads, const std::string& range = "") {
    auto fast = spt::plan::open_gray_frames(pattern, range, false, threads);
    ASSERT_TRUE(fast.ok()) << fast.error().message;
    auto slow = spt::video::open_source(pattern, range, false);
    ASSERT_TRUE(slow.ok()) << slow.error().message;
    // The sampled cut scan reads the same files by position (open_gray_frame_files).
    auto by_pos = spt::plan::open_gray_frame_files(pattern, range);
    ASSERT_TRUE(by_pos.ok()) << by_pos.error().message;
    const bool video = spt::io::is_video_file(pattern);
    ASSERT_EQ(bool(*by_pos), !video) << pattern << ": sequences read by position, videos in order";
    if (!video) EXPECT_EQ((*by_pos)->count(), size_t(frames));
    int n = 0;
    for (;; ++n) {
        long number = -1;
        cv::Mat g;
        auto a = (*fast)->next(number, g);
        spt::video::SourceFrame f;
        auto b = (*slow)->next(f);
        ASSERT_TRUE(a.ok()) << a.error().message;
        ASSERT_TRUE(b.ok()) << b.error().message;
        ASSERT_EQ(*a, *b);
        if (!*a) break;
        EXPECT_EQ(number, f.number);
        cv::Mat rgb(int(f.image.height), int(f.image.width), CV_8UC3, f.image.rgb.data()), want;
        cv::cvtColor(rgb, want, cv::COLOR_RGB2GRAY);
        ASSERT_EQ(g.size(), want.size());
        EXPECT_EQ(cv::countNonZero(g != want), 0) << pattern << " frame " << number << ", " << threads << " threads";
        if (video) continue;
        EXPECT_EQ(number, (*by_pos)->first() + n);
        const auto at = (*by_pos)->read(size_t(n));
        ASSERT_TRUE(at.problem.empty()) << at.problem;
        ASSERT_EQ(at.gray.size(), want.size());
        EXPECT_EQ(cv::countNonZero(at.gray != want), 0) << pattern << " frame " << number << " by position";
    }
    EXPECT_EQ(n, frames);
}

TEST(PlanGrayFrames, EightBitSequencesReadAsThePainterReadsThem) {
    const std::string media = SPT_MEDIA_DIR;
    ASSERT_TRUE(fs::exists(media + "/exr/earth/earth.0003.exr")) << "the shared media are needed: " << media;
    TempDir d;
    for (int i = 1; i <= 3; ++i) {
        auto img = spt::io::read_image(media + "/exr/earth/earth.000" + std::to_string(i) + ".exr");
        ASSERT_TRUE(img.ok());
        ASSERT_TRUE(spt::io::write_image(d.file("p." + std::to_string(40 + i) + ".png"), img->width, img->height,
                                         img->rgb.data()).ok());
    }
    for (int threads : {1, 2, 3}) {  // decoded ahead on several threads: the same frames, in order
        expect_same_gray(d.file("p.%02d.png"), 3, threads);  // 8-bit RGB: the byte path
        expect_same_gray(media + "/exr/earth/earth.####.exr", 48, threads);  // half float: the painter's path
    }
    // Half floats map through read_image's table: every half value in every channel, 1 and 3
    // channels (the earth frames above are half too).
    for (int nch : {1, 3}) {
        std::vector<uint16_t> px(65536 * size_t(nch));
        for (size_t i = 0; i < px.size(); ++i) px[i] = uint16_t(i * 40503u + uint32_t(nch));
        for (int f = 1; f <= 2; ++f) {
            const std::string path = d.file("h" + std::to_string(nch) + "." + std::to_string(f) + ".exr");
            auto out = OIIO::ImageOutput::create(path);
            ASSERT_TRUE(out);
            ASSERT_TRUE(out->open(path, OIIO::ImageSpec(256, 256, nch, OIIO::TypeDesc::HALF)));
            ASSERT_TRUE(out->write_image(OIIO::TypeDesc::HALF, px.data()));
            ASSERT_TRUE(out->close());
            std::reverse(px.begin(), px.end());
        }
        expect_same_gray(d.file("h" + std::to_string(nch) + ".@.exr"), 2, 2);
    }
    expect_same_gray(media + "/video/city.mpg", 190, 1);  // a video: BGR straight to gray
    expect_same_gray(media + "/video/city.mpg", 16, 1, "110-125");
    // A missing frame is an error naming it, or the previous frame with --skip-bad-frames.
    fs::remove(d.file("p.42.png"));
    for (int threads : {1, 2}) {
        auto g = spt::plan::open_gray_frames(d.file("p.%02d.png"), "", false, threads);
        ASSERT_TRUE(g.ok());
        long number = 0;
        cv::Mat m;
        ASSERT_TRUE((*g)->next(number, m).ok());
        auto miss = (*g)->next(number, m);
        ASSERT_FALSE(miss.ok());
        EXPECT_NE(miss.error().message.find("p.42.png: frame 42 is missing"), std::string::npos) << miss.error().message;
        g = spt::plan::open_gray_frames(d.file("p.%02d.png"), "", true, threads);
        ASSERT_TRUE(g.ok());
        cv::Mat first, second, third;
        ASSERT_TRUE((*g)->next(number, first).ok());
        auto rep = (*g)->next(number, second);
        ASSERT_TRUE(rep.ok() && *rep);
        EXPECT_EQ(number, 42);
        EXPECT_EQ(cv::countNonZero(first != second), 0);
        auto last = (*g)->next(number, third);
        ASSERT_TRUE(last.ok() && *last);
        EXPECT_EQ(number, 43);
        auto img = spt::io::read_image(d.file("p.43.png"));
        ASSERT_TRUE(img.ok());
        cv::Mat rgb(int(img->height), int(img->width), CV_8UC3, img->rgb.data()), want;
        cv::cvtColor(rgb, want, cv::COLOR_RGB2GRAY);
        EXPECT_EQ(cv::countNonZero(third != want), 0) << "frame 43, " << threads << " threads";
        auto end = (*g)->next(number, third);
        ASSERT_TRUE(end.ok());
        EXPECT_FALSE(*end);
    }
}

}  // namespace
