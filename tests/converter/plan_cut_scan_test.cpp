// spt plan's sampled cut scan (plan/sampled_cuts.hpp) finds the cuts the full scan finds on the
// real clips and on sequences cut together from the shared media (cuts at and between samples,
// a cut right after another, cuts near the start and the end, a cut inside a source clip), for
// several steps and thread counts; and the limit the README states, shown: a flash or an insert
// shorter than the step that falls between two samples of one shot is not seen.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>
#include "frames/ffmpeg_video.hpp"

#include "io/image_io.hpp"
#include "io/progress.hpp"
#include "plan/planner.hpp"
#include "temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using spt_test::TempDir;

const std::string kMedia = SPT_MEDIA_DIR;

std::vector<long> cuts_of(const std::string& input, bool full, int step, int threads, uint64_t* decoded = nullptr,
                          int history = 4) {
    spt::plan::PlanOptions o;
    o.input = input;
    o.cut_scan = full ? spt::plan::CutScan::Full : spt::plan::CutScan::Sampled;
    o.cut_step = step;
    o.cut_history = history;
    o.threads = threads;
    spt::io::Progress progress(spt::io::ProgressMode::None, "plan", 0);
    spt::plan::PlanStats stats;
    auto p = spt::plan::make_plan(o, progress, &stats);
    EXPECT_TRUE(p.ok()) << input << ": " << (p.ok() ? "" : p.error().message);
    if (!p.ok()) return {};
    if (decoded) *decoded = stats.decoded;
    return p->cuts;
}

std::string str(const std::vector<long>& v) {
    std::string s;
    for (long x : v) s += std::to_string(x) + " ";
    return s;
}

// Source clips made alike (480x270 RGB PNG) from the shared media: name -> frame files.
class Pool {
public:
    explicit Pool(const fs::path& dir) : dir_(dir) {
        fs::create_directories(dir);
        spt::video::FfmpegVideo cap;
        EXPECT_TRUE(cap.open(kMedia + "/video/city.mpg").ok()) << "the shared media are needed: " << kMedia;
        cv::Mat f;
        long n = 0;
        while (*cap.next(n, f)) add("city", f);  // its own hard cut at frame 116
        for (int i = 1; i <= 48; ++i) add_file("earth", frame_name("exr/earth/earth.", i, ".exr"));
        for (int i = 1; i <= 24; ++i) add_file("orbit", frame_name("exr/orbit/orbit.", i, ".exr"));
        for (int i = 0; i <= 60; ++i) add_file("taffy", frame_name("cartoon/taffy/f.", i, ".png"));
        for (int i = 0; i <= 60; ++i) add_file("star", frame_name("cartoon/star/f.", i, ".png"));
        // Static shots: one file, 100 frames.
        for (const char* s : {"stills/coffee.png", "stills/astronaut.png", "stills/kodim07.tif"}) {
            const std::string name = fs::path(s).stem().string();
            add_file(name, kMedia + "/" + s);
            clips_[name].resize(100, clips_[name].front());
        }
        add("white", cv::Mat(270, 480, CV_8UC3, cv::Scalar(255, 255, 255)));
    }
    const std::vector<fs::path>& operator[](const std::string& name) const { return clips_.at(name); }

private:
    static std::string frame_name(const char* head, int i, const char* tail) {
        char b[32];
        std::snprintf(b, sizeof b, "%04d", i);
        return kMedia + "/" + head + b + tail;
    }
    void add_file(const std::string& name, const std::string& path) {
        auto img = spt::io::read_image(path);
        ASSERT_TRUE(img.ok()) << path;
        cv::Mat rgb(int(img->height), int(img->width), CV_8UC3, img->rgb.data()), bgr;
        cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
        add(name, bgr);
    }
    void add(const std::string& name, const cv::Mat& bgr) {
        cv::Mat m;
        cv::resize(bgr, m, cv::Size(480, 270), 0, 0, cv::INTER_AREA);
        auto& v = clips_[name];
        const fs::path p = dir_ / (name + "." + std::to_string(v.size()) + ".png");
        cv::Mat rgb;
        cv::cvtColor(m, rgb, cv::COLOR_BGR2RGB);
        ASSERT_TRUE(spt::io::write_image(p.string(), uint32_t(rgb.cols), uint32_t(rgb.rows), rgb.data).ok());
        v.push_back(p);
    }
    fs::path dir_;
    std::map<std::string, std::vector<fs::path>> clips_;
};

struct Segment {
    std::string clip;
    int from, count;  // frames from..from+count-1 of the clip
};

// A sequence numbered from `first` made of the segments (symlinks into the pool).
std::string cut_together(const TempDir& d, const Pool& pool, const std::string& name, long first,
                         const std::vector<Segment>& segs) {
    const fs::path dir = d.path / name;
    fs::create_directories(dir);
    long n = first;
    for (const Segment& s : segs)
        for (int i = 0; i < s.count; ++i) {
            char b[32];
            std::snprintf(b, sizeof b, "s.%05ld.png", n++);
            fs::create_symlink(pool[s.clip].at(size_t(s.from + i)), dir / b);
        }
    return (dir / "s.#####.png").string();
}

TEST(PlanCutScan, SampledFindsTheFullScansCutsOnRealClips) {
    for (const char* clip : {"video/city.mpg", "video/butterfly-cartoon.avi"}) {
        const std::string in = kMedia + "/" + clip;
        const std::vector<long> full = cuts_of(in, true, 1, 2);
        for (int step : {4, 8, 16, 32})
            for (int history : {4, 12})
                EXPECT_EQ(str(cuts_of(in, false, step, 2, nullptr, history)), str(full))
                    << clip << " step " << step << " history " << history;
        if (std::string(clip) == "video/city.mpg") EXPECT_EQ(str(full), "0 116 ") << "city.mpg's hard cut";
    }
    // The EXR sequences and a cartoon, as sequences (read by position, not in order).
    for (const char* seq : {"exr/earth/earth.####.exr", "exr/orbit/orbit.####.exr", "cartoon/taffy/f.####.png"}) {
        const std::string in = kMedia + "/" + seq;
        const std::vector<long> full = cuts_of(in, true, 1, 2);
        for (int step : {4, 16}) EXPECT_EQ(str(cuts_of(in, false, step, 2)), str(full)) << seq << " step " << step;
    }
}

TEST(PlanCutScan, SampledFindsTheFullScansCutsOnSequencesCutTogether) {
    TempDir d;
    const Pool pool(d.path / "pool");
    ASSERT_FALSE(HasFailure());
    struct Case {
        const char* name;
        long first;
        std::vector<Segment> segs;
    };
    const std::vector<Case> cases = {
        // city.mpg whole (its own cut), then cuts on a sample (frame 192 of step 16) and between.
        {"clips", 2, {{"city", 0, 190}, {"earth", 0, 48}, {"taffy", 5, 37}, {"orbit", 0, 24}, {"coffee", 0, 21}}},
        // Cuts right after cuts: shots of 1, 2, 3, 4 and 5 frames between different shots.
        {"short", 1001, {{"earth", 0, 30}, {"taffy", 0, 1}, {"orbit", 0, 2}, {"astronaut", 0, 3}, {"star", 0, 4},
                         {"city", 20, 5}, {"kodim07", 0, 30}, {"taffy", 10, 3}, {"earth", 20, 28}}},
        // Cuts near the start and the end.
        {"ends", 0, {{"orbit", 0, 1}, {"earth", 0, 2}, {"taffy", 0, 3}, {"city", 30, 40}, {"star", 0, 2}, {"coffee", 0, 1}}},
        {"ends2", 7, {{"star", 0, 3}, {"city", 120, 50}, {"orbit", 3, 20}, {"earth", 0, 1}}},
        // A white shot (a flash of several frames) that covers a sample, and hard cuts into and out
        // of flat white frames.
        {"flash", 0, {{"city", 0, 60}, {"white", 0, 1}, {"white", 0, 1}, {"white", 0, 1}, {"white", 0, 1},
                      {"white", 0, 1}, {"city", 65, 40}, {"white", 0, 1}, {"taffy", 0, 30}}},
    };
    for (const Case& c : cases) {
        const std::string in = cut_together(d, pool, c.name, c.first, c.segs);
        uint64_t all = 0, read = 0;
        const std::vector<long> full = cuts_of(in, true, 1, 2, &all);
        EXPECT_GE(full.size(), 2u) << c.name << ": the full scan should see these cuts: " << str(full);
        for (int step : {8, 16, 32})
            for (int threads : {1, 2}) {
                EXPECT_EQ(str(cuts_of(in, false, step, threads, &read)), str(full))
                    << c.name << " step " << step << " threads " << threads;
                EXPECT_LT(read, all) << c.name << ": the sampled scan read every frame";
            }
        // The full scan's own verdict rule (12 pairs of history): the same cuts too.
        EXPECT_EQ(str(cuts_of(in, false, 16, 2, nullptr, 12)), str(full)) << c.name << " history 12";
    }
}

TEST(PlanCutScan, WhatTheSampledScanDoesNotSee) {
    TempDir d;
    const Pool pool(d.path / "pool");
    ASSERT_FALSE(HasFailure());
    // One white frame inside the static coffee shot, between samples (numbers 0..79, step 16:
    // samples 0, 16, 32, ...): the full scan calls the flash a cut (a shot starts on it and, too
    // soon after it for another verdict, the coffee shot goes on); the sampled scan compares
    // frames 16 and 32, which are alike, and does not read the flash.
    const std::string between = cut_together(d, pool, "between", 0, {{"coffee", 0, 20}, {"white", 0, 1}, {"coffee", 0, 39}, {"coffee", 0, 20}});
    EXPECT_EQ(str(cuts_of(between, true, 1, 2)), "0 20 ");
    EXPECT_EQ(str(cuts_of(between, false, 16, 2)), "0 ") << "the sampled scan saw a flash between samples";
    // The same flash on a sample (frame 32) is found on its exact frame.
    const std::string on = cut_together(d, pool, "on", 0, {{"coffee", 0, 32}, {"white", 0, 1}, {"coffee", 0, 47}});
    EXPECT_EQ(str(cuts_of(on, true, 1, 2)), "0 32 ");
    EXPECT_EQ(str(cuts_of(on, false, 16, 2)), "0 32 ");
    // An insert of 6 frames of another shot that returns to the same static shot, between samples:
    // the full scan sees the cut into it (the cut back comes 6 frames later, also called).
    const std::string insert = cut_together(d, pool, "insert", 0, {{"coffee", 0, 18}, {"earth", 0, 6}, {"coffee", 0, 40}});
    EXPECT_EQ(str(cuts_of(insert, true, 1, 2)), "0 18 24 ");
    EXPECT_EQ(str(cuts_of(insert, false, 16, 2)), "0 ") << "the sampled scan saw an insert between samples";
    EXPECT_EQ(str(cuts_of(insert, false, 4, 2)), "0 18 24 ") << "a step shorter than the insert finds it";
    // A verdict on 4 pairs of history where the full scan weighs 12: after a burst of cuts too
    // close together to be called, then 5 calm frames, the full scan's history still holds the
    // burst and refuses the next cut; the default --cut-history 4 no longer sees it. 12 pairs
    // give the full scan's verdict.
    const std::string burst = cut_together(d, pool, "burst", 0,
                                           {{"orbit", 0, 1}, {"earth", 0, 1}, {"taffy", 0, 1}, {"city", 0, 5}, {"coffee", 0, 40}});
    EXPECT_EQ(str(cuts_of(burst, true, 1, 2)), "0 ");
    EXPECT_EQ(str(cuts_of(burst, false, 16, 2, nullptr, 4)), "0 8 ") << "the cut into the coffee shot";
    EXPECT_EQ(str(cuts_of(burst, false, 16, 2, nullptr, 12)), "0 ");
}

}  // namespace

namespace {

TEST(PlanCutScan, BadFramesItReadsAreErrorsOrSkipped) {
    TempDir d;
    const Pool pool(d.path / "pool");
    ASSERT_FALSE(HasFailure());
    const std::string in = cut_together(d, pool, "bad", 0, {{"city", 0, 40}, {"earth", 0, 30}});
    fs::remove(d.path / "bad" / "s.00032.png");  // a sample of step 16
    auto plan = [&](bool full, bool skip) {
        spt::plan::PlanOptions o;
        o.input = in;
        o.cut_scan = full ? spt::plan::CutScan::Full : spt::plan::CutScan::Sampled;
        o.skip_bad_frames = skip;
        spt::io::Progress progress(spt::io::ProgressMode::None, "plan", 0);
        return spt::plan::make_plan(o, progress);
    };
    for (bool full : {true, false}) {
        auto p = plan(full, false);
        ASSERT_FALSE(p.ok()) << (full ? "full" : "sampled") << ": a missing frame it reads is an error";
        EXPECT_NE(p.error().message.find("frame 32 is missing"), std::string::npos) << p.error().message;
    }
    auto full = plan(true, true), sampled = plan(false, true);
    ASSERT_TRUE(full.ok() && sampled.ok());
    EXPECT_EQ(str(full->cuts), "0 40 ");
    EXPECT_EQ(str(sampled->cuts), str(full->cuts)) << "--skip-bad-frames: the frame before it, as in the full scan";
}

}  // namespace
