// Loading the user's own stroke templates from a folder, and its errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/image_io.hpp"
#include "io/template_loader.hpp"

namespace fs = std::filesystem;
using namespace spt;

namespace {

struct TempDir {
    fs::path path;
    explicit TempDir(const std::string& name) : path(fs::path(SPT_BINARY_DIR) / ("paint_templates_test_" + name)) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
};

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
    TempDir d("sizes");
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
    auto missing = io::load_templates("/nonexistent/spt-templates");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("/nonexistent/spt-templates"), std::string::npos);

    TempDir empty("empty");
    std::ofstream(empty.path / "readme.txt") << "no images";
    auto none = io::load_templates(empty.path.string());
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().message.find("no image"), std::string::npos);

    TempDir big("big");
    write_gray(big.path / "huge.png", 1025, 4, 255);
    auto huge = io::load_templates(big.path.string());
    ASSERT_FALSE(huge.ok());
    EXPECT_EQ(huge.error().code, Code::LimitExceeded);
    EXPECT_NE(huge.error().message.find("huge.png"), std::string::npos);

    TempDir blank("blank");
    write_gray(blank.path / "zero.png", 8, 8, 0);
    auto zero = io::load_templates(blank.path.string());
    ASSERT_FALSE(zero.ok());
    EXPECT_NE(zero.error().message.find("zero.png"), std::string::npos);

    TempDir bad("bad");
    std::ofstream(bad.path / "broken.png") << "this is not a PNG";
    auto broken = io::load_templates(bad.path.string());
    ASSERT_FALSE(broken.ok());
    EXPECT_NE(broken.error().message.find("broken.png"), std::string::npos);
}
