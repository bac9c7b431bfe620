// The built `spt paint` on real media: outputs exist and decode, usage errors exit 2, and the
// file bytes do not depend on --threads.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "io/image_io.hpp"
#include "spt/reader.hpp"
#include "spt/render.hpp"

namespace fs = std::filesystem;
using namespace spt;

namespace {

const std::string kTool = SPT_TOOL;
// Per process: CTest runs every test case as its own process, several at once, and they all
// write stdout.txt/stderr.txt here.
const fs::path kOut = fs::path(SPT_BINARY_DIR) / ("paint_cli_test_out." + std::to_string(::getpid()));
struct RemoveAtExit {
    ~RemoveAtExit() { std::error_code ec; fs::remove_all(kOut, ec); }
} remove_at_exit;

int run(const std::string& args) {
    const std::string cmd = kTool + " paint " + args + " > " + (kOut / "stdout.txt").string() + " 2> " +
                            (kOut / "stderr.txt").string();
    const int rc = std::system(cmd.c_str());
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

// A small real still (chelsea resized), made once with the tool chain's own image writer.
std::string small_still() {
    const fs::path p = kOut / "chelsea-small.png";
    if (fs::exists(p)) return p.string();
    auto img = io::read_image(std::string(SPT_MEDIA_DIR) + "/stills/chelsea.png");
    if (!img) return {};
    const uint32_t W = img->width / 4, H = img->height / 4;
    std::vector<uint8_t> rgb(size_t(W) * H * 3);
    for (uint32_t y = 0; y < H; ++y)
        for (uint32_t x = 0; x < W; ++x)
            for (int c = 0; c < 3; ++c) rgb[(size_t(y) * W + x) * 3 + c] = img->rgb[((size_t(y) * 4) * img->width + x * 4) * 3 + c];
    if (!io::write_image(p.string(), W, H, rgb.data()).ok()) return {};
    return p.string();
}

class PaintCli : public ::testing::Test {
protected:
    void SetUp() override {
        if (kTool.empty() || !fs::exists(kTool)) GTEST_FAIL() << "spt tool not built";
        fs::create_directories(kOut);
        still_ = small_still();
        if (still_.empty()) GTEST_FAIL() << "media missing: " << SPT_MEDIA_DIR << "/stills/chelsea.png";
    }
    std::string still_;
};

}  // namespace

TEST_F(PaintCli, PaintsARealStillWithPreviewAndSideBySide) {
    const fs::path spt = kOut / "chelsea.spt", prev = kOut / "chelsea-preview.png", sbs = kOut / "chelsea-sbs.png";
    ASSERT_EQ(run(still_ + " -o " + spt.string() + " --seed 3 --preview " + prev.string() + " --side-by-side " +
                  sbs.string() + " --progress none --roi 20,20,40,30"),
              0)
        << slurp(kOut / "stderr.txt");
    auto rd = Reader::open(spt.string());
    ASSERT_TRUE(rd.ok()) << rd.error().message;
    EXPECT_TRUE((*rd)->complete());
    const StreamInfo& info = (*rd)->info();
    ASSERT_EQ(info.rois.size(), 1u);
    EXPECT_EQ(info.rois[0].x, 20u);
    bool has_seed = false;
    for (const auto& kv : info.metadata) has_seed |= kv.first == "painter.seed" && kv.second == "3";
    EXPECT_TRUE(has_seed);
    auto live = (*rd)->strokes_at(0);
    ASSERT_TRUE(live.ok());
    EXPECT_GT((*live)->size(), 100u);
    // The preview is the decoded painting.
    auto r = Renderer::create(info.header, info.templates);
    ASSERT_TRUE(r.ok());
    Canvas c(info.header.width, info.header.height);
    ASSERT_TRUE((*r)->render(c, **live).ok());
    auto pv = io::read_image(prev.string());
    ASSERT_TRUE(pv.ok());
    EXPECT_EQ(pv->rgb, c.rgb);
    auto sb = io::read_image(sbs.string());
    ASSERT_TRUE(sb.ok());
    EXPECT_EQ(sb->width, 2 * info.header.width);
}

TEST_F(PaintCli, SameSeedSameBytesForAnyThreadCount) {
    const fs::path a = kOut / "t1.spt", b = kOut / "t2.spt";
    ASSERT_EQ(run(still_ + " -o " + a.string() + " --threads 1 --progress none --max-strokes 2000 --lambda 0"), 0);
    ASSERT_EQ(run(still_ + " -o " + b.string() + " --threads 2 --progress json --max-strokes 2000 --lambda 0"), 0);
    EXPECT_EQ(slurp(a), slurp(b));
    // --progress json: one object per line, ending with an "end" event.
    const std::string out = slurp(kOut / "stdout.txt");
    EXPECT_NE(out.find("\"event\":\"end\""), std::string::npos) << out;
    EXPECT_NE(out.find("\"strokes\":2000"), std::string::npos) << out;
}

TEST_F(PaintCli, UsageErrorsExitTwoAndWorkErrorsExitOne) {
    EXPECT_EQ(run("--help"), 0);
    EXPECT_NE(slurp(kOut / "stdout.txt").find("--target-psnr"), std::string::npos);
    EXPECT_EQ(run(still_), 2);  // no -o
    EXPECT_EQ(run(still_ + " -o x.spt --sets 2"), 2);
    EXPECT_EQ(run(still_ + " -o x.spt --orient sideways"), 2);
    EXPECT_EQ(run(still_ + " -o x.spt --bogus"), 2);
    EXPECT_EQ(run(still_ + " -o x.spt --roi-file /nonexistent.json"), 2);
    EXPECT_EQ(run("/nonexistent/image.png -o " + (kOut / "x.spt").string()), 1);
    EXPECT_NE(slurp(kOut / "stderr.txt").find("/nonexistent/image.png"), std::string::npos);
    EXPECT_EQ(run("frames/f.####.png -o " + (kOut / "x.spt").string()), 1);
    EXPECT_NE(slurp(kOut / "stderr.txt").find("frames/f.####.png: folder"), std::string::npos);
    EXPECT_EQ(run(still_ + " -o " + (kOut / "x.spt").string() + " --templates /nonexistent/dir --progress none"), 1);
    EXPECT_FALSE(fs::exists(kOut / "x.spt"));
}

TEST_F(PaintCli, RoiFileIsReadAndBadOnesAreRejected) {
    const fs::path good = kOut / "rois.json", bad = kOut / "bad.json", spt = kOut / "roi.spt";
    std::ofstream(good) << R"({"rois":[{"x":5,"y":6,"w":30,"h":20},{"x":50,"y":10,"w":10,"h":10,"frames":[0,3]},{"x":1,"y":1,"w":9,"h":9,"frames":"0-2"},{"x":1,"y":1,"w":9,"h":9,"frames":"5-9"}]})";
    std::ofstream(bad) << R"({"rois":[{"x":5,"y":6,"w":0,"h":20}]})";
    ASSERT_EQ(run(still_ + " -o " + spt.string() + " --roi-file " + good.string() + " --progress none --max-strokes 500"), 0)
        << slurp(kOut / "stderr.txt");
    auto rd = Reader::open(spt.string());
    ASSERT_TRUE(rd.ok());
    ASSERT_EQ((*rd)->info().rois.size(), 3u);  // the one of frames 5-9 is not in a still
    EXPECT_EQ((*rd)->info().rois[1].w, 10u);
    EXPECT_EQ(run(still_ + " -o " + spt.string() + " --roi-file " + bad.string()), 2);
    EXPECT_NE(slurp(kOut / "stderr.txt").find("rois[0]"), std::string::npos);
}
