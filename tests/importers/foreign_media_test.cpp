// Real files written by other shape painters (/work/shared/media/foreign): each import renders
// close to the tool's own PNG. The floors are regressions guards a little under the measured
// figures (bench/import_bench.py prints them); they fail if an importer's geometry breaks.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/image_io.hpp"
#include "spt_import/evaluate.hpp"
#include "spt_import/importer.hpp"

using namespace spt;

namespace {

struct Sample { const char* file; const char* png; double floor_db; };

const Sample kSamples[] = {
    {"coffee-primitive-ellipses.svg", "coffee-primitive-ellipses.png", 47.5},
    {"coffee-primitive-triangles.svg", "coffee-primitive-triangles.png", 48.5},
    {"coffee-geometrize-circles.svg", "coffee-geometrize-circles.png", 48.0},
    {"coffee-geometrize-triangles.svg", "coffee-geometrize-triangles.png", 40.0},
    {"coffee-geometrize-rotellipses.svg", "coffee-geometrize-rotellipses.png", 34.0},
    {"coffee-geometrize-rotrects.svg", "coffee-geometrize-rotrects.png", 44.0},
    {"coffee-geometrize-circles.json", "coffee-geometrize-circles.png", 48.0},
    {"coffee-geometrize-triangles.json", "coffee-geometrize-triangles.png", 40.0},
    {"coffee-geometrize-rotellipses.json", "coffee-geometrize-rotellipses.png", 34.0},
    {"coffee-geometrize-rotrects.json", "coffee-geometrize-rotrects.png", 44.0},
};

}  // namespace

class ForeignMedia : public ::testing::TestWithParam<Sample> {};

TEST_P(ForeignMedia, ImportRendersCloseToTheToolsOwnPng) {
    const Sample& s = GetParam();
    const std::string dir = std::string(SPT_MEDIA_DIR) + "/foreign/";
    if (!std::filesystem::exists(dir + s.file)) GTEST_FAIL() << "media missing: " << dir << s.file;
    auto ref = io::read_image(dir + s.png);
    ASSERT_TRUE(ref.ok()) << ref.error().message;
    import::ImportOptions o;
    o.canvas_size = std::make_pair(ref->width, ref->height);
    auto doc = import::import_path(dir + s.file, "", o);
    ASSERT_TRUE(doc.ok()) << doc.error().message;
    EXPECT_EQ(doc->report.strokes, 300u);
    if (!doc->report.background_stated) {
        auto bg = import::fit_background(*doc, ref->rgb.data());
        ASSERT_TRUE(bg.ok());
        import::set_background(*doc, *bg);
    }
    auto canvas = import::render_frame(*doc, 0);
    ASSERT_TRUE(canvas.ok()) << canvas.error().message;
    ASSERT_EQ(canvas->width, ref->width);
    const double p = import::psnr_rgb8(canvas->rgb.data(), ref->rgb.data(), size_t(ref->width) * ref->height);
    std::printf("%s: PSNR %.2f dB against the tool's PNG\n", s.file, p);
    EXPECT_GE(p, s.floor_db);
}

INSTANTIATE_TEST_SUITE_P(Foreign, ForeignMedia, ::testing::ValuesIn(kSamples), [](const auto& info) {
    std::string n = info.param.file;
    for (auto& c : n) if (!std::isalnum((unsigned char)c)) c = '_';
    return n;
});
