// Loading the user's own stroke templates from a folder, and its errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/image_io.hpp"
#include "io/template_loader.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using namespace spt;

namespace {

using spt_test::TempDir;

// A folder `name` inside the test's folder.
fs::path folder(const TempDir& d, const std::string& name) {
    const fs::path p = d.path / name;
    fs::create_directories(p);
    return p;
}

// The error of loading templates from `dir`, which must fail.
Error load_error(const fs::path& dir) {
    auto t = io::load_templates(dir.string());
    EXPECT_FALSE(t.ok()) << dir;
    return t.ok() ? Error{} : t.error();
}

void write_gray(const fs::path& p, uint32_t w, uint32_t h, uint8_t v) {
    std::vector<uint8_t> rgb(size_t(w) * h * 3, v);
    ASSERT_TRUE(io::write_image(p.string(), w, h, rgb.data()).ok());
}

}  // namespace

TEST(PaintTemplates, ShippedFoldersLoadAsBitmaps) {
    // The built-in set's PNGs (16x16, make_templates.py) and the textured brushes (60x60).
    auto t = io::load_templates(std::string(SPT_SOURCE_DIR) + "/converter/templates");
    ASSERT_TRUE(t.ok()) << t.error().message;
    ASSERT_EQ(t->size(), 3u);
    EXPECT_EQ((*t)[0].name, "0-rectangle");
    EXPECT_EQ((*t)[2].name, "2-ellipse");
    for (const auto& x : *t) {
        EXPECT_EQ(x.kind, TemplateKind::Bitmap);
        EXPECT_EQ(x.width, 16);
        EXPECT_EQ(x.height, 16);
    }
    EXPECT_EQ((*t)[0].pixels, std::vector<uint8_t>(256, 255));
    auto b = io::load_templates(std::string(SPT_SOURCE_DIR) + "/converter/templates/brushes");
    ASSERT_TRUE(b.ok()) << b.error().message;
    ASSERT_EQ(b->size(), 2u);
    EXPECT_EQ((*b)[1].name, "1-dry-brush");
    EXPECT_EQ((*b)[1].width, 60);
}

TEST(PaintTemplates, AnySizeUpTo1024AndNameOrder) {
    TempDir d;
    write_gray(d.path / "b.png", 17, 5, 200);
    write_gray(d.path / "a.png", 1024, 2, 9);
    std::ofstream(d.path / "notes.txt") << "ignored";
    auto t = io::load_templates(d.path.string());
    ASSERT_TRUE(t.ok()) << t.error().message;
    ASSERT_EQ(t->size(), 2u);
    EXPECT_EQ((*t)[0].width, 1024);
    EXPECT_EQ((*t)[1].width, 17);
    EXPECT_EQ((*t)[1].pixels[0], 200);  // RGB with equal channels keeps its value
}

TEST(PaintTemplates, ErrorsNameTheProblem) {
    EXPECT_NE(load_error("/nonexistent/spt-templates").message.find("/nonexistent/spt-templates"), std::string::npos);
    TempDir d;
    const fs::path empty = folder(d, "empty"), big = folder(d, "big"), blank = folder(d, "blank"), bad = folder(d, "bad");
    std::ofstream(empty / "readme.txt") << "no images";
    EXPECT_NE(load_error(empty).message.find("no image"), std::string::npos);
    write_gray(big / "huge.png", 1025, 4, 255);
    const Error huge = load_error(big);
    EXPECT_EQ(huge.code, Code::LimitExceeded);
    EXPECT_NE(huge.message.find("huge.png"), std::string::npos);
    write_gray(blank / "zero.png", 8, 8, 0);
    EXPECT_NE(load_error(blank).message.find("zero.png"), std::string::npos);
    std::ofstream(bad / "broken.png") << "this is not a PNG";
    EXPECT_NE(load_error(bad).message.find("broken.png"), std::string::npos);
}
