// The farm's state folder against planted symlinks (issue 36): spt farm and the wrappers it
// writes put every file there through a fresh name renamed into place, never through a link.
// Slurm is stood in for by an sbatch that prints a job id and a squeue that lists nothing; the
// wrappers are run by hand as a farm node would.
#include <cstdlib>

#include "hostile/plan_test_util.hpp"

using namespace spt_test;

namespace {

// sbatch and squeue stand-ins first on PATH for this process and the commands it runs.
void fake_slurm(const TempDir& d) {
    fs::create_directories(d.path / "bin");
    write_text(d.file("bin/sbatch"), "#!/bin/sh\necho 4242\n");
    write_text(d.file("bin/squeue"), "#!/bin/sh\nexit 0\n");
    for (const char* n : {"bin/sbatch", "bin/squeue"})
        fs::permissions(d.path / n, fs::perms::owner_all, fs::perm_options::add);
    static std::string path;
    path = d.file("bin") + ":" + (std::getenv("PATH") ? std::getenv("PATH") : "/usr/bin:/bin");
    ::setenv("PATH", path.c_str(), 1);
}

// fake_slurm, with an sbatch that records its arguments in bin/sbatch.args and an scontrol
// that reports `max_array_size`.
void fake_slurm_recording(const TempDir& d, int max_array_size) {
    fake_slurm(d);
    write_text(d.file("bin/sbatch"), "#!/bin/sh\necho \"$@\" >> \"$(dirname \"$0\")/sbatch.args\"\necho 4242\n");
    write_text(d.file("bin/scontrol"),
               "#!/bin/sh\necho 'MaxArraySize            = " + std::to_string(max_array_size) + "'\n");
    for (const char* n : {"bin/sbatch", "bin/scontrol"})
        fs::permissions(d.path / n, fs::perms::owner_all, fs::perm_options::add);
}

int run_bash(const std::string& script, const std::string& arg = "") {
    const std::string cmd = "/bin/bash " + shell_quote(script) + (arg.empty() ? "" : " " + shell_quote(arg)) +
                            " >/dev/null 2>&1 </dev/null";
    const int st = std::system(cmd.c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

}  // namespace

// Issue 36 item 3: with slurm_tasks.sh, slurm_join.sh and run/shot-0.done made symlinks to
// other files, spt farm slurm overwrote the first two targets and truncated the third; the
// task wrapper's `>` and `>>` wrote its pid and attempt lines through links the same way.
TEST(HostileFarm, SymlinksInTheStateFolderAreReplacedNotWrittenThrough) {
    TempDir d;
    fake_slurm(d);
    const std::string plan = d.file("p.json"), state = d.file("p.farm");
    ASSERT_FALSE(tiny_plan(d, plan).empty());
    auto r = run_spt(d, {"farm", "slurm", plan, "-o", d.file("out.spt")});
    ASSERT_EQ(r.code, 0) << r.err;
    // The wrappers, run as the farm would: a link at each marker the task writes.
    std::vector<std::string> victims;
    auto plant = [&](const std::string& at) {
        const std::string v = d.file("victim" + std::to_string(victims.size()));
        write_text(v, "mine");
        fs::remove(at);
        fs::create_symlink(v, at);
        victims.push_back(v);
    };
    plant(state + "/run/shot-0.pid");
    plant(state + "/run/shot-0.attempts");
    ASSERT_EQ(run_bash(state + "/task.sh", "0"), 0);
    EXPECT_EQ(slurp(state + "/run/shot-0.attempts"), "1 0\n");
    EXPECT_FALSE(fs::is_symlink(state + "/run/shot-0.attempts"));
    EXPECT_TRUE(fs::exists(state + "/run/shot-0.done"));
    plant(state + "/run/shot-0.done");  // the join reads it as a file only
    plant(state + "/run/join.done");
    ASSERT_EQ(run_bash(state + "/task.sh", "1"), 0);
    ASSERT_EQ(run_bash(state + "/join.sh"), 0);
    EXPECT_FALSE(fs::is_symlink(state + "/run/join.done"));
    EXPECT_EQ(run_spt(d, {"verify", d.file("out.spt")}).code, 0);
    // Submitted again with shot 1 lost: shot 0 is reused (its done marker written afresh), shot
    // 1 queued, and the scripts written again, each over a link.
    fs::remove(state + "/shots/shot-00001.spt");
    plant(state + "/slurm_tasks.sh");
    plant(state + "/slurm_join.sh");
    plant(state + "/task.sh");
    plant(state + "/logs/join.log");
    r = run_spt(d, {"farm", "slurm", plan, "-o", d.file("out.spt")});
    ASSERT_EQ(r.code, 0) << r.err;
    for (const std::string& v : victims) EXPECT_EQ(slurp(v), "mine") << v;
    for (const char* f : {"slurm_join.sh", "task.sh", "run/shot-0.done"})
        EXPECT_FALSE(fs::is_symlink(state + "/" + f)) << f;
    EXPECT_FALSE(fs::exists(state + "/logs/join.log"));
    // A folder of the state made a link is refused: what goes in it would go elsewhere.
    fs::rename(state + "/shots", d.file("elsewhere"));
    fs::create_directory_symlink(d.file("elsewhere"), state + "/shots");
    EXPECT_TRUE(failed_with(run_spt(d, {"farm", "slurm", plan, "-o", d.file("out.spt")}), 1,
                            {state + "/shots: is a symlink"}));
}

// Issue 36 item 9: task.sh used the state folder's path as a printf format, so a plan named
// with a % painted every shot to a wrong name (or none) and the join found nothing.
TEST(HostileFarm, APercentInThePlanPathPaintsTheRightShot) {
    TempDir d;
    fake_slurm(d);
    const std::string plan = d.file("p%d%s.json"), state = d.file("p%d%s.farm");
    ASSERT_FALSE(tiny_plan(d, plan).empty());
    auto r = run_spt(d, {"farm", "slurm", plan, "-o", d.file("out.spt")});
    ASSERT_EQ(r.code, 0) << r.err;
    for (const char* k : {"0", "1"}) EXPECT_EQ(run_bash(state + "/task.sh", k), 0) << k;
    EXPECT_TRUE(fs::exists(state + "/shots/shot-00000.spt"));
    EXPECT_TRUE(fs::exists(state + "/shots/shot-00001.spt"));
    ASSERT_EQ(run_bash(state + "/join.sh"), 0);
    EXPECT_EQ(run_spt(d, {"verify", d.file("out.spt")}).code, 0);
}

// Issue 36 item 6: spt farm status read each shot's attempts marker line by line without
// bound; one grown huge (here 256 MiB of zeros, no newline) was read whole into one line.
TEST(HostileFarm, AHugeAttemptsMarkerIsRefusedNotRead) {
    TempDir d;
    fake_slurm(d);
    const std::string plan = d.file("p.json"), state = d.file("p.farm");
    ASSERT_FALSE(tiny_plan(d, plan).empty());
    ASSERT_EQ(run_spt(d, {"farm", "slurm", plan, "-o", d.file("out.spt")}).code, 0);
    const std::string a = state + "/run/shot-1.attempts";
    std::ofstream(a, std::ios::binary).flush();
    fs::resize_file(a, uint64_t(256) << 20);
    const auto r = run_spt(d, {"farm", "status", plan});
    EXPECT_TRUE(failed_with(r, 1, {a, "the farm state file is 268435456 bytes, over the limit of 1 MiB"}));
}

// Issue 36 item 10: the array list named every shot (40,000 shots passed the 128 KiB argument
// limit and sbatch could not start), and Slurm's MaxArraySize was a ceiling nobody was told of.
TEST(HostileFarm, TheArrayListIsRangesAndMaxArraySizeIsNamedUpFront) {
    TempDir d;
    fake_slurm_recording(d, 1001);
    const std::string plan = d.file("p.json");
    ASSERT_FALSE(tiny_plan(d, plan).empty());
    auto r = run_spt(d, {"farm", "slurm", plan, "-o", d.file("out.spt")});
    ASSERT_EQ(r.code, 0) << r.err;
    const std::string args = slurp(d.file("bin/sbatch.args"));
    EXPECT_NE(args.find("--array=0-1 "), std::string::npos) << args;

    // A cluster whose arrays stop below the plan's last shot: refused before anything is queued.
    TempDir e;
    fake_slurm_recording(e, 1);
    const std::string plan2 = e.file("p.json");
    ASSERT_FALSE(tiny_plan(e, plan2).empty());
    auto refused = run_spt(e, {"farm", "slurm", plan2, "-o", e.file("out.spt")});
    EXPECT_NE(refused.code, 0);
    EXPECT_NE(refused.err.find("MaxArraySize (1)"), std::string::npos) << refused.err;
    EXPECT_FALSE(fs::exists(e.file("bin/sbatch.args"))) << "nothing was submitted";
}

// Issue 35: sbatch ran through popen with hand-quoted arguments and its stderr in a fixed /tmp
// name. Now it is started with an argv; a plan in a folder whose name a shell would act on is
// submitted as it is, and sbatch's refusal is reported with its message and the file in the
// state folder that holds its stderr.
TEST(HostileFarm, SbatchGetsTheArgvAsItIsAndItsStderrIsReported) {
    TempDir d;
    fake_slurm_recording(d, 1001);
    fs::create_directories(d.file("a b 'c' $(touch pwned)"));
    const std::string plan = d.file("a b 'c' $(touch pwned)/p.json");
    ASSERT_FALSE(tiny_plan(d, plan).empty());
    auto r = run_spt(d, {"farm", "slurm", plan, "-o", d.file("out.spt")});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(slurp(d.file("bin/sbatch.args")).find(d.file("a b 'c' $(touch pwned)/p.farm/slurm_tasks.sh")), std::string::npos);
    EXPECT_FALSE(fs::exists(d.file("pwned")));

    TempDir e;
    fake_slurm(e);
    write_text(e.file("bin/sbatch"), "#!/bin/sh\necho 'sbatch: error: Batch job submission failed: Invalid account' >&2\nexit 1\n");
    const std::string plan2 = e.file("p.json");
    ASSERT_FALSE(tiny_plan(e, plan2).empty());
    auto refused = run_spt(e, {"farm", "slurm", plan2, "-o", e.file("out.spt")});
    EXPECT_EQ(refused.code, 1);
    const std::string log = e.file("p.farm/logs/sbatch.stderr");
    EXPECT_NE(refused.err.find("sbatch failed (exit 1): sbatch: error: Batch job submission failed: Invalid account"),
              std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find(log), std::string::npos) << refused.err;
    EXPECT_EQ(slurp(log), "sbatch: error: Batch job submission failed: Invalid account\n");
}
