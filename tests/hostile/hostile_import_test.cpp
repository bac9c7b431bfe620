// Stroke lists over their counts (issue 36 item 6): the JSON parser checks a list's length
// against the importer's limit as it reads, so a list is refused before the parse tree holds it.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include "converter/cli_test_util.hpp"
#include "hostile/spawn_quiet.hpp"

using namespace spt_test;

namespace {

// Runs spt with `args` (output discarded); its exit code and peak resident size in MiB.
std::pair<int, long> run_measured_mib(const std::vector<std::string>& args) {
    const auto [code, kib] = spt_test::run_measured(args);
    return {code, kib / 1024};
}

}  // namespace

// A polygon of 1,000,000 vertices (the limit is 65,536) took about 400 MB and seconds before
// it was refused (10 million: 3.7 GB); so did a point of a million numbers.
TEST(HostileImport, AListOverItsCountIsRefusedBeforeItIsHeld) {
    TempDir d;
    const std::string head = "{\"format\": \"spt-strokes\", \"version\": 2, \"canvas\": {\"width\": 64, \"height\": 64}, "
                             "\"frames\": [{\"type\": \"key\", \"strokes\": [{\"type\": \"polygon\", \"color\": [1, 2, 3, 255], "
                             "\"points\": [";
    std::string many = head, wide = head + "[1";
    for (int i = 0; i < 1000000; ++i) many += i ? ", [1, 2]" : "[1, 2]";
    for (int i = 0; i < 1000000; ++i) wide += ", 2";
    many += "]}]}]}\n";
    wide += "], [3, 4], [5, 6]]}]}]}\n";
    { std::ofstream(d.file("many.json")) << many; }
    { std::ofstream(d.file("wide.json")) << wide; }
    auto r = run_spt(d, {"import", d.file("many.json"), "-o", d.file("o.spt")});
    EXPECT_TRUE(failed_with(r, 1, {d.file("many.json") + ":1:", "\"points\" holds more than 65536 items"}));
    r = run_spt(d, {"import", d.file("wide.json"), "-o", d.file("o.spt")});
    EXPECT_TRUE(failed_with(r, 1, {d.file("wide.json") + ":1:", "\"points\"[0] holds more than 16 items"}));
    // What it took beyond the command's own start-up (its libraries): a few MB, not the list.
    const std::string min = std::string(SPT_SOURCE_DIR) + "/tests/hostile/inputs/strokes_min.json";
    const auto base = run_measured_mib({"import", min, "-o", d.file("min.spt")});
    const auto big = run_measured_mib({"import", d.file("many.json"), "-o", d.file("o.spt")});
    EXPECT_EQ(base.first, 0);
    EXPECT_EQ(big.first, 1);
    EXPECT_LT(big.second - base.second, 64) << "MiB beyond start-up";
    EXPECT_FALSE(fs::exists(d.file("o.spt")));
    // At the limit the polygon is read (and refused later only for what it is, if anything).
    std::string ok = head;
    for (int i = 0; i < 65536; ++i) ok += i ? ", [1, 2]" : "[1, 2]";
    ok += "]}]}]}\n";
    { std::ofstream(d.file("ok.json")) << ok; }
    r = run_spt(d, {"import", d.file("ok.json"), "-o", d.file("o.spt")});
    EXPECT_EQ(r.err.find("holds more than"), std::string::npos) << r.err;
}
