// Cyclic OCIO configs (issue 36 item 7): OCIO 2.1 follows a colour space's references by
// recursion without noticing a loop, so a config whose colour space refers to itself, directly
// or through others, crashed spt (SIGSEGV) through --ocio, $OCIO and spt render --view alike.
#include <cstdlib>

#include "converter/cli_test_util.hpp"
#include "converter/ocio_test_config.hpp"

using namespace spt_test;

namespace {

std::string input(const std::string& name) { return std::string(SPT_SOURCE_DIR) + "/tests/hostile/inputs/" + name; }

// A config with a linear reference space, a display with a view of `view_space`, and `spaces`
// (YAML list items) after the reference.
std::string config(const std::string& spaces, const std::string& extra = "", const std::string& view_space = "a") {
    return "ocio_profile_version: 2\n"
           "roles:\n  default: lin_rec709\n  reference: lin_rec709\n  scene_linear: lin_rec709\n  loop_role: a\n"
           "file_rules:\n  - !<Rule> {name: Default, colorspace: default}\n"
           "displays:\n  sRGB:\n    - !<View> {name: Raw, colorspace: lin_rec709}\n"
           "    - !<View> {name: Bad, colorspace: " + view_space + "}\n" + extra +
           "colorspaces:\n  - !<ColorSpace>\n    name: lin_rec709\n    encoding: scene-linear\n" + spaces;
}

std::string space(const std::string& name, const std::string& to_ref, const std::string& more = "") {
    return "  - !<ColorSpace>\n    name: " + name + "\n    encoding: scene-linear\n" + more +
           "    to_scene_reference: " + to_ref + "\n";
}

void write(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

}  // namespace

TEST(HostileOcio, ACyclicConfigIsAnErrorNotACrash) {
    TempDir d;
    ASSERT_EQ(run_spt(d, {"paint", input("good.png"), "-o", d.file("g.spt"), "--max-strokes", "20"}).code, 0);
    const std::pair<const char*, std::string> cases[] = {
        {"itself", config(space("a", "!<ColorSpaceTransform> {src: a, dst: lin_rec709}"))},
        {"two spaces", config(space("a", "!<ColorSpaceTransform> {src: b, dst: lin_rec709}") +
                              space("b", "!<ColorSpaceTransform> {src: lin_rec709, dst: a}"))},
        {"an alias", config(space("a", "!<ColorSpaceTransform> {src: also_a, dst: lin_rec709}", "    aliases: [also_a]\n"))},
        {"a role", config(space("a", "!<ColorSpaceTransform> {src: loop_role, dst: lin_rec709}"))},
        {"a group", config(space("a", "!<GroupTransform> {children: [!<MatrixTransform> {}, "
                                      "!<ColorSpaceTransform> {src: a, dst: lin_rec709}]}"))},
        {"a look", config(space("a", "!<LookTransform> {src: lin_rec709, dst: lin_rec709, looks: +grade}"),
                          "looks:\n  - !<Look>\n    name: grade\n    process_space: a\n"
                          "    transform: !<MatrixTransform> {}\n")},
    };
    for (const auto& [what, text] : cases) {
        const std::string cfg = d.file("loop.ocio");
        write(cfg, text);
        const std::string said = "go round in a loop";
        auto r = run_spt(d, {"paint", input("good.png"), "-o", d.file("o.spt"), "--colorspace", "a", "--ocio", cfg});
        EXPECT_TRUE(r.code == 1 || r.code == 2) << what << ": exit " << r.code;
        EXPECT_TRUE(failed_with(r, kAnyFailure, {cfg, said})) << what;
        r = run_spt(d, {"render", d.file("g.spt"), "-o", d.file("v.png"), "--view", "Bad", "--ocio", cfg});
        EXPECT_TRUE(r.code == 1 || r.code == 2) << what << ": exit " << r.code;
        EXPECT_TRUE(failed_with(r, kAnyFailure, {cfg, said})) << what;
        // $OCIO set by someone else: the built-in config is used, and the loop is said.
        ::setenv("OCIO", cfg.c_str(), 1);
        r = run_spt(d, {"paint", input("good.png"), "-o", d.file("o.spt"), "--colorspace", "a"});
        ::unsetenv("OCIO");
        EXPECT_TRUE(r.code == 1 || r.code == 2) << what << ": exit " << r.code;
        EXPECT_TRUE(failed_with(r, kAnyFailure, {cfg, said})) << what;
        EXPECT_FALSE(fs::exists(d.file("o.spt"))) << what;
        EXPECT_FALSE(fs::exists(d.file("v.png"))) << what;
    }
    // References that do not loop are a config like any other.
    const std::string ok = d.file("ok.ocio");
    write(ok, config(space("a", "!<ColorSpaceTransform> {src: b, dst: lin_rec709}") +
                     space("b", "!<MatrixTransform> {matrix: [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1]}")));
    auto r = run_spt(d, {"paint", input("good.png"), "-o", d.file("o.spt"), "--colorspace", "a", "--ocio", ok,
                         "--max-strokes", "20"});
    EXPECT_EQ(r.code, 0) << r.err;
    r = run_spt(d, {"render", d.file("g.spt"), "-o", d.file("v.png"), "--view", "Bad", "--ocio", ok});
    EXPECT_EQ(r.code, 0) << r.err;
    r = run_spt(d, {"render", d.file("g.spt"), "-o", d.file("s.png"), "--view", "Raw",
                    "--ocio", write_studio_ocio(d.file("studio.ocio"))});
    EXPECT_EQ(r.code, 0) << r.err;
}
