// spt::is_valid_utf8: the Writer refuses text a reader or a JSON export could not carry (issue 20).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include "spt/spt.hpp"
#include "format/test_dir.hpp"

using namespace spt;
using namespace spt::testing;
namespace fs = std::filesystem;

namespace {

}  // namespace

TEST(Utf8, AcceptsWellFormedAndRejectsTheRest) {
    EXPECT_TRUE(is_valid_utf8(""));
    EXPECT_TRUE(is_valid_utf8("plain ascii"));
    EXPECT_TRUE(is_valid_utf8("caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x8E\xA8 \xF4\x8F\xBF\xBF"));
    size_t at = 99;
    EXPECT_FALSE(is_valid_utf8("ab\xFF", &at));
    EXPECT_EQ(at, 2u);
    EXPECT_FALSE(is_valid_utf8("\xC0\xAF"));          // overlong '/'
    EXPECT_FALSE(is_valid_utf8("\xE0\x80\xAF"));      // overlong
    EXPECT_FALSE(is_valid_utf8("\xED\xA0\x80"));      // surrogate U+D800
    EXPECT_FALSE(is_valid_utf8("\xF4\x90\x80\x80"));  // above U+10FFFF
    EXPECT_FALSE(is_valid_utf8("\xE2\x82"));          // truncated
    EXPECT_FALSE(is_valid_utf8("\x80"));              // lone continuation
    EXPECT_EQ(printable_text("a\xFF\xC3\xA9\n"), "a\\xff\xC3\xA9\\x0a");
    // ESC, DEL and the C1 control U+009B (CSI) are made visible; U+00A0 is text.
    EXPECT_EQ(printable_text("\x1b[2J\x7f\xC2\x9b" "2J\xC2\xA0"), "\\x1b[2J\\x7f\\u009b2J\xC2\xA0");
}

TEST(WriterText, RefusesMetadataThatIsNotUtf8NamingTheKey) {
    TestDir d;
    StreamInfo info = small_info();
    info.metadata = {{"software", "ok"}, {"title", "caf\xE9"}};
    auto w = Writer::create(d / "o.spt", info);
    ASSERT_FALSE(w.ok());
    EXPECT_NE(w.error().message.find("metadata key \"title\": the value is not valid UTF-8 (byte 3)"), std::string::npos)
        << w.error().message;
    info.metadata = {{"ti\xFFtle", "x"}};
    w = Writer::create(d / "o.spt", info);
    ASSERT_FALSE(w.ok());
    EXPECT_NE(w.error().message.find("metadata key \"ti\\xfftle\" is not valid UTF-8"), std::string::npos) << w.error().message;
    info.metadata.clear();
    info.templates[0].name = "\xC0\xAF";
    w = Writer::create(d / "o.spt", info);
    ASSERT_FALSE(w.ok());
    EXPECT_NE(w.error().message.find("template 0"), std::string::npos) << w.error().message;
    EXPECT_TRUE(d.names().empty()) << "nothing is written for a refused file";
}
