// `spt paint` of render output (issue 17): an orbit EXR frame (Cycles, transparent film, a
// glowing sphere up to ~21) paints with --color-encoding auto / --alpha auto into an alpha +
// scene-linear .spt that decodes transparent where the film is and keeps the glow; the bytes do
// not depend on --threads; 8-bit input without alpha still paints the plain way.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "cli_test_util.hpp"
#include "frames/scene_image.hpp"
#include "spt/color.hpp"
#include "spt/reader.hpp"

using namespace spt;
using namespace spt_test;

namespace {

const std::string kOrbit = std::string(SPT_MEDIA_DIR) + "/exr/orbit/orbit.0012.exr";

}  // namespace

TEST(PaintSceneCli, OrbitFrameBecomesAnAlphaLinearPainting) {
    ASSERT_TRUE(fs::exists(kOrbit)) << "test media missing: " << kOrbit;
    TempDir dir;
    const std::string out = dir.file("orbit.spt");
    RunResult r = run_spt(dir, {"paint", kOrbit, "-o", out, "--threads", "2", "--progress", "none"});
    ASSERT_EQ(r.code, 0) << r.err;
    auto rd = Reader::open(out);
    ASSERT_TRUE(rd.ok()) << rd.error().message;
    const Header& h = (*rd)->info().header;
    EXPECT_TRUE(h.alpha);
    EXPECT_EQ(h.color, ColorEncoding::LinearHalf);
    Canvas c(h);
    ASSERT_TRUE((*rd)->render_frame(0, c).ok());
    auto src = io::read_scene_image(kOrbit);
    ASSERT_TRUE(src.ok()) << src.error().message;
    ASSERT_EQ(src->width, h.width);
    ASSERT_TRUE(src->has_alpha);
    size_t clear_n = 0, clear_ok = 0;
    double alpha_err = 0, peak = 0, peak_src = 0, log_err = 0;
    const size_t n = size_t(h.width) * h.height;
    for (size_t i = 0; i < n; ++i) {
        const float a = src->rgba[4 * i + 3];
        if (a == 0) { ++clear_n; clear_ok += c.alpha[i] == 0; }
        alpha_err += std::abs(c.alpha[i] / 255.0 - a);
        for (int k = 0; k < 3; ++k) {
            const double v = half_to_float(c.rgb16[3 * i + k]), s = src->rgba[4 * i + k];
            peak = std::max(peak, v);
            peak_src = std::max(peak_src, s);
            log_err += std::abs(std::log2((v + 1e-3) / (s + 1e-3)));
        }
    }
    ASSERT_GT(clear_n, n / 4);
    std::printf("orbit.0012: %s; transparent source pixels painted alpha 0: %.1f%%; alpha MAE %.4f; "
                "peak %.2f (source %.2f); mean |log2| error %.3f stops\n",
                r.err.c_str(), 100.0 * clear_ok / clear_n, alpha_err / n, peak, peak_src, log_err / (3.0 * n));
    EXPECT_GT(double(clear_ok) / double(clear_n), 0.9);
    EXPECT_GT(peak, 5.0);
    EXPECT_LT(alpha_err / n, 0.05);
}

TEST(PaintSceneCli, SameBytesForAnyThreadCount) {
    ASSERT_TRUE(fs::exists(kOrbit)) << "test media missing: " << kOrbit;
    TempDir dir;
    const std::string a = dir.file("t1.spt"), b = dir.file("t3.spt");
    ASSERT_EQ(run_spt(dir, {"paint", kOrbit, "-o", a, "--threads", "1", "--progress", "none", "--seed", "5"}).code, 0);
    ASSERT_EQ(run_spt(dir, {"paint", kOrbit, "-o", b, "--threads", "3", "--progress", "none", "--seed", "5"}).code, 0);
    const std::string x = slurp(a), y = slurp(b);
    ASSERT_GT(x.size(), 200u);
    EXPECT_EQ(x, y);
}

TEST(PaintSceneCli, EightBitInputWithoutAlphaStaysPlain) {
    const std::string png = std::string(SPT_MEDIA_DIR) + "/stills/chelsea.png";
    ASSERT_TRUE(fs::exists(png)) << "test media missing: " << png;
    TempDir dir;
    const std::string out = dir.file("plain.spt");
    ASSERT_EQ(run_spt(dir, {"paint", png, "-o", out, "--max-strokes", "200", "--progress", "none"}).code, 0);
    auto rd = Reader::open(out);
    ASSERT_TRUE(rd.ok());
    EXPECT_TRUE((*rd)->info().header.plain_color());
    EXPECT_LT((*rd)->info().header.version_minor, kAlphaLinearMinorVersion);
}
