// spt render of the format 1.3 golden files (tests/format/golden, SPEC.md 9.4) gives the golden
// canvas back from its image files: the half EXR's codes and alpha, and the straight 8-bit
// PNG premultiplied again, hash to MANIFEST.txt's render_fnv1a64 of every frame.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

#include "cli_test_util.hpp"
#include "format/golden_canonical.hpp"
#include "spt/spt.hpp"

using namespace spt;
using spt_test::run_spt;
using spt_test::TempDir;

namespace {

const std::string kGolden = std::string(SPT_SOURCE_DIR) + "/tests/format/golden/";

struct Entry {
    std::string file;
    long frame;
    std::string render_hash;
};

std::vector<Entry> manifest(const std::string& prefix) {
    std::ifstream in(kGolden + "MANIFEST.txt");
    EXPECT_TRUE(in) << "cannot read " << kGolden << "MANIFEST.txt";
    std::vector<Entry> out;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#' || line.rfind(prefix, 0) != 0) continue;
        std::istringstream s(line);
        Entry e;
        std::string live, live_hash;
        s >> e.file >> e.frame >> live >> live_hash >> e.render_hash;
        if (e.file.find(".stored.") == std::string::npos) out.push_back(e);
    }
    return out;
}

// The image's samples as floats (EXR) or 8-bit values (PNG), as stored (no un-premultiplying).
std::vector<float> read_pixels(const std::string& path, int& nch, OIIO::TypeDesc type) {
    OIIO::ImageSpec hint;
    hint.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &hint);
    if (!in) {
        ADD_FAILURE() << path << ": " << OIIO::geterror();
        return {};
    }
    nch = in->spec().nchannels;
    std::vector<float> px(size_t(in->spec().width) * in->spec().height * nch);
    std::vector<uint8_t> b(px.size());
    if (type == OIIO::TypeDesc::UINT8) {
        EXPECT_TRUE(in->read_image(0, 0, 0, nch, type, b.data()));
        for (size_t i = 0; i < b.size(); ++i) px[i] = b[i];
    } else {
        EXPECT_TRUE(in->read_image(0, 0, 0, nch, OIIO::TypeDesc::FLOAT, px.data()));
    }
    return px;
}

// Renders every frame MANIFEST.txt lists for the golden files named `prefix`... (at least
// `at_least` of them) to an `ext` image with spt render, reads its samples back as `type`, and
// checks that the canvas `to_canvas` rebuilds from them hashes to the frame's render_fnv1a64.
using ToCanvas = std::function<void(const Header&, const std::vector<float>& px, int nch, Canvas& c)>;
void expect_images_hash_back(const std::string& prefix, size_t at_least, const std::string& ext, OIIO::TypeDesc type,
                             const ToCanvas& to_canvas) {
    TempDir d;
    const auto entries = manifest(prefix);
    ASSERT_GE(entries.size(), at_least) << "MANIFEST.txt lists no " << prefix << " files";
    for (const auto& e : entries) {
        const std::string out = d.file("f" + ext);
        auto r = run_spt(d, {"render", kGolden + e.file, "-o", out, "--frame", std::to_string(e.frame)});
        ASSERT_EQ(r.code, 0) << e.file << ": " << r.err;
        auto rd = Reader::open(kGolden + e.file);
        ASSERT_TRUE(rd.ok());
        const Header& h = (*rd)->info().header;
        int nch = 0;
        const auto px = read_pixels(out, nch, type);
        Canvas c(h);
        to_canvas(h, px, nch, c);
        EXPECT_EQ(spt::testing::hex64(spt::testing::fnv1a64(spt::testing::render_bytes(c))), e.render_hash)
            << e.file << " frame " << e.frame;
    }
}

}  // namespace

TEST(RenderGoldenOutputs, LinearExrHoldsTheGoldenCanvas) {
    expect_images_hash_back("linear_", 5, ".exr", OIIO::TypeDesc::HALF,
                            [](const Header& h, const std::vector<float>& px, int nch, Canvas& c) {
                                ASSERT_EQ(nch, h.alpha ? 4 : 3);
                                const size_t n = size_t(h.width) * h.height;
                                for (size_t i = 0; i < n; ++i) {
                                    // exact: the value is a half
                                    for (int k = 0; k < 3; ++k) c.rgb16[i * 3 + k] = float_to_half_code(px[i * nch + k]);
                                    if (h.alpha) c.alpha[i] = uint8_t(std::lround(px[i * 4 + 3] * 255.f));
                                }
                            });
}

TEST(RenderGoldenOutputs, StraightPngPremultipliesBackToTheGoldenCanvas) {
    expect_images_hash_back("alpha_", 2, ".png", OIIO::TypeDesc::UINT8,
                            [](const Header& h, const std::vector<float>& px, int nch, Canvas& c) {
                                ASSERT_TRUE(h.alpha && h.color == ColorEncoding::Srgb8);
                                ASSERT_EQ(nch, 4);
                                for (size_t i = 0; i < size_t(h.width) * h.height; ++i) {
                                    const uint8_t a = uint8_t(px[i * 4 + 3]);
                                    c.alpha[i] = a;
                                    for (int k = 0; k < 3; ++k) c.rgb[i * 3 + k] = blend8(0, uint8_t(px[i * 4 + k]), a);
                                }
                            });
}
