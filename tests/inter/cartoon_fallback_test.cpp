// `--style cartoon` is never larger than the default painter at the same --target-psnr
// (issue 34): where its polygons do not pay (a photograph, texture), the default painter's
// painting is written, and stderr says so.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/image_io.hpp"
#include "spt/reader.hpp"
#include "video/change_clips.hpp"
#include "video/synthetic.hpp"

using namespace spt;

namespace {

struct Painted {
    int status = -1;
    std::string err;
    uint64_t bytes = 0;
    std::string options;  // painter.options
};

Painted paint(const std::string& input, const std::string& out, const std::string& extra) {
    const std::string log = out + ".log";
    const std::string cmd = std::string(SPT_TOOL) + " paint '" + input + "' -o '" + out +
                            "' --seed 1 --target-psnr 30 --threads 2 --progress none " + extra + " 2> '" + log + "'";
    Painted r;
    r.status = std::system(cmd.c_str());
    std::ifstream f(log);
    std::stringstream ss;
    ss << f.rdbuf();
    r.err = ss.str();
    std::error_code ec;
    r.bytes = std::filesystem::file_size(out, ec);
    if (auto rd = Reader::open(out); rd.ok())
        for (const auto& [k, v] : (*rd)->info().metadata)
            if (k == "painter.options") r.options = v;
    return r;
}

}  // namespace

TEST(CartoonFallback, APhotographGetsTheDefaultPaintersSmallerFileAndSaysSo) {
    const auto dir = spt_test::temp_dir("fallback_still");
    const std::string photo = std::string(SPT_SOURCE_DIR) + "/samples/coffee-320.png";
    const Painted def = paint(photo, (dir / "default.spt").string(), "");
    const Painted car = paint(photo, (dir / "cartoon.spt").string(), "--style cartoon");
    ASSERT_EQ(def.status, 0) << def.err;
    ASSERT_EQ(car.status, 0) << car.err;
    EXPECT_LE(car.bytes, def.bytes);
    EXPECT_NE(car.err.find("the default painter paints"), std::string::npos) << car.err;
    EXPECT_EQ(car.options.find("style=cartoon"), std::string::npos) << "the file says what painted it: " << car.options;
}

TEST(CartoonFallback, AFlatDrawingKeepsTheCartoonPainting) {
    const auto dir = spt_test::temp_dir("fallback_flat");
    const auto clips = spt_test::change_clips(192, 128, 4);
    const auto& still = clips.front();  // outlined flat shapes over fine paper
    const std::string png = (dir / "flat.png").string();
    ASSERT_TRUE(io::write_image(png, still.width, still.height, still.frames[0].data()).ok());
    const Painted car = paint(png, (dir / "cartoon.spt").string(), "--style cartoon");
    ASSERT_EQ(car.status, 0) << car.err;
    EXPECT_EQ(car.err.find("the default painter paints"), std::string::npos) << car.err;
    EXPECT_NE(car.options.find("style=cartoon"), std::string::npos) << car.options;
}

TEST(CartoonFallback, ATexturedClipIsNeverLargerThanTheDefaultPainters) {
    const auto dir = spt_test::temp_dir("fallback_clip");
    // The encoder tests' textured scene: smooth colour fields under hard-edged discs, panning.
    for (int i = 0; i < 4; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "f.%04d.png", i);
        const auto rgb = spt_test::scene_frame(0, i, 160, 96);
        ASSERT_TRUE(io::write_image((dir / name).string(), 160, 96, rgb.data()).ok());
    }
    const std::string seq = (dir / "f.####.png").string();
    const Painted def = paint(seq, (dir / "default.spt").string(), "");
    const Painted car = paint(seq, (dir / "cartoon.spt").string(), "--style cartoon");
    ASSERT_EQ(def.status, 0) << def.err;
    ASSERT_EQ(car.status, 0) << car.err;
    EXPECT_LE(car.bytes, def.bytes) << car.err;
}
