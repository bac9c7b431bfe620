// spt cat: joins, its refusals (named files, exit 1), and a plan's shots (once each, in order,
// complete).
#include "converter/cli_test_util.hpp"

#include "spt/concat.hpp"

namespace {

using namespace spt_test;

// A shot file of plan `id`: `frames` frames of test_info(), tagged as shot k of n.
void write_shot(const std::string& path, const std::string& id, int k, int n, int frames, long first,
                long tagged_last = -1) {
    spt::StreamInfo info = test_info();
    info.metadata.emplace_back("plan.id", id);
    info.metadata.emplace_back("part.shot", std::to_string(k) + "/" + std::to_string(n));
    const long last = tagged_last >= 0 ? tagged_last : first + frames - 1;
    info.metadata.emplace_back("part.frames", std::to_string(first) + "-" + std::to_string(last));
    info.metadata.emplace_back("source.first_frame", std::to_string(first));
    std::mt19937 rng(uint32_t(k + 1));
    auto w = spt::Writer::create(path, info);
    ASSERT_TRUE(w.ok());
    for (int i = 0; i < frames; ++i) {
        spt::Frame f;
        f.index = uint32_t(i);
        f.type = i == 0 ? spt::FrameType::Key : spt::FrameType::Inter;
        for (int s = 0; s < 12; ++s) f.added.push_back(random_stroke(rng));
        ASSERT_TRUE((*w)->append(f).ok());
    }
    ASSERT_TRUE((*w)->finish().ok());
}

TEST(CatCli, JoinsAndTheResultVerifies) {
    REQUIRE_TOOL();
    TempDir d;
    write_test_spt(d.file("a.spt"), 12, 5, spt::Coding::Range, 1);
    write_test_spt(d.file("b.spt"), 7, 3, spt::Coding::Range, 2);
    RunResult r = run_spt(d, {"cat", d.file("a.spt"), d.file("b.spt"), d.file("a.spt"), "-o", d.file("ab.spt")});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.out.find("3 parts, 31 frames"), std::string::npos) << r.out;
    r = run_spt(d, {"verify", d.file("ab.spt")});
    EXPECT_EQ(r.code, 0) << r.err;
    // Frame 12 of the join renders as frame 0 of b.
    ASSERT_EQ(run_spt(d, {"render", d.file("ab.spt"), "--frame", "12", "-o", d.file("j.png")}).code, 0);
    ASSERT_EQ(run_spt(d, {"render", d.file("b.spt"), "--frame", "0", "-o", d.file("b.png")}).code, 0);
    EXPECT_EQ(slurp(d.file("j.png")), slurp(d.file("b.png")));
    // The output may not be a part; a missing part is named.
    EXPECT_EQ(run_spt(d, {"cat", d.file("a.spt"), "-o", d.file("a.spt")}).code, 2);
    EXPECT_TRUE(refused(d, {"cat", d.file("a.spt"), d.file("nope.spt"), "-o", d.file("x.spt")}, 1, {"nope.spt"},
                        d.file("x.spt")));
}

// --list FILE: parts one a line after those on the command line (a farm's join of more shots
// than a command line holds): the same bytes as naming them all.
TEST(CatCli, AListFileGivesTheSamePartsAsTheCommandLine) {
    REQUIRE_TOOL();
    TempDir d;
    write_test_spt(d.file("a.spt"), 12, 5, spt::Coding::Range, 1);
    write_test_spt(d.file("b.spt"), 7, 3, spt::Coding::Range, 2);
    write_text(d.file("parts.list"), d.file("b.spt") + "\n\n" + d.file("a.spt") + "\n");
    ASSERT_EQ(run_spt(d, {"cat", d.file("a.spt"), d.file("b.spt"), d.file("a.spt"), "-o", d.file("named.spt")}).code, 0);
    RunResult r = run_spt(d, {"cat", d.file("a.spt"), "--list", d.file("parts.list"), "-o", d.file("listed.spt")});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(slurp(d.file("listed.spt")), slurp(d.file("named.spt")));
    // A missing list is named; a list with no parts and nothing else is a usage error.
    EXPECT_TRUE(refused(d, {"cat", "--list", d.file("nope.list"), "-o", d.file("x.spt")}, 1, {"nope.list"},
                        d.file("x.spt")));
    write_text(d.file("empty.list"), "\n");
    EXPECT_EQ(run_spt(d, {"cat", "--list", d.file("empty.list"), "-o", d.file("x.spt")}).code, 2);
}

TEST(CatCli, RefusesADifferentCanvasNamingTheFile) {
    REQUIRE_TOOL();
    TempDir d;
    write_test_spt(d.file("a.spt"), 6, 5);
    spt::StreamInfo info = test_info();
    info.header.width = 65;
    {
        auto w = spt::Writer::create(d.file("wide.spt"), info);
        ASSERT_TRUE(w.ok());
        spt::Frame f;
        ASSERT_TRUE((*w)->append(f).ok());
        ASSERT_TRUE((*w)->finish().ok());
    }
    EXPECT_TRUE(refused(d, {"cat", d.file("a.spt"), d.file("wide.spt"), "-o", d.file("x.spt")}, 1,
                        {d.file("wide.spt") + ": cannot be joined", "65x48"}, d.file("x.spt")));
}

TEST(CatCli, APlansShotsJoinOnceEachInOrderAndComplete) {
    REQUIRE_TOOL();
    TempDir d;
    write_shot(d.file("s0.spt"), "p1", 0, 3, 4, 1001);
    write_shot(d.file("s1.spt"), "p1", 1, 3, 3, 1005);
    write_shot(d.file("s2.spt"), "p1", 2, 3, 5, 1008);
    write_shot(d.file("other.spt"), "p2", 1, 3, 3, 1005);
    write_shot(d.file("short.spt"), "p1", 1, 3, 2, 1005, 1007);  // interrupted: 2 of 3 frames
    RunResult r = run_spt(d, {"cat", d.file("s0.spt"), d.file("s1.spt"), d.file("s2.spt"), "-o", d.file("all.spt")});
    ASSERT_EQ(r.code, 0) << r.err;
    auto rd = spt::Reader::open(d.file("all.spt"));
    ASSERT_TRUE(rd.ok());
    EXPECT_EQ(spt::first_frame_number((*rd)->info()), 1001u);
    for (const auto& [k, v] : (*rd)->info().metadata) EXPECT_NE(k.rfind("part.", 0), 0u) << k;

    auto join_refused = [&](const std::vector<std::string>& parts, const std::string& file, const std::string& words) {
        std::vector<std::string> args = {"cat"};
        for (const auto& p : parts) args.push_back(d.file(p));
        args.insert(args.end(), {"-o", d.file("x.spt")});
        EXPECT_TRUE(refused(d, args, 1, {d.file(file), words}, d.file("x.spt"))) << words;
    };
    join_refused({"s0.spt", "s2.spt"}, "s2.spt", "shot 1 is missing");
    join_refused({"s0.spt", "s1.spt"}, "s1.spt", "shots 2-2 are missing");
    join_refused({"s0.spt", "s1.spt", "s1.spt", "s2.spt"}, "s1.spt", "extra");
    join_refused({"s0.spt", "s1.spt", "s2.spt", "s2.spt"}, "s2.spt", "extra");
    join_refused({"s0.spt", "other.spt", "s2.spt"}, "other.spt", "plan p2");
    join_refused({"s0.spt", "short.spt", "s2.spt"}, "short.spt", "holds 2 of its 3 frames");
}

}  // namespace
