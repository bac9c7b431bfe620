// Decodes every committed golden file and compares each frame's live list with MANIFEST.txt.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "format/coding_random_streams.hpp"
#include "format/golden_canonical.hpp"

using namespace spt;
using namespace spt::testing;

namespace {

const std::string kDir = std::string(SPT_SOURCE_DIR) + "/tests/format/golden";

struct Row { std::string file; size_t frame; size_t strokes; std::string hash, render; };

std::vector<Row> manifest() {
    std::vector<Row> rows;
    std::ifstream f(kDir + "/MANIFEST.txt");
    std::string line;
    while (std::getline(f, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream is(line);
        Row r;
        is >> r.file >> r.frame >> r.strokes >> r.hash >> r.render;
        rows.push_back(r);
    }
    return rows;
}

}  // namespace

TEST(GoldenConformance, EveryManifestFrameDecodesToItsHash) {
    const auto rows = manifest();
    ASSERT_GE(rows.size(), 20u) << "MANIFEST.txt missing or short";
    std::map<std::string, std::unique_ptr<Reader>> open;
    for (const auto& r : rows) {
        SCOPED_TRACE(r.file + " frame " + std::to_string(r.frame));
        auto& rd = open[r.file];
        if (!rd) {
            auto o = Reader::open(kDir + "/" + r.file);
            ASSERT_TRUE(o.ok()) << o.error().message;
            rd = std::move(*o);
            EXPECT_TRUE(rd->complete());
        }
        auto s = rd->strokes_at(r.frame);
        ASSERT_TRUE(s.ok()) << s.error().message;
        EXPECT_EQ((*s)->size(), r.strokes);
        const bool linear = rd->info().header.color == ColorEncoding::LinearHalf;
        EXPECT_EQ(hex64(fnv1a64(canonical_stored_bytes(**s, linear, rd->info().header.curve_grid))), r.hash);
    }
}

// The rendered pixels of every golden frame, through both of the renderer's paths.
TEST(GoldenConformance, EveryManifestFrameRendersToItsHash) {
    const auto rows = manifest();
    std::map<std::string, std::unique_ptr<Reader>> open;
    for (const auto& r : rows) {
        SCOPED_TRACE(r.file + " frame " + std::to_string(r.frame));
        ASSERT_EQ(r.render.size(), 16u) << "MANIFEST.txt lacks the render hash";
        auto& rd = open[r.file];
        if (!rd) {
            auto o = Reader::open(kDir + "/" + r.file);
            ASSERT_TRUE(o.ok()) << o.error().message;
            rd = std::move(*o);
        }
        const Header& h = rd->info().header;
        auto renderer = Renderer::create(h, rd->info().templates);
        ASSERT_TRUE(renderer.ok()) << renderer.error().message;
        auto s = rd->strokes_at(r.frame);
        ASSERT_TRUE(s.ok()) << s.error().message;
        Canvas tiled(h), single(h), played;
        ASSERT_TRUE((*renderer)->render(tiled, **s).ok());
        for (const auto& st : **s) ASSERT_TRUE((*renderer)->draw(single, st).ok());
        ASSERT_TRUE(rd->render_frame(r.frame, played).ok());
        EXPECT_EQ(hex64(fnv1a64(render_bytes(tiled))), r.render);
        EXPECT_EQ(hex64(fnv1a64(render_bytes(single))), r.render);
        EXPECT_EQ(hex64(fnv1a64(render_bytes(played))), r.render);
    }
}

TEST(GoldenConformance, StoredTwinsAreStoredAndRangeFilesAreRangeCoded) {
    for (const auto& r : manifest()) {
        auto o = Reader::open(kDir + "/" + r.file);
        ASSERT_TRUE(o.ok());
        const bool stored = r.file.find(".stored.spt") != std::string::npos;
        // replay_*.spt: frame coding 2 (SPEC.md 7.7) in every frame, which needs format 1.1.
        const bool replay = !stored && r.file.rfind("replay_", 0) == 0;
        const Coding want = stored ? Coding::Stored : replay ? Coding::Replay : Coding::Range;
        for (const auto& e : (*o)->frames()) EXPECT_EQ(e.coding, want) << r.file;
        if (replay) EXPECT_GE((*o)->info().header.version_minor, 1) << r.file;
    }
}

// Coding 2 is covered by a key frame and by an inter frame (removals, motion, block region).
TEST(GoldenConformance, ReplayGoldenHasKeyAndInterFrames) {
    auto o = Reader::open(kDir + "/replay_paint.spt");
    ASSERT_TRUE(o.ok()) << o.error().message;
    bool key = false, inter = false;
    for (const auto& e : (*o)->frames()) {
        ASSERT_EQ(e.coding, Coding::Replay);
        (e.type == FrameType::Key ? key : inter) = true;
    }
    EXPECT_TRUE(key && inter);
}

TEST(GoldenConformance, SpecialCasesAreWhatTheyClaim) {
    auto ni = Reader::open(kDir + "/no_index.spt");
    ASSERT_TRUE(ni.ok());
    EXPECT_FALSE((*ni)->has_index());
    EXPECT_TRUE((*ni)->complete());
    auto ua = Reader::open(kDir + "/unknown_ancillary.stored.spt");
    ASSERT_TRUE(ua.ok());
    EXPECT_TRUE((*ua)->has_index());
    const auto b = read_bytes(kDir + "/unknown_ancillary.stored.spt");
    EXPECT_NE(std::string(b.begin(), b.end()).find("xtRa"), std::string::npos);
    auto im = Reader::open(kDir + "/inter_motion.spt");
    ASSERT_TRUE(im.ok());
    EXPECT_EQ((*im)->info().header.sets.size(), 16u);
    EXPECT_EQ((*im)->info().header.orientations.size(), 64u);
}
