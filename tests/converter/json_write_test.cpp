// spt's JSON number form and layouts (json/ write.hpp): every figure spt prints is written as
// it was by the writer that nlohmann-json replaced (printf "%.6g", whole numbers exactly), so
// these strings are the contract of spt info --json, spt compare --json, progress lines and plans.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "spt_json/write.hpp"

using spt::json::Doc;
using spt::json::dump;
using spt::json::number;

TEST(JsonWrite, NumbersAsSixSignificantDigits) {
    EXPECT_EQ(dump(number(3)), "3");                          // not nlohmann's "3.0"
    EXPECT_EQ(dump(number(-42)), "-42");
    EXPECT_EQ(dump(number(0.5)), "0.5");
    EXPECT_EQ(dump(number(1.0 / 3.0)), "0.333333");           // not 0.3333333333333333
    EXPECT_EQ(dump(number(28.123456789)), "28.1235");
    EXPECT_EQ(dump(number(0.0001234)), "0.0001234");
    EXPECT_EQ(dump(number(0.00001234)), "1.234e-05");
    EXPECT_EQ(dump(number(123456.7)), "123457");              // rounds to a whole number
    EXPECT_EQ(dump(number(8e15)), "8000000000000000");        // whole: every digit
    EXPECT_EQ(dump(number(9.5e15)), "9.5e+15");
    EXPECT_EQ(dump(number(-0.0)), "0");
    EXPECT_EQ(dump(number(std::nan(""))), "null");
    EXPECT_EQ(dump(number(-std::numeric_limits<double>::infinity())), "null");
}

TEST(JsonWrite, StringsEscapedForTerminals) {
    // Invalid UTF-8 becomes U+FFFD; DEL and C1 controls are escaped, other UTF-8 kept.
    EXPECT_EQ(dump(Doc("a\xff" "b")), "\"a\xef\xbf\xbd" "b\"");
    EXPECT_EQ(dump(Doc("x\x7f" "y\xc2\x9b" "z\xc3\xa9")), "\"x\\u007fy\\u009bz\xc3\xa9\"");
    EXPECT_EQ(dump(Doc({{"k\x7f", "v"}})), "{\"k\\u007f\":\"v\"}");  // keys too
}

TEST(JsonWrite, PrettyAndCompact) {
    const Doc d = {{"b", 1}, {"a", Doc::array()}, {"c", {{"x", number(0.25)}}}};  // order kept
    EXPECT_EQ(dump(d), "{\"b\":1,\"a\":[],\"c\":{\"x\":0.25}}");
    EXPECT_EQ(dump(d, 2), "{\n  \"b\": 1,\n  \"a\": [],\n  \"c\": {\n    \"x\": 0.25\n  }\n}");
}

TEST(JsonWrite, LayoutBreaksChosenContainers) {
    const Doc d = {{"n", 1}, {"list", {{{"a", 1}, {"b", {1, 2}}}, {{"a", 2}, {"b", Doc::array()}}}}, {"none", Doc::array()}};
    const auto broken = [](const Doc&, std::string_view key, int depth) {
        return depth == 0 || key == "list" || key == "none";
    };
    EXPECT_EQ(spt::json::dump_layout(d, broken),
              "{\n  \"n\": 1,\n  \"list\": [\n    {\"a\": 1, \"b\": [1, 2]},\n    {\"a\": 2, \"b\": []}\n  ],\n"
              "  \"none\": [\n  ]\n}");
}
