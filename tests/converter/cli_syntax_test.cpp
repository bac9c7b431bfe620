// The shared command-line layer (converter/src/cli/args.hpp, on CLI11): `--name=value` means
// `--name value` on every command, `spt paint` included; help is generated from the option
// declarations; bad command lines exit 2.
#include <gtest/gtest.h>

#include "cli_test_util.hpp"

using namespace spt_test;

TEST(CliSyntax, EqualsFormMeansTheSameAsTwoWords) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string f = d.file("a.spt");
    write_test_spt(f, 6, 3);
    // render: --output=, --frames=, --progress=
    auto a = run_spt(d, {"render", f, "--output=" + d.file("eq.####.png"), "--frames=1-2", "--progress=none"});
    ASSERT_EQ(a.code, 0) << a.err;
    auto b = run_spt(d, {"render", f, "-o", d.file("sp.####.png"), "--frames", "1-2", "--progress", "none"});
    ASSERT_EQ(b.code, 0) << b.err;
    for (const char* n : {"0001", "0002"})
        EXPECT_EQ(slurp(d.file(std::string("eq.") + n + ".png")), slurp(d.file(std::string("sp.") + n + ".png"))) << n;
    EXPECT_FALSE(fs::exists(d.file("eq.0000.png")));
    // pack: --output=
    auto p = run_spt(d, {"pack", f, "--output=" + d.file("p.spt"), "--stored"});
    ASSERT_EQ(p.code, 0) << p.err;
    EXPECT_EQ(run_spt(d, {"verify", d.file("p.spt")}).code, 0);
    // export: --frames= (SVG) and --output=
    auto e = run_spt(d, {"export", f, "--output=" + d.file("x.svg"), "--frames=2"});
    ASSERT_EQ(e.code, 0) << e.err;
    EXPECT_NE(slurp(d.file("x.svg")).find("<svg"), std::string::npos);
    // import: --output= and --fps=
    auto j = run_spt(d, {"export", f, "-o", d.file("x.json")});
    ASSERT_EQ(j.code, 0) << j.err;
    auto i1 = run_spt(d, {"import", d.file("x.json"), "--output=" + d.file("i1.spt"), "--quiet"});
    auto i2 = run_spt(d, {"import", d.file("x.json"), "-o", d.file("i2.spt"), "--quiet"});
    ASSERT_EQ(i1.code, 0) << i1.err;
    ASSERT_EQ(i2.code, 0) << i2.err;
    EXPECT_EQ(slurp(d.file("i1.spt")), slurp(d.file("i2.spt")));
    // A malformed value through = is refused like the spaced form.
    EXPECT_EQ(run_spt(d, {"render", f, "--output=" + d.file("z.png"), "--frame=-1"}).code, 2);
    EXPECT_EQ(run_spt(d, {"render", f, "--output=" + d.file("z.png"), "--progress=loud"}).code, 2);
    // A flag takes no value.
    EXPECT_EQ(run_spt(d, {"info", f, "--json=x"}).code, 2);
}

TEST(CliSyntax, PaintTakesTheEqualsFormToo) {
    REQUIRE_TOOL();
    TempDir d;
    {
        spt::Canvas c(32, 24, {200, 40, 30});
        for (uint32_t y = 0; y < 24; ++y)
            for (uint32_t x = 16; x < 32; ++x) c.row(y)[x * 3 + 1] = 220;
        std::ofstream ppm(d.file("in.ppm"), std::ios::binary);
        ppm << "P6\n32 24\n255\n";
        ppm.write(reinterpret_cast<const char*>(c.rgb.data()), std::streamsize(c.rgb.size()));
    }
    // Issue 19: `spt paint --target-psnr=28` used to be refused.
    auto a = run_spt(d, {"paint", d.file("in.ppm"), "--output=" + d.file("a.spt"), "--target-psnr=28",
                         "--max-strokes=300", "--seed=7", "--progress=none", "--threads=1"});
    ASSERT_EQ(a.code, 0) << a.err;
    auto b = run_spt(d, {"paint", d.file("in.ppm"), "-o", d.file("b.spt"), "--target-psnr", "28",
                         "--max-strokes", "300", "--seed", "7", "--progress", "none", "--threads", "2"});
    ASSERT_EQ(b.code, 0) << b.err;
    EXPECT_EQ(slurp(d.file("a.spt")), slurp(d.file("b.spt")));
    EXPECT_TRUE(refused(d, {"paint", d.file("in.ppm"), "--output=" + d.file("c.spt"), "--sets=2"}, 2, {"--sets"},
                        d.file("c.spt")));
}

TEST(CliSyntax, HelpIsGeneratedFromTheOptionDeclarations) {
    REQUIRE_TOOL();
    TempDir d;
    struct Want { const char* cmd; std::vector<const char*> options; };
    const Want wants[] = {
        {"paint", {"-o, --output FILE", "--target-psnr DB", "--roi x,y,w,h", "(repeatable)", "--seed N",
                   "(default: 1)", "sequences and video:", "--flow-orientation", "exit status"}},
        {"render", {"-o, --output OUT", "--frames RANGE", "--progress MODE", "(default: auto)"}},
        {"info", {"--json", "--frames", "--no-fields"}},
        {"verify", {"arguments:"}},
        {"pack", {"--stored"}},
        {"import", {"-o, --output OUT.spt", "--from NAME", "-q, --quiet", "Importers (--from):"}},
        {"export", {"-o, --output OUT", "--frames RANGE", "--vector-only"}},
        {"compare", {"--json"}},
    };
    for (const auto& w : wants) {
        for (const char* h : {"--help", "-h"}) {
            auto r = run_spt(d, {w.cmd, h});
            EXPECT_EQ(r.code, 0) << w.cmd;
            EXPECT_TRUE(r.err.empty()) << w.cmd << ": " << r.err;
            EXPECT_EQ(r.out.rfind(std::string("spt ") + w.cmd + ": ", 0), 0u) << r.out;
            EXPECT_NE(r.out.find(std::string("usage: spt ") + w.cmd), std::string::npos) << r.out;
            EXPECT_NE(r.out.find("-h, --help"), std::string::npos) << r.out;
            for (const char* o : w.options) EXPECT_NE(r.out.find(o), std::string::npos) << w.cmd << " lacks " << o << "\n" << r.out;
            // Wrapped at 100 columns.
            std::istringstream lines(r.out);
            for (std::string line; std::getline(lines, line);) EXPECT_LE(line.size(), 100u) << w.cmd << ": " << line;
        }
    }
    // --help wins over everything else on the line, even a missing required argument.
    EXPECT_EQ(run_spt(d, {"render", "--help"}).code, 0);
}

TEST(CliSyntax, BadCommandLinesExitTwoWithTheCommandNamed) {
    REQUIRE_TOOL();
    TempDir d;
    for (const auto& args : std::vector<std::vector<std::string>>{
             {"paint"}, {"paint", "in.png"}, {"paint", "in.png", "-o"}, {"paint", "a.png", "b.png", "-o", "x.spt"},
             {"paint", "in.png", "-o", "x.spt", "--bogus=1"}, {"import", "x.json", "--from"},
             {"export", "x.spt", "--output"}, {"export", "x.spt", "-o", "x.json", "--vector-only"},
             {"export", "x.spt", "-o", "x.html", "--vector-only"}, {"compare", "a.png", "b.png", "--min-psnr=abc"}}) {
        auto r = run_spt(d, args);
        EXPECT_EQ(r.code, 2) << args[0] << " " << r.err;
        EXPECT_EQ(r.err.rfind("spt " + args[0] + ": ", 0), 0u) << r.err;
        EXPECT_NE(r.err.find("spt " + args[0] + " --help"), std::string::npos) << r.err;
    }
    // An unknown option is named even when the required arguments are missing too.
    for (const std::string cmd : {"paint", "render", "cat", "info"}) {
        auto r = run_spt(d, {cmd, "--bogus"});
        EXPECT_EQ(r.code, 2) << cmd;
        EXPECT_NE(r.err.find("--bogus"), std::string::npos) << cmd << ": " << r.err;
    }
}
