// `spt paint` on video files through the built binary (SPT_TOOL): a video with alpha paints the
// alpha canvas its frames as a PNG sequence paint, and a damaged file is an error naming it.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "spt/reader.hpp"
#include "video_input_util.hpp"

using namespace spt;
using namespace spt_video_input;

namespace {

struct SptRun {
    int code = -1;
    std::string err;
};

SptRun spt_run(const Dir& d, const std::string& args) {
    if (!fs::exists(SPT_TOOL)) ADD_FAILURE() << "spt binary not built";
    const std::string errf = d.file("stderr.txt");
    const int st = std::system((std::string("'") + SPT_TOOL + "' " + args + " >/dev/null 2>'" + errf + "' </dev/null").c_str());
    SptRun r;
    r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    std::ifstream in(errf);
    r.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    return r;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

TEST(VideoInputCli, AnAlphaVideoPaintsAsThePngSequenceOfItsFrames) {
    Dir d("cli_alpha");
    const std::string mov = d.file("png.mov");
    make_video(mov, "-f lavfi -i testsrc2=s=96x64:r=12 -frames:v 4 -vf \"format=rgba,geq=r='r(X,Y)':g='g(X,Y)':"
                    "b='b(X,Y)':a='if(lt(X,48),0,255)'\" -c:v png -pix_fmt rgba");
    fs::create_directories(d.path / "seq");
    run_ok("ffmpeg -v error -nostdin -y -i '" + mov + "' -start_number 0 '" + d.file("seq/f.%04d.png") + "'");
    SptRun r = spt_run(d, "paint '" + mov + "' -o '" + d.file("v.spt") + "' --seed 1 --max-strokes 300");
    ASSERT_EQ(r.code, 0) << r.err;
    r = spt_run(d, "paint '" + d.file("seq/f.####.png") + "' -o '" + d.file("s.spt") + "' --seed 1 --max-strokes 300 --fps 12");
    ASSERT_EQ(r.code, 0) << r.err;
    auto reader = Reader::open(d.file("v.spt"));
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    EXPECT_TRUE((*reader)->info().header.alpha) << "a video with alpha should paint an alpha canvas";
    ASSERT_EQ((*reader)->frames().size(), 4u);
    ASSERT_EQ(spt_run(d, "render '" + d.file("v.spt") + "' -o '" + d.file("v.####.png") + "'").code, 0);
    ASSERT_EQ(spt_run(d, "render '" + d.file("s.spt") + "' -o '" + d.file("s.####.png") + "'").code, 0);
    for (const char* n : {"0000", "0001", "0002", "0003"}) {
        const std::string a = slurp(d.file(std::string("v.") + n + ".png")), b = slurp(d.file(std::string("s.") + n + ".png"));
        EXPECT_FALSE(a.empty());
        EXPECT_EQ(a, b) << "frame " << n << " of the video's painting differs from the sequence's";
    }
}

TEST(VideoInputCli, ADamagedVideoIsAnErrorNamingIt) {
    Dir d("cli_damaged");
    const std::string good = d.file("good.mp4"), cut = d.file("cut.mp4");
    make_video(good, "-f lavfi -i testsrc2=s=96x64:r=24 -frames:v 24 -c:v libx264 -pix_fmt yuv420p");
    fs::copy_file(good, cut);
    fs::resize_file(cut, fs::file_size(good) / 2);  // without its index (moov is at the end)
    for (const char* cmd : {"paint", "plan"}) {
        SptRun r = spt_run(d, std::string(cmd) + " '" + cut + "' -o '" + d.file(std::string("out.") + cmd) + "'");
        EXPECT_EQ(r.code, 1) << cmd << ": " << r.err;
        EXPECT_NE(r.err.find(cut), std::string::npos) << cmd << ": " << r.err;
        EXPECT_NE(r.err.find("cannot open this video file"), std::string::npos) << cmd << ": " << r.err;
    }
}
