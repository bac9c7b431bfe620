// An EXR sequence with alpha (orbit: Cycles, transparent film, a torus and a glowing sphere
// moving) paints into alpha canvases in scene-linear colour: every frame decodes transparent
// where the source is, the painted matte follows the moving objects (strokes of areas that
// became transparent are removed, not left behind), the glow survives, and the bytes do not
// depend on the thread count.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "frames/scene_image.hpp"
#include "spt/color.hpp"
#include "spt/reader.hpp"
#include "video/video_encoder.hpp"
#include "video/video_paint.hpp"

using namespace spt;
using namespace spt::video;

namespace {

const std::string kPattern = std::string(SPT_MEDIA_DIR) + "/exr/orbit/orbit.####.exr";

std::string temp(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("spt_scene_video_" + std::to_string(::getpid()) + "_" + name)).string();
}

VideoPaintOptions orbit_options(const std::string& out, int threads) {
    VideoPaintOptions o;
    o.input = kPattern;
    o.output = out;
    o.frames = "1-10";
    o.color_encoding = "auto";
    o.alpha = "auto";
    o.paint.seed = 3;
    o.paint.threads = threads;
    o.install_signal_handlers = false;
    return o;
}

std::vector<char> bytes(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), {}};
}

// Centroid of the pixels at least half opaque.
bool centroid(const std::vector<float>& a, uint32_t w, uint32_t h, double& cx, double& cy) {
    double sx = 0, sy = 0, n = 0;
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x)
            if (a[size_t(y) * w + x] >= 0.5f) { sx += x; sy += y; n += 1; }
    if (n == 0) return false;
    cx = sx / n;
    cy = sy / n;
    return true;
}

struct Matte {
    double first_clear = 0, last_clear = 0, worst_clear = 1;  // share of transparent source pixels at alpha 0
    double first_shift = 0, worst_shift = 0;  // painted matte centroid against the source's, pixels
    double peak = 0;
    VideoPaintReport rep;
};

void paint_and_measure(double transparent_share, Matte& m) {
    const std::string out = temp("orbit.spt");
    io::Progress progress(io::ProgressMode::None, "paint", 0);
    VideoPaintOptions o = orbit_options(out, 2);
    if (transparent_share > 0) o.transparent_share = transparent_share;
    VideoPaintReport& rep = m.rep;
    Status st = video_paint(o, progress, &rep);
    ASSERT_TRUE(st.ok()) << st.error().message;
    auto rd = Reader::open(out);
    ASSERT_TRUE(rd.ok()) << rd.error().message;
    const Header& h = (*rd)->info().header;
    ASSERT_TRUE(h.alpha);
    ASSERT_EQ(h.color, ColorEncoding::LinearHalf);
    ASSERT_EQ((*rd)->frames().size(), 10u);
    Canvas c(h);
    double& worst_clear = m.worst_clear;
    double& worst_shift = m.worst_shift;
    double& peak = m.peak;
    for (uint32_t f = 0; f < 10; ++f) {
        ASSERT_TRUE((*rd)->render_frame(f, c).ok());
        char name[64];
        std::snprintf(name, sizeof name, "/exr/orbit/orbit.%04u.exr", f + 1);
        auto src = io::read_scene_image(std::string(SPT_MEDIA_DIR) + name);
        ASSERT_TRUE(src.ok()) << src.error().message;
        const size_t n = size_t(h.width) * h.height;
        std::vector<float> sa(n), pa(n);
        size_t clear = 0, clear_ok = 0;
        for (size_t i = 0; i < n; ++i) {
            sa[i] = src->rgba[4 * i + 3];
            pa[i] = c.alpha[i] / 255.0f;
            if (sa[i] == 0) { ++clear; clear_ok += c.alpha[i] == 0; }
            for (int k = 0; k < 3; ++k) peak = std::max(peak, double(half_to_float(c.rgb16[3 * i + k])));
        }
        double sx, sy, px, py;
        ASSERT_TRUE(centroid(sa, h.width, h.height, sx, sy));
        ASSERT_TRUE(centroid(pa, h.width, h.height, px, py));
        if (std::getenv("SPT_TEST_VERBOSE")) std::printf("frame %u: clear %.3f shift %.2f\n", f, double(clear_ok) / double(clear), std::hypot(sx - px, sy - py));
        const double share = double(clear_ok) / double(clear), shift = std::hypot(sx - px, sy - py);
        if (f == 0) { m.first_clear = share; m.first_shift = shift; }
        m.last_clear = share;
        worst_clear = std::min(worst_clear, share);
        worst_shift = std::max(worst_shift, shift);
    }
    std::printf("orbit 1-10: %llu bytes, %llu strokes added, %llu removed; worst frame: %.1f%% of the transparent "
                "source pixels alpha 0, matte centroid %.2f px off; peak %.1f\n",
                (unsigned long long)rep.bytes, (unsigned long long)rep.strokes_added,
                (unsigned long long)rep.strokes_removed, 100 * worst_clear, worst_shift, peak);
    std::filesystem::remove(out);
}

}  // namespace

TEST(SceneVideo, OrbitAlphaFollowsTheObjects) {
    ASSERT_TRUE(std::filesystem::exists(std::string(SPT_MEDIA_DIR) + "/exr/orbit/orbit.0001.exr"))
        << "test media missing: " << kPattern;
    Matte m;
    paint_and_measure(0, m);
    // Inter frames stay as clear as the key frame and the matte does not trail the objects.
    EXPECT_GT(m.first_clear, 0.97);
    EXPECT_GE(m.worst_clear, m.first_clear - 0.005);
    EXPECT_LT(m.worst_shift, m.first_shift + 1.0);
    EXPECT_GT(m.peak, 5.0);
    EXPECT_LT(m.peak, 40.0);  // the source peaks at ~21; no colour runs away
}

// A disc over a transparent background that vanishes: its strokes must go (over-compositing
// can only add alpha, so only removal clears it).
TEST(SceneVideo, StrokesOfAreasThatBecameTransparentDoNotLinger) {
    const uint32_t W = 64, H = 48;
    auto run = [&](double share) {
        VideoPaintOptions o;
        o.output = temp("vanish.spt");
        o.sets = 4;
        o.paint.seed = 5;
        o.paint.threads = 1;
        o.paint.lambda = 2;
        o.detect_cuts = false;
        o.repaint_key_fraction = 1.0;
        o.install_signal_handlers = false;
        o.scene.alpha = true;
        o.transparent_share = share;
        auto enc = VideoEncoder::create(o, W, H, Rational{24, 1});
        EXPECT_TRUE(enc.ok()) << enc.error().message;
        double left = 1;
        if (!enc.ok()) return left;
        for (int f = 0; f < 7; ++f) {
            std::vector<uint8_t> rgb(size_t(W) * H * 3, 0), alpha(size_t(W) * H, 0);
            for (uint32_t y = 0; y < H; ++y)
                for (uint32_t x = 0; x < W; ++x) {
                    const double cx = 20 + 2 * f, cy = 24;
                    if (f >= 4 || std::hypot(x + 0.5 - cx, y + 0.5 - cy) > 10) continue;
                    const size_t i = size_t(y) * W + x;
                    alpha[i] = 255;
                    rgb[3 * i] = 220; rgb[3 * i + 1] = 120; rgb[3 * i + 2] = 40;
                }
            auto r = (*enc)->add_frame(rgb.data(), alpha.data(), nullptr, f);
            EXPECT_TRUE(r.ok()) << r.error().message;
            if (!r.ok()) return left;
            EXPECT_EQ(r->type, f == 0 ? FrameType::Key : FrameType::Inter) << f;
            size_t opaque = 0;
            for (uint8_t a : (*enc)->canvas().alpha) opaque += a > 16;
            left = double(opaque) / double(W * H);
        }
        EXPECT_TRUE((*enc)->finish().ok());
        std::filesystem::remove(o.output);
        return left;
    };
    const double with_removal = run(VideoPaintOptions{}.transparent_share), without = run(10.0);
    std::printf("vanished disc: %.1f%% of the canvas still opaque with removal, %.1f%% without\n",
                100 * with_removal, 100 * without);
    EXPECT_GT(without, 0.05);  // the disc (10% of the canvas) lingers without removal
    EXPECT_LT(with_removal, 0.01);
}

TEST(SceneVideo, SameBytesForAnyThreadCount) {
    ASSERT_TRUE(std::filesystem::exists(std::string(SPT_MEDIA_DIR) + "/exr/orbit/orbit.0001.exr"))
        << "test media missing: " << kPattern;
    const std::string a = temp("t1.spt"), b = temp("t3.spt");
    io::Progress progress(io::ProgressMode::None, "paint", 0);
    VideoPaintOptions oa = orbit_options(a, 1), ob = orbit_options(b, 3);
    oa.frames = ob.frames = "1-5";
    ASSERT_TRUE(video_paint(oa, progress).ok());
    ASSERT_TRUE(video_paint(ob, progress).ok());
    const auto x = bytes(a), y = bytes(b);
    ASSERT_GT(x.size(), 500u);
    EXPECT_EQ(x, y);
    std::filesystem::remove(a);
    std::filesystem::remove(b);
}
