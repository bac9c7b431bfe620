// Importers and exporters: exact shapes, sequences, round trips through the JSON stroke list,
// and clean failures on bad input.
#include <gtest/gtest.h>
#include <png.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "spt/reader.hpp"
#include "spt_import/codec.hpp"
#include "spt_import/export.hpp"
#include "spt_import/evaluate.hpp"
#include "spt_import/geometrize.hpp"
#include "spt_import/importer.hpp"

using namespace spt;
namespace fs = std::filesystem;

namespace {

// One folder per test process (CTest runs each case as its own process), removed at exit.
fs::path temp_dir() {
    static const fs::path d = fs::temp_directory_path() / ("spt_import_test_" + std::to_string(::getpid()));
    static const struct RemoveAtExit {
        ~RemoveAtExit() { std::error_code ec; fs::remove_all(d, ec); }
    } remove_at_exit;
    fs::create_directories(d);
    return d;
}

void write(const fs::path& p, const std::string& s) {
    std::ofstream(p, std::ios::binary) << s;
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

Result<import::Document> import_text(const std::string& name, const std::string& text, const std::string& from = {},
                                     const import::ImportOptions& o = {}) {
    fs::path p = temp_dir() / name;
    write(p, text);
    return import::import_path(p.string(), from, o);
}

// A document using every stroke kind, a bitmap template, inter frames with removal and motion.
import::Document rich_document() {
    import::Document d;
    d.info.header = import::default_header(64, 48, {10, 20, 30});
    d.info.header.sets = {{24, 8}, {8, 4}};
    d.info.templates = import::default_templates();
    Template bm;
    bm.kind = TemplateKind::Bitmap;
    bm.width = 5; bm.height = 3; bm.name = "bristle \"q\"";
    for (int i = 0; i < 15; ++i) bm.pixels.push_back(uint8_t(i * 17));
    d.info.templates.push_back(bm);
    d.info.metadata = {{"title", "round trip"}, {"author", "t\u00e9st"}};
    Frame k;
    k.index = 0;
    k.added.push_back(Stroke::make_stamp({1, 3, 5, 16 * 10 + 3, 16 * 12 + 15, {1, 2, 3, 200}}));
    k.added.push_back(Stroke::make_affine({0, 160, 170, 80, -7, 9, 33, {200, 100, 50, 128}}));
    k.added.push_back(Stroke::make_affine({3, -17, 400, -100, 5, 3, 90, {0, 0, 0, 255}}));
    CurveStroke c;
    c.color = {9, 8, 7, 77};
    c.points = {{16, 16, 32}, {500, 300, 7}, {-3, 700, 0}};
    k.added.push_back(Stroke::make_curve(c));
    d.frames.push_back(k);
    Frame in;
    in.index = 1;
    in.type = FrameType::Inter;
    in.removed = {1, 3};
    in.motion.block_size = 32;
    in.motion.cols = 2; in.motion.rows = 2;
    in.motion.vectors = {{1, -1}, {16, 0}, {0, 0}, {-5, 40}};
    in.added.push_back(Stroke::make_affine({2, 300, 300, 40, 0, 0, 40, {5, 5, 5, 5}}));
    PolygonStroke pg;
    pg.color = {40, 50, 60, 180};
    pg.supersample = 4;
    pg.points = {{-20, 8}, {300, 40}, {520, 700}, {17, 333}, {160, 160}};
    in.added.push_back(Stroke::make_polygon(pg));
    d.frames.push_back(in);
    Frame k2;
    k2.index = 2;
    k2.added.push_back(Stroke::make_stamp({0, 0, 0, 0, 0, {255, 255, 255, 255}}));
    d.frames.push_back(k2);
    return d;
}

}  // namespace

TEST(ImportSvg, PrimitiveStyleShapesAreExactAffineStrokes) {
    const char* svg =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"100\" height=\"50\">\n"
        "<rect x=\"0\" y=\"0\" width=\"100\" height=\"50\" fill=\"#102030\" />\n"
        "<g transform=\"scale(1.000000) translate(0.5 0.5)\">\n"
        "<g transform=\"translate(10 20) rotate(90) scale(4 2)\"><ellipse fill=\"#ff0000\" fill-opacity=\"0.501961\" cx=\"0\" cy=\"0\" rx=\"1\" ry=\"1\" /></g>\n"
        "<polygon fill=\"#00ff00\" points=\"1,2 9,2 1,6\" />\n"
        "<rect x=\"2\" y=\"3\" width=\"4\" height=\"6\" fill=\"rgb(1,2,3)\" opacity=\"0.5\"/>\n"
        "</g></svg>\n";
    auto d = import_text("a.svg", svg);
    ASSERT_TRUE(d.ok()) << d.error().message;
    EXPECT_EQ(d->info.header.background, (Rgb8{0x10, 0x20, 0x30}));
    ASSERT_EQ(d->frames.size(), 1u);
    const auto& s = d->frames[0].added;
    ASSERT_EQ(s.size(), 3u);
    // Ellipse: centre (10.5, 20.5); u axis rotated 90 degrees: (0, 4); v axis: (-2, 0).
    EXPECT_EQ(s[0].affine.tmpl, 0);
    EXPECT_EQ(s[0].affine.tx, 168); EXPECT_EQ(s[0].affine.ty, 328);
    EXPECT_EQ(s[0].affine.a, 0); EXPECT_EQ(s[0].affine.c, 64);
    EXPECT_EQ(s[0].affine.b, -32); EXPECT_EQ(s[0].affine.d, 0);
    EXPECT_EQ(s[0].affine.color, (Rgba8{255, 0, 0, 128}));
    // Triangle (1.5,2.5) (9.5,2.5) (1.5,6.5): vertices are exact images of the template's.
    const auto& t = s[1].affine;
    EXPECT_EQ(t.tmpl, 2);
    EXPECT_EQ(t.tx - t.a - t.b, 24); EXPECT_EQ(t.ty - t.c - t.d, 40);
    EXPECT_EQ(t.tx + t.a - t.b, 152); EXPECT_EQ(t.ty + t.c - t.d, 40);
    EXPECT_EQ(t.tx - t.a + t.b, 24); EXPECT_EQ(t.ty - t.c + t.d, 104);
    EXPECT_EQ(s[2].affine.tmpl, 1);
    EXPECT_EQ(s[2].affine.color, (Rgba8{1, 2, 3, 128}));
    EXPECT_EQ(d->report.max_q4_error_px, 0.0);
}

TEST(ImportSvg, ViewBoxMatrixAndPolygonStrokes) {
    const char* svg =
        "<svg viewBox=\"0 0 50 25\" width=\"100\" height=\"50\">"
        "<polygon transform=\"matrix(1 0 0 1 1 1)\" points=\"0,0 10,0 10,10 0,10 -5,5\" fill=\"#000\"/>"
        "<polygon points=\"0,0 4,1 5,5 1,4\" fill=\"#fff\"/></svg>";
    auto d = import_text("b.svg", svg);
    ASSERT_TRUE(d.ok()) << d.error().message;
    const auto& s = d->frames[0].added;
    ASSERT_EQ(s.size(), 2u);  // pentagon: one polygon stroke; parallelogram: one rectangle
    EXPECT_EQ(d->report.approximated, 0u);
    ASSERT_EQ(s[0].kind, StrokeKind::Polygon);
    // Translated by (1, 1), then scaled by 2 by the viewBox, in Q4.
    const std::vector<PolygonVertex> want{{32, 32}, {352, 32}, {352, 352}, {32, 352}, {-128, 192}};
    EXPECT_EQ(s[0].polygon.points, want);
    EXPECT_EQ(s[0].polygon.supersample, 8);  // anti-aliased source: sampled like the templates
    EXPECT_EQ(s[0].polygon.color, (Rgba8{0, 0, 0, 255}));
    EXPECT_EQ(s[1].affine.tmpl, 1);
    EXPECT_EQ(s[1].affine.tx, 16 * 5);  // centre (2.5, 2.5) scaled by 2
}

TEST(ImportGeometrize, ShapesTypesAndBackground) {
    const char* js =
        "{\"shapes\":\n[{\"type\":1, \"data\":[0,0,19,9],\"color\":[9,8,7,255],\"score\":0.1},\n"
        "{\"type\":32, \"data\":[5,5,3],\"color\":[1,2,3,128]},\n"
        "{\"type\":16, \"data\":[5,5,3,2,90],\"color\":[1,2,3,128]},\n"
        "{\"type\":4, \"data\":[0,0,5,0,0,5],\"color\":[1,2,3,128]},\n"
        "{\"type\":2, \"data\":[1,1,5,3,0],\"color\":[1,2,3,128]},\n"
        "{\"type\":256, \"data\":[1,1,5,3,7,7],\"color\":[1,2,3,128]}]}";
    auto d = import_text("g.json", js);
    ASSERT_TRUE(d.ok()) << d.error().message;
    EXPECT_EQ(d->info.header.width, 20u);
    EXPECT_EQ(d->info.header.height, 10u);
    EXPECT_EQ(d->info.header.background, (Rgb8{9, 8, 7}));
    EXPECT_TRUE(d->report.background_stated);
    const auto& s = d->frames[0].added;
    ASSERT_GE(s.size(), 7u);
    EXPECT_EQ(s[0].kind, StrokeKind::Affine);
    // The polyline, then the two canvas-coloured strips geometrize never paints over.
    EXPECT_EQ(s[s.size() - 3].kind, StrokeKind::Curve);
    EXPECT_TRUE(d->canvas_strips);
    for (size_t k = s.size() - 2; k < s.size(); ++k) {
        ASSERT_EQ(s[k].kind, StrokeKind::Affine);
        EXPECT_EQ(s[k].affine.color, (Rgba8{9, 8, 7, 255}));
    }
    // set_background recolours the strips with the canvas.
    import::Document d2 = *d;
    import::set_background(d2, {1, 2, 3});
    EXPECT_EQ(d2.frames[0].added.back().affine.color, (Rgba8{1, 2, 3, 255}));
}

// The fitted strokes paint exactly geometrize's pixels for circles and rectangles (its
// rasteriser, re-derived in geometrize_scan.cpp and checked against its PNGs by the media test).
TEST(ImportGeometrize, StrokesPaintGeometrizesPixels) {
    const char* js =
        "{\"shapes\":[{\"type\":1, \"data\":[0,0,39,29],\"color\":[0,0,0,255]},\n"
        "{\"type\":32, \"data\":[17,14,9],\"color\":[255,255,255,255]},\n"
        "{\"type\":1, \"data\":[30,3,36,8],\"color\":[255,255,255,255]}]}";
    auto d = import_text("g3.json", js);
    ASSERT_TRUE(d.ok()) << d.error().message;
    auto c = import::render_frame(*d, 0);
    ASSERT_TRUE(c.ok());
    size_t white = 0;
    for (uint32_t y = 0; y < 30; ++y)
        for (uint32_t x = 0; x < 40; ++x) {
            const int dx = int(x) - 17, dy = int(y) - 14;
            const bool in_circle = dx * dx + dy * dy <= 81;
            const bool in_rect = x >= 30 && x <= 36 && y >= 3 && y < 8;  // rows y1 .. y2 - 1
            const bool w = c->rgb[(size_t(y) * 40 + x) * 3] == 255;
            EXPECT_EQ(w, in_circle || in_rect) << x << "," << y;
            white += w;
        }
    EXPECT_GT(white, 200u);
}

// Rotated ellipses are geometrize's 20-gons of truncated vertices: polygon strokes on its own
// vertices paint its pixels (its span rule re-derived in geometrize_scan.cpp).
TEST(ImportGeometrize, RotatedEllipsesAreAlmostExactPolygons) {
    const char* js =
        "{\"shapes\":[{\"type\":1, \"data\":[0,0,59,49],\"color\":[0,0,0,255]},\n"
        "{\"type\":16, \"data\":[28,24,22,9,37],\"color\":[255,255,255,255]},\n"
        "{\"type\":16, \"data\":[40,12,6,13,200],\"color\":[255,255,255,255]}]}";
    auto d = import_text("g4.json", js);
    ASSERT_TRUE(d.ok()) << d.error().message;
    const auto& s = d->frames[0].added;
    ASSERT_GE(s.size(), 2u);
    EXPECT_EQ(s[0].kind, StrokeKind::Polygon);
    EXPECT_EQ(s[1].kind, StrokeKind::Polygon);
    // One vertex per geometrize vertex (no connectors), so the n-gon codes by conic prediction.
    EXPECT_EQ(s[0].polygon.points.size(), 20u);
    EXPECT_LE(s[1].polygon.points.size(), 20u);
    std::vector<uint8_t> want(60 * 50, 0);
    for (const auto& sh : {std::vector<double>{28, 24, 22, 9, 37}, std::vector<double>{40, 12, 6, 13, 200}})
        for (const auto& sp : import::geometrize::spans(16, sh, 60, 50))
            for (int32_t x = sp.x0; x <= sp.x1; ++x) want[size_t(sp.y) * 60 + size_t(x)] = 1;
    auto c = import::render_frame(*d, 0);
    ASSERT_TRUE(c.ok());
    size_t differ = 0, white = 0;
    for (size_t i = 0; i < want.size(); ++i) {
        const bool w = c->rgb[3 * i] == 255;
        differ += w != bool(want[i]);
        white += w;
    }
    EXPECT_GT(white, 500u);
    EXPECT_LE(differ, 4u) << "of " << white;  // ties of the two edge rules, a few at most
}

TEST(ImportGeometrize, NeedsCanvasSizeWithoutBackground) {
    const char* js = "{\"shapes\":[{\"type\":32, \"data\":[5,5,3],\"color\":[1,2,3,128]}]}";
    auto d = import_text("g2.json", js);
    ASSERT_FALSE(d.ok());
    EXPECT_NE(d.error().message.find("--size"), std::string::npos);
    import::ImportOptions o;
    o.canvas_size = std::make_pair(30u, 20u);
    auto d2 = import_text("g2.json", js, "", o);
    ASSERT_TRUE(d2.ok()) << d2.error().message;
    EXPECT_FALSE(d2->report.background_stated);
}

TEST(ImportErrors, NameFileLineAndElement) {
    struct Case { const char* name; const char* text; const char* expect; };
    const Case cases[] = {
        {"e1.svg", "<svg width=\"10\" height=\"10\">\n<path d=\"M0 0\"/></svg>", "e1.svg:2: <path>"},
        {"e2.svg", "<svg width=\"10\" height=\"10\">\n\n<circle r=\"x\"/></svg>", "e2.svg:3:"},
        {"e3.svg", "<svg width=\"1e9\" height=\"10\"/>", "above the limits"},
        {"e4.svg", "<svg width=\"10\" height=\"10\"><rect width=\"1\" height=\"1\" fill=\"url(#g)\"/></svg>", "unsupported colour"},
        {"e5.json", "{\"shapes\":[\n{\"type\":3, \"data\":[1],\"color\":[1,2,3,4]}]}", "e5.json:2: shapes[0]: unknown shape type 3"},
        {"e6.json", "{\"shapes\":[{\"type\":32, \"data\":[1,2],\"color\":[1,2,3,4]}]}", "needs 3"},
        {"e7.json", "{\"format\":\"spt-strokes\",\"version\":1,\"canvas\":{\"width\":10,\"height\":10},\n\"frames\":[{\"strokes\":[\n{\"type\":\"blob\"}]}]}", "e7.json:3: frames[0].strokes[0]: unknown stroke type"},
        {"e8.json", "{\"format\":\"spt-strokes\",\"version\":4}", "version 4"},
        {"e9.json", "{\"format\":\"spt-strokes\",\"version\":1,\"canvas\":{\"width\":100000,\"height\":10},\"frames\":[]}", "canvas.width"},
        // The points of polygon (version 2) and curve strokes: how many, and each one's shape.
        {"e10.json", "{\"format\":\"spt-strokes\",\"version\":2,\"canvas\":{\"width\":10,\"height\":10},\"strokes\":[\n"
                     "{\"type\":\"polygon\",\"color\":[1,2,3],\"points\":[[0,0],[1,1]]}]}",
         "e10.json:2: frames[0].strokes[0].points: 3..65536 vertices required"},
        {"e11.json", "{\"format\":\"spt-strokes\",\"version\":2,\"canvas\":{\"width\":10,\"height\":10},\"strokes\":[\n"
                     "{\"type\":\"polygon\",\"color\":[1,2,3],\"points\":[[0,0],[1,1],[2]]}]}",
         "strokes[0].points[2] must be [x, y]"},
        {"e12.json", "{\"format\":\"spt-strokes\",\"version\":2,\"canvas\":{\"width\":10,\"height\":10},\"strokes\":[\n"
                     "{\"type\":\"curve\",\"color\":[1,2,3],\"points\":[]}]}",
         "e12.json:2: frames[0].strokes[0].points: 1..65536 points required"},
        {"e13.json", "{\"format\":\"spt-strokes\",\"version\":2,\"canvas\":{\"width\":10,\"height\":10},\"strokes\":[\n"
                     "{\"type\":\"curve\",\"color\":[1,2,3],\"points\":[[0,0]]}]}",
         "strokes[0].points[0] must be [x, y, width]"},
        // Header tables and ROIs hold tuples of a fixed length.
        {"e14.json", "{\"format\":\"spt-strokes\",\"version\":1,\"canvas\":{\"width\":10,\"height\":10},\"frames\":[],\n"
                     "\"sets\":[[4,4],[2]]}",
         "e14.json:2: sets[1] must be [width, height]"},
        {"e15.json", "{\"format\":\"spt-strokes\",\"version\":1,\"canvas\":{\"width\":10,\"height\":10},\"frames\":[],\n"
                     "\"orientations\":[[16384,0,0]]}",
         "e15.json:2: orientations[0] must be [cos_q14, sin_q14]"},
        {"e16.json", "{\"format\":\"spt-strokes\",\"version\":1,\"canvas\":{\"width\":10,\"height\":10},\"frames\":[],\n"
                     "\"rois\":[[0,0,1,1,2]]}",
         "e16.json:2: rois[0] must be [first_frame, last_frame, x, y, w, h]"},
        {"e17.json", "{\"format\":\"spt-strokes\",\"version\":1,\"canvas\":{\"width\":10,\"height\":10},\"frames\":[],\n"
                     "\"sets\":[]}",
         "e17.json:2: sets must hold 1..16 entries"},
        {"e18.json", "{\"format\":\"spt-strokes\",\"version\":1,\"canvas\":{\"width\":10,\"height\":10},\"frames\":[],\n"
                     "\"orientations\":[]}",
         "e18.json:2: orientations must hold 1..64 entries"},
    };
    for (const auto& c : cases) {
        auto d = import_text(c.name, c.text);
        ASSERT_FALSE(d.ok()) << c.name;
        EXPECT_NE(d.error().message.find(c.expect), std::string::npos) << c.name << ": " << d.error().message;
    }
}

TEST(ImportSequence, SharedPrefixBecomesInterFrames) {
    fs::path dir = temp_dir() / "seq";
    fs::create_directories(dir);
    const std::string head = "<svg width=\"20\" height=\"20\"><rect width=\"20\" height=\"20\" fill=\"#fff\"/>";
    const std::string a = "<circle cx=\"5\" cy=\"5\" r=\"3\" fill=\"#f00\"/>";
    const std::string b = "<circle cx=\"9\" cy=\"5\" r=\"3\" fill=\"#0f0\"/>";
    const std::string c = "<circle cx=\"5\" cy=\"9\" r=\"2\" fill=\"#00f\"/>";
    write(dir / "s.0001.svg", head + a + "</svg>");
    write(dir / "s.0002.svg", head + a + b + "</svg>");
    write(dir / "s.0003.svg", head + a + c + "</svg>");
    write(dir / "s.0004.svg", head + c + "</svg>");
    auto d = import::import_path((dir / "s.####.svg").string(), "");
    ASSERT_TRUE(d.ok()) << d.error().message;
    ASSERT_EQ(d->frames.size(), 4u);
    EXPECT_EQ(d->frames[0].type, FrameType::Key);
    EXPECT_EQ(d->frames[1].type, FrameType::Inter);
    EXPECT_EQ(d->frames[1].added.size(), 1u);
    EXPECT_EQ(d->frames[2].type, FrameType::Inter);
    EXPECT_EQ(d->frames[2].removed, std::vector<uint32_t>{1});
    EXPECT_EQ(d->frames[3].type, FrameType::Key);
    auto pct = import::import_path((dir / "s.%04d.svg").string(), "");
    ASSERT_TRUE(pct.ok());
    EXPECT_EQ(pct->frames.size(), 4u);
    auto folder = import::import_path(dir.string(), "");
    ASSERT_TRUE(folder.ok());
    EXPECT_EQ(folder->frames.size(), 4u);
}

// import(export(x)) gives the same .spt bytes, for both codings.
TEST(RoundTrip, JsonExportImportIsByteIdentical) {
    for (Coding coding : {Coding::Range, Coding::Stored}) {
        fs::path dir = temp_dir();
        const std::string a = (dir / "rt_a.spt").string(), b = (dir / "rt_b.spt").string(), j = (dir / "rt.json").string();
        WriterOptions wo;
        wo.coding = coding;
        auto w = import::write_document(rich_document(), a, wo);
        ASSERT_TRUE(w.ok()) << w.error().message;
        auto doc = import::read_document(a);
        ASSERT_TRUE(doc.ok()) << doc.error().message;
        const std::string text = import::export_json(*doc);
        write(j, text);
        auto back = import::import_path(j, "");
        ASSERT_TRUE(back.ok()) << back.error().message;
        EXPECT_EQ(import::export_json(*back), text);
        auto w2 = import::write_document(*back, b, wo);
        ASSERT_TRUE(w2.ok()) << w2.error().message;
        EXPECT_EQ(slurp(a), slurp(b)) << "coding " << int(coding);
    }
}

// Format 1.4: the golden anti-aliased curves (grids 0, 2, 3, 4, 16 in a flagged file) through
// JSON and back, byte for byte in both codings; and a version-1 document cannot give a grid.
TEST(RoundTrip, AntiAliasedCurvesThroughJson) {
    for (const char* name : {"curves_aa.spt", "curves_aa.stored.spt"}) {
        const std::string a = std::string(SPT_SOURCE_DIR) + "/tests/format/golden/" + name;
        fs::path dir = temp_dir();
        const std::string b = (dir / "aa_b.spt").string(), j = (dir / "aa.json").string();
        auto doc = import::read_document(a);
        ASSERT_TRUE(doc.ok()) << doc.error().message;
        const std::string text = import::export_json(*doc);
        EXPECT_NE(text.find("\"curve_grid\": true"), std::string::npos);
        EXPECT_NE(text.find("\"supersample\": 16"), std::string::npos);
        write(j, text);
        auto back = import::import_path(j, "");
        ASSERT_TRUE(back.ok()) << back.error().message;
        EXPECT_TRUE(back->info.header.curve_grid);
        WriterOptions wo;
        wo.coding = std::string(name).find("stored") != std::string::npos ? Coding::Stored : Coding::Range;
        auto w2 = import::write_document(*back, b, wo);
        ASSERT_TRUE(w2.ok()) << w2.error().message;
        EXPECT_EQ(slurp(a), slurp(b)) << name;
    }
    const char* v1 =
        "{\"format\": \"spt-strokes\", \"version\": 1, \"canvas\": {\"width\": 40, \"height\": 30},\n"
        " \"strokes\": [{\"type\": \"curve\", \"supersample\": 4, \"points\": [[1,1,2],[30,2,2]], \"color\": [9,80,200]}]}";
    auto d = import_text("v1curve.json", v1);
    ASSERT_FALSE(d.ok());
    EXPECT_NE(d.error().message.find("supersample needs version 2"), std::string::npos) << d.error().message;
    // A grid of 1 is no grid (SPEC.md 8.5, 8.8): refused for polygons and curves alike, naming the stroke.
    for (const char* type : {"polygon", "curve"}) {
        const std::string pts = std::string(type) == "curve" ? "[[1,1,2],[30,2,2]]" : "[[1,1],[30,2],[5,20]]";
        const std::string v2 =
            "{\"format\": \"spt-strokes\", \"version\": 2, \"canvas\": {\"width\": 40, \"height\": 30},\n"
            " \"strokes\": [{\"type\": \"" + std::string(type) + "\", \"supersample\": 1, \"points\": " + pts +
            ", \"color\": [9,80,200]}]}";
        auto g = import_text("grid1.json", v2.c_str());
        ASSERT_FALSE(g.ok()) << type;
        EXPECT_NE(g.error().message.find("grid1.json:2: frames[0].strokes[0].supersample must be 0 or 2..16"), std::string::npos)
            << g.error().message;
    }
}

TEST(RoundTrip, ShapeStrokesAndDefaultTemplates) {
    const char* js =
        "{\"format\": \"spt-strokes\", \"version\": 1, \"canvas\": {\"width\": 40, \"height\": 30, \"background\": \"#ffffff\"},\n"
        " \"strokes\": [{\"type\": \"shape\", \"template\": \"ellipse\", \"center\": [20, 15], \"size\": [10, 4], \"angle\": 90,\n"
        "   \"color\": \"#ff000080\"}, {\"type\": \"shape\", \"template\": 1, \"center\": [5.5, 5.5], \"size\": [3, 3], \"color\": [0, 0, 255], \"opacity\": 0.5},\n"
        "   {\"type\": \"polygon\", \"points\": [[0,0],[10,0],[0,10]], \"color\": [1,2,3]}]}";
    auto d = import_text("shape.json", js);
    ASSERT_TRUE(d.ok()) << d.error().message;
    const auto& s = d->frames[0].added;
    ASSERT_EQ(s.size(), 3u);
    EXPECT_EQ(s[0].affine.tx, 320); EXPECT_EQ(s[0].affine.c, 80); EXPECT_EQ(s[0].affine.b, -32);
    EXPECT_EQ(s[0].affine.color.a, 0x80);
    EXPECT_EQ(s[1].affine.color, (Rgba8{0, 0, 255, 128}));
    EXPECT_EQ(s[2].affine.tmpl, 2);
}

TEST(ImportJson, Version2PolygonIsOneStrokeAndOneShape) {
    const char* js =
        "{\"format\": \"spt-strokes\", \"version\": 2, \"canvas\": {\"width\": 40, \"height\": 30},\n"
        " \"strokes\": [{\"type\": \"polygon\", \"points\": [[0,0],[30,2],[3,25],[1,9]], \"color\": [9,80,200]}]}";
    auto d = import_text("v2poly.json", js);
    ASSERT_TRUE(d.ok()) << d.error().message;
    ASSERT_EQ(d->frames[0].added.size(), 1u);
    EXPECT_EQ(d->frames[0].added[0].kind, StrokeKind::Polygon);
    EXPECT_EQ(d->report.shapes, 1u);
    EXPECT_EQ(d->report.strokes, 1u);
}

TEST(Document, DropUnusedTablesKeepsThePixels) {
    // Templates 0 and 1 unused (2 is the triangle), no stamps: one template and one orientation
    // are left, the stroke's template id follows, and every pixel stays the same.
    const char* js =
        "{\"format\": \"spt-strokes\", \"version\": 1, \"canvas\": {\"width\": 40, \"height\": 30},\n"
        " \"strokes\": [{\"type\": \"polygon\", \"points\": [[0,0],[30,2],[3,25]], \"color\": [9,80,200]}]}";
    auto d = import_text("drop.json", js);
    ASSERT_TRUE(d.ok()) << d.error().message;
    ASSERT_EQ(d->info.templates.size(), 3u);
    ASSERT_EQ(d->frames[0].added[0].affine.tmpl, 2);
    auto before = import::render_frame(*d, 0);
    ASSERT_TRUE(before.ok());
    import::drop_unused_tables(*d);
    ASSERT_EQ(d->info.templates.size(), 1u);
    EXPECT_EQ(d->info.templates[0].kind, TemplateKind::Triangle);
    EXPECT_EQ(d->frames[0].added[0].affine.tmpl, 0);
    EXPECT_EQ(d->info.header.orientations.size(), 1u);
    auto after = import::render_frame(*d, 0);
    ASSERT_TRUE(after.ok());
    EXPECT_EQ(after->rgb, before->rgb);

    // A stamp reads the orientation table: it stays whole.
    auto rich = rich_document();
    const size_t orientations = rich.info.header.orientations.size();
    bool stamp = false;
    for (const auto& f : rich.frames)
        for (const auto& s : f.added) stamp = stamp || s.kind == StrokeKind::Stamp;
    ASSERT_TRUE(stamp);
    import::drop_unused_tables(rich);
    EXPECT_EQ(rich.info.header.orientations.size(), orientations);
}

TEST(Export, SvgHoldsEveryStrokeAndReimports) {
    auto d = rich_document();
    auto svg = import::export_svg(d.info, d.frames[0].added);
    ASSERT_TRUE(svg.ok()) << svg.error().message;
    EXPECT_NE(svg->find("<mask id=\"t3\""), std::string::npos);
    EXPECT_NE(svg->find("data:image/png;base64,"), std::string::npos);
    EXPECT_NE(svg->find("<ellipse"), std::string::npos);
    // Analytic shapes only: re-importing the SVG gives the same affine strokes.
    import::Document a;
    a.info.header = import::default_header(64, 48, {255, 255, 255});
    a.info.templates = import::default_templates();
    std::vector<Stroke> list = {Stroke::make_affine({0, 160, 170, 80, -7, 9, 33, {200, 100, 50, 128}}),
                                Stroke::make_affine({1, 16, 32, 48, 0, 0, 64, {1, 2, 3, 255}}),
                                Stroke::make_affine({2, 300, 200, -40, 8, 16, 40, {9, 9, 9, 9}})};
    auto s2 = import::export_svg(a.info, list);
    ASSERT_TRUE(s2.ok());
    auto back = import_text("exp.svg", *s2);
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_EQ(back->frames[0].added.size(), 3u);
    for (size_t i = 0; i < 3; ++i) EXPECT_TRUE(back->frames[0].added[i] == list[i]) << i;
}

TEST(Codec, PngDecodesToThePixelsAndBase64RoundTrips) {
    for (int channels : {1, 3, 4}) {
        std::vector<uint8_t> px(size_t(350) * 200 * channels);
        for (size_t i = 0; i < px.size(); ++i) px[i] = uint8_t(i * 7 + i / 350);
        auto png = import::encode_png(350, 200, channels, px.data());
        ASSERT_GT(png.size(), 8u);
        EXPECT_EQ(png[1], 'P');
        png_image img{};
        img.version = PNG_IMAGE_VERSION;
        ASSERT_TRUE(png_image_begin_read_from_memory(&img, png.data(), png.size())) << img.message;
        EXPECT_EQ(img.width, 350u);
        EXPECT_EQ(img.height, 200u);
        img.format = channels == 4 ? PNG_FORMAT_RGBA : channels == 3 ? PNG_FORMAT_RGB : PNG_FORMAT_GRAY;
        std::vector<uint8_t> back(PNG_IMAGE_SIZE(img));
        ASSERT_TRUE(png_image_finish_read(&img, nullptr, back.data(), 0, nullptr)) << img.message;
        EXPECT_EQ(back, px) << channels << " channels";
        auto b64 = import::base64_encode(png.data(), png.size());
        auto dec = import::base64_decode(b64);
        ASSERT_TRUE(dec.has_value());
        EXPECT_EQ(*dec, png);
    }
    EXPECT_FALSE(import::base64_decode("ab$c").has_value());
    EXPECT_EQ(import::base64_encode(reinterpret_cast<const uint8_t*>("any carnal pleas"), 16), "YW55IGNhcm5hbCBwbGVhcw==");
}

TEST(ImportCli, NothingWrittenOnBadInput) {
    fs::path dir = temp_dir();
    auto d = import_text("bad.svg", "<svg width=\"10\" height=\"10\"><rect/>");
    ASSERT_FALSE(d.ok());
    EXPECT_FALSE(fs::exists(dir / "bad.spt"));
}
