// retrace_outline: the regions an inter frame traced anew are traced again at coarser outlines,
// the others kept as they were, and the cheapest painting that reaches the target is kept; a
// frame that kept every region, or one painted without a target, never tries; a trial that
// loses makes the next wait longer. End to end: the star's morphing outline takes fewer bytes
// than at its interval's tolerance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <vector>

#include "cartoon/retrace_outline.hpp"
#include "converter/cli_test_util.hpp"
#include "spt/spt.hpp"

namespace {

using spt::cartoon::choose_retrace_outline;
using spt::cartoon::InterFrame;
using spt::cartoon::kRetraceFactors;
using spt::cartoon::RetraceTrials;

constexpr uint32_t kSide = 8;
const std::vector<uint8_t> kModel(kSide * kSide * 3, 100);
const spt::paint::ImageView kView{kSide, kSide, kModel.data()};

// A painted frame of `cost` estimated bytes, its canvas `error` levels off the model in every
// sample (0: exact; 10: 28.1 dB).
InterFrame painted(double cost, int error) {
    InterFrame r;
    r.cost = cost;
    r.canvas = spt::Canvas(kSide, kSide, {uint8_t(100 + error), uint8_t(100 + error), uint8_t(100 + error)});
    return r;
}

// Records the tolerances asked for (of an interval at 0.5 px) and answers 0.5 times factor i
// with answers[i].
struct FakePainter {
    std::vector<InterFrame> answers;
    std::vector<double> asked;
    spt::Result<InterFrame> operator()(double t) {
        asked.push_back(t);
        for (size_t i = 0; i < kRetraceFactors.size(); ++i)
            if (t == 0.5 * kRetraceFactors[i]) return answers.at(i);
        ADD_FAILURE() << "asked for " << t << " px";
        return answers.at(0);
    }
};

// How many paintings choose_retrace_outline asks for, for a frame at 500 estimated bytes that
// traced a region anew or not, with a target of `target` dB; each trial is cheaper.
size_t trials_asked(bool any_retraced, double target) {
    FakePainter fake{{painted(1, 0), painted(1, 0)}};
    RetraceTrials trials;
    auto r = choose_retrace_outline(painted(500, 0), any_retraced, 0.5, target, kView, trials, std::ref(fake), false);
    EXPECT_TRUE(r);
    return fake.asked.size();
}

TEST(RetraceOutline, OnlyAFrameThatRetracedARegionTriesWithATarget) {
    EXPECT_EQ(trials_asked(true, 36), kRetraceFactors.size());
    EXPECT_EQ(trials_asked(false, 36), 0u) << "every region was kept";
    EXPECT_EQ(trials_asked(true, 0), 0u) << "without a target a coarser outline must not cost quality";
}

// A polygon told apart by its red.
spt::Stroke shape(uint8_t red) {
    spt::PolygonStroke p;
    p.color = {red, 0, 0, 255};
    p.points = {{0, 0}, {160, 0}, {0, 160}};
    return spt::Stroke::make_polygon(p);
}

spt::cartoon::FillLayer layer(std::vector<std::pair<int, uint8_t>> region_and_red) {
    spt::cartoon::FillLayer f;
    for (auto [region, red] : region_and_red) {
        f.strokes.push_back(shape(red));
        f.region.push_back(region);
    }
    return f;
}

TEST(RetraceOutline, ARegionIsRetracedWhenEveryStrokeOfItWasAdded) {
    const auto traced = layer({{1, 10}, {1, 11}, {2, 20}, {4, 40}, {4, 41}});
    spt::Frame f;
    f.added = {shape(10), shape(11), shape(41)};  // region 1 whole, region 4 in part
    spt::StampStroke st;
    f.added.push_back(spt::Stroke::make_stamp(st));
    EXPECT_EQ(spt::cartoon::retraced_regions(traced, f), (std::vector<bool>{false, true, false, false, false}));
}

TEST(RetraceOutline, RetracedRegionsTakeTheCoarserStrokesInDrawingOrder) {
    const auto interval = layer({{1, 10}, {1, 11}, {2, 20}, {3, 30}, {5, 50}});
    const auto coarse = layer({{1, 110}, {2, 120}, {3, 130}, {3, 131}, {4, 140}});
    const std::vector<bool> retraced = {false, true, false, true, false, true};
    const auto mixed = spt::cartoon::with_coarser_regions(interval, coarse, retraced);
    std::vector<int> reds;
    for (const spt::Stroke& s : mixed) reds.push_back(s.polygon.color.r);
    // Region 1 coarse, 2 as it was, 3 coarse (two strokes now), 4 only coarse and not retraced:
    // left out, 5 retraced but gone at the coarser tolerance.
    EXPECT_EQ(reds, (std::vector<int>{110, 20, 130, 131}));
}

TEST(RetraceOutline, TheCheapestPaintingThatReachesTheTargetIsKept) {
    // The first factor is cheapest but misses the target (28 dB); the second reaches it for less.
    FakePainter fake{{painted(100, 10), painted(300, 0)}};
    RetraceTrials trials;
    auto r = choose_retrace_outline(painted(500, 0), true, 0.5, 36, kView, trials, std::ref(fake), false);
    ASSERT_TRUE(r);
    std::sort(fake.asked.begin(), fake.asked.end());  // the first factor runs last without threads
    EXPECT_EQ(fake.asked, (std::vector<double>{0.5 * kRetraceFactors[0], 0.5 * kRetraceFactors[1]}));
    EXPECT_EQ(r->cost, 300);
    EXPECT_EQ(trials.wait, 0u) << "a trial that won: the next frame tries again";
}

TEST(RetraceOutline, ALosingTrialWaitsTwiceAsLongEachTime) {
    RetraceTrials trials;
    std::vector<int> tried_at;
    for (int frame = 0; frame < 40; ++frame) {
        FakePainter fake{{painted(900, 0), painted(900, 0)}};  // never cheaper
        auto r = choose_retrace_outline(painted(500, 0), true, 0.5, 36, kView, trials, std::ref(fake), false);
        ASSERT_TRUE(r);
        EXPECT_EQ(r->cost, 500);
        if (!fake.asked.empty()) tried_at.push_back(frame);
    }
    // Periods 2, 4, 8, 16, then 16.
    EXPECT_EQ(tried_at, (std::vector<int>{0, 2, 6, 14, 30}));
}

// The star morphs from frame 42 on: every frame retraces its fill and outline, and at 36 dB a
// coarser outline than the interval's 0.5 px often pays (frames 44-50 measured 5,286 bytes
// against 5,811 with --outline-tolerance 0.5, which tries nothing). The key frames are the same.
TEST(RetraceOutline, TheStarsMorphTakesFewerBytes) {
    spt_test::TempDir dir;
    auto paint = [&](const std::string& out, std::vector<std::string> extra) {
        std::vector<std::string> args = {"paint", std::string(SPT_MEDIA_DIR) + "/cartoon/star/f.####.png", "-o",
                                         dir.file(out), "--style", "cartoon", "--frames", "44-50", "--target-psnr",
                                         "36", "--seed", "1", "--threads", "2", "--progress", "none"};
        args.insert(args.end(), extra.begin(), extra.end());
        const auto r = spt_test::run_spt(dir, args);
        ASSERT_EQ(r.code, 0) << r.err;
        EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
    };
    paint("trials.spt", {});
    paint("fixed.spt", {"--outline-tolerance", "0.5"});
    const auto a = std::filesystem::file_size(dir.file("trials.spt")), b = std::filesystem::file_size(dir.file("fixed.spt"));
    EXPECT_LT(double(a), 0.95 * double(b)) << "--outline-tolerance 0.5: " << b << " bytes";
    auto ra = spt::Reader::open(dir.file("trials.spt"));
    auto rb = spt::Reader::open(dir.file("fixed.spt"));
    ASSERT_TRUE(ra && rb);
    EXPECT_TRUE(**(*ra)->strokes_at(0) == **(*rb)->strokes_at(0));
    const auto v = spt_test::run_spt(dir, {"verify", dir.file("trials.spt")});
    EXPECT_EQ(v.code, 0) << v.out << v.err;
    std::printf("star 44-50: %ju bytes, %ju with --outline-tolerance 0.5\n", uintmax_t(a), uintmax_t(b));
}

}  // namespace
