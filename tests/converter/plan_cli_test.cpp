// Farm plans: spt plan cuts a real sequence into shots; shots painted apart, in any order, in
// separate processes with other thread counts, and joined with spt cat are byte for byte
// `spt paint --plan` in one process; a shot's frames depend on its own frames only.
#include "converter/cli_test_util.hpp"

#include "plan/plan.hpp"
#include "spt/concat.hpp"

namespace {

using namespace spt_test;

// 22 frames numbered 101-122: earth 1-12, then a hard cut to orbit 1-10 (both 480x270 EXR).
std::string two_shot_sequence(const TempDir& d) {
    const std::string media = SPT_MEDIA_DIR;
    EXPECT_TRUE(fs::exists(media + "/exr/orbit/orbit.0010.exr")) << "the shared media are needed: " << media;
    fs::create_directories(d.path / "seq");
    char src[256], dst[64];
    for (int i = 1; i <= 22; ++i) {
        if (i <= 12) std::snprintf(src, sizeof src, "%s/exr/earth/earth.%04d.exr", media.c_str(), i);
        else std::snprintf(src, sizeof src, "%s/exr/orbit/orbit.%04d.exr", media.c_str(), i - 12);
        std::snprintf(dst, sizeof dst, "s.%04d.exr", 100 + i);
        fs::create_symlink(src, d.path / "seq" / dst);
    }
    return (d.path / "seq" / "s.####.exr").string();
}

std::vector<std::string> frames_of(const std::string& path) {
    auto r = spt::Reader::open(path);
    EXPECT_TRUE(r.ok()) << path;
    std::vector<std::string> out;
    if (!r.ok()) return out;
    for (size_t i = 0; i < (*r)->frames().size(); ++i) {
        auto live = (*r)->strokes_at(i);
        EXPECT_TRUE(live.ok());
        std::string s;
        for (const spt::Stroke& k : **live) {
            const spt::Rgba8& c = k.color();
            s += std::to_string(int(k.kind)) + ":" + std::to_string(k.stamp.x) + "," + std::to_string(k.stamp.y) + "," +
                 std::to_string(c.r) + std::to_string(c.g) + std::to_string(c.b) + std::to_string(c.a) + ";";
        }
        out.push_back(s);
    }
    return out;
}

TEST(PlanCli, ShotsPaintedApartJoinToTheOneProcessPainting) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string seq = two_shot_sequence(d);
    ASSERT_FALSE(HasFailure());
    const std::string plan = d.file("plan.json");
    RunResult r = run_spt(d, {"plan", seq, "-o", plan, "--max-strokes", "300", "--keyframe-interval", "4",
                              "--max-task-frames", "8", "--seed", "77", "--progress", "none"});
    ASSERT_EQ(r.code, 0) << r.err;
    // Frames decode on every core by default: one thread writes the same plan, byte for byte.
    r = run_spt(d, {"plan", seq, "-o", d.file("plan1.json"), "--max-strokes", "300", "--keyframe-interval", "4",
                    "--max-task-frames", "8", "--seed", "77", "--progress", "none", "--threads", "1"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(slurp(plan) == slurp(d.file("plan1.json"))) << "the plan depends on --threads";
    auto p = spt::plan::read_plan(plan);
    ASSERT_TRUE(p.ok()) << p.error().message;
    EXPECT_EQ(p->first, 101);
    EXPECT_EQ(p->last, 122);
    EXPECT_EQ(p->cuts, (std::vector<long>{101, 113})) << "the earth -> orbit cut";
    ASSERT_EQ(p->shots.size(), 4u);
    EXPECT_TRUE(p->shots[0].starts_at_cut && !p->shots[1].starts_at_cut && p->shots[2].starts_at_cut);
    EXPECT_EQ(p->shots[2].first, 113);
    for (const auto& s : p->shots) {
        EXPECT_LE(s.frames(), 8u);
        EXPECT_EQ((s.first - p->shots[s.index == 0 || s.starts_at_cut ? s.index : s.index - 1].first) % 4, 0);
    }
    EXPECT_NE(p->shots[0].seed, p->shots[1].seed);

    r = run_spt(d, {"paint", "--plan", plan, "-o", d.file("whole.spt"), "--progress", "none"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_FALSE(fs::exists(d.file("whole.spt.shots.partial")));
    // The farm: separate processes, out of order, one thread each.
    std::vector<std::string> parts(4);
    for (int k : {3, 1, 0, 2}) {
        parts[size_t(k)] = d.file("shot" + std::to_string(k) + ".spt");
        r = run_spt(d, {"paint", "--plan", plan, "--shot", std::to_string(k), "-o", parts[size_t(k)], "--threads", "1",
                        "--progress", "none"});
        ASSERT_EQ(r.code, 0) << r.err;
    }
    std::vector<std::string> cat = {"cat"};
    cat.insert(cat.end(), parts.begin(), parts.end());
    cat.insert(cat.end(), {"-o", d.file("joined.spt")});
    r = run_spt(d, cat);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "") << "no metadata dropped";
    const std::string whole = slurp(d.file("whole.spt"));
    ASSERT_GT(whole.size(), 1000u);
    EXPECT_TRUE(whole == slurp(d.file("joined.spt"))) << "the join differs from the one-process painting";

    // The painting keeps the source numbers and the plan's id; its key frames include the plan's.
    auto rd = spt::Reader::open(d.file("whole.spt"));
    ASSERT_TRUE(rd.ok());
    EXPECT_EQ(spt::first_frame_number((*rd)->info()), 101u);
    EXPECT_EQ((*rd)->frames().size(), 22u);
    for (const auto& s : p->shots)
        for (long k : s.key_frames) EXPECT_EQ((*rd)->frames()[size_t(k - 101)].type, spt::FrameType::Key) << k;
    EXPECT_EQ(run_spt(d, {"verify", d.file("whole.spt")}).code, 0);

    // Nothing in a shot depends on another: plan only the second scene and its first shot
    // paints the same frames as shot 2 of the whole plan.
    const std::string plan2 = d.file("plan2.json");
    r = run_spt(d, {"plan", seq, "--frames", "113-122", "-o", plan2, "--max-strokes", "300", "--keyframe-interval", "4",
                    "--max-task-frames", "8", "--seed", "77", "--progress", "none"});
    ASSERT_EQ(r.code, 0) << r.err;
    r = run_spt(d, {"paint", "--plan", plan2, "--shot", "0", "-o", d.file("alone.spt"), "--progress", "none"});
    ASSERT_EQ(r.code, 0) << r.err;
    const auto a = frames_of(d.file("alone.spt")), b = frames_of(parts[2]);
    ASSERT_EQ(a.size(), 4u);
    EXPECT_TRUE(a == b);

    // A shot left out, or a shot of the other plan, is refused by name.
    r = run_spt(d, {"cat", parts[0], parts[1], parts[3], "-o", d.file("x.spt")});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find(parts[3] + ": is shot 3"), std::string::npos) << r.err;
    r = run_spt(d, {"cat", parts[0], parts[1], d.file("alone.spt"), parts[3], "-o", d.file("x.spt")});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find(d.file("alone.spt")), std::string::npos) << r.err;
}

TEST(PlanCli, BadPlansAndShotsAreRefused) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string seq = two_shot_sequence(d);
    ASSERT_FALSE(HasFailure());
    const std::string plan = d.file("plan.json");
    ASSERT_EQ(run_spt(d, {"plan", seq, "-o", plan, "--max-strokes", "100", "--progress", "none"}).code, 0);
    RunResult r = run_spt(d, {"paint", "--plan", plan, "--shot", "9", "-o", d.file("x.spt")});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("shots 0-1"), std::string::npos) << r.err;
    // A plan edited by hand no longer matches its id.
    std::string text = slurp(plan);
    const size_t at = text.find("\"last\": 122");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 11, "\"last\": 121");
    {
        std::ofstream f(d.file("edited.json"));
        f << text;
    }
    r = run_spt(d, {"paint", "--plan", d.file("edited.json"), "-o", d.file("x.spt")});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find(d.file("edited.json")), std::string::npos) << r.err;
    r = run_spt(d, {"paint", "--plan", d.file("none.json"), "-o", d.file("x.spt")});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("none.json: no such plan file"), std::string::npos) << r.err;
    // Stills and stepped ranges have no plan.
    EXPECT_EQ(run_spt(d, {"plan", std::string(SPT_MEDIA_DIR) + "/stills/coffee.png", "-o", d.file("p.json")}).code, 2);
    r = run_spt(d, {"plan", seq, "--frames", "101-120x2", "-o", d.file("p.json")});
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find("one range"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(d.file("x.spt")));
}

// A cartoon plan: its tasks paint with the cartoon painter (polygons, lines, stamps), and the
// shots painted apart join to the one-process painting with the source's frame numbers.
TEST(PlanCli, CartoonPlansPaintCartoonShots) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string media = SPT_MEDIA_DIR;
    ASSERT_TRUE(fs::exists(media + "/cartoon/star/f.0011.png")) << "the shared media are needed: " << media;
    fs::create_directories(d.path / "seq");
    char src[256], dst[64];
    for (int i = 0; i < 12; ++i) {
        std::snprintf(src, sizeof src, "%s/cartoon/star/f.%04d.png", media.c_str(), i);
        std::snprintf(dst, sizeof dst, "s.%04d.png", 101 + i);
        fs::create_symlink(src, d.path / "seq" / dst);
    }
    const std::string seq = (d.path / "seq" / "s.####.png").string(), plan = d.file("plan.json");
    RunResult r = run_spt(d, {"plan", seq, "-o", plan, "--style", "cartoon", "--target-psnr", "34", "--max-task-frames",
                              "6", "--seed", "5", "--min-region", "5", "--min-color-share", "0.002", "--progress", "none"});
    ASSERT_EQ(r.code, 0) << r.err;
    auto p = spt::plan::read_plan(plan);
    ASSERT_TRUE(p.ok()) << p.error().message;
    ASSERT_EQ(p->shots.size(), 2u);
    auto job_value = [&](const char* name) {
        for (const spt::plan::JobOption& o : p->job)
            if (o.name == name && o.values.size() == 1) return o.values[0];
        return std::string("(absent)");
    };
    ASSERT_FALSE(p->job.empty());
    EXPECT_EQ(p->job.front().name, "style") << "the style first: a plan's tasks paint in the style it was made with";
    EXPECT_EQ(job_value("style"), "cartoon");
    EXPECT_EQ(job_value("min-region"), "5") << "the cartoon options travel with the plan";
    EXPECT_EQ(job_value("min-color-share"), "0.002");
    r = run_spt(d, {"paint", "--plan", plan, "-o", d.file("whole.spt"), "--progress", "none"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "") << "the shots join without a warning";
    std::vector<std::string> cat = {"cat"};
    for (int k : {1, 0}) {
        const std::string part = d.file("shot" + std::to_string(k) + ".spt");
        r = run_spt(d, {"paint", "--plan", plan, "--shot", std::to_string(k), "-o", part, "--threads", "1",
                        "--progress", "none"});
        ASSERT_EQ(r.code, 0) << r.err;
    }
    cat.insert(cat.end(), {d.file("shot0.spt"), d.file("shot1.spt"), "-o", d.file("joined.spt")});
    r = run_spt(d, cat);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_TRUE(slurp(d.file("whole.spt")) == slurp(d.file("joined.spt"))) << "the join differs from the one-process painting";

    auto rd = spt::Reader::open(d.file("whole.spt"));
    ASSERT_TRUE(rd.ok());
    EXPECT_EQ(spt::first_frame_number((*rd)->info()), 101u);
    EXPECT_EQ((*rd)->frames().size(), 12u);
    EXPECT_EQ((*rd)->frames()[6].type, spt::FrameType::Key) << "shot 1 starts with a key frame";
    size_t polygons = 0;
    for (const spt::Stroke& s : **(*rd)->strokes_at(0)) polygons += s.kind == spt::StrokeKind::Polygon;
    EXPECT_GE(polygons, 2u) << "painted by the cartoon painter";
    std::string options;
    for (const auto& [k, v] : (*rd)->info().metadata)
        if (k == "painter.options") options = v;
    EXPECT_NE(options.find("style=cartoon"), std::string::npos) << options;
    r = run_spt(d, {"render", d.file("whole.spt"), "-o", d.file("r.####.png")});
    ASSERT_EQ(r.code, 0) << r.err;
    r = run_spt(d, {"compare", d.file("r.####.png"), seq});
    ASSERT_EQ(r.code, 0) << r.err;
    const size_t at = r.out.find("PSNR mean ");
    ASSERT_NE(at, std::string::npos) << r.out;
    EXPECT_GE(std::stod(r.out.substr(at + 10)), 34.0) << r.out;

    // The cartoon options travel with the plan.
    r = run_spt(d, {"plan", seq, "-o", d.file("plan2.json"), "--style", "cartoon", "--no-lines", "--outline-tolerance",
                    "0.5", "--progress", "none"});
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string text = slurp(d.file("plan2.json"));
    EXPECT_NE(text.find("\"no-lines\": true"), std::string::npos) << text;
    EXPECT_NE(text.find("\"outline-tolerance\": \"0.5\""), std::string::npos) << text;
}

TEST(PlanSplit, ShotsSplitIntoBalancedTasksOnKeyFrameSteps) {
    using spt::plan::split_shot;
    EXPECT_EQ(split_shot(0, 99, 10, 0).size(), 1u);
    EXPECT_EQ(split_shot(0, 99, 10, 100).size(), 1u);
    // 250 frames, steps of 24, tasks of at most 100: 3 tasks of 4, 4, 3 steps (the last shorter).
    auto s = split_shot(1001, 1250, 24, 100);
    ASSERT_EQ(s.size(), 3u);
    long at = 1001;
    for (const auto& [a, b] : s) {
        EXPECT_EQ(a, at);
        EXPECT_EQ((a - 1001) % 24, 0);
        EXPECT_LE(b - a + 1, 100);
        EXPECT_GE(b - a + 1, 72 - 24);
        at = b + 1;
    }
    EXPECT_EQ(at, 1251);
    // A key frame interval above the task size: tasks of nearly equal length.
    s = split_shot(0, 99, 500, 30);
    ASSERT_EQ(s.size(), 4u);
    for (const auto& [a, b] : s) EXPECT_TRUE(b - a + 1 == 25) << a << "-" << b;
}

}  // namespace
