// spt info against text in a file meant for the terminal (issue 36 item 11): metadata and
// template names are the file's own UTF-8 text, and ESC, BEL, DEL or the C1 control U+009B
// (CSI) in them reached the terminal raw, where they clear the screen, set the window title or
// recolour what follows. Now they are shown as \x1b, \u009b and the like, in both outputs.
#include "converter/cli_test_util.hpp"

using namespace spt_test;

namespace {

#define EXPECT_HAS(text, what) EXPECT_NE((text).find(what), std::string::npos) << "missing \"" << (what) << "\" in: " << (text)

// What a terminal would act on: C0 controls but newline, DEL, and C1 controls in UTF-8.
std::string first_control(const std::string& s) {
    for (size_t i = 0; i < s.size(); ++i) {
        const uint8_t c = uint8_t(s[i]);
        if ((c < 0x20 && c != '\n') || c == 0x7F || (c == 0xC2 && i + 1 < s.size() && uint8_t(s[i + 1]) <= 0x9F))
            return "byte " + std::to_string(c) + " at " + std::to_string(i);
    }
    return "";
}

}  // namespace

TEST(HostileInfo, ControlCharactersInTheFileAreShownNotSent) {
    TempDir d;
    const std::string in = d.file("escapes.spt");
    {
        spt::StreamInfo info = test_info();
        info.metadata = {{"title", "\x1b]0;owned\x07\x1b[2J\x1b[31mred"},
                         {"csi\xC2\x9b" "2J", "del\x7f"}};
        info.templates[2].name = "blob\x1b[0m";
        auto w = spt::Writer::create(in, info);
        ASSERT_TRUE(w.ok()) << w.error().message;
        spt::Frame key;
        ASSERT_TRUE((*w)->append(key).ok());
        ASSERT_TRUE((*w)->finish().ok());
    }
    auto r = run_spt(d, {"info", in});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(first_control(r.out), "") << r.out;
    EXPECT_HAS(r.out, "meta        title = \\x1b]0;owned\\x07\\x1b[2J\\x1b[31mred\n");
    EXPECT_HAS(r.out, "meta        csi\\u009b2J = del\\x7f\n");
    EXPECT_HAS(r.out, "\"blob\\x1b[0m\"");

    // JSON escapes keep the value: a parser reads back exactly the file's text.
    r = run_spt(d, {"info", in, "--json"});
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(first_control(r.out), "") << r.out;
    EXPECT_HAS(r.out, "\"title\": \"\\u001b]0;owned\\u0007\\u001b[2J\\u001b[31mred\"");
    EXPECT_HAS(r.out, "\"csi\\u009b2J\": \"del\\u007f\"");
    EXPECT_HAS(r.out, "\"blob\\u001b[0m\"");
}
