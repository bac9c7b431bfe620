// `spt paint` as a video encoder, through the built binary (SPT_TOOL): interruption by SIGINT
// and SIGTERM mid-encode, a video file (AVI, MJPG) as input, and `spt render --frames` on the
// middle of the result against sequential decoding.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "io/image_io.hpp"
#include "spt/reader.hpp"
#include "spt/render.hpp"
#include "synthetic.hpp"
#include "io/ffmpeg_writer.hpp"

using namespace spt;
namespace fs = std::filesystem;

namespace {

bool have_tool() { return std::string(SPT_TOOL).size() > 0 && fs::exists(SPT_TOOL); }

// Runs the tool to completion; returns its exit code (-1 when it did not exit normally).
int run_tool(const std::vector<std::string>& args) {
    std::string cmd = std::string("'") + SPT_TOOL + "'";
    for (const auto& a : args) cmd += " '" + a + "'";
    cmd += " >/dev/null 2>&1 </dev/null";
    const int st = std::system(cmd.c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

// A frame sequence dir/seq.####.png of a moving scene.
void write_sequence(const fs::path& dir, int frames, uint32_t w, uint32_t h) {
    for (int f = 0; f < frames; ++f) {
        const auto rgb = spt_test::scene_frame(0, f, w, h);
        char name[64];
        std::snprintf(name, sizeof name, "seq.%04d.png", f);
        ASSERT_TRUE(io::write_image((dir / name).string(), w, h, rgb.data()).ok());
    }
}

struct Interrupted {
    int exit_code = -1;
    bool signalled = false;     // the process died of the signal (a second one, not ours)
    double frames_seen = 0;     // frames done per the last progress line before the signal
    bool sent = false;
};

// Starts `spt paint` with JSON progress on a pipe, waits until it reports `after` finished
// frames, sends `sig` and waits for the process to end.
Interrupted paint_and_interrupt(const std::vector<std::string>& args, int sig, double after) {
    Interrupted r;
    int fds[2];
    if (::pipe(fds) != 0) return r;
    const pid_t pid = ::fork();
    if (pid < 0) return r;
    if (pid == 0) {
        ::dup2(fds[1], STDOUT_FILENO);
        const int devnull = ::open("/dev/null", O_WRONLY);
        if (devnull >= 0) ::dup2(devnull, STDERR_FILENO);
        ::close(fds[0]);
        ::close(fds[1]);
        std::vector<char*> argv;
        argv.push_back(const_cast<char*>(SPT_TOOL));
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(SPT_TOOL, argv.data());
        ::_exit(127);
    }
    ::close(fds[1]);
    FILE* in = ::fdopen(fds[0], "r");
    char line[4096];
    while (in && std::fgets(line, sizeof line, in)) {
        const std::string l = line;
        const size_t k = l.find("\"done\":");
        if (l.find("\"progress\"") == std::string::npos || k == std::string::npos) continue;
        r.frames_seen = std::atof(l.c_str() + k + 7);
        if (r.frames_seen >= after) {
            ::kill(pid, sig);
            r.sent = true;
            break;
        }
    }
    // Drain the rest so the child never blocks on a full pipe.
    while (in && std::fgets(line, sizeof line, in)) {
    }
    if (in) std::fclose(in);
    int st = 0;
    ::waitpid(pid, &st, 0);
    r.exit_code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r.signalled = WIFSIGNALED(st);
    return r;
}

// Paints a `frames`-frame 96x64 sequence written into `dir` to dir/out.spt, one thread (the
// painterly painter, or with `cartoon` the cartoon one), and sends `sig` once it has reported 3
// frames.
Interrupted interrupt_a_sequence_paint(const fs::path& dir, int frames, int sig, bool cartoon) {
    write_sequence(dir, frames, 96, 64);
    std::vector<std::string> args = {"paint", (dir / "seq.####.png").string(), "-o", (dir / "out.spt").string(),
                                     "--threads", "1", "--progress", "json"};
    if (cartoon) args.insert(args.end(), {"--style", "cartoon", "--target-psnr", "30"});
    else args.insert(args.end(), {"--sets", "4", "--max-strokes", "400"});
    return paint_and_interrupt(args, sig, 3);
}

void check_interrupt(int sig, bool cartoon = false) {
    if (!have_tool()) GTEST_FAIL() << "spt binary not built";
    const auto dir = spt_test::temp_dir("cli_sig" + std::to_string(sig) + (cartoon ? "c" : ""));
    const int total = 150;
    const std::string out = (dir / "out.spt").string();
    const Interrupted r = interrupt_a_sequence_paint(dir, total, sig, cartoon);
    ASSERT_TRUE(r.sent) << "the encode ended before reporting 3 frames";
    EXPECT_FALSE(r.signalled) << "one signal stops cleanly; it must not kill the process";
    EXPECT_FALSE(fs::exists(out + ".partial")) << "a .partial file was left behind";
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string n = e.path().filename().string();
        EXPECT_TRUE(n == "out.spt" || (n.rfind("seq.", 0) == 0 && e.path().extension() == ".png"))
            << "left behind: " << n;
    }
    if (!fs::exists(out)) return;  // nothing at the output path is also a clean outcome
    // Its own exit status (README): stopped cleanly, the output is valid.
    EXPECT_EQ(r.exit_code, 3) << "an interrupted paint with a valid output exits 3";
    EXPECT_EQ(run_tool({"verify", out}), 0) << "the interrupted output is not a valid .spt";
    auto reader = Reader::open(out);
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    ASSERT_TRUE((*reader)->complete());
    const size_t n = (*reader)->frames().size();
    EXPECT_GE(double(n), r.frames_seen) << "finished frames are missing";
    EXPECT_LT(n, size_t(total)) << "the encode was not stopped early";
    // Every stored frame decodes.
    auto renderer = Renderer::create((*reader)->info().header, (*reader)->info().templates);
    ASSERT_TRUE(renderer.ok());
    Canvas c;
    for (size_t f = 0; f < n; ++f) {
        auto live = (*reader)->strokes_at(f);
        ASSERT_TRUE(live.ok()) << "frame " << f << ": " << live.error().message;
        ASSERT_TRUE((*renderer)->render(c, **live).ok());
    }
}

}  // namespace

TEST(VideoCli, SigintLeavesAValidFileOrNothing) { check_interrupt(SIGINT); }

TEST(VideoCli, SigtermLeavesAValidFileOrNothing) { check_interrupt(SIGTERM); }

TEST(VideoCli, CartoonSigintLeavesAValidFileOrNothing) { check_interrupt(SIGINT, true); }

TEST(VideoCli, CartoonSigtermLeavesAValidFileOrNothing) { check_interrupt(SIGTERM, true); }

// SIGKILL cannot be caught: the output is an unnamed file (O_TMPFILE) until it is complete, so
// the folder holds nothing new at all afterwards (issue 20).
TEST(VideoCli, SigkillLeavesNothing) {
    if (!have_tool()) GTEST_FAIL() << "spt binary not built";
    const auto dir = spt_test::temp_dir("cli_sigkill");
    const Interrupted r = interrupt_a_sequence_paint(dir, 150, SIGKILL, false);
    ASSERT_TRUE(r.sent) << "the encode ended before reporting 3 frames";
    EXPECT_TRUE(r.signalled);
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string n = e.path().filename().string();
        EXPECT_TRUE(n.rfind("seq.", 0) == 0 && e.path().extension() == ".png") << "left behind: " << n;
    }
}

TEST(VideoCli, PaintsAnAviAndRenderSeeksIntoTheMiddle) {
    if (!have_tool()) GTEST_FAIL() << "spt binary not built";
    const auto dir = spt_test::temp_dir("cli_avi");
    const std::string avi = (dir / "clip.avi").string();
    const int w = 96, h = 64, frames = 16;
    {
        video::VideoFileWriter vw;  // Motion JPEG in AVI
        Status st = vw.open(avi, ".avi", avi, 12.0, uint32_t(w), uint32_t(h));
        if (!st) GTEST_FAIL() << st.error().message;
        for (int f = 0; f < frames; ++f) {
            auto rgb = spt_test::scene_frame(0, f, w, h);
            ASSERT_TRUE(vw.write_rgb(rgb.data()).ok());
        }
        ASSERT_TRUE(vw.finish().ok());
    }
    const std::string out = (dir / "clip.spt").string();
    ASSERT_EQ(run_tool({"paint", avi, "-o", out, "--sets", "4", "--max-strokes", "400", "--threads", "2",
                        "--progress", "none"}),
              0);
    ASSERT_EQ(run_tool({"verify", out}), 0);
    auto reader = Reader::open(out);
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    const auto& info = (*reader)->info();
    ASSERT_EQ((*reader)->frames().size(), size_t(frames));
    EXPECT_EQ(info.header.fps, (Rational{12, 1})) << "frame rate from the container";
    EXPECT_EQ(info.header.width, uint32_t(w));

    // Frames 7-9 through `spt render --frames` (the index seek) against decoding every frame
    // from the start in order.
    const std::string pattern = (dir / "mid.####.png").string();
    ASSERT_EQ(run_tool({"render", out, "-o", pattern, "--frames", "7-9", "--progress", "none"}), 0);
    auto renderer = Renderer::create(info.header, info.templates);
    ASSERT_TRUE(renderer.ok());
    std::vector<Stroke> live;
    Canvas c;
    for (size_t f = 0; f < 10; ++f) {
        auto got = (*reader)->read_frame(f);
        ASSERT_TRUE(got.ok()) << got.error().message;
        ASSERT_TRUE(apply_frame(live, *got, info.header).ok());
        if (f < 7) continue;
        ASSERT_TRUE((*renderer)->render(c, live).ok());
        char name[64];
        std::snprintf(name, sizeof name, "mid.%04zu.png", f);
        auto img = io::read_image((dir / name).string());
        ASSERT_TRUE(img.ok()) << name << ": " << img.error().message;
        ASSERT_EQ(img->rgb.size(), c.rgb.size());
        EXPECT_TRUE(img->rgb == c.rgb) << "frame " << f << " rendered by seeking differs from sequential decoding";
    }
}
