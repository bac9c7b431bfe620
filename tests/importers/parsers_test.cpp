// The hand-rolled JSON and XML parsers: values, line numbers in errors, limits.
#include <gtest/gtest.h>

#include "spt_import/json.hpp"
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
