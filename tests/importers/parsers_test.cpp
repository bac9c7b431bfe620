// The JSON layer (json/, on nlohmann-json) and the SVG importers' XML (pugixml): values, line
// numbers in errors, limits.
#include <gtest/gtest.h>

#include "spt_json/json.hpp"
#include "spt_import/xml.hpp"

using namespace spt;

namespace {

// The error of a parse that must fail (empty when it parsed); `what` names the input.
template <class R>
Error error_of(const R& r, const std::string& what = {}) {
    EXPECT_FALSE(r.ok()) << "parsed: " << what;
    return r.ok() ? Error{} : r.error();
}

}  // namespace

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
        const Error v = error_of(json::parse(c.text, "t.json"), c.text);
        EXPECT_NE(v.message.find(c.expect), std::string::npos) << v.message;
    }
}

TEST(Json, DepthLimitStopsDeepNesting) {
    std::string deep(100000, '[');
    const Error v = error_of(json::parse(deep, "deep.json"));
    EXPECT_NE(v.message.find("nesting"), std::string::npos);
}

TEST(Xml, ParsesElementsAttributesEntities) {
    const std::string text = "<?xml version=\"1.0\"?>\n<!DOCTYPE svg>\n<svg a='1 &amp; 2'>\n <!-- c -->\n <g><rect x=\"&#65;\"/></g>\n</svg>\n";
    auto d = xml::Document::parse(text, "t.svg");
    ASSERT_TRUE(d.ok()) << d.error().message;
    const pugi::xml_node e = (*d)->root();
    EXPECT_STREQ(e.name(), "svg");
    EXPECT_STREQ(e.attribute("a").value(), "1 & 2");
    const pugi::xml_node g = e.child("g");
    ASSERT_TRUE(g);
    EXPECT_EQ((*d)->line(g), 5u);
    EXPECT_EQ((*d)->line(e), 3u);
    EXPECT_STREQ(g.child("rect").attribute("x").value(), "A");
    EXPECT_EQ(xml::local_name(e), "svg");
}

TEST(Xml, ErrorsNameFileAndLine) {
    struct Case { const char* text; const char* expect; };
    const Case cases[] = {
        {"<svg>\n<g>\n</svg>", "t.svg:3: end tag </svg>"},
        {"<svg a=1/>", "quoted"},
        {"<svg a='1' a='2'/>", "duplicate attribute"},
        {"<svg>\n<g>\n</g>", "not closed"},
        {"<svg/><x/>", "after the root"},
        {"<!-- x", "unterminated"},
        {"<svg><![CDATA[ x</svg>", "CDATA"},
        {"", "root element"},
    };
    for (const auto& c : cases) {
        const Error e = error_of(xml::Document::parse(c.text, "t.svg"), c.text);
        EXPECT_NE(e.message.find(c.expect), std::string::npos) << e.message;
        EXPECT_EQ(e.message.rfind("t.svg", 0), 0u) << e.message;
    }
}

TEST(Xml, NoEntityIsDefinedByTheDocument) {
    // Entity declarations (billion laughs, external entities) are refused, never expanded;
    // a reference to an undeclared entity stays as written.
    for (const char* dtd : {"<!DOCTYPE svg [<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;&a;&a;\">]>",
                            "<!DOCTYPE svg [\n<!ENTITY x SYSTEM \"file:///etc/passwd\">\n]>"}) {
        const Error d = error_of(xml::Document::parse(std::string(dtd) + "\n<svg t=\"&b;&x;\">&b;</svg>", "t.svg"), dtd);
        EXPECT_NE(d.message.find("declares entities"), std::string::npos) << d.message;
    }
    auto d = xml::Document::parse("<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" \"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd\">\n"
                                  "<svg t=\"&foo;&amp;\">&b;</svg>", "t.svg");
    ASSERT_TRUE(d.ok()) << d.error().message;
    EXPECT_STREQ((*d)->root().attribute("t").value(), "&foo;&");
}

TEST(Xml, DepthLimit) {
    std::string deep;
    for (int i = 0; i < 1000; ++i) deep += "<g>";
    const Error e = error_of(xml::Document::parse(deep, "deep.svg"));  // unterminated too: the depth is named
    EXPECT_NE(e.message.find("deeper"), std::string::npos) << e.message;
    for (int i = 0; i < 1000; ++i) deep += "</g>";
    const Error f = error_of(xml::Document::parse(deep, "deep.svg"));
    EXPECT_NE(f.message.find("deeper"), std::string::npos) << f.message;
}

TEST(Xml, ElementAndSizeLimitsBeforeParsing) {
    xml::ParseLimits lim;
    lim.max_elements = 3;
    const Error many = error_of(xml::Document::parse("<svg><g/><g/><g/></svg>", "t.svg", lim));
    EXPECT_EQ(many.code, Code::LimitExceeded);
    EXPECT_TRUE(xml::Document::parse("<svg><g/><g/></svg>", "t.svg", lim).ok());
    lim = {};
    lim.max_bytes = 8;
    const Error big = error_of(xml::Document::parse("<svg></svg>", "t.svg", lim));
    EXPECT_EQ(big.code, Code::LimitExceeded);
}

TEST(Json, ErrorsGiveLineAndColumnAndTheByteOffset) {
    const Error v = error_of(json::parse("{\n  \"a\": [1,\n    tru]\n}", "t.json"));
    EXPECT_EQ(v.message.rfind("t.json:3:", 0), 0u) << v.message;
    EXPECT_NE(v.message.find("t.json:3:8:"), std::string::npos) << v.message;  // the byte after "tru"
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
    const Error big = error_of(json::parse("[1, 2, 3, 4, 5]", "t.json", lim));
    EXPECT_EQ(big.code, Code::LimitExceeded);
    lim = {};
    lim.max_values = 4;
    const Error many = error_of(json::parse("[1, 2, 3, 4, 5]", "t.json", lim));
    EXPECT_EQ(many.code, Code::LimitExceeded);
    EXPECT_NE(many.message.find("too many"), std::string::npos);
    // Duplicate keys in a large object (the set path) as in a small one.
    std::string obj = "{";
    for (int i = 0; i < 100; ++i) obj += "\"k" + std::to_string(i) + "\": " + std::to_string(i) + ", ";
    const Error dup = error_of(json::parse(obj + "\"k42\": 0}", "t.json"));
    EXPECT_NE(dup.message.find("duplicate key \"k42\""), std::string::npos) << dup.message;
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

TEST(Xml, LinesSurviveTheInPlaceParse) {
    // pugixml rewrites the buffer (terminators after names, newlines in attribute values turned
    // to spaces); lines come from an index of the text as it was.
    auto d = xml::Document::parse("<svg\n  a=\"1\n2\n3\">\n<g\n/>\n\n<rect/></svg>", "t.svg");
    ASSERT_TRUE(d.ok()) << d.error().message;
    EXPECT_STREQ((*d)->root().attribute("a").value(), "1 2 3");
    EXPECT_EQ((*d)->line((*d)->root().child("g")), 5u);
    EXPECT_EQ((*d)->line((*d)->root().child("rect")), 8u);
    EXPECT_EQ((*d)->elements(), 3u);
    (*d)->release((*d)->root().child("g"));
    EXPECT_FALSE((*d)->root().child("g"));
    EXPECT_EQ((*d)->line((*d)->root().child("rect")), 8u);
}
