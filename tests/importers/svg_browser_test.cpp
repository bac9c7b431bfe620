// `spt export -o X.svg` renders in a real browser (headless Chromium) close to `spt render`.
// Skips when chromium or the spt tool is missing. Prints the PSNR it measures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/image_io.hpp"
#include "spt/reader.hpp"
#include "spt_import/evaluate.hpp"
#include "spt_import/importer.hpp"

using namespace spt;
namespace fs = std::filesystem;

namespace {

const char* kChromium = "/usr/bin/chromium";
const char* kInkscape = "/usr/bin/inkscape";

fs::path work_dir(const std::string& name) {
    fs::path d = fs::temp_directory_path() / ("spt_browser_" + std::to_string(::getpid()) + "_" + name);
    fs::create_directories(d);
    return d;
}

// Screenshots d/out.svg in Chromium; returns its top-left w x h pixels (RGB), empty on failure.
std::vector<uint8_t> chromium_shot(const fs::path& d, uint32_t w, uint32_t h) {
    const std::string png = (d / "shot.png").string();
    // A wrapper page with no margins shows the SVG at its pixel size at the origin.
    std::ofstream(d / "page.html") << "<!DOCTYPE html><html><body style=\"margin:0\"><img src=\"out.svg\" style=\"display:block\"></body></html>";
    const std::string cmd = std::string(kChromium) +
                            " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking"
                            " --disable-component-update --disable-sync --user-data-dir='" + (d / "profile").string() +
                            "' --screenshot='" + png + "' --window-size=" + std::to_string(std::max(w, 800u)) + "," + std::to_string(std::max(h, 600u)) +
                            " --hide-scrollbars --default-background-color=00000000 'file://" + (d / "page.html").string() +
                            "' >/dev/null 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    auto shot = io::read_image(png);
    EXPECT_TRUE(shot.ok()) << (shot.ok() ? "" : shot.error().message);
    // Headless Chromium has a minimum window size: the window is at least 800x600 and the
    // painting is its top-left corner.
    if (!shot.ok() || shot->width < w || shot->height < h) {
        ADD_FAILURE() << "screenshot is " << (shot.ok() ? shot->width : 0) << "x" << (shot.ok() ? shot->height : 0);
        return {};
    }
    std::vector<uint8_t> crop;
    for (uint32_t y = 0; y < h; ++y) {
        const uint8_t* row = shot->rgb.data() + size_t(y) * shot->width * 3;
        crop.insert(crop.end(), row, row + size_t(w) * 3);
    }
    return crop;
}

// d/out.svg drawn by Inkscape (its own renderer, cairo) on white, as RGB; empty on failure.
std::vector<uint8_t> inkscape_render(const fs::path& d, uint32_t w, uint32_t h) {
    const std::string png = (d / "inkscape.png").string();
    const std::string cmd = std::string(kInkscape) + " --export-type=png --export-filename='" + png +
                            "' --export-background=white --export-background-opacity=1 '" + (d / "out.svg").string() +
                            "' >/dev/null 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    auto img = io::read_image(png);
    EXPECT_TRUE(img.ok()) << (img.ok() ? "" : img.error().message);
    if (!img.ok() || img->width != w || img->height != h) {
        ADD_FAILURE() << "Inkscape drew " << (img.ok() ? img->width : 0) << "x" << (img.ok() ? img->height : 0);
        return {};
    }
    return img->rgb;
}

// Exports `doc` through the spt tool, screenshots it in Chromium, returns the PSNR against
// spt::Renderer's rendering of the same frame.
double browser_psnr(const import::Document& doc, const std::string& name) {
    const fs::path d = work_dir(name);
    const std::string spt = (d / "in.spt").string(), svg = (d / "out.svg").string();
    auto w = import::write_document(doc, spt);
    EXPECT_TRUE(w.ok()) << (w.ok() ? "" : w.error().message);
    const std::string exp = std::string(SPT_TOOL) + " export '" + spt + "' -o '" + svg + "'";
    EXPECT_EQ(std::system(exp.c_str()), 0) << exp;
    const auto& h = doc.info.header;
    auto crop = chromium_shot(d, h.width, h.height);
    auto ref = import::render_frame(doc, doc.frames.size() - 1);
    EXPECT_TRUE(ref.ok());
    if (crop.empty() || !ref.ok()) return 0;
    std::error_code ec;
    fs::remove_all(d, ec);
    return import::psnr_rgb8(crop.data(), ref->rgb.data(), size_t(h.width) * h.height);
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

bool have_tools() { return fs::exists(kChromium) && std::string(SPT_TOOL).size() > 0 && fs::exists(SPT_TOOL); }

// Imports the shared media file `rel` (foreign/...) into `doc`; fails when it is missing.
void import_media(const std::string& rel, import::Document& doc) {
    const std::string f = std::string(SPT_MEDIA_DIR) + "/" + rel;
    if (!fs::exists(f)) GTEST_FAIL() << "media missing: " << f;
    auto d = import::import_path(f, "");
    ASSERT_TRUE(d.ok()) << d.error().message;
    doc = std::move(*d);
}

}  // namespace

TEST(SvgInBrowser, ShapePaintingMatchesRenderer) {
    if (!have_tools()) GTEST_FAIL() << "needs " << kChromium << " and the spt tool";
    import::Document doc;
    ASSERT_NO_FATAL_FAILURE(import_media("foreign/coffee-primitive-ellipses.svg", doc));
    const double p = browser_psnr(doc, "shapes");
    std::printf("chromium vs spt render, primitive ellipses: PSNR %.2f dB\n", p);
    EXPECT_GE(p, 30.0);  // edges differ: browsers anti-alias, spt samples pixel centres
}

TEST(SvgInBrowser, PolygonsMatchRenderer) {
    if (!have_tools()) GTEST_FAIL() << "needs " << kChromium << " and the spt tool";
    // geometrize's rotated ellipses import as 20-vertex polygon strokes (format 1.2).
    import::Document doc;
    ASSERT_NO_FATAL_FAILURE(import_media("foreign/coffee-geometrize-rotellipses.svg", doc));
    size_t polygons = 0;
    for (const auto& s : doc.frames.back().added) polygons += s.kind == StrokeKind::Polygon;
    ASSERT_GE(polygons, 250u);
    const double p = browser_psnr(doc, "polygons");
    std::printf("chromium vs spt render, geometrize rotated ellipses as polygons: PSNR %.2f dB\n", p);
    EXPECT_GE(p, 28.0);  // browsers anti-alias the edges that spt samples at pixel centres
}

TEST(SvgInBrowser, BitmapStampsAndCurvesMatchRenderer) {
    if (!have_tools()) GTEST_FAIL() << "needs " << kChromium << " and the spt tool";
    import::Document d;
    d.info.header = import::default_header(160, 120, {240, 235, 220});
    d.info.header.sets = {{40, 12}, {16, 6}};
    d.info.templates = import::default_templates();
    Template bm;  // a soft-edged bristle mark
    bm.kind = TemplateKind::Bitmap;
    bm.width = 32; bm.height = 8;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 32; ++x) {
            const double u = (x + 0.5) / 16 - 1, v = (y + 0.5) / 4 - 1;
            bm.pixels.push_back(uint8_t(std::max(0.0, 1 - u * u - v * v) * 255));
        }
    d.info.templates.push_back(bm);
    Frame f;
    uint32_t seed = 1;
    auto rnd = [&](uint32_t n) { seed = seed * 1664525u + 1013904223u; return (seed >> 8) % n; };
    for (int i = 0; i < 120; ++i) {
        StampStroke s;
        s.set = uint8_t(rnd(2)); s.tmpl = 3; s.orient = uint8_t(rnd(8));
        s.x = int32_t(rnd(160 * 16)); s.y = int32_t(rnd(120 * 16));
        s.color = {uint8_t(rnd(256)), uint8_t(rnd(256)), uint8_t(rnd(256)), uint8_t(128 + rnd(128))};
        f.added.push_back(Stroke::make_stamp(s));
    }
    CurveStroke c;
    c.color = {20, 40, 160, 160};
    c.points = {{160, 160, 64}, {800, 400, 32}, {1600, 1200, 96}, {2400, 300, 48}};
    f.added.push_back(Stroke::make_curve(c));
    d.frames.push_back(f);
    const double p = browser_psnr(d, "stamps");
    std::printf("chromium vs spt render, bitmap stamps and a curve: PSNR %.2f dB\n", p);
    EXPECT_GE(p, 30.0);
}

// A cartoon painting's first frame as SVG: `spt paint SRC ARGS`, its live strokes, the SVG text
// `spt export` writes, and the PSNR of Chromium's and of Inkscape's drawing of it against
// `spt render`.
struct VectorFrame {
    std::vector<Stroke> live;
    std::string svg;
    std::string note;  // what spt export said on stderr
    double psnr = 0, inkscape_psnr = 0;
};

bool is_vector(const Stroke& s) { return s.kind == StrokeKind::Polygon || s.kind == StrokeKind::Curve; }

// With `vector_only`, the SVG is exported with --vector-only and compared with the file's
// polygons and curves alone, rendered by libspt.
void paint_as_svg(const std::string& name, const std::string& src, const std::string& args, VectorFrame& out,
                  bool vector_only = false) {
    ASSERT_TRUE(have_tools()) << "needs " << kChromium << " and the spt tool";
    ASSERT_TRUE(fs::exists(kInkscape)) << "needs " << kInkscape << " (Debian package inkscape; ./setup.sh test installs it)";
    ASSERT_TRUE(fs::exists(src)) << "media missing: " << src;
    const fs::path d = work_dir(name);
    const std::string spt = (d / "c.spt").string(), svg = (d / "out.svg").string(), ref = (d / "ref.png").string();
    const std::string tool = std::string(SPT_TOOL) + " ";
    const std::string paint = tool + "paint '" + src + "' " + args + " --style cartoon --threads 1 --progress none -o '" + spt + "'";
    ASSERT_EQ(std::system(paint.c_str()), 0) << paint;
    auto reader = Reader::open(spt);
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    auto live = (*reader)->strokes_at(0);
    ASSERT_TRUE(live.ok()) << live.error().message;
    out.live = **live;
    const std::string note = (d / "note.txt").string();
    const std::string exp = tool + "export '" + spt + "' -o '" + svg + "'" + (vector_only ? " --vector-only" : "") + " 2> '" + note + "'";
    const std::string ren = tool + "render '" + spt + "' -o '" + ref + "'";
    ASSERT_EQ(std::system(exp.c_str()), 0) << exp;
    ASSERT_EQ(std::system(ren.c_str()), 0) << ren;
    std::stringstream text, said;
    text << std::ifstream(svg).rdbuf();
    out.svg = text.str();
    said << std::ifstream(note).rdbuf();
    out.note = said.str();
    const auto& h = (*reader)->info().header;
    std::vector<uint8_t> expected;
    if (vector_only) {
        std::vector<Stroke> vector;
        for (const Stroke& s : out.live)
            if (is_vector(s)) vector.push_back(s);
        auto renderer = Renderer::create(h, (*reader)->info().templates);
        ASSERT_TRUE(renderer.ok()) << renderer.error().message;
        Canvas c(h);
        ASSERT_TRUE((*renderer)->render(c, vector).ok());
        expected = c.rgb;
    } else {
        auto r = io::read_image(ref);
        ASSERT_TRUE(r.ok()) << r.error().message;
        expected = r->rgb;
    }
    auto crop = chromium_shot(d, h.width, h.height);
    ASSERT_FALSE(crop.empty());
    ASSERT_EQ(expected.size(), size_t(h.width) * h.height * 3);
    out.psnr = import::psnr_rgb8(crop.data(), expected.data(), size_t(h.width) * h.height);
    const auto ink = inkscape_render(d, h.width, h.height);
    ASSERT_FALSE(ink.empty());
    out.inkscape_psnr = import::psnr_rgb8(ink.data(), expected.data(), size_t(h.width) * h.height);
    std::error_code ec;
    fs::remove_all(d, ec);
}

size_t count_kind(const std::vector<Stroke>& v, StrokeKind k) {
    return size_t(std::count_if(v.begin(), v.end(), [k](const Stroke& s) { return s.kind == k; }));
}

// A flat-colour frame painted by `spt paint --style cartoon` is vector art in SVG: one filled
// <polygon> per polygon stroke, no masks or embedded images, and a browser and Inkscape draw it
// close to `spt render`. Needs the real painter, media, Chromium and Inkscape: without them it
// fails.
TEST(SvgInBrowser, CartoonFrameIsVectorArt) {
    VectorFrame f;
    ASSERT_NO_FATAL_FAILURE(paint_as_svg("cartoon", std::string(SPT_MEDIA_DIR) + "/cartoon/star/f.0030.png",
                                         "--alpha off --target-psnr 36", f));
    const size_t polygons = count_kind(f.live, StrokeKind::Polygon);
    ASSERT_GE(polygons, 5u);
    ASSERT_EQ(polygons, f.live.size()) << "the star still at 36 dB is polygons only";
    const std::string& t = f.svg;
    EXPECT_EQ(count(t, "<mask"), 0u);
    EXPECT_EQ(count(t, "<image"), 0u);
    EXPECT_EQ(count(t, "<polygon ") + count(t, "<path "), polygons);
    EXPECT_EQ(count(t, "fill-rule=\"nonzero\" fill=\"#"), polygons) << "every polygon filled with its colour";
    EXPECT_EQ(count(t, "<"), polygons + 4) << "nothing but <?xml>, <svg>, the background <rect>, the polygons, </svg>";
    std::printf("chromium vs spt render, cartoon star (%zu polygons): PSNR %.2f dB; Inkscape %.2f dB\n", polygons, f.psnr,
                f.inkscape_psnr);
    EXPECT_GE(f.psnr, 40.0);  // measured 46.2: browsers anti-alias analytically, spt on a 4x4/8x8 grid
    EXPECT_GE(f.inkscape_psnr, 40.0);  // measured 51.5
}

// The butterfly's lines (format 1.4 anti-aliased curves) in SVG: stroked polylines with round
// caps and joins where a line has one width, a browser draws them close to `spt render`.
TEST(SvgInBrowser, CartoonLinesAreStrokedPaths) {
    VectorFrame f;
    // A target the polygons and lines reach alone: no stamps, the frame is vector art.
    ASSERT_NO_FATAL_FAILURE(paint_as_svg("lines", std::string(SPT_MEDIA_DIR) + "/video/butterfly-cartoon.avi",
                                         "--frames 40 --target-psnr 28", f));
    const size_t curves = count_kind(f.live, StrokeKind::Curve);
    ASSERT_GE(curves, 20u);
    ASSERT_EQ(count_kind(f.live, StrokeKind::Stamp), 0u);
    const std::string& t = f.svg;
    EXPECT_EQ(count(t, "url(#"), 0u) << "no stroke drawn through a template's mask (a video's file keeps its templates)";
    EXPECT_GE(count(t, "<polyline "), curves / 2) << "most lines have one width";
    EXPECT_EQ(count(t, "stroke-linecap=\"round\" stroke-linejoin=\"round\""), count(t, "<polyline "));
    std::printf("chromium vs spt render, butterfly frame 40 (%zu lines): PSNR %.2f dB; Inkscape %.2f dB\n", curves, f.psnr,
                f.inkscape_psnr);
    EXPECT_GE(f.psnr, 40.0);  // measured 45.6
    EXPECT_GE(f.inkscape_psnr, 40.0);  // measured 54.0
}

// A cartoon painted to 36 dB holds residual stamps: its SVG draws them through masks, and
// `spt export --vector-only` leaves them out, so the frame's fills and lines are plain vector
// art that a browser and Inkscape draw close to those strokes rendered by libspt.
TEST(SvgInBrowser, CartoonVectorOnlyLeavesTheStampsOut) {
    VectorFrame all, vec;
    const std::string src = std::string(SPT_MEDIA_DIR) + "/video/butterfly-cartoon.avi";
    // The palette of every colour that covers 1e-4 of the pixels: many fills and lines (the
    // sparser palette's trial would draw more of the frame with stamps).
    const std::string args = "--frames 40 --target-psnr 36 --min-color-share 0.0001";
    ASSERT_NO_FATAL_FAILURE(paint_as_svg("with-stamps", src, args, all));
    ASSERT_NO_FATAL_FAILURE(paint_as_svg("vector-only", src, args, vec, true));
    const size_t stamps = count_kind(vec.live, StrokeKind::Stamp), polygons = count_kind(vec.live, StrokeKind::Polygon);
    const size_t curves = count_kind(vec.live, StrokeKind::Curve);
    ASSERT_GE(stamps, 100u) << "at 36 dB the butterfly's fills need stamps";
    ASSERT_GE(polygons, 100u);
    ASSERT_GE(curves, 20u);
    EXPECT_GE(count(all.svg, "url(#"), 1u) << "without the flag the stamps are drawn through their template's mask";
    const std::string& t = vec.svg;
    EXPECT_EQ(count(t, "<mask"), 0u) << "no mask for a template nothing draws";
    EXPECT_EQ(count(t, "<image"), 0u);
    EXPECT_EQ(count(t, "url(#"), 0u);
    EXPECT_EQ(count(t, "fill-rule=\"nonzero\" fill=\"#"), polygons) << "every polygon, filled with its colour";
    EXPECT_NE(vec.note.find("left out " + std::to_string(stamps) + " stamp and affine strokes"), std::string::npos) << vec.note;
    std::printf("chromium vs libspt, butterfly frame 40 without its %zu stamps (%zu polygons, %zu lines): PSNR %.2f dB; "
                "Inkscape %.2f dB\n", stamps, polygons, curves, vec.psnr, vec.inkscape_psnr);
    EXPECT_GE(vec.psnr, 40.0);  // measured 45.9 (2,127 stamps left out)
    EXPECT_GE(vec.inkscape_psnr, 40.0);  // measured 54.0
}
