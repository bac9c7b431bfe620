// The option table is the one list of a paint job's options: a row added here (as a test build
// would) must reach spt paint's and spt plan's --help, the job a plan stores, painter.options and
// --options-json, with nothing else edited; and every painting row must survive a plan.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <set>
#include <string>
#include <vector>

#include "cli/paint_options.hpp"
#include "cli/plan_job.hpp"
#include "converter/cli_test_util.hpp"
#include "job/option_table.hpp"

using namespace spt_test;
using spt::job::OptionKind;
using spt::job::OptionRow;
using spt::job::OptionScope;

namespace {

// Runs parse_paint_options on `args` (without the command name); returns the exit code.
int parse(std::vector<std::string> args, spt::job::PaintJob& o, const char* command = "paint") {
    args.insert(args.begin(), command);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    return spt::cli::parse_paint_options(int(args.size()), argv.data(), o, command);
}

std::string help_of(const char* command) {
    spt::job::PaintJob o;
    testing::internal::CaptureStdout();
    EXPECT_EQ(parse({"--help"}, o, command), 0);
    return testing::internal::GetCapturedStdout();
}

int g_knob = 0;  // where the test row stores its value

// A row as a new option would be added: an integer that shapes the painting.
struct TestRow {
    TestRow() {
        OptionRow r;
        r.name = "test-knob";
        r.metavar = "K";
        r.kind = OptionKind::Integer;
        r.lo = 1;
        r.hi = 9;
        r.help = "a knob only the option table's test has";
        r.set = [](spt::job::PaintJob&, const std::string& v) { g_knob = std::stoi(v); return std::string(); };
        r.get = [](const spt::job::PaintJob&) { return g_knob ? std::vector<std::string>{std::to_string(g_knob)} : std::vector<std::string>{}; };
        r.canon_rank = 1000;
        r.canon = [](std::ostream& s, const spt::job::PaintJob&) { if (g_knob) s << " test-knob=" << g_knob; };
        spt::job::option_rows().push_back(r);
    }
    ~TestRow() { spt::job::option_rows().pop_back(); g_knob = 0; }
};

}  // namespace

TEST(OptionTable, ARowReachesEveryFrontEnd) {
    const TestRow added;
    EXPECT_NE(help_of("paint").find("--test-knob K"), std::string::npos);
    EXPECT_NE(help_of("plan").find("--test-knob K"), std::string::npos);
    spt::job::PaintJob o;
    ASSERT_EQ(parse({"in.png", "-o", "out.spt", "--test-knob", "7"}, o), -1);
    EXPECT_EQ(g_knob, 7);
    EXPECT_NE(o.canonical().find(" test-knob=7"), std::string::npos) << o.canonical();
    bool in_plan = false;
    for (const auto& opt : spt::cli::plan_job(o)) in_plan |= opt.name == "test-knob" && opt.values == std::vector<std::string>{"7"};
    EXPECT_TRUE(in_plan) << "the job a plan stores";
    const auto doc = nlohmann::json::parse(spt::job::options_json());
    bool listed = false;
    for (const auto& r : doc["options"]) listed |= r["name"] == "test-knob" && r["min"] == 1 && r["max"] == 9;
    EXPECT_TRUE(listed) << "--options-json";
    // Its range comes from the row too.
    spt::job::PaintJob bad;
    testing::internal::CaptureStderr();
    EXPECT_EQ(parse({"in.png", "-o", "out.spt", "--test-knob", "12"}, bad), 2);
    EXPECT_NE(testing::internal::GetCapturedStderr().find("--test-knob: expected 1..9, got '12'"), std::string::npos);
}

// Whatever a job holds, the plan's copy paints the same: stored, read back, stored again, the
// painting options and their canonical spelling are the same.
TEST(OptionTable, EveryPaintingRowSurvivesAPlan) {
    TempDir d;
    write_text(d.file("rois.json"), R"({"rois":[{"x":1,"y":2,"w":3,"h":4,"frames":"0-3"}]})");
    const std::vector<std::vector<std::string>> jobs = {
        {},
        {"--style", "cartoon", "--outline-tolerance", "0.7", "--outline-smooth", "0.25", "--min-region", "12",
         "--min-color-share", "0.001", "--no-lines", "--target-psnr", "31.5", "--target-bytes", "5000/s"},
        {"--sets", "4", "--max-strokes", "777", "--threshold", "0.02", "--lambda", "3.125", "--temperature", "0",
         "--orient", "random", "--background", "1,2,3", "--stored", "--coding", "1", "--color-step", "5",
         "--roi", "1,1,8,8", "--roi", "2,2,4,4", "--roi-file", d.file("rois.json"), "--color-encoding", "linear",
         "--alpha", "on", "--layer", "ViewLayer.Combined", "--skip-bad-frames", "--keyframe-interval", "7",
         "--cut-threshold", "2.5", "--flow", "farneback", "--max-inter-strokes", "9", "--motion-block", "32",
         "--flow-orientation", "--templates", d.path.string()},
        {"--set-sizes", "30x30,10x10"},
    };
    for (std::vector<std::string> args : jobs) {
        args.insert(args.begin(), {"in.png", "-o", "out.spt"});
        spt::job::PaintJob o;
        ASSERT_EQ(parse(args, o), -1) << args.size();
        spt::plan::Plan p;
        p.job = spt::cli::plan_job(o);
        spt::job::PaintJob back;
        ASSERT_EQ(spt::cli::apply_plan_job(p, "p.json", back), "");
        EXPECT_EQ(back.canonical(), o.canonical());
        const auto again = spt::cli::plan_job(back);
        ASSERT_EQ(again.size(), p.job.size());
        for (size_t i = 0; i < again.size(); ++i) {
            EXPECT_EQ(again[i].name, p.job[i].name);
            EXPECT_EQ(again[i].values, p.job[i].values) << again[i].name;
        }
    }
}

// The rows themselves: unique names, a setter each, and every painting row stored by plans.
TEST(OptionTable, RowsAreWellFormed) {
    std::set<std::string> names;
    for (const OptionRow& r : spt::job::option_rows()) {
        EXPECT_TRUE(names.insert(r.name).second) << r.name;
        EXPECT_TRUE(bool(r.set)) << r.name;
        EXPECT_FALSE(r.help.empty()) << r.name;
        if (r.scope == OptionScope::Painting) EXPECT_TRUE(bool(r.get)) << r.name << " would not travel with a plan";
        if (r.kind == OptionKind::Integer || r.kind == OptionKind::Number) EXPECT_LT(r.lo, r.hi) << r.name;
        if (r.kind == OptionKind::Choice) EXPECT_FALSE(r.choices.empty()) << r.name;
    }
}

// The real command: --options-json lists the table, alone (no input or output asked for).
TEST(OptionTable, OptionsJsonFromTheCommand) {
    TempDir d;
    const RunResult r = run_spt(d, {"paint", "--options-json"});
    ASSERT_EQ(r.code, 0) << r.err;
    const auto doc = nlohmann::json::parse(r.out);
    EXPECT_EQ(doc["format"], "spt-paint-options");
    std::vector<std::string> names;
    for (const auto& o : doc["options"]) names.push_back(o["name"]);
    std::vector<std::string> rows;
    for (const OptionRow& o : spt::job::option_rows()) rows.push_back(o.name);
    EXPECT_EQ(names, rows);
}
