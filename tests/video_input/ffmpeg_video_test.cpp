// Video input through FFmpeg's libraries (converter/src/frames/ffmpeg_video.hpp): exact seek
// against sequential decoding for every frame, variable frame rate, rotation, 10-bit, the three
// alpha containers, damaged files, and the decoding a farm task's range costs. The files are
// made here with the `ffmpeg` command, small and synthetic.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "io/sequence.hpp"
#include "frames/ffmpeg_video.hpp"
#include "frames/video_reader.hpp"
#include "frames/video_scene.hpp"
#include "frames/scene_image.hpp"
#include "video_input_util.hpp"

using namespace spt;
using namespace spt_video_input;

namespace {

// Every frame of a file, decoded from the start.
std::vector<cv::Mat> decode_all(const std::string& path, std::vector<long>* numbers = nullptr) {
    video::FfmpegVideo v;
    Status st = v.open(path);
    EXPECT_TRUE(st.ok()) << st.error().message;
    std::vector<cv::Mat> frames;
    long n = 0;
    cv::Mat m;
    for (;;) {
        Result<bool> got = v.next(n, m);
        EXPECT_TRUE(got.ok()) << got.error().message;
        if (!got || !*got) break;
        if (numbers) numbers->push_back(n);
        frames.push_back(m.clone());
    }
    return frames;
}

bool same(const cv::Mat& a, const cv::Mat& b) {
    return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

// Opens the file afresh for every frame, seeks to it and compares with sequential decoding;
// each seek decodes from the key frame before its frame (`gop` frames apart), not the start.
void expect_exact_seek(const std::string& path, size_t frames, uint64_t gop) {
    std::vector<long> numbers;
    const std::vector<cv::Mat> all = decode_all(path, &numbers);
    ASSERT_EQ(all.size(), frames) << path;
    for (size_t i = 0; i < numbers.size(); ++i) ASSERT_EQ(numbers[i], long(i)) << path;
    for (long n = 0; n < long(frames); ++n) {
        video::FfmpegVideo v;
        ASSERT_TRUE(v.open(path).ok());
        ASSERT_TRUE(v.seek(n).ok());
        long got_n = -1;
        cv::Mat m;
        Result<bool> got = v.next(got_n, m);
        ASSERT_TRUE(got.ok() && *got) << path << " frame " << n;
        EXPECT_EQ(got_n, n) << path;
        EXPECT_TRUE(same(m, all[size_t(n)])) << path << ": frame " << n << " after a seek differs from sequential decoding";
        EXPECT_LE(v.decoded_frames(), 2 * gop + 4) << path << ": frame " << n << " decoded from too far back";
    }
    // Backwards within one reader too.
    video::FfmpegVideo v;
    ASSERT_TRUE(v.open(path).ok());
    for (long n : {long(frames) - 1, 3L, long(frames) / 2, 0L}) {
        ASSERT_TRUE(v.seek(n).ok());
        long got_n = -1;
        cv::Mat m;
        ASSERT_TRUE(*v.next(got_n, m));
        EXPECT_EQ(got_n, n);
        EXPECT_TRUE(same(m, all[size_t(n)])) << path << ": frame " << n << " (seeking back)";
    }
}

}  // namespace

TEST(FfmpegVideo, ExactSeekEqualsSequentialDecodeH264WithBFrames) {
    Dir d("seek_h264");
    const std::string f = d.file("gop.mp4");
    make_video(f, "-f lavfi -i testsrc2=s=96x64:r=24 -frames:v 60 -c:v libx264 -g 12 -bf 3 -pix_fmt yuv420p");
    expect_exact_seek(f, 60, 12);
}

TEST(FfmpegVideo, ExactSeekEqualsSequentialDecodeMpeg2ProgramStream) {
    // MPEG-PS seeks by scanning for timestamps, not by an index: the seek must check where it landed.
    Dir d("seek_mpg");
    const std::string f = d.file("gop.mpg");
    make_video(f, "-f lavfi -i testsrc2=s=96x64:r=25 -frames:v 50 -c:v mpeg2video -g 10 -bf 2 -f mpeg");
    expect_exact_seek(f, 50, 10);
}

TEST(FfmpegVideo, ExactSeekEqualsSequentialDecodeMpeg4Avi) {
    Dir d("seek_avi");
    const std::string f = d.file("gop.avi");
    make_video(f, "-f lavfi -i testsrc2=s=96x64:r=18 -frames:v 40 -c:v mpeg4 -g 8");
    expect_exact_seek(f, 40, 8);
}

TEST(FfmpegVideo, ExactSeekOnTheSharedCityClip) {
    // OpenCV's seek gave frame 13 for frames 1 and 8 of this MPEG-2 program stream (open GOPs).
    const std::string f = std::string(SPT_MEDIA_DIR) + "/video/city.mpg";
    ASSERT_TRUE(fs::exists(f)) << f << " is missing (the shared media)";
    const auto all = decode_all(f);
    ASSERT_EQ(all.size(), 190u);
    for (long n : {1L, 8L, 13L, 14L, 115L, 116L, 117L, 189L}) {
        video::FfmpegVideo v;
        ASSERT_TRUE(v.open(f).ok());
        ASSERT_TRUE(v.seek(n).ok());
        long got_n = -1;
        cv::Mat m;
        ASSERT_TRUE(*v.next(got_n, m));
        EXPECT_EQ(got_n, n);
        EXPECT_TRUE(same(m, all[size_t(n)])) << "city.mpg frame " << n << " after a seek";
    }
}

TEST(FfmpegVideo, VariableFrameRateFramesAreNumberedInTimeOrder) {
    // 30 frames whose durations change (1/24 s, then 3/24 s, then 2/24 s): frame N is the Nth
    // timestamp, so numbers run 0..29 with no gaps or repeats, and a seek finds each.
    Dir d("vfr");
    const std::string f = d.file("vfr.mkv");
    make_video(f, "-f lavfi -i testsrc2=s=96x64:r=24 -frames:v 30 "
                  "-vf \"setpts='if(lt(N,10),N,if(lt(N,20),10+(N-10)*3,40+(N-20)*2))/24/TB'\" "
                  "-fps_mode passthrough -c:v libx264 -g 7 -bf 2");
    std::istringstream times(capture("ffprobe -v error -select_streams v:0 -show_entries packet=pts_time -of csv=p=0 '" +
                                     f + "' | sort -g"));
    std::vector<double> t;
    for (double x; times >> x;) t.push_back(x);
    ASSERT_EQ(t.size(), 30u);
    std::set<long> steps;
    for (size_t i = 1; i < t.size(); ++i) steps.insert(std::lround((t[i] - t[i - 1]) * 1000));
    ASSERT_GT(*steps.begin(), 30) << "two frames (nearly) share a time";
    ASSERT_LT(*steps.begin(), 50);
    ASSERT_GT(*steps.rbegin(), 100) << "the file is not variable-rate";
    expect_exact_seek(f, 30, 7);
}

TEST(FfmpegVideo, RotationMetadataIsApplied) {
    // The same stream copied with a display matrix: frames come out turned as FFmpeg's own
    // player turns them (fftools' rule: minus the matrix's counterclockwise angle).
    Dir d("rot");
    const std::string plain = d.file("plain.mp4");
    make_video(plain, "-f lavfi -i testsrc2=s=96x64:r=24 -frames:v 5 -c:v libx264 -pix_fmt yuv420p");
    const auto a = decode_all(plain);
    ASSERT_EQ(a.size(), 5u);
    for (int tag : {90, 180, 270}) {
        const std::string rotated = d.file("rotated" + std::to_string(tag) + ".mp4");
        run_ok("ffmpeg -v error -nostdin -y -i '" + plain + "' -c copy -metadata:s:v:0 rotate=" + std::to_string(tag) +
               " '" + rotated + "'");
        video::FfmpegVideo v;
        ASSERT_TRUE(v.open(rotated).ok());
        EXPECT_NE(v.rotation(), 0) << tag;
        EXPECT_EQ(v.width(), v.rotation() == 180 ? 96 : 64);
        EXPECT_EQ(v.height(), v.rotation() == 180 ? 64 : 96);
        // FFmpeg's player (autorotate) as the reference for the direction: its filters turn the
        // YUV planes before converting, so compare closely rather than bit for bit.
        const std::string raw = d.file("player.bgr");
        run_ok("ffmpeg -v error -nostdin -y -i '" + rotated + "' -frames:v 1 -f rawvideo -pix_fmt bgr24 '" + raw + "'");
        std::ifstream in(raw, std::ios::binary);
        std::vector<uint8_t> ref((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        ASSERT_EQ(ref.size(), size_t(96 * 64 * 3)) << tag;
        const auto b = decode_all(rotated);
        ASSERT_EQ(b.size(), 5u);
        cv::Mat player(v.height(), v.width(), CV_8UC3, ref.data());
        EXPECT_LT(cv::norm(player, b[0], cv::NORM_L1) / double(ref.size()), 2.0)
            << tag << ": frame 0 is not turned the way FFmpeg's player turns it";
        const int code = v.rotation() == 90 ? cv::ROTATE_90_CLOCKWISE
                         : v.rotation() == 180 ? cv::ROTATE_180 : cv::ROTATE_90_COUNTERCLOCKWISE;
        for (size_t i = 0; i < a.size(); ++i) {
            cv::Mat r;
            cv::rotate(a[i], r, code);
            EXPECT_TRUE(same(r, b[i])) << tag << ": frame " << i << " is not the plain frame turned";
        }
    }
}

TEST(FfmpegVideo, TenAndTwelveBitSourcesAreReadAtTheirDepth) {
    // A luma ramp of 10- or 12-bit codes across 1024 columns, lossless (FFV1): more than 256
    // levels survive, which no 8-bit path could give.
    Dir d("deep");
    for (int bits : {10, 12}) {
        const std::string fmt = "yuv444p" + std::to_string(bits) + "le";
        const std::string f = d.file("ramp" + std::to_string(bits) + ".mkv");
        const std::string lum = bits == 10 ? "X" : "X*4";
        const std::string mid = bits == 10 ? "512" : "2048";
        make_video(f, "-f lavfi -i nullsrc=s=1024x8:r=24 -frames:v 2 -vf \"format=" + fmt + ",geq=lum='" + lum + "':cb=" +
                          mid + ":cr=" + mid + "\" -c:v ffv1 -pix_fmt " + fmt);
        video::FfmpegVideo v;
        ASSERT_TRUE(v.open(f).ok());
        EXPECT_TRUE(v.deep());
        EXPECT_EQ(v.bit_depth(), bits);
        EXPECT_FALSE(v.has_alpha());
        long n = 0;
        cv::Mat m;
        ASSERT_TRUE(*v.next(n, m));
        ASSERT_EQ(m.type(), CV_16UC4);
        std::set<uint16_t> levels;
        for (int x = 0; x < m.cols; ++x) levels.insert(m.ptr<uint16_t>(4)[x * 4 + 1]);
        EXPECT_GT(levels.size(), 600u) << bits << "-bit: green levels along the ramp";
    }
}

TEST(FfmpegVideo, AlphaContainersGiveTheirAlpha) {
    // Left half transparent, right half opaque, in each container users' compositors write.
    Dir d("alpha");
    const std::string src = "-f lavfi -i testsrc2=s=96x64:r=12 -frames:v 4 -vf \"format=rgba,geq=r='r(X,Y)':g='g(X,Y)':"
                            "b='b(X,Y)':a='if(lt(X,48),0,255)'\" ";
    struct Case {
        const char* name;
        const char* args;
    };
    for (const Case& c : {Case{"prores4444.mov", "-c:v prores_ks -profile:v 4444 -pix_fmt yuva444p10le"},
                          Case{"vp9alpha.webm", "-c:v libvpx-vp9 -pix_fmt yuva420p -b:v 1M"},
                          Case{"png.mov", "-c:v png -pix_fmt rgba"}}) {
        const std::string f = d.file(c.name);
        make_video(f, src + c.args);
        video::FfmpegVideo v;
        Status st = v.open(f);
        ASSERT_TRUE(st.ok()) << st.error().message;
        EXPECT_TRUE(v.has_alpha()) << c.name;
        EXPECT_TRUE(v.deep()) << c.name;
        long n = 0;
        cv::Mat m;
        ASSERT_TRUE(*v.next(n, m)) << c.name;
        ASSERT_EQ(m.type(), CV_16UC4) << c.name;
        using Px = cv::Vec<uint16_t, 4>;
        EXPECT_LT(m.at<Px>(32, 10)[3], 2000) << c.name << ": left half should be transparent";
        EXPECT_GT(m.at<Px>(32, 80)[3], 63000) << c.name << ": right half should be opaque";
    }
}

TEST(FfmpegVideo, DamagedFilesGiveAnErrorNamingThem) {
    Dir d("damaged");
    const std::string good = d.file("good.mp4");
    make_video(good, "-f lavfi -i testsrc2=s=96x64:r=24 -frames:v 24 -c:v libx264 -pix_fmt yuv420p");
    // Cut before its index (the moov box is at the end of an mp4): nothing can be read.
    const std::string cut = d.file("cut.mp4");
    fs::copy_file(good, cut);
    fs::resize_file(cut, fs::file_size(good) / 2);
    // Not a video at all.
    const std::string junk = d.file("junk.mp4");
    std::ofstream(junk) << std::string(5000, 'x');
    for (const std::string& f : {cut, junk, d.file("missing.mp4")}) {
        video::FfmpegVideo v;
        Status st = v.open(f);
        ASSERT_FALSE(st.ok()) << f;
        EXPECT_NE(st.error().message.find(f), std::string::npos) << st.error().message;
        Result<uint64_t> n = video::count_video_packets(f);
        ASSERT_FALSE(n.ok()) << f;
        EXPECT_NE(n.error().message.find(f), std::string::npos) << n.error().message;
    }
    // A header that claims a picture over the size limit (40000 wide) is refused before any
    // picture is allocated.
    const std::string wide = d.file("wide.y4m");
    std::ofstream(wide) << "YUV4MPEG2 W40000 H100 F24:1 Ip A1:1 C420jpeg\nFRAME\n" << std::string(1000, '\x80');
    {
        video::FfmpegVideo v;
        Status st = v.open(wide);
        ASSERT_FALSE(st.ok());
        EXPECT_NE(st.error().message.find(wide + ": the video is 40000x100, over the size limit"), std::string::npos)
            << st.error().message;
    }
    // A Matroska file cut short still decodes what it holds, and says it ends early.
    const std::string mkv = d.file("short.mkv");
    make_video(mkv, "-f lavfi -i testsrc2=s=96x64:r=24 -frames:v 48 -c:v libx264 -g 12 -pix_fmt yuv420p");
    fs::resize_file(mkv, fs::file_size(mkv) / 2);
    video::FfmpegVideo v;
    ASSERT_TRUE(v.open(mkv).ok());
    EXPECT_LT(v.packet_frames(), 48u);
    long n = 0;
    cv::Mat m;
    size_t got = 0;
    while (*v.next(n, m)) ++got;
    EXPECT_GT(got, 0u);
    EXPECT_LT(got, 48u);
}

TEST(FfmpegVideo, ARangeDecodesFromTheKeyFrameBeforeIt) {
    // What a farm task costs: frames 120-143 of a 240-frame file with a key frame every 24
    // decode one group of pictures and the range, not the 120 frames before it.
    Dir d("range");
    const std::string f = d.file("long.mp4");
    make_video(f, "-f lavfi -i testsrc2=s=96x64:r=24 -frames:v 240 -c:v libx264 -g 24 -keyint_min 24 -sc_threshold 0 "
                  "-bf 2 -pix_fmt yuv420p");
    std::vector<long> numbers;
    const auto all = decode_all(f, &numbers);
    ASSERT_EQ(all.size(), 240u);
    Result<io::FrameRange> range = io::parse_frame_range("130-153");
    ASSERT_TRUE(range.ok());
    video::VideoReader r(f, *range);
    ASSERT_TRUE(r.open().ok());
    long n = 0, want = 130;
    cv::Mat m;
    while (*r.next(n, m)) {
        EXPECT_EQ(n, want);
        EXPECT_TRUE(same(m, all[size_t(n)])) << "frame " << n;
        ++want;
    }
    EXPECT_EQ(want, 154);
    EXPECT_LE(r.decoded_frames(), 24u + 24u + 4u) << "decoded from further back than the key frame before 130";
    // A range of two spans seeks over the gap.
    range = io::parse_frame_range("5-6,200-201");
    ASSERT_TRUE(range.ok());
    video::VideoReader r2(f, *range);
    ASSERT_TRUE(r2.open().ok());
    std::vector<long> got;
    while (*r2.next(n, m)) {
        got.push_back(n);
        EXPECT_TRUE(same(m, all[size_t(n)])) << "frame " << n;
    }
    EXPECT_EQ(got, (std::vector<long>{5, 6, 200, 201}));
    EXPECT_LE(r2.decoded_frames(), 2u * 30u);
}

TEST(FfmpegVideo, AnAlphaVideoFrameReadsAsThePngOfItDoes) {
    // PNG in MOV holds PNG frames: frame 0 read for an alpha canvas must be the scene image the
    // scene-linear reader makes of the same frame written as a PNG file.
    Dir d("alpha_png");
    const std::string mov = d.file("png.mov"), png = d.file("f0.png");
    make_video(mov, "-f lavfi -i testsrc2=s=96x64:r=12 -frames:v 2 -vf \"format=rgba,geq=r='r(X,Y)':g='g(X,Y)':"
                    "b='b(X,Y)':a='if(lt(X,48),X*5,255)'\" -c:v png -pix_fmt rgba");
    run_ok("ffmpeg -v error -nostdin -y -i '" + mov + "' -frames:v 1 '" + png + "'");
    Result<io::SceneImage> v = video::first_scene_frame(mov, {});
    ASSERT_TRUE(v.ok()) << v.error().message;
    Result<io::SceneImage> p = io::read_scene_image(png);
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_TRUE(v->has_alpha);
    ASSERT_EQ(v->rgba.size(), p->rgba.size());
    double worst = 0;
    size_t differ = 0;
    for (size_t i = 0; i < v->rgba.size(); ++i) {
        worst = std::max(worst, double(std::abs(v->rgba[i] - p->rgba[i])));
        if (v->rgba[i] != p->rgba[i] && differ++ < 4)
            ADD_FAILURE() << "sample " << i << " (channel " << i % 4 << "): video " << v->rgba[i] << ", png " << p->rgba[i]
                          << ", alpha " << p->rgba[i - i % 4 + 3];
    }
    EXPECT_EQ(differ, 0u) << "largest difference " << worst;
}
