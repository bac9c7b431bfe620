// The Lottie importer on the synthetic files of tests/importers/lottie (one per feature group;
// tests/web/lottie_test.mjs compares their renders with lottie-web) and on hostile input:
// every bound refuses with a message naming the file, and what the format cannot hold is named
// in one warning each.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "spt_import/importer.hpp"

using namespace spt;
using namespace spt::import;

namespace {

const std::string kDir = std::string(SPT_SOURCE_DIR) + "/tests/importers/lottie/";

Result<Document> load_text(const std::string& text) {
    const Importer* imp = find_importer("lottie");
    EXPECT_NE(imp, nullptr);
    return imp->load("in.json", text, ImportOptions{});
}

size_t count(const std::vector<Stroke>& v, StrokeKind k) {
    return size_t(std::count_if(v.begin(), v.end(), [&](const Stroke& s) { return s.kind == k; }));
}

size_t notes_with(const Document& d, const std::string& what) {
    return size_t(std::count_if(d.report.notes.begin(), d.report.notes.end(),
                                [&](const std::string& n) { return n.find(what) != std::string::npos; }));
}

// A composition of one shape layer holding `shapes` (JSON text), on a 100 x 100 canvas.
std::string comp(const std::string& shapes, const std::string& extra_layer_fields = "", const std::string& top = "") {
    return R"({"v":"5.7.0","fr":30,"ip":0,"op":2,"w":100,"h":100,)" + top + R"("layers":[{"ty":4,"ind":1,"ip":0,"op":2,"st":0,)" +
           extra_layer_fields + R"("ks":{},"shapes":)" + shapes + "}]}";
}

const char* kSquare = R"([{"ty":"rc","p":{"a":0,"k":[50,50]},"s":{"a":0,"k":[20,20]},"r":{"a":0,"k":0}},)"
                      R"({"ty":"fl","c":{"a":0,"k":[1,0,0,1]},"o":{"a":0,"k":100}}])";

}  // namespace

TEST(Lottie, DetectedByContentAndExtension) {
    auto d = import_path(kDir + "shapes.json", "");
    ASSERT_TRUE(d.ok()) << d.error().message;
    auto z = import_path(kDir + "shapes.lottie", "");
    ASSERT_TRUE(z.ok()) << z.error().message;
    // The archive holds the same animation: the same strokes.
    ASSERT_EQ(z->frames.size(), d->frames.size());
    EXPECT_TRUE(z->frames[0].added == d->frames[0].added);
}

TEST(Lottie, ShapesAreOnePolygonEachWithHoles) {
    auto d = import_path(kDir + "shapes.json", "lottie");
    ASSERT_TRUE(d.ok()) << d.error().message;
    EXPECT_TRUE(d->info.header.alpha);
    EXPECT_EQ(d->info.header.width, 200u);
    const auto& s = d->frames.at(0).added;
    // Rounded rectangle, ellipse, star, hexagon, and the path with its hole (one polygon).
    ASSERT_EQ(s.size(), 5u);
    EXPECT_EQ(count(s, StrokeKind::Polygon), 5u);
    // Drawn bottom first: the last group (the dark path) first, the rectangle last.
    EXPECT_EQ(s.back().polygon.color.r, 230);
    EXPECT_EQ(s.front().polygon.color.a, 255);
    // The hexagon (polystar "sy": 2, a plain number) has its 6 vertices, not a star's 12.
    EXPECT_EQ(s[1].polygon.points.size(), 6u);
    // The translucent ellipse keeps its 60% opacity.
    EXPECT_EQ(s[3].polygon.color.a, 153);
    // Every outline point within 1/16 px: the rounding is at most sqrt(2)/32.
    EXPECT_LE(d->report.max_q4_error_px, 0.0443);
}

TEST(Lottie, RoundStrokesAreCurvesOthersOutlines) {
    auto d = import_path(kDir + "strokes.json", "lottie");
    ASSERT_TRUE(d.ok()) << d.error().message;
    const auto& s = d->frames.at(0).added;
    ASSERT_EQ(count(s, StrokeKind::Curve), 1u);  // the round-capped, round-joined zigzag
    const auto curve = std::find_if(s.begin(), s.end(), [](const Stroke& x) { return x.kind == StrokeKind::Curve; });
    EXPECT_EQ(curve->curve.points.size(), 5u);
    EXPECT_EQ(curve->curve.points[0].width, 8u * 16);
    EXPECT_EQ(curve->curve.points[0].x, 20 * 16);
    // Butt/miter and square/bevel zigzags, the circle's stroke and fill: polygons (the long
    // outlines cut into bands of whole pixel rows, which bounds their rendering work).
    EXPECT_GE(count(s, StrokeKind::Polygon), 4u);
    for (uint8_t red : {230, 26, 242})  // red zigzag, green zigzag, yellow fill
        EXPECT_TRUE(std::any_of(s.begin(), s.end(), [&](const Stroke& x) { return x.kind == StrokeKind::Polygon && x.polygon.color.r == red; }))
            << int(red);
}

TEST(Lottie, KeyframesMoveTheShapesEveryFrame) {
    auto d = import_path(kDir + "animation.json", "lottie");
    ASSERT_TRUE(d.ok()) << d.error().message;
    EXPECT_EQ(d->frames.size(), 60u);
    auto lists = live_lists(*d);
    ASSERT_TRUE(lists.ok());
    // The eased position: the circle (the bottom layer, drawn first) moves right over frames 0..50.
    auto first_x = [&](size_t f) { return (*lists)[f].front().polygon.points[0].x; };
    EXPECT_LT(first_x(0), first_x(25));
    EXPECT_LT(first_x(25), first_x(50));
    EXPECT_EQ(first_x(50), first_x(59));  // past the last keyframe: held
    // The hold keyframe: opacity 40% from frame 20 to 44, 100% from 45.
    EXPECT_EQ((*lists)[30].front().polygon.color.a, 102);
    EXPECT_EQ((*lists)[30].back().polygon.color.a, 179);  // the square's group opacity, 70%
    EXPECT_EQ((*lists)[44].front().polygon.color.a, 102);
    EXPECT_EQ((*lists)[45].front().polygon.color.a, 255);
}

TEST(Lottie, PrecompsSeeTheirStartTimeAndTimeRemapping) {
    auto d = import_path(kDir + "precomp.json", "lottie");
    ASSERT_TRUE(d.ok()) << d.error().message;
    auto lists = live_lists(*d);
    ASSERT_TRUE(lists.ok());
    // Frame 5: the late copy (ip 10) is not drawn yet: solid, remapped star, first star.
    EXPECT_EQ((*lists)[5].size(), 3u);
    EXPECT_EQ((*lists)[15].size(), 4u);
    // The solid layer is the bottom stroke, its colour #33aa88.
    EXPECT_EQ((*lists)[15][0].polygon.color.g, 0xaa);
}

TEST(Lottie, TrimPathsShortenTheOutline) {
    auto d = import_path(kDir + "trim.json", "lottie");
    ASSERT_TRUE(d.ok()) << d.error().message;
    auto lists = live_lists(*d);
    ASSERT_TRUE(lists.ok());
    // The circle's trim end grows from 0: nothing at frame 0, a longer curve later.
    auto circle_points = [&](size_t f) {
        size_t n = 0;
        for (const Stroke& s : (*lists)[f])
            if (s.kind == StrokeKind::Curve) n += s.curve.points.size();
        return n;
    };
    EXPECT_EQ(circle_points(0), 0u);
    EXPECT_LT(circle_points(10), circle_points(30));
}

TEST(Lottie, WhatTheFormatCannotHoldIsNamedOnceEach) {
    const std::string shapes = std::string(kSquare).insert(std::string(kSquare).size() - 1, R"(,{"ty":"gf","g":{"p":2,"k":{"a":0,"k":[0,1,0,0,1,0,0,1]}},"o":{"a":0,"k":100}})");
    const std::string text =
        R"({"v":"5.7.0","fr":30,"ip":0,"op":3,"w":100,"h":100,"assets":[{"id":"img","w":10,"h":10,"p":"a.png"}],"layers":[)"
        R"({"ty":4,"ind":1,"ip":0,"op":3,"st":0,"hasMask":true,"masksProperties":[{"mode":"a"}],)"
        R"("ks":{"o":{"a":0,"k":100,"x":"value * 2"}},"shapes":)" + shapes + "},"
        R"({"ty":2,"ind":2,"ip":0,"op":3,"st":0,"refId":"img","ks":{}},)"
        R"({"ty":5,"ind":3,"ip":0,"op":3,"st":0,"ks":{},"t":{}}]})";
    auto d = load_text(text);
    ASSERT_TRUE(d.ok()) << d.error().message;
    EXPECT_EQ(notes_with(*d, "masks are not held"), 1u);
    EXPECT_EQ(notes_with(*d, "expressions are not evaluated"), 1u);
    EXPECT_EQ(notes_with(*d, "image asset(s)"), 1u);
    EXPECT_EQ(notes_with(*d, "image layers are not drawn"), 1u);
    EXPECT_EQ(notes_with(*d, "text layers"), 1u);
    EXPECT_EQ(notes_with(*d, "gradient fills"), 1u);
    // Still drawn: the square, twice (the gradient as its mean colour, the red fill), each frame.
    EXPECT_EQ(d->frames.at(0).added.size(), 2u);
}

TEST(LottieHostile, APrecompThatHoldsItselfIsRefused) {
    auto r = load_text(R"({"v":"5.7.0","fr":30,"ip":0,"op":2,"w":100,"h":100,"assets":[{"id":"a","layers":[)"
                       R"({"ty":0,"ind":1,"refId":"a","ip":0,"op":2,"st":0,"ks":{}}]}],)"
                       R"("layers":[{"ty":0,"ind":1,"refId":"a","ip":0,"op":2,"st":0,"ks":{}}]})");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("in.json: precomps nested deeper than 16"), std::string::npos) << r.error().message;
}

TEST(LottieHostile, HugeKeyframeCountsAreRefused) {
    std::string k;
    for (int i = 0; i < 70000; ++i) k += (i ? "," : "") + std::string(R"({"t":)") + std::to_string(i) + R"(,"s":[)" + std::to_string(i % 100) + "]}";
    std::string text = R"({"v":"5.7.0","fr":30,"ip":0,"op":2,"w":100,"h":100,"layers":[{"ty":4,"ind":1,"ip":0,"op":2,"st":0,)"
                       R"("ks":{"r":{"a":1,"k":[)" + k + R"(]}},"shapes":)" + kSquare + "}]}";
    auto r = load_text(text);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("in.json: a property has 70000 keyframes, above the limit of 65536"), std::string::npos)
        << r.error().message;
}

TEST(LottieHostile, APathOfTenMillionVerticesIsRefusedBeforeItIsHeld) {
    std::string v;
    v.reserve(size_t(6e7));
    for (int i = 0; i < 10000000; ++i) v += i ? ",[0,0]" : "[0,0]";
    auto r = load_text(comp(R"([{"ty":"sh","ks":{"a":0,"k":{"c":true,"v":[)" + v + R"(]}}},{"ty":"fl","c":{"a":0,"k":[1,0,0,1]}}])"));
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, Code::LimitExceeded) << r.error().message;
    EXPECT_NE(r.error().message.find("in.json"), std::string::npos) << r.error().message;
}

TEST(LottieHostile, APathAboveOnePolygonsVerticesIsRefused) {
    std::string v;
    for (int i = 0; i < 70000; ++i) v += (i ? ",[" : "[") + std::to_string(i % 90) + "," + std::to_string(i % 7) + "]";
    auto r = load_text(comp(R"([{"ty":"sh","ks":{"a":0,"k":{"c":true,"v":[)" + v + R"(]}}},{"ty":"fl","c":{"a":0,"k":[1,0,0,1]}}])"));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("in.json: a path has 70000 vertices, above the limit of 65536"), std::string::npos)
        << r.error().message;
}

TEST(LottieHostile, FilesAboveTheSizeCapAreRefusedBeforeParsing) {
    std::string text = comp(kSquare);
    text.append(size_t(65) << 20, ' ');
    auto r = load_text(text);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("above the Lottie importer's 67108864-byte limit"), std::string::npos) << r.error().message;
}

TEST(LottieHostile, EvaluationWorkOverAllFramesIsBounded) {
    // 4,000 vertices a frame is fine; 65,000 frames of them is 2.6e8 points, above the bound.
    std::string v;
    for (int i = 0; i < 4000; ++i) v += (i ? ",[" : "[") + std::to_string(i % 90) + "," + std::to_string(i % 7) + "]";
    std::string text = comp(R"([{"ty":"sh","ks":{"a":0,"k":{"c":true,"v":[)" + v + R"(]}}},{"ty":"fl","c":{"a":0,"k":[1,0,0,1]}}])");
    text.replace(text.find(R"("op":2,"w")"), 6, R"("op":65000)");
    text.replace(text.find(R"("op":2,"st")"), 6, R"("op":65000)");
    auto r = load_text(text);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("evaluation work limit"), std::string::npos) << r.error().message;
}

TEST(LottieHostile, BadCanvasAndRatesAreNamed) {
    auto r = load_text(R"({"v":"5","fr":30,"ip":0,"op":2,"w":0,"h":100,"layers":[]})");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("in.json: canvas"), std::string::npos) << r.error().message;
    r = load_text(R"({"v":"5","fr":30,"ip":5,"op":2,"w":10,"h":10,"layers":[]})");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("\"op\" must be after \"ip\""), std::string::npos) << r.error().message;
    r = load_text(R"({"v":"5","fr":30,"ip":0,"w":10,"h":10,"layers":[]})");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("\"op\" is missing"), std::string::npos) << r.error().message;
}

#include "spt_import/export.hpp"

// Export: polygons and their frames come back exactly through the Lottie importer (vertices are
// Q4 values written exactly, straight segments need no flattening).
TEST(LottieExport, PolygonsRoundTripThroughTheImporter) {
    auto d = import_path(kDir + "precomp.json", "lottie");
    ASSERT_TRUE(d.ok()) << d.error().message;
    LottieExportStats st;
    auto text = export_lottie(*d, false, st);
    ASSERT_TRUE(text.ok()) << text.error().message;
    auto back = load_text(*text);
    ASSERT_TRUE(back.ok()) << back.error().message;
    auto a = live_lists(*d), b = live_lists(*back);
    ASSERT_TRUE(a.ok() && b.ok());
    ASSERT_EQ(a->size(), b->size());
    for (size_t f = 0; f < a->size(); ++f) {
        ASSERT_EQ((*a)[f].size(), (*b)[f].size()) << "frame " << f;
        for (size_t k = 0; k < (*a)[f].size(); ++k) {
            EXPECT_EQ((*a)[f][k].polygon.points, (*b)[f][k].polygon.points) << "frame " << f << " stroke " << k;
            EXPECT_EQ((*a)[f][k].polygon.color.a, (*b)[f][k].polygon.color.a) << "frame " << f << " stroke " << k;
        }
    }
    // An unchanged stroke is one layer over its frames: the solid, drawn in all 60 frames.
    EXPECT_LT(st.layers, 60u * 4);
}

TEST(LottieExport, VectorOnlyLeavesOutStampsAndCountsBitmaps) {
    Document d;
    d.info.header = default_header(32, 32, Rgb8{255, 255, 255});
    d.info.templates = default_templates();
    Template bitmap;
    bitmap.kind = TemplateKind::Bitmap;
    bitmap.width = bitmap.height = 1;
    bitmap.pixels = {255};
    d.info.templates.push_back(bitmap);
    Frame f;
    StampStroke s;
    s.x = s.y = 100;
    f.added.push_back(Stroke::make_stamp(s));
    s.tmpl = 3;  // the bitmap
    f.added.push_back(Stroke::make_stamp(s));
    PolygonStroke p;
    p.points = {{0, 0}, {160, 0}, {0, 160}};
    f.added.push_back(Stroke::make_polygon(p));
    d.frames.push_back(f);
    LottieExportStats all, vec;
    ASSERT_TRUE(export_lottie(d, false, all).ok());
    EXPECT_EQ(all.layers, 2u);
    EXPECT_EQ(all.left_out_bitmaps, 1u);
    auto text = export_lottie(d, true, vec);
    ASSERT_TRUE(text.ok());
    EXPECT_EQ(vec.layers, 1u);
    EXPECT_EQ(vec.left_out_vector_only, 2u);
    // The opaque canvas is a solid layer of its colour.
    EXPECT_NE(text->find(R"("ty":1)"), std::string::npos);
    EXPECT_NE(text->find("#ffffff"), std::string::npos);
}

// Dashes: the circle's pattern (14 on, 8 off around 251 px) gives 11 or 12 round-capped curves.
TEST(Lottie, DashesSplitTheStroke) {
    auto d = import_path(kDir + "dashes.json", "lottie");
    ASSERT_TRUE(d.ok()) << d.error().message;
    EXPECT_EQ(notes_with(*d, "dash"), 0u);
    const auto& s = d->frames.at(0).added;
    const size_t curves = count(s, StrokeKind::Curve);
    EXPECT_GE(curves, 11u);
    EXPECT_LE(curves, 13u);
    EXPECT_GE(count(s, StrokeKind::Polygon), 1u);
}

TEST(LottieHostile, TinyDashesAndHugeFrameCountsAreRefused) {
    auto r = load_text(comp(R"([{"ty":"el","p":{"a":0,"k":[50,50]},"s":{"a":0,"k":[80,80]}},{"ty":"st","w":{"a":0,"k":1},)"
                            R"("c":{"a":0,"k":[0,0,0,1]},"d":[{"n":"d","v":{"a":0,"k":1e-300}},{"n":"g","v":{"a":0,"k":1e-300}}]}])"));
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("in.json: a dash pattern makes more than 65536 dashes"), std::string::npos) << r.error().message;
    r = load_text(R"({"v":"5","fr":30,"ip":0,"op":1e300,"w":10,"h":10,"layers":[]})");
    ASSERT_FALSE(r.ok());
    EXPECT_NE(r.error().message.find("in.json: 1e+300 frames is above the limit of 65536"), std::string::npos) << r.error().message;
}
