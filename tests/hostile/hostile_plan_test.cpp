// Crafted plans (issue 36): a plan comes from anywhere and its id is a checksum anyone can
// recompute, so what it may make a task do is limited by what it may hold, not by the id.
#include <chrono>

#include "converter/ocio_test_config.hpp"
#include "hostile/plan_test_util.hpp"

using namespace spt_test;

#define EXPECT_HAS(text, what) EXPECT_NE((text).find(what), std::string::npos) << "missing \"" << (what) << "\" in: " << (text)

// Issue 36 item 1: paint_args ending in "-o", "victim.txt" wrote the shot over victim.txt and
// never wrote the asked-for output, with exit 0. Every argument that is not a painter option
// is now refused, naming the plan and the argument, and nothing is written.
TEST(HostilePlan, PaintArgsMayHoldOnlyPainterOptions) {
    TempDir d;
    const std::string plan = d.file("p.json");
    const std::string text = tiny_plan(d, plan);
    ASSERT_FALSE(text.empty());
    const std::string victim = d.file("victim.txt");
    const std::vector<std::vector<std::string>> crafted = {
        {"-o", victim},          {"--output", victim},       {"--output=" + victim}, {victim},
        {"--plan", plan},        {"--shot", "1"},            {"--threads", "2"},     {"--progress", "json"},
        {"--preview", victim},   {"--side-by-side", victim}, {"--seed", "5"},        {"--frames", "1-1"},
        {"--lambda", "-o"},      {"--lambda"},               {"--stored=" + victim}, {"-h"},
    };
    for (const auto& extra : crafted) {
        write_text(victim, "mine");
        write_text(d.file("c.json"), with_paint_args(text, extra));
        const auto r = run_spt(d, {"paint", "--plan", d.file("c.json"), "--shot", "0", "-o", d.file("asked.spt")});
        // The argument named: the option, or for a value that would pass for one, the value.
        const std::string named = extra.size() == 2 && extra[0] == "--lambda" ? extra[1] : extra[0];
        EXPECT_TRUE(failed_with(r, 1, {d.file("c.json"), "\"paint_args\"", "'" + named + "'",
                                       "a plan may hold only painter options"}))
            << extra.front();
        EXPECT_EQ(slurp(victim), "mine") << extra.front();
        EXPECT_FALSE(fs::exists(d.file("asked.spt"))) << extra.front();
    }
    // The plan's input and frame rate become arguments too: neither may pass for an option.
    std::string t = text;
    const size_t in = t.find("\"input\": \"");
    t.insert(in + 10, "--output=" + victim + "#");
    write_text(d.file("c.json"), resign(t));
    auto r = run_spt(d, {"paint", "--plan", d.file("c.json"), "--shot", "0", "-o", d.file("asked.spt")});
    EXPECT_TRUE(failed_with(r, 1, {d.file("c.json"), "\"input\""}));
    t = text;
    const size_t fps = t.find("\"fps\": \"");
    t.insert(fps + 8, "--output=" + victim + "#");
    write_text(d.file("c.json"), resign(t));
    r = run_spt(d, {"paint", "--plan", d.file("c.json"), "--shot", "0", "-o", d.file("asked.spt")});
    EXPECT_TRUE(failed_with(r, 1, {d.file("c.json"), "\"fps\""}));
    EXPECT_EQ(slurp(victim), "mine");
    // Painter options re-signed into a plan are a plan's own business: they paint.
    write_text(d.file("c.json"), with_paint_args(text, {"--max-strokes", "20", "--stored", "--lambda=0.5"}));
    r = run_spt(d, {"paint", "--plan", d.file("c.json"), "--shot", "0", "-o", d.file("asked.spt")});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_TRUE(fs::exists(d.file("asked.spt")));
}

// Issue 36 item 2: a shot that failed (here: its input is gone) removed whatever was at -o, a
// file of the user's or an empty folder. It now removes only an output this run linked there.
TEST(HostilePlan, AFailedShotRemovesOnlyWhatItCreated) {
    TempDir d;
    const std::string plan = d.file("p.json");
    ASSERT_FALSE(tiny_plan(d, plan).empty());
    fs::rename(d.path / "seq", d.path / "gone");
    write_text(d.file("keep.spt"), "keep");
    fs::create_directories(d.path / "folder");
    for (const char* out : {"keep.spt", "folder"}) {
        const auto r = run_spt(d, {"paint", "--plan", plan, "--shot", "0", "-o", d.file(out)});
        EXPECT_EQ(r.code, 1) << out << ": " << r.err;
    }
    EXPECT_EQ(slurp(d.file("keep.spt")), "keep");
    EXPECT_TRUE(fs::is_directory(d.path / "folder"));
    // With its input back, the same shot paints over the old file.
    fs::rename(d.path / "gone", d.path / "seq");
    const auto r = run_spt(d, {"paint", "--plan", plan, "--shot", "0", "-o", d.file("keep.spt")});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(run_spt(d, {"verify", d.file("keep.spt")}).code, 0);
}

// Issue 36 item 6: a 2 GB sparse plan was read whole (4.3 GB of memory, 16 s) before its parse
// error; spt farm status the same, and its job.json too. The size is now checked first.
TEST(HostilePlan, APlanOrStateFileOverTheCapIsRefusedBeforeReading) {
    TempDir d;
    const std::string plan = d.file("p.json");
    ASSERT_FALSE(tiny_plan(d, plan).empty());
    auto sparse = [&](const std::string& path) {
        std::ofstream(path, std::ios::binary).flush();
        fs::resize_file(path, uint64_t(256) << 20);  // zeros: no parser gets past byte 0
    };
    sparse(d.file("big.json"));
    const auto t0 = std::chrono::steady_clock::now();
    auto r = run_spt(d, {"paint", "--plan", d.file("big.json"), "--shot", "0", "-o", d.file("o.spt")});
    EXPECT_TRUE(failed_with(r, 1, {d.file("big.json"), "the plan file is 268435456 bytes, over the limit of 32 MiB"}));
    r = run_spt(d, {"farm", "status", d.file("big.json")});
    EXPECT_TRUE(failed_with(r, 1, {d.file("big.json"), "over the limit of 32 MiB"}));
    // A sound plan whose farm state was replaced by a huge file.
    fs::create_directories(d.path / "p.farm" / "run");
    sparse(d.file("p.farm/job.json"));
    r = run_spt(d, {"farm", "status", plan});
    EXPECT_TRUE(failed_with(r, 1, {d.file("p.farm/job.json"), "the farm state file is 268435456 bytes"}));
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));
    EXPECT_FALSE(fs::exists(d.file("o.spt")));
}

// The other side of the rule: every option spt plan writes into paint_args is one a plan may
// hold, so that no plan spt writes is refused when read (farm status reads the plan first).
TEST(HostilePlan, EveryOptionSptPlanWritesIsAccepted) {
    TempDir d;
    const std::string seq = tiny_sequence(d);
    write_text(d.file("roi.json"), "{\"rois\": [{\"x\": 0, \"y\": 0, \"w\": 4, \"h\": 4}]}");
    fs::create_directories(d.path / "t");
    fs::copy_file(fs::path(SPT_SOURCE_DIR) / "tests/hostile/inputs/good.png", d.path / "t" / "a.png");
    const std::vector<std::vector<std::string>> styles = {
        {"--sets", "4", "--target-psnr", "30", "--roi", "0,0,4,4", "--roi-file", d.file("roi.json"), "--stored",
         "--target-bytes", "5000", "--fps", "25", "--skip-bad-frames", "--flow-orientation", "--color-encoding",
         "linear", "--alpha", "on", "--colorspace", "sRGB", "--ocio", write_studio_ocio(d.file("studio.ocio")),
         "--templates", d.file("t"), "--layer", "foo"},
        {"--style", "cartoon", "--outline-tolerance", "0.7", "--outline-smooth", "1", "--min-region", "5",
         "--min-color-share", "0.01", "--no-lines"},
    };
    for (const auto& opts : styles) {
        std::vector<std::string> args = {"plan", seq, "-o", d.file("p.json")};
        args.insert(args.end(), opts.begin(), opts.end());
        auto r = run_spt(d, args);
        ASSERT_EQ(r.code, 0) << opts[0] << ": " << r.err;
        r = run_spt(d, {"farm", "status", d.file("p.json")});
        EXPECT_TRUE(failed_with(r, 1, {"not submitted to a farm"})) << opts[0];
    }
}
