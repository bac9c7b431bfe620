// Crafted plans (issue 36): a plan comes from anywhere and its id is a checksum anyone can
// recompute, so what it may make a task do is limited by what it may hold, not by the id.
#include <chrono>

#include "converter/ocio_test_config.hpp"
#include "hostile/plan_test_util.hpp"

using namespace spt_test;

#define EXPECT_HAS(text, what) EXPECT_NE((text).find(what), std::string::npos) << "missing \"" << (what) << "\" in: " << (text)

// Issue 36 item 1: paint_args ending in "-o", "victim.txt" wrote the shot over victim.txt and
// never wrote the asked-for output, with exit 0. A plan now stores its job by option name, and
// every name that is not a painter option of the option table is refused, naming the plan and
// the option, and nothing is written.
TEST(HostilePlan, AJobMayHoldOnlyPainterOptions) {
    TempDir d;
    const std::string plan = d.file("p.json");
    const std::string text = tiny_plan(d, plan);
    ASSERT_FALSE(text.empty());
    const std::string victim = d.file("victim.txt");
    const std::string v = spt::json::quote(victim);
    const std::vector<std::pair<std::string, std::string>> crafted = {
        {"output", "\"output\": " + v},       {"o", "\"o\": " + v},
        {"plan", "\"plan\": " + v},           {"shot", "\"shot\": \"1\""},
        {"threads", "\"threads\": \"2\""},    {"progress", "\"progress\": \"json\""},
        {"preview", "\"preview\": " + v},     {"side-by-side", "\"side-by-side\": " + v},
        {"seed", "\"seed\": \"5\""},          {"frames", "\"frames\": \"1-1\""},
        {"stored", "\"stored\": " + v},       {"roi", "\"roi\": \"1,1,8,8\""},
        {"help", "\"help\": true"},           {"max-task-frames", "\"max-task-frames\": \"3\""},
    };
    for (const auto& [name, member] : crafted) {
        write_text(victim, "mine");
        fs::remove(d.file("asked.spt"));
        write_text(d.file("c.json"), with_job(text, {member}));
        const auto r = run_spt(d, {"paint", "--plan", d.file("c.json"), "--shot", "0", "-o", d.file("asked.spt")});
        EXPECT_TRUE(failed_with(r, 1, {d.file("c.json"), "\"job\" option", "'" + name + "'",
                                       "a plan may hold only painter options"}))
            << name;
        EXPECT_EQ(slurp(victim), "mine") << name;
        EXPECT_FALSE(fs::exists(d.file("asked.spt"))) << name;
    }
    // A name spelt as no option is is the plan model's to refuse, whatever reads the plan.
    write_text(d.file("c.json"), with_job(text, {"\"--output\": " + v}));
    auto r = run_spt(d, {"paint", "--plan", d.file("c.json"), "--shot", "0", "-o", d.file("asked.spt")});
    EXPECT_TRUE(failed_with(r, 1, {d.file("c.json"), "\"job\" key '--output' is not an option name"})) << r.err;
    // A plan of version 1 (argv in "paint_args") is refused with a word on planning again.
    std::string old = text;
    old.replace(old.find("\"version\": 2"), 12, "\"version\": 1");
    write_text(d.file("c.json"), resign(old));
    r = run_spt(d, {"paint", "--plan", d.file("c.json"), "--shot", "0", "-o", d.file("asked.spt")});
    EXPECT_TRUE(failed_with(r, 1, {d.file("c.json"), "plan version 1", "plan again"})) << r.err;
    // The plan's input and frame rate become arguments too: neither may pass for an option.
    std::string t = text;
    const size_t in = t.find("\"input\": \"");
    t.insert(in + 10, "--output=" + victim + "#");
    write_text(d.file("c.json"), resign(t));
    r = run_spt(d, {"paint", "--plan", d.file("c.json"), "--shot", "0", "-o", d.file("asked.spt")});
    EXPECT_TRUE(failed_with(r, 1, {d.file("c.json"), "\"input\""}));
    t = text;
    const size_t fps = t.find("\"fps\": \"");
    t.insert(fps + 8, "--output=" + victim + "#");
    write_text(d.file("c.json"), resign(t));
    r = run_spt(d, {"paint", "--plan", d.file("c.json"), "--shot", "0", "-o", d.file("asked.spt")});
    EXPECT_TRUE(failed_with(r, 1, {d.file("c.json"), "\"fps\""}));
    EXPECT_EQ(slurp(victim), "mine");
    // Painter options re-signed into a plan are a plan's own business: they paint.
    write_text(d.file("c.json"), with_job(text, {"\"stored\": true", "\"target-psnr\": \"20\""}));
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
