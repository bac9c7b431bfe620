// The spt command against hostile or careless use (issue 20): every case checks the exit
// status, the message, and what is on disk afterwards; where nothing may be written, that the
// folder holds nothing new. Inputs: tests/hostile/inputs (make_inputs.py says how each is made).
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "converter/cli_test_util.hpp"
#include "hostile/spawn_quiet.hpp"
#include "io/image_io.hpp"

using namespace spt_test;

namespace {

std::string input(const std::string& name) { return std::string(SPT_SOURCE_DIR) + "/tests/hostile/inputs/" + name; }
std::string golden(const std::string& name) { return std::string(SPT_SOURCE_DIR) + "/tests/format/golden/" + name; }

// The folder's entries, the captured-output files excepted, sorted.
std::vector<std::string> names(const TempDir& d) {
    std::vector<std::string> v;
    for (const auto& e : fs::directory_iterator(d.path)) {
        const std::string n = e.path().filename().string();
        if (n != ".stdout" && n != ".stderr") v.push_back(n);
    }
    std::sort(v.begin(), v.end());
    return v;
}
using Names = std::vector<std::string>;

size_t count(const std::string& s, const std::string& what) {
    size_t n = 0;
    for (size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
    return n;
}

#define EXPECT_HAS(text, what) EXPECT_NE((text).find(what), std::string::npos) << "missing \"" << (what) << "\" in: " << (text)

// Starts spt, sends `sig` after `after`, waits; true when the signal ended it.
bool run_and_signal(const std::vector<std::string>& args, int sig, std::chrono::milliseconds after, int* exit_code) {
    const pid_t pid = spt_test::spawn_spt_quietly(args);
    std::this_thread::sleep_for(after);
    ::kill(pid, sig);
    int st = 0;
    ::waitpid(pid, &st, 0);
    *exit_code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    return WIFSIGNALED(st);
}

// A noise image the painter needs many seconds for.
std::string noise_image(const TempDir& d) {
    const uint32_t w = 1024, h = 1024;
    std::vector<uint8_t> px(size_t(w) * h * 3);
    std::mt19937 rng(7);
    for (auto& p : px) p = uint8_t(rng());
    const std::string path = d.file("noise.png");
    EXPECT_TRUE(spt::io::write_image(path, w, h, px.data()).ok());
    return path;
}

}  // namespace

// ---- images that are truncated, empty, not images, or lie about their size ----

TEST(HostileCli, BrokenImagesFailNamingTheFileAndWriteNothing) {
    TempDir d;
    const std::pair<const char*, const char*> cases[] = {
        {"truncated.png", "cannot read pixels"},     {"empty.png", "cannot read image"},
        {"not_an_image.png", "cannot read image"},   {"lying_size.png", "1000000x1000000, over the size limit"},
        {"lying_rows.png", "cannot read pixels"},
    };
    for (const auto& [file, what] : cases) {
        auto r = run_spt(d, {"paint", input(file), "-o", d.file("o.spt"), "--preview", d.file("p.png")});
        EXPECT_TRUE(failed_with(r, 1, {input(file), what})) << file;
        EXPECT_EQ(names(d), Names{}) << file;
    }
}

// ---- a video cut short ----

// A video that ends before the frames its header promises (a copy that stopped early) decoded
// up to the damage and was painted as if that were all of it, with nothing said. Now both
// painters and the plan's scans say so, naming the file; a range wholly past the end fails.
TEST(HostileCli, AVideoCutShortIsSaidAndARangePastItsEndFails) {
    TempDir d;
    const std::string cut = input("video_30f_cut.avi");
    const std::string said = "video_30f_cut.avi: decoding stopped at frame 1, but its header says 30 frames";
    for (const char* style : {"painterly", "cartoon"}) {
        auto r = run_spt(d, {"paint", cut, "-o", d.file("o.spt"), "--style", style, "--max-strokes", "50"});
        EXPECT_EQ(r.code, 0) << style << ": " << r.err;
        EXPECT_HAS(r.err, said);
        EXPECT_HAS(r.err, "read 1 of the 30 frames asked for");
        r = run_spt(d, {"info", d.file("o.spt"), "--json"});
        EXPECT_HAS(r.out, "\"frames_found\": 1");
        fs::remove(d.file("o.spt"));
        r = run_spt(d, {"paint", cut, "-o", d.file("o.spt"), "--style", style, "--frames", "10-20"});
        EXPECT_TRUE(failed_with(r, 1, {said, "read 0 of the 11 frames asked for"})) << style;
        EXPECT_EQ(names(d), Names{}) << style;
    }
    for (const char* scan : {"full", "sampled"}) {
        auto r = run_spt(d, {"plan", cut, "-o", d.file("p.plan.json"), "--cut-scan", scan});
        EXPECT_EQ(r.code, 0) << scan << ": " << r.err;
        EXPECT_HAS(r.err, said);
    }
    // The whole file decodes all it promises: nothing is said.
    auto r = run_spt(d, {"paint", input("video_30f.avi"), "-o", d.file("w.spt"), "--max-strokes", "50"});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("decoding stopped"), std::string::npos) << r.err;
    r = run_spt(d, {"plan", input("video_30f.avi"), "-o", d.file("w.plan.json"), "--cut-scan", "full"});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err.find("decoding stopped"), std::string::npos) << r.err;
}

// ---- damaged .spt files ----

// Issue 20 item 4: this rendered 1 of 5 frames, printed nothing and exited 0.
TEST(HostileCli, RenderOfADamagedFileWritesWhatItCanNamesTheFrameAndFails) {
    TempDir d;
    auto r = run_spt(d, {"render", input("frame1_length_ffffffff.spt"), "-o", d.file("o.####.png")});
    EXPECT_TRUE(failed_with(r, 1, {"frame 1 (byte offset 717) could not be rendered", "claims 4294967295 bytes",
                                   "wrote 1 of 5 frames"}));
    EXPECT_EQ(names(d), Names{"o.0000.png"});
    // Asking only for what survives succeeds; asking for a lost frame fails, writing nothing.
    TempDir e;
    r = run_spt(e, {"render", input("frame1_length_ffffffff.spt"), "-o", e.file("o.png"), "--frame", "0"});
    EXPECT_EQ(r.code, 0) << r.err;
    r = run_spt(e, {"render", input("frame1_length_ffffffff.spt"), "-o", e.file("d.png")});
    EXPECT_EQ(r.code, 0) << "a single image is frame 0: " << r.err;
    EXPECT_EQ(names(e), (Names{"d.png", "o.png"}));
    r = run_spt(e, {"render", input("frame1_length_ffffffff.spt"), "-o", e.file("x.png"), "--frame", "3"});
    EXPECT_TRUE(failed_with(r, 1, {"frame 1 (byte offset 717) could not be rendered"}));
    EXPECT_EQ(names(e), (Names{"d.png", "o.png"}));
    r = run_spt(e, {"render", input("frame1_length_ffffffff.spt"), "-o", e.file("s.####.png"), "--frames", "0-2"});
    EXPECT_TRUE(failed_with(r, 1, {"wrote 1 of 3 frames"}));
    EXPECT_EQ(names(e), (Names{"d.png", "o.png", "s.0000.png"}));
}

TEST(HostileCli, TruncatedFileRendersItsWholeFramesAndFails) {
    TempDir d;
    auto r = run_spt(d, {"render", input("truncated.spt"), "-o", d.file("o.####.png")});
    EXPECT_TRUE(failed_with(r, 1, {"frame 2 (byte offset 756) could not be rendered", "wrote 2 of 5 frames"}));
    EXPECT_EQ(names(d), (Names{"o.0000.png", "o.0001.png"}));
    r = run_spt(d, {"info", input("truncated.spt")});
    EXPECT_HAS(r.out, "INCOMPLETE (no end chunk)");
}

// It was reported "INCOMPLETE (no end chunk)" although it has one.
TEST(HostileCli, AFileWithACopyAppendedIsReportedAsTrailingData) {
    TempDir d;
    auto r = run_spt(d, {"info", input("appended_copy.spt")});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_HAS(r.out, "956 bytes follow IEND at byte offset 956");
    EXPECT_EQ(r.out.find("no end chunk"), std::string::npos) << r.out;
    r = run_spt(d, {"verify", input("appended_copy.spt")});
    EXPECT_EQ(r.code, 1);
    r = run_spt(d, {"render", input("appended_copy.spt"), "-o", d.file("o.####.png")});
    EXPECT_EQ(r.code, 0) << "every frame renders: " << r.err;
    EXPECT_HAS(r.err, "warning");
    EXPECT_EQ(names(d).size(), 5u);
}

TEST(HostileCli, AHugeStrokeCountNamesTheStrokeLimit) {
    TempDir d;
    auto r = run_spt(d, {"verify", input("huge_stroke_count.spt")});
    EXPECT_TRUE(
        failed_with(r, 1, {"frame 0 (FRAM chunk at byte offset 438)", "134217728 strokes exceed the stroke limit of"}));
    r = run_spt(d, {"render", input("huge_stroke_count.spt"), "-o", d.file("o.####.png")});
    EXPECT_TRUE(failed_with(r, 1, {"wrote 2 of 5 frames"}));  // frames 1-2 need frame 0; 3 is a key frame
    EXPECT_EQ(names(d), (Names{"o.0003.png", "o.0004.png"}));
}

TEST(HostileCli, LyingHeadersAndChunkLengthsFailBeforeAllocatingAndWriteNothing) {
    const std::pair<const char*, const char*> cases[] = {
        {"head_huge_canvas.spt", "canvas 2147483648x2147483648 exceeds the limits"},
        {"tmpl_length_past_end.spt", "chunk 'TMPL' at byte offset 376 claims 2147483632 bytes"},
    };
    for (const auto& [file, what] : cases) {
        TempDir d;
        for (const std::vector<std::string>& cmd :
             {std::vector<std::string>{"verify", input(file)}, {"info", input(file)},
              {"render", input(file), "-o", d.file("o.####.png")}, {"pack", input(file), "-o", d.file("o.spt")},
              {"export", input(file), "-o", d.file("o.json")}}) {
            auto r = run_spt(d, cmd);
            EXPECT_TRUE(failed_with(r, 1, {what})) << cmd[0] << " " << file;
        }
        EXPECT_EQ(names(d), Names{}) << file;
    }
}

// ---- text that is not UTF-8 ----

TEST(HostileCli, InvalidUtf8IsRefusedAtImportAndExport) {
    TempDir d;
    auto r = run_spt(d, {"import", input("strokes_bad_utf8.json"), "-o", d.file("o.spt")});
    EXPECT_TRUE(failed_with(
        r, 1, {"strokes_bad_utf8.json:1:105: the value of key \"title\" in \"metadata\" is not valid UTF-8"}));
    r = run_spt(d, {"export", input("meta_not_utf8.spt"), "-o", d.file("o.json")});
    EXPECT_TRUE(failed_with(r, 1, {"metadata key \"painter.seed\" holds bytes that are not UTF-8"}));
    EXPECT_EQ(names(d), Names{});
}

TEST(HostileCli, SvgCanvasOf1e93IsNamedAsItIs) {
    TempDir d;
    auto r = run_spt(d, {"import", input("svg_1e93.svg"), "-o", d.file("o.spt")});
    EXPECT_TRUE(failed_with(r, 1, {"canvas 1e+93x10 is above the limits"}));
    EXPECT_EQ(names(d), Names{});
}

// ---- an export that import could not read back ----

// spt export refused JSON above spt import's 256 MiB input limit only by a check nothing
// tested. A 16384x16384 canvas has 2048x2048 motion blocks of 8 pixels; a field whose every
// vector equals its prediction codes as one run (SPEC.md 7.5), but exports as about 109 MB of
// "[-2047.9375, -2047.9375], ". Three such frames make a file of a few hundred bytes whose JSON
// is about 327 MB: the refusal is exercised without writing the limit's worth to disk.
TEST(HostileCli, ExportRefusesJsonThatImportCouldNotReadBack) {
    TempDir d;
    const std::string big = d.file("big.spt");
    {
        spt::StreamInfo info = test_info();
        info.header.width = info.header.height = 16384;
        auto w = spt::Writer::create(big, info);
        ASSERT_TRUE(w.ok()) << w.error().message;
        spt::Frame key;
        ASSERT_TRUE((*w)->append(key).ok());
        for (uint32_t i = 1; i <= 3; ++i) {
            spt::Frame f;
            f.index = i;
            f.type = spt::FrameType::Inter;
            f.motion.block_size = 8;
            f.motion.cols = f.motion.rows = 2048;
            f.motion.vectors.assign(size_t(2048) * 2048, {int16_t(-32767), int16_t(-32767)});
            auto s = (*w)->append(f);
            ASSERT_TRUE(s.ok()) << s.error().message;
        }
        ASSERT_TRUE((*w)->finish().ok());
    }
    ASSERT_LT(fs::file_size(big), 4096u) << "the crafted file should be small";
    const size_t limit = size_t(256) << 20;
    auto r = run_spt(d, {"export", big, "-o", d.file("o.json")});
    EXPECT_TRUE(failed_with(r, 1, {d.file("o.json") + ": the JSON would be ",
                                   "bytes, above the " + std::to_string(limit) + " that spt import reads back; nothing written"}));
    EXPECT_EQ(names(d), Names{"big.spt"});
}

// ---- outputs: symlinks, folders ----

// Every command that writes a file, as {args before the output, the output name, args after}.
struct Writing {
    const char* what;
    std::vector<std::string> before;
    std::string out;
    std::vector<std::string> after;
};
std::vector<Writing> writing_commands() {
    return {
        {"paint", {"paint", input("good.png"), "-o"}, "o.spt", {"--max-strokes", "50"}},
        {"paint --preview", {"paint", input("good.png"), "-o", "SCRATCH.spt", "--max-strokes", "50", "--preview"}, "o.png", {}},
        {"import", {"import", input("strokes_min.json"), "-o"}, "o.spt", {}},
        {"pack", {"pack", golden("inter_motion.stored.spt"), "-o"}, "o.spt", {}},
        {"export json", {"export", golden("inter_motion.spt"), "-o"}, "o.json", {}},
        {"export svg", {"export", golden("inter_motion.spt"), "--frames", "2", "-o"}, "o.svg", {}},
        {"render", {"render", golden("inter_motion.spt"), "-o"}, "o.png", {}},
        {"render exr of a 1.3 file", {"render", golden("linear_alpha.spt"), "-o"}, "o.exr", {}},
        {"cat", {"cat", golden("inter_motion.spt"), golden("inter_motion.stored.spt"), "-o"}, "o.spt", {}},
        {"plan", {"plan", std::string(SPT_MEDIA_DIR) + "/exr/orbit/orbit.####.exr", "--frames", "1-3", "-o"}, "o.plan.json", {}},
    };
}
std::vector<std::string> args_of(const Writing& w, const TempDir& d, const std::string& out) {
    std::vector<std::string> a;
    for (const auto& s : w.before) a.push_back(s == "SCRATCH.spt" ? d.file("scratch.spt") : s);
    a.push_back(out);
    a.insert(a.end(), w.after.begin(), w.after.end());
    return a;
}

// Issue 20 item 3: "ln -s victim.txt o.spt.partial" made spt overwrite victim.txt.
TEST(HostileCli, SymlinksAtOutputNamesAreNeverFollowed) {
    for (const Writing& w : writing_commands()) {
        TempDir d;
        { std::ofstream(d.file("victim.txt")) << "victim"; }
        fs::create_symlink("victim.txt", d.path / (w.out + ".partial"));
        fs::create_symlink("victim.txt", d.path / w.out);
        auto r = run_spt(d, args_of(w, d, d.file(w.out)));
        EXPECT_EQ(r.code, 0) << w.what << ": " << r.err;
        EXPECT_EQ(slurp(d.file("victim.txt")), "victim") << w.what;
        EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(d.path / w.out))) << w.what << ": the output is still a symlink";
        Names want{"victim.txt", w.out, w.out + ".partial"};
        if (w.what == std::string("paint --preview")) want.push_back("scratch.spt");
        std::sort(want.begin(), want.end());
        EXPECT_EQ(names(d), want) << w.what;
    }
}

TEST(HostileCli, MissingAndReadOnlyFoldersFailNamingThePathAndLeaveNothing) {
    for (const Writing& w : writing_commands()) {
        TempDir d;
        auto r = run_spt(d, args_of(w, d, d.file("missing/" + w.out)));
        EXPECT_TRUE(failed_with(r, 1, {d.file("missing/" + w.out)})) << w.what;
        EXPECT_EQ(names(d), Names{}) << w.what;
        // Read-only: a mode-0555 folder, or for root (who writes anywhere) /proc/self.
        std::string ro = "/proc/self";
        if (::geteuid() != 0) {
            fs::create_directories(d.path / "ro");
            ::chmod((d.path / "ro").c_str(), 0555);
            ro = d.file("ro");
        }
        r = run_spt(d, args_of(w, d, ro + "/" + w.out));
        EXPECT_TRUE(failed_with(r, 1, {ro + "/" + w.out})) << w.what << " into " << ro;
        if (::geteuid() != 0) {
            EXPECT_TRUE(fs::is_empty(d.path / "ro")) << w.what;
            ::chmod((d.path / "ro").c_str(), 0755);
            fs::remove(d.path / "ro");
        }
        EXPECT_EQ(names(d), Names{}) << w.what;
    }
}

// A folder as output was refused only after the whole paint, the path printed twice.
TEST(HostileCli, AnOutputThatIsAFolderIsRefusedFirstAndNamedOnce) {
    TempDir d;
    fs::create_directories(d.path / "out.spt");
    auto r = run_spt(d, {"paint", input("good.png"), "-o", d.file("out.spt")});
    EXPECT_TRUE(failed_with(r, 1, {"is a folder"}));
    EXPECT_EQ(count(r.err, d.file("out.spt")), 1u) << r.err;
    EXPECT_EQ(r.err.find("strokes"), std::string::npos) << "refused after painting: " << r.err;
    EXPECT_EQ(names(d), Names{"out.spt"});
    EXPECT_TRUE(fs::is_empty(d.path / "out.spt"));
}

// --preview x.xyz failed with exit 1 but left OUT.spt.
TEST(HostileCli, AnUnwritablePreviewIsRefusedBeforeTheSptIsWritten) {
    TempDir d;
    auto r = run_spt(d, {"paint", input("good.png"), "-o", d.file("o.spt"), "--preview", d.file("x.xyz")});
    EXPECT_TRUE(failed_with(r, 1, {"--preview " + d.file("x.xyz")}));
    EXPECT_EQ(names(d), Names{});
}

// spt paint --target-bytes coded its trials to the fixed name OUT.rate-search: two paints into
// one folder, or a user's file of that name, collided, and the user's file was deleted. The
// trials now go to an unnamed file: whatever has that name is untouched, nothing else appears.
TEST(HostileCli, ATargetSizePaintLeavesOtherNamesAlone) {
    // The 8-bit painter, the cartoon painter, and the alpha / scene-linear (format 1.3) painter.
    const std::vector<std::vector<std::string>> paints = {
        {"--style", "painterly"}, {"--style", "cartoon"}, {"--alpha", "on", "--color-encoding", "linear"}};
    for (const auto& how : paints) {
        const std::string style = how[1] == "on" ? "linear alpha" : how[1];
        TempDir d;
        { std::ofstream(d.file("o.spt.rate-search")) << "mine"; }
        fs::create_symlink("victim.txt", d.path / "o.spt.partial");
        std::vector<std::string> args = {"paint", input("good.png"), "-o", d.file("o.spt"), "--target-bytes", "700"};
        args.insert(args.end(), how.begin(), how.end());
        auto r = run_spt(d, args);
        ASSERT_EQ(r.code, 0) << style << ": " << r.err;
        EXPECT_EQ(slurp(d.file("o.spt.rate-search")), "mine") << style;
        EXPECT_EQ(names(d), (Names{"o.spt", "o.spt.partial", "o.spt.rate-search"})) << style;
        EXPECT_FALSE(fs::exists(d.path / "victim.txt")) << style;
        // The trials were measured: the still painter's search reports the size of the best
        // trial, which the final paint (the same lambda) reproduces byte for byte.
        if (style == "painterly")
            EXPECT_HAS(r.err, "gives " + std::to_string(fs::file_size(d.path / "o.spt")) + " bytes");
        EXPECT_EQ(run_spt(d, {"verify", d.file("o.spt")}).code, 0) << style;
    }
}

// spt paint --plan without --shot painted its shots into the fixed folder OUT.shots.partial,
// deleting whatever had that name first. The shots now go to a fresh mkdtemp folder.
TEST(HostileCli, PaintingAPlanLeavesOtherNamesAlone) {
    TempDir d;
    auto r = run_spt(d, {"plan", std::string(SPT_MEDIA_DIR) + "/exr/orbit/orbit.####.exr", "--frames", "1-4",
                         "--max-task-frames", "2", "-o", d.file("p.json")});
    ASSERT_EQ(r.code, 0) << r.err;
    fs::create_directories(d.path / "o.spt.shots.partial");
    { std::ofstream(d.file("o.spt.shots.partial/mine")) << "mine"; }
    r = run_spt(d, {"paint", "--plan", d.file("p.json"), "-o", d.file("o.spt")});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(slurp(d.file("o.spt.shots.partial/mine")), "mine");
    EXPECT_EQ(names(d), (Names{"o.spt", "o.spt.shots.partial", "p.json"}));
    EXPECT_EQ(run_spt(d, {"verify", d.file("o.spt")}).code, 0);
}

// ---- signals ----

// Killed mid-paint (SIGKILL cannot be caught; SIGINT's default ends the process): the output
// was an unnamed file, so nothing at all is left.
TEST(HostileCli, AKilledPaintLeavesNothing) {
    for (int sig : {SIGKILL, SIGINT, SIGTERM}) {
        TempDir d;
        const std::string img = noise_image(d);
        int code = 0;
        const bool signalled = run_and_signal({"paint", img, "-o", d.file("o.spt"), "--preview", d.file("p.png"),
                                               "--max-strokes", "16000000", "--target-psnr", "90", "--threads", "1"},
                                              sig, std::chrono::milliseconds(1000), &code);
        EXPECT_TRUE(signalled) << "signal " << sig << ": the paint ended by itself (exit " << code << ")";
        EXPECT_EQ(names(d), Names{"noise.png"}) << "signal " << sig;
    }
    // Killed in the trials of a rate search: they had no name either.
    TempDir d;
    const std::string img = noise_image(d);
    int code = 0;
    EXPECT_TRUE(run_and_signal({"paint", img, "-o", d.file("o.spt"), "--max-strokes", "16000000", "--target-bytes", "4000000",
                                "--threads", "1"},
                               SIGKILL, std::chrono::milliseconds(1000), &code))
        << "the paint ended by itself (exit " << code << ")";
    EXPECT_EQ(names(d), Names{"noise.png"});
}
