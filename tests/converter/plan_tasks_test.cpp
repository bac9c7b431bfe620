// Plans that leave the cuts to their tasks (--cut-scan tasks, the default for a video file): the
// plan counts the frames without decoding them; each task runs the painter's cut detector on its
// own frames; shots painted apart and joined are still byte for byte the one-process painting.
#include "converter/cli_test_util.hpp"

#include "io/progress.hpp"
#include "plan/frame_span.hpp"
#include "plan/plan.hpp"
#include "plan/planner.hpp"
#include "spt/concat.hpp"

namespace {

using namespace spt_test;

const std::string kCity = std::string(SPT_MEDIA_DIR) + "/video/city.mpg";  // 190 frames, a hard cut at 116

spt::Result<spt::plan::Plan> plan_of(const std::string& input, const std::string& frames, spt::plan::CutScan scan,
                                     spt::plan::PlanStats* stats = nullptr) {
    spt::plan::PlanOptions o;
    o.input = input;
    o.frames = frames;
    o.cut_scan = scan;
    o.max_task_frames = 48;
    o.keyframe_interval = 24;
    spt::io::Progress progress(spt::io::ProgressMode::None, "plan", 0);
    return spt::plan::make_plan(o, progress, stats);
}

TEST(PlanTasks, AVideoIsCountedNotDecoded) {
    ASSERT_TRUE(fs::exists(kCity)) << "the shared media are needed: " << kCity;
    auto n = spt::plan::count_video_packets(kCity);
    ASSERT_TRUE(n.ok()) << n.error().message;
    EXPECT_EQ(*n, 190u) << "every frame OpenCV decodes is one packet";
    spt::plan::PlanStats stats;
    auto p = plan_of(kCity, "", spt::plan::CutScan::Auto, &stats);
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->cut_scan, "tasks") << "a video file's default";
    EXPECT_EQ(stats.decoded, 1u) << "only the first frame, for the canvas";
    EXPECT_EQ(p->first, 0);
    EXPECT_EQ(p->last, 189);
    EXPECT_EQ(p->cuts, (std::vector<long>{0}));
    EXPECT_EQ(p->width, 720u);
    EXPECT_EQ(p->height, 405u);
    EXPECT_EQ(p->fps, "25/1");
    ASSERT_EQ(p->shots.size(), 4u);  // 190 frames in tasks of at most 48, on steps of 24
    for (const auto& s : p->shots) {
        EXPECT_LE(s.frames(), 48u);
        EXPECT_EQ(s.first % 24, 0);
    }
    // The same frames, canvas and rate as a plan that scans them.
    auto sampled = plan_of(kCity, "", spt::plan::CutScan::Sampled);
    ASSERT_TRUE(sampled.ok()) << sampled.error().message;
    EXPECT_EQ(sampled->cuts, (std::vector<long>{0, 116}));
    EXPECT_EQ(std::tie(sampled->first, sampled->last, sampled->width, sampled->height, sampled->fps),
              std::tie(p->first, p->last, p->width, p->height, p->fps));
    // A range past the end ends at the last frame; one that starts past it is an error naming the file.
    auto tail = plan_of(kCity, "180-400", spt::plan::CutScan::Tasks);
    ASSERT_TRUE(tail.ok()) << tail.error().message;
    EXPECT_EQ(tail->first, 180);
    EXPECT_EQ(tail->last, 189);
    auto past = plan_of(kCity, "300-400", spt::plan::CutScan::Tasks);
    ASSERT_FALSE(past.ok());
    EXPECT_NE(past.error().message.find("city.mpg: --frames 300-400: the video has frames 0-189"), std::string::npos)
        << past.error().message;
}

TEST(PlanTasks, ASequenceKeepsItsNumbersAndRange) {
    const std::string media = SPT_MEDIA_DIR;
    const std::string seq = media + "/exr/earth/earth.####.exr";
    for (const char* frames : {"", "5-30"}) {
        auto t = plan_of(seq, frames, spt::plan::CutScan::Tasks), s = plan_of(seq, frames, spt::plan::CutScan::Sampled);
        ASSERT_TRUE(t.ok() && s.ok()) << (t.ok() ? s.error().message : t.error().message);
        EXPECT_EQ(std::tie(t->first, t->last, t->width, t->height, t->fps),
                  std::tie(s->first, s->last, s->width, s->height, s->fps))
            << frames;
        EXPECT_EQ(t->cuts, (std::vector<long>{t->first}));
    }
    EXPECT_EQ(plan_of(seq, "", spt::plan::CutScan::Auto)->cut_scan, "sampled") << "a sequence's default";
}

TEST(PlanTasks, TasksFindTheCutsAndJoinToTheOneProcessPainting) {
    REQUIRE_TOOL();
    TempDir d;
    ASSERT_TRUE(fs::exists(kCity)) << "the shared media are needed: " << kCity;
    const std::string plan = d.file("plan.json");
    // Frames 100-131 in tasks of at most 12 (100-109, 110-120, 121-131): the cut at 116 falls
    // inside the second task, which must find it itself (key frames are otherwise 100 apart).
    RunResult r = run_spt(d, {"plan", kCity, "--frames", "100-131", "-o", plan, "--max-strokes", "200",
                              "--keyframe-interval", "100", "--max-task-frames", "12", "--seed", "9", "--progress", "none"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("1 read, tasks cut scan), cuts found by the tasks, 3 shots"), std::string::npos) << r.err;
    auto p = spt::plan::read_plan(plan);
    ASSERT_TRUE(p.ok()) << p.error().message;
    ASSERT_EQ(p->shots.size(), 3u);
    EXPECT_EQ(p->shots[1].first, 110);
    EXPECT_EQ(p->shots[1].last, 120);

    r = run_spt(d, {"paint", "--plan", plan, "-o", d.file("whole.spt"), "--progress", "none"});
    ASSERT_EQ(r.code, 0) << r.err;
    std::vector<std::string> parts(3);
    for (int k : {2, 0, 1}) {
        parts[size_t(k)] = d.file("shot" + std::to_string(k) + ".spt");
        r = run_spt(d, {"paint", "--plan", plan, "--shot", std::to_string(k), "-o", parts[size_t(k)], "--threads", "1",
                        "--progress", "none"});
        ASSERT_EQ(r.code, 0) << r.err;
    }
    r = run_spt(d, {"cat", parts[0], parts[1], parts[2], "-o", d.file("joined.spt")});
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string whole = slurp(d.file("whole.spt"));
    ASSERT_GT(whole.size(), 1000u);
    EXPECT_TRUE(whole == slurp(d.file("joined.spt"))) << "the join differs from the one-process painting";

    auto rd = spt::Reader::open(d.file("whole.spt"));
    ASSERT_TRUE(rd.ok());
    EXPECT_EQ(spt::first_frame_number((*rd)->info()), 100u);
    ASSERT_EQ((*rd)->frames().size(), 32u);
    std::vector<long> keys;
    for (size_t i = 0; i < 32; ++i)
        if ((*rd)->frames()[i].type == spt::FrameType::Key) keys.push_back(100 + long(i));
    EXPECT_EQ(keys, (std::vector<long>{100, 110, 116, 121})) << "task starts, and the cut its task found";
}

TEST(PlanTasks, AFileThatIsNoVideoIsAnErrorNamingIt) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string bad = d.file("not-a-video.mp4");
    std::FILE* f = std::fopen(bad.c_str(), "wb");
    ASSERT_TRUE(f);
    std::fputs("this is text, not a video\n", f);
    std::fclose(f);
    EXPECT_TRUE(refused(d, {"plan", bad, "-o", d.file("p.json"), "--progress", "none"}, kAnyFailure,
                        {"not-a-video.mp4"}, d.file("p.json")));
}

}  // namespace
