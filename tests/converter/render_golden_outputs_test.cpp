// spt render of the format 1.3 golden files (tests/format/golden, SPEC.md 9.4) gives the golden
// canvas back from its image files: the half EXR's codes and alpha, and the straight 8-bit
// PNG premultiplied again, hash to MANIFEST.txt's render_fnv1a64 of every frame.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>
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

}  // namespace

TEST(RenderGoldenOutputs, LinearExrHoldsTheGoldenCanvas) {
    TempDir d;
    const auto entries = manifest("linear_");
    ASSERT_GE(entries.size(), 5u) << "MANIFEST.txt lists no linear_ files";
    for (const auto& e : entries) {
        const std::string out = d.file("f.exr");
        auto r = run_spt(d, {"render", kGolden + e.file, "-o", out, "--frame", std::to_string(e.frame)});
        ASSERT_EQ(r.code, 0) << e.file << ": " << r.err;
        auto rd = Reader::open(kGolden + e.file);
        ASSERT_TRUE(rd.ok());
        const Header& h = (*rd)->info().header;
        int nch = 0;
        const auto px = read_pixels(out, nch, OIIO::TypeDesc::HALF);
        ASSERT_EQ(nch, h.alpha ? 4 : 3) << e.file;
        Canvas c(h);
        const size_t n = size_t(h.width) * h.height;
        for (size_t i = 0; i < n; ++i) {
            for (int k = 0; k < 3; ++k) c.rgb16[i * 3 + k] = float_to_half_code(px[i * nch + k]);  // exact: the value is a half
            if (h.alpha) c.alpha[i] = uint8_t(std::lround(px[i * 4 + 3] * 255.f));
        }
        EXPECT_EQ(spt::testing::hex64(spt::testing::fnv1a64(spt::testing::render_bytes(c))), e.render_hash)
            << e.file << " frame " << e.frame;
    }
}

TEST(RenderGoldenOutputs, StraightPngPremultipliesBackToTheGoldenCanvas) {
    TempDir d;
    const auto entries = manifest("alpha_");
    ASSERT_GE(entries.size(), 2u) << "MANIFEST.txt lists no alpha_ files";
    for (const auto& e : entries) {
        const std::string out = d.file("f.png");
        auto r = run_spt(d, {"render", kGolden + e.file, "-o", out, "--frame", std::to_string(e.frame)});
        ASSERT_EQ(r.code, 0) << e.file << ": " << r.err;
        auto rd = Reader::open(kGolden + e.file);
        ASSERT_TRUE(rd.ok());
        const Header& h = (*rd)->info().header;
        ASSERT_TRUE(h.alpha && h.color == ColorEncoding::Srgb8);
        int nch = 0;
        const auto px = read_pixels(out, nch, OIIO::TypeDesc::UINT8);
        ASSERT_EQ(nch, 4);
        Canvas c(h);
        for (size_t i = 0; i < size_t(h.width) * h.height; ++i) {
            const uint8_t a = uint8_t(px[i * 4 + 3]);
            c.alpha[i] = a;
            for (int k = 0; k < 3; ++k) c.rgb[i * 3 + k] = blend8(0, uint8_t(px[i * 4 + k]), a);
        }
        EXPECT_EQ(spt::testing::hex64(spt::testing::fnv1a64(spt::testing::render_bytes(c))), e.render_hash)
            << e.file << " frame " << e.frame;
    }
}
