// farm/process: the farm's clients run with posix_spawnp and an argv. A path or argument holding
// spaces, quotes and $(...) reaches the program as it is (no shell reads it), and a failing
// command's stderr, written into the folder the caller names, is what its error reports.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "farm/process.hpp"
#include "format/test_dir.hpp"

namespace fs = std::filesystem;
using spt::testing::TestDir;

namespace {

void write_script(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
    fs::permissions(path, fs::perms::owner_all, fs::perm_options::add);
}

std::string slurp(const std::string& path) {
    std::ifstream f(path);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

}  // namespace

TEST(FarmProcess, ArgumentsReachTheProgramAsTheyAre) {
    TestDir d;
    // The folder of the program itself is a name a shell would act on.
    const std::string dir = d / "a b 'c' \"d\" $(touch pwned) `touch pwned2`";
    fs::create_directories(dir);
    const std::string prog = dir + "/print args";
    write_script(prog, "#!/bin/sh\nfor a in \"$@\"; do printf '<%s>\\n' \"$a\"; done\n");
    const std::vector<std::string> argv = {prog, "x y", "it's", "\"q\"", "$(touch pwned3)", "a;b|c&&d", "$HOME", ""};
    spt::Result<std::string> out = spt::farm::run_capture(argv, d / "stderr.txt");
    ASSERT_TRUE(out) << out.error().message;
    EXPECT_EQ(*out, "<x y>\n<it's>\n<\"q\">\n<$(touch pwned3)>\n<a;b|c&&d>\n<$HOME>\n<>\n");
    for (const char* n : {"pwned", "pwned2", "pwned3"}) {
        EXPECT_FALSE(fs::exists(d / n)) << n;
        EXPECT_FALSE(fs::exists(n)) << n;
    }
}

TEST(FarmProcess, AFailingCommandsStderrIsReportedAndKeptInTheFolderGiven) {
    TestDir d;
    fs::create_directories(d / "state dir/logs");
    const std::string prog = d / "fails";
    write_script(prog, "#!/bin/sh\necho 'sbatch: first line' >&2\necho 'sbatch: error: Batch job submission failed: "
                       "Invalid partition name specified' >&2\necho partial\nexit 3\n");
    const std::string err = spt::farm::stderr_file_for(d / "state dir", prog);
    EXPECT_EQ(err, d / "state dir/logs/fails.stderr");
    spt::Result<std::string> out = spt::farm::run_capture({prog, "--parsable"}, err);
    ASSERT_FALSE(out);
    const std::string& m = out.error().message;
    EXPECT_NE(m.find(prog + " failed (exit 3)"), std::string::npos) << m;
    EXPECT_NE(m.find("Invalid partition name specified"), std::string::npos) << m;
    EXPECT_NE(m.find(err), std::string::npos) << m;
    EXPECT_EQ(slurp(err), "sbatch: first line\nsbatch: error: Batch job submission failed: Invalid partition name specified\n");
    // A second run empties the file first.
    write_script(prog, "#!/bin/sh\necho ok\n");
    spt::Result<std::string> ok = spt::farm::run_capture({prog}, err);
    ASSERT_TRUE(ok) << ok.error().message;
    EXPECT_EQ(*ok, "ok\n");
    EXPECT_EQ(slurp(err), "");
}

TEST(FarmProcess, AMissingProgramOrUnwritableStderrIsAnError) {
    TestDir d;
    spt::Result<std::string> out = spt::farm::run_capture({"spt-no-such-program"}, d / "e.txt");
    ASSERT_FALSE(out);
    EXPECT_NE(out.error().message.find("cannot run spt-no-such-program"), std::string::npos) << out.error().message;
    // stderr is never written through a symlink.
    fs::create_symlink(d / "elsewhere", d / "link");
    out = spt::farm::run_capture({"true"}, d / "link");
    ASSERT_FALSE(out);
    EXPECT_NE(out.error().message.find(d / "link"), std::string::npos) << out.error().message;
    EXPECT_FALSE(fs::exists(d / "elsewhere"));
}
