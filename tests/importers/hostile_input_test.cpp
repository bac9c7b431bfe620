// Crafted importer input (issue 20): parsed numbers outside an integer's range, invalid UTF-8 in
// the text a .spt carries, absurd sequence patterns. Each fails cleanly, naming what is wrong.
#include <gtest/gtest.h>

#include <string>

#include "spt/utf8.hpp"
#include "spt_import/importer.hpp"

using namespace spt;
using namespace spt::import;

namespace {

Result<Document> load(const char* importer, const std::string& text) {
    const Importer* imp = find_importer(importer);
    EXPECT_NE(imp, nullptr) << importer;
    return imp->load("in", text, ImportOptions{});
}

const char* kJsonHead =
    R"({"format": "spt-strokes", "version": 1, "canvas": {"width": 8, "height": 8}, )";

}  // namespace

// 1e93 became int64_t(1e93), undefined behaviour that printed "-9223372036854775808x10".
TEST(HostileImport, SvgCanvasOfAHugeNumberIsRefusedAndNamedExactly) {
    auto r = load("svg", R"(<svg xmlns="http://www.w3.org/2000/svg" width="1e93" height="10"></svg>)");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("canvas 1e+93x10 is above the limits"), std::string::npos) << r.error().message;
    EXPECT_EQ(r.error().message.find("-9223372036854775808"), std::string::npos) << r.error().message;
}

// Colour components saturate (clamp_round) rather than convert out of range.
TEST(HostileImport, SvgColourComponentsOutOfRangeSaturate) {
    auto r = load("svg", R"(<svg xmlns="http://www.w3.org/2000/svg" width="4" height="4">)"
                         R"x(<rect x="1" y="1" width="2" height="2" fill="rgb(1e300,300,-5)"/></svg>)x");
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_FALSE(r->frames.at(0).added.empty());
    const Stroke& s = r->frames[0].added.back();
    ASSERT_EQ(s.kind, StrokeKind::Affine);
    EXPECT_EQ(s.affine.color.r, 255);
    EXPECT_EQ(s.affine.color.g, 255);
    EXPECT_EQ(s.affine.color.b, 0);
}

// uint32_t(-3.0) + 1 was undefined behaviour (a huge or zero canvas in practice).
TEST(HostileImport, GeometrizeBackgroundLeftOfTheOriginIsRefused) {
    auto r = load("geometrize-json", R"({"shapes": [{"type": 1, "data": [-10, -10, -3, -3], "color": [1, 2, 3, 255]}]})");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("background rectangle ends before the origin"), std::string::npos) << r.error().message;
}

// std::stoi threw out_of_range on a pattern width of 13 digits (an uncaught exception).
TEST(HostileImport, SequencePatternWithAHugeWidthMatchesNothing) {
    auto r = expand_inputs("/nonexistent-spt-dir/frame_%09999999999999d.json");
    ASSERT_FALSE(r.ok());
}

// SPEC.md 3.3: metadata is UTF-8. It was accepted as bytes, and `spt export` then wrote invalid JSON.
TEST(HostileImport, JsonMetadataValueOfInvalidUtf8IsRefusedNamingTheKey) {
    auto r = load("spt-json", std::string(kJsonHead) + "\"metadata\": {\"title\": \"caf\xE9\"}, \"frames\": [{\"type\": \"key\", \"strokes\": []}]}");
    ASSERT_FALSE(r.ok());
    // The JSON layer (json/, on nlohmann-json) refuses it while it reads, naming where.
    EXPECT_NE(r.error().message.find("the value of key \"title\" in \"metadata\" is not valid UTF-8"), std::string::npos)
        << r.error().message;
    EXPECT_EQ(r.error().message.rfind("in:1:105:", 0), 0u) << r.error().message;
}

TEST(HostileImport, JsonMetadataKeyOfInvalidUtf8IsRefused) {
    auto r = load("spt-json", std::string(kJsonHead) + "\"metadata\": {\"ti\xC0\xAFtle\": \"x\"}, \"frames\": [{\"type\": \"key\", \"strokes\": []}]}");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("a key of \"metadata\" is not valid UTF-8"), std::string::npos) << r.error().message;
}

TEST(HostileImport, JsonTemplateNameOfInvalidUtf8IsRefused) {
    auto r = load("spt-json", std::string(kJsonHead) +
                                  "\"templates\": [{\"kind\": \"ellipse\", \"name\": \"\xED\xA0\x80\"}], \"frames\": [{\"type\": \"key\", \"strokes\": []}]}");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("not valid UTF-8"), std::string::npos) << r.error().message;
}

TEST(HostileImport, ValidUtf8MetadataStillImports) {
    auto r = load("spt-json", std::string(kJsonHead) + "\"metadata\": {\"title\": \"caf\xC3\xA9 \xF0\x9F\x8E\xA8\"}, \"frames\": [{\"type\": \"key\", \"strokes\": []}]}");
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r->info.metadata.at(0).second, "caf\xC3\xA9 \xF0\x9F\x8E\xA8");
}

// Found by the instrumented fuzz target: the geometrize ellipse rasteriser squared its row in
// int (46341^2 overflows: an ellipse of ry 60000) and turned NaN into an int (a denormal ry
// made rx/ry infinite). Both import now; the inputs are also in the geometrize corpus.
TEST(HostileImport, GeometrizeEllipsesOfExtremeRadiiImport) {
    for (const char* ry : {"60000", "1e-40"}) {
        auto r = load("geometrize-json", std::string(R"({"shapes": [{"type": 1, "data": [0, 0, 63, 47], "color": [255, 255, 255, 255]},)") +
                                             R"({"type": 8, "data": [10, 10, 5, )" + ry + R"(], "color": [1, 2, 3, 128]}]})");
        ASSERT_TRUE(r.ok()) << ry << ": " << r.error().message;
        EXPECT_EQ(r->info.header.width, 64u);
    }
}
