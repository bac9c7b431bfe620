// The hand-rolled JSON and XML parsers: values, line numbers in errors, limits.
#include <gtest/gtest.h>

#include "spt_json/json.hpp"
#include "spt_import/xml.hpp"

using namespace spt;

TEST(Json, ParsesValuesAndLines) {
    auto v = json::parse("{\"a\": [1, -2.5e1, true, null],\n \"b\": \"x\\u00e9\\n\"}", "t.json");
    ASSERT_TRUE(v.ok()) << v.error().message;
    const json::Value* a = v->find("a");
    ASSERT_NE(a, nullptr);
    ASSERT_EQ(a->items.size(), 4u);
    EXPECT_EQ(a->items[1].number, -25);
    EXPECT_TRUE(a->items[2].boolean);
    const json::Value* b = v->find("b");
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->line, 2u);
    EXPECT_EQ(b->text, "x\xc3\xa9\n");
}

TEST(Json, ErrorsNameFileAndLine) {
    struct Case { const char* text; const char* expect; };
    const Case cases[] = {
        {"{\n\"a\": 1,\n}", "t.json:3:"},
        {"[1, 2", "t.json:1:"},
        {"{\"a\": 01}", "t.json:1:"},
        {"{\"a\": 1, \"a\": 2}", "duplicate key"},
        {"\"\\ud800\"", "surrogate"},
        {"[1e999]", "out of range"},
        {"{} x", "after the JSON value"},
        {"", "end of document"},
    };
    for (const auto& c : cases) {
        auto v = json::parse(c.text, "t.json");
        ASSERT_FALSE(v.ok()) << c.text;
        EXPECT_NE(v.error().message.find(c.expect), std::string::npos) << v.error().message;
    }
}

TEST(Json, DepthLimitStopsDeepNesting) {
    std::string deep(100000, '[');
    auto v = json::parse(deep, "deep.json");
    ASSERT_FALSE(v.ok());
    EXPECT_NE(v.error().message.find("nesting"), std::string::npos);
}

TEST(Xml, ParsesElementsAttributesEntities) {
    auto e = xml::parse("<?xml version=\"1.0\"?>\n<!DOCTYPE svg>\n<svg a='1 &amp; 2'>\n <!-- c -->\n <g><rect x=\"&#65;\"/></g>\n</svg>\n", "t.svg");
    ASSERT_TRUE(e.ok()) << e.error().message;
    EXPECT_EQ(e->name, "svg");
    EXPECT_EQ(e->attr("a")->value, "1 & 2");
    ASSERT_EQ(e->children.size(), 1u);
    EXPECT_EQ(e->children[0].line, 5u);
    EXPECT_EQ(e->children[0].children[0].attr("x")->value, "A");
}

TEST(Xml, ErrorsNameFileAndLine) {
    struct Case { const char* text; const char* expect; };
    const Case cases[] = {
        {"<svg>\n<g>\n</svg>", "t.svg:3:"},
        {"<svg a=1/>", "quoted"},
        {"<svg a='1' a='2'/>", "duplicate attribute"},
        {"<svg>&foo;</svg>", "unknown entity"},
        {"<svg>", "not closed"},
        {"<svg/><x/>", "after the root"},
        {"<!-- x", "unterminated"},
    };
    for (const auto& c : cases) {
        auto e = xml::parse(c.text, "t.svg");
        ASSERT_FALSE(e.ok()) << c.text;
        EXPECT_NE(e.error().message.find(c.expect), std::string::npos) << e.error().message;
    }
}

TEST(Xml, DepthLimit) {
    std::string deep;
    for (int i = 0; i < 1000; ++i) deep += "<g>";
    auto e = xml::parse(deep, "deep.svg");
    ASSERT_FALSE(e.ok());
    EXPECT_NE(e.error().message.find("deeper"), std::string::npos);
}

TEST(Json, ErrorsGiveLineAndColumnAndTheByteOffset) {
    auto v = json::parse("{\n  \"a\": [1,\n    tru]\n}", "t.json");
    ASSERT_FALSE(v.ok());
    EXPECT_EQ(v.error().message.rfind("t.json:3:", 0), 0u) << v.error().message;
    EXPECT_NE(v.error().message.find("t.json:3:8:"), std::string::npos) << v.error().message;  // the byte after "tru"
    // Lines of values after multi-line strings, numbers at line ends and nested containers.
    auto ok = json::parse("[1\n,\n{\"k\":\n\"v\"},\n[\n]\n, 2.5e0\n]", "t.json");
    ASSERT_TRUE(ok.ok()) << ok.error().message;
    EXPECT_EQ(ok->items[0].line, 1u);
    EXPECT_EQ(ok->items[1].line, 3u);
    EXPECT_EQ(ok->items[1].members[0].second.line, 4u);
    EXPECT_EQ(ok->items[2].line, 5u);
    EXPECT_EQ(ok->items[3].line, 7u);
    EXPECT_EQ(ok->items[3].text, "2.5e0");
}

TEST(Json, LimitsAreCheckedBeforeTheDocumentIsBuilt) {
    json::ParseLimits lim;
    lim.max_bytes = 10;
    auto big = json::parse("[1, 2, 3, 4, 5]", "t.json", lim);
    ASSERT_FALSE(big.ok());
    EXPECT_EQ(big.error().code, Code::LimitExceeded);
    lim = {};
    lim.max_values = 4;
    auto many = json::parse("[1, 2, 3, 4, 5]", "t.json", lim);
    ASSERT_FALSE(many.ok());
    EXPECT_EQ(many.error().code, Code::LimitExceeded);
    EXPECT_NE(many.error().message.find("too many"), std::string::npos);
    // Duplicate keys in a large object (the set path) as in a small one.
    std::string obj = "{";
    for (int i = 0; i < 100; ++i) obj += "\"k" + std::to_string(i) + "\": " + std::to_string(i) + ", ";
    auto dup = json::parse(obj + "\"k42\": 0}", "t.json");
    ASSERT_FALSE(dup.ok());
    EXPECT_NE(dup.error().message.find("duplicate key \"k42\""), std::string::npos) << dup.error().message;
    EXPECT_TRUE(json::parse(obj + "\"k100\": 0}", "t.json").ok());
}

TEST(Json, OneEscaperForEveryWriter) {
    EXPECT_EQ(json::quote("a\"b\\c\n\t\x01"), "\"a\\\"b\\\\c\\n\\t\\u0001\"");
    EXPECT_EQ(json::quote("caf\xc3\xa9"), "\"caf\xc3\xa9\"");            // valid UTF-8 as it is
    EXPECT_EQ(json::quote("a\xff" "b"), "\"a\xef\xbf\xbd" "b\"");         // invalid: U+FFFD
    auto back = json::parse(json::quote("x\xc3\xa9\x1f\xe2\x82"), "t.json");
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_EQ(back->text, "x\xc3\xa9\x1f\xef\xbf\xbd");
    // Invalid UTF-8 inside a document is refused.
    EXPECT_FALSE(json::parse("\"a\xff\"", "t.json").ok());
}
