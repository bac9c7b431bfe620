// Rendering work bounded per file (issue 36, item 4): a few KB of canvas-sized translucent
// affine strokes in one key frame, then empty inter frames. Every empty frame was rendered
// again from scratch (30 renders), and a frame near the per-frame fill limit could take
// minutes. Now a still frame keeps the picture drawn before it, and a file whose frames
// would need more fill work than its budget (SPEC.md B.7) is refused before it is drawn.
#include <chrono>

#include "converter/cli_test_util.hpp"
#include "spt/spt.hpp"

using namespace spt_test;

namespace {

// A range-coded side x side file of one ellipse template: `key`, then 29 empty inter frames.
std::string key_then_empty(const TempDir& d, const std::string& name, uint32_t side, const spt::Frame& key) {
    spt::StreamInfo info;
    info.header.width = info.header.height = side;
    info.header.sets = {{4, 4}};
    info.header.orientations = spt::default_orientations(1);
    info.header.fps = {24, 1};
    info.templates.resize(1);
    info.templates[0].kind = spt::TemplateKind::Ellipse;
    spt::WriterOptions o;
    o.coding = spt::Coding::Range;
    const std::string path = d.file(name);
    auto w = spt::Writer::create(path, info, o);
    EXPECT_TRUE(w.ok());
    EXPECT_TRUE((*w)->append(key).ok());
    for (uint32_t i = 1; i < 30; ++i) {
        spt::Frame f;
        f.index = i;
        f.type = spt::FrameType::Inter;
        EXPECT_TRUE((*w)->append(f).ok());
    }
    EXPECT_TRUE((*w)->finish().ok());
    return path;
}

// One key frame of `strokes` half-transparent affine ellipses covering a side x side canvas,
// then 29 empty inter frames, range-coded (the file: about 15 KB).
std::string still_file(const TempDir& d, const std::string& name, uint32_t side, int strokes) {
    spt::Frame key;
    for (int i = 0; i < strokes; ++i) {
        spt::AffineStroke a;
        a.tx = a.ty = int32_t(side * 8);  // the centre, Q4
        a.a = a.d = int32_t(side * 8);    // reaching every edge
        a.color = {uint8_t(i * 37), uint8_t(i * 11), 200, 128};
        key.added.push_back(spt::Stroke::make_affine(a));
    }
    return key_then_empty(d, name, side, key);
}

// run_spt, timed.
RunResult timed(const TempDir& d, const std::vector<std::string>& args, double* seconds) {
    const auto t0 = std::chrono::steady_clock::now();
    RunResult r = run_spt(d, args);
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("spt %s: %.2f s\n", args[0].c_str(), *seconds);
    return r;
}

}  // namespace

// 8,000 strokes on 256x256 (2^29 units, within the file's budget): one render, not 30.
TEST(HostileRenderWork, StillFramesAfterAHeavyKeyFrameAreNotRenderedAgain) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string in = still_file(d, "still.spt", 256, 8000);
    double s = 0;
    auto r = timed(d, {"verify", in}, &s);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("OK, 30 frames"), std::string::npos) << r.out;
    EXPECT_LT(s, 20.0) << "spt verify renders every still frame again";
    r = timed(d, {"render", in, "-o", d.file("f####.png")}, &s);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_LT(s, 20.0) << "spt render renders every still frame again";
    ASSERT_TRUE(fs::exists(d.file("f0029.png")));
    EXPECT_EQ(slurp(d.file("f0000.png")), slurp(d.file("f0029.png")));
}

// The scale: 8,000 strokes on 1024x1024 (2^33 units, 18.6 s a frame there) in about
// 20 KB, over the file's budget (2^30 + 2^18 a byte): refused before anything is drawn,
// naming the file and the frame; render writes nothing.
TEST(HostileRenderWork, AFileOverItsFillBudgetIsRefusedBeforeItIsDrawn) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string in = still_file(d, "heavy.spt", 1024, 8000);
    const std::string said = in + ": frame 0 (FRAM chunk at byte offset ";
    const std::string why = "units of rendering work";
    double s = 0;
    auto r = timed(d, {"verify", in}, &s);
    EXPECT_TRUE(failed_with(r, 1, {said, why, "the limit for a file of"}));
    EXPECT_LT(s, 5.0);
    r = timed(d, {"render", in, "-o", d.file("f####.png")}, &s);
    EXPECT_TRUE(failed_with(r, 1, {said, why, "wrote 0 of 30 frames"}));
    EXPECT_LT(s, 5.0);
    EXPECT_FALSE(fs::exists(d.file("f0000.png")));
}

namespace {

// One key frame of `n` canvas-tall quadrilaterals on a 1024x1024 canvas sampled 16 x 16 (2 edges
// x 1024 rows x 256 samples: 2^19 units of polygon work each), then 29 empty inter frames.
std::string polygon_file(const TempDir& d, const std::string& name, int n, bool curves = false) {
    spt::Frame key;
    for (int i = 0; i < n && curves; ++i) {
        // 63 segments from corner to corner: each one's box is the canvas (2^20 units).
        spt::CurveStroke c;
        c.color = {uint8_t(i * 37), uint8_t(i * 11), 200, 128};
        for (int k = 0; k < 64; ++k) c.points.push_back({k % 2 ? 16 * 1023 : 0, k % 2 ? 16 * 1023 : 0, 16});
        key.added.push_back(spt::Stroke::make_curve(c));
    }
    for (int i = 0; i < n && !curves; ++i) {
        spt::PolygonStroke p;
        p.color = {uint8_t(i * 37), uint8_t(i * 11), 200, 128};
        p.supersample = 16;
        const int32_t x = 16 * (i % 1000), s = 16 * 1024;
        p.points = {{x, 0}, {x + 16 * 20, 0}, {x + 16 * 20, s}, {x, s}};
        key.added.push_back(spt::Stroke::make_polygon(p));
    }
    return key_then_empty(d, name, 1024, key);
}

}  // namespace

// Polygons at 94% of the per-frame limit (480 x 2^19 units, 2^27.9) in a few KB took about 19 s
// a frame; the file's polygon budget (2^26 + 2^12 a byte) refuses it before it is drawn.
// 100 of them (2^25.6, within the base) still verify.
TEST(HostileRenderWork, AFileOverItsPolygonBudgetIsRefusedBeforeItIsDrawn) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string in = polygon_file(d, "poly.spt", 480);
    std::printf("%s: %llu bytes\n", in.c_str(), (unsigned long long)fs::file_size(in));
    double s = 0;
    auto r = timed(d, {"verify", in}, &s);
    EXPECT_TRUE(failed_with(r, 1, {in + ": frame 0 (FRAM chunk at byte offset ", "the file's polygons past",
                                   "the limit for a file of"}));
    EXPECT_LT(s, 5.0);
    r = timed(d, {"render", in, "-o", d.file("f####.png")}, &s);
    EXPECT_TRUE(failed_with(r, 1, {"the file's polygons past", "wrote 0 of 30 frames"}));
    EXPECT_LT(s, 5.0);
    const std::string ok = polygon_file(d, "fewer.spt", 100);
    r = timed(d, {"verify", ok}, &s);
    EXPECT_EQ(r.code, 0) << r.err;
}

// Curves likewise: 60 curves of 63 canvas-sized segments (2^31.9 units of curve work, under the
// per-frame 2^33) over the file's curve budget (2^31 + 2^12 a byte); 20 of them verify.
TEST(HostileRenderWork, AFileOverItsCurveBudgetIsRefusedBeforeItIsDrawn) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string in = polygon_file(d, "curves.spt", 60, true);
    std::printf("%s: %llu bytes\n", in.c_str(), (unsigned long long)fs::file_size(in));
    double s = 0;
    auto r = timed(d, {"verify", in}, &s);
    EXPECT_TRUE(failed_with(r, 1, {in + ": frame 0 (FRAM chunk at byte offset ", "the file's curves past",
                                   "the limit for a file of"}));
    EXPECT_LT(s, 5.0);
    r = timed(d, {"verify", polygon_file(d, "fewer.spt", 20, true)}, &s);
    EXPECT_EQ(r.code, 0) << r.err;
}
