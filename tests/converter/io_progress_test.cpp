// Progress: JSON lines are valid JSON with the documented keys; modes parse.
#include <gtest/gtest.h>

#include <sstream>
#include <thread>

#include "io/progress.hpp"
#include "spt_json/json.hpp"
#include "spt_json/write.hpp"
#include "io_json_check.hpp"

using namespace spt::io;
using spt_test::Json;
using spt_test::JsonParser;

namespace {

std::vector<Json> parse_lines(const std::string& text) {
    std::vector<Json> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        Json j;
        std::string err;
        EXPECT_TRUE(JsonParser::parse(line, j, &err)) << err << ": " << line;
        out.push_back(j);
    }
    return out;
}

}  // namespace

TEST(IoProgress, ParsesModes) {
    ProgressMode m;
    ASSERT_TRUE(parse_progress_mode("json", m));
    EXPECT_EQ(m, ProgressMode::Json);
    ASSERT_TRUE(parse_progress_mode("plain", m));
    EXPECT_EQ(m, ProgressMode::Plain);
    ASSERT_TRUE(parse_progress_mode("none", m));
    ASSERT_TRUE(parse_progress_mode("auto", m));
    EXPECT_FALSE(parse_progress_mode("bar", m));
}

TEST(IoProgress, JsonLinesAreValid) {
    testing::internal::CaptureStdout();
    {
        Progress p(ProgressMode::Json, "paint \"frames\"\n", 4);
        for (int i = 1; i <= 4; ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(210));
            p.update(i, "frame " + std::to_string(i) + " \xC3\xA9 \x01");
        }
        p.finish(true, "done");
    }
    const auto lines = parse_lines(testing::internal::GetCapturedStdout());
    ASSERT_GE(lines.size(), 3u);
    EXPECT_EQ(lines.front()["event"].str, "start");
    EXPECT_EQ(lines.back()["event"].str, "end");
    EXPECT_TRUE(lines.back()["ok"].b);
    EXPECT_EQ(lines.back()["done"].num, 4);
    EXPECT_EQ(lines.back()["percent"].num, 100);
    EXPECT_EQ(lines.front()["task"].str, "paint \"frames\"\n");
    for (const auto& j : lines)
        for (const char* k : {"event", "task", "done", "total", "percent", "elapsed", "eta", "fps", "detail"})
            EXPECT_TRUE(j.has(k)) << k;
    bool saw_progress = false;
    for (const auto& j : lines) saw_progress |= j["event"].str == "progress";
    EXPECT_TRUE(saw_progress);
}

TEST(IoProgress, AbandonedWorkEndsNotOk) {
    testing::internal::CaptureStdout();
    { Progress p(ProgressMode::Json, "t", 0); p.update(1); }
    const auto lines = parse_lines(testing::internal::GetCapturedStdout());
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_FALSE(lines.back()["ok"].b);
    EXPECT_EQ(lines.back()["total"].type, Json::Null);  // unknown total
}

TEST(IoProgress, NoneAndAutoInPipesPrintNothing) {
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    {
        Progress a(ProgressMode::None, "t", 3);
        a.update(2);
        a.finish(true);
    }
    EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(IoJson, QuotesAndNumbers) {
    EXPECT_EQ(spt::json::quote("a\"b\\c\n"), "\"a\\\"b\\\\c\\n\"");
    EXPECT_EQ(spt::json::quote("\xff"), "\"\xEF\xBF\xBD\"");
    EXPECT_EQ(spt::json::dump(spt::json::number(3)), "3");
    EXPECT_EQ(spt::json::dump(spt::json::number(0.5)), "0.5");
    EXPECT_EQ(spt::json::dump(spt::json::number(1.0 / 0.0)), "null");
    const spt::json::Doc d = {{"a", 1}, {"b", {1, "x"}}, {"c", spt::json::Doc::object()}};
    const std::string text = spt::json::dump(d, 2);
    Json j;
    std::string err;
    ASSERT_TRUE(JsonParser::parse(text, j, &err)) << err << text;
    EXPECT_EQ(j["b"][1].str, "x");
}
