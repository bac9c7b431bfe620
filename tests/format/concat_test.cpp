// spt::concatenate (SPEC.md 9.6): a join of parts written apart is byte for byte the file one
// Writer writes for the same frames; refusals name the part; metadata and ROIs combine.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "spt/concat.hpp"
#include "spt/spt.hpp"

namespace {

namespace fs = std::filesystem;
using namespace spt;

struct Tmp {
    fs::path dir;
    Tmp() {
        dir = fs::temp_directory_path() / ("spt_concat_" + std::to_string(::getpid()) + "_" +
                                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    ~Tmp() { fs::remove_all(dir); }
    std::string operator()(const std::string& n) const { return (dir / n).string(); }
};

std::string slurp(const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

StreamInfo base_info() {
    StreamInfo info;
    info.header.width = 40;
    info.header.height = 30;
    info.header.fps = {25, 1};
    info.header.sets = {{10, 5}, {4, 2}};
    info.header.orientations = default_orientations(8);
    Template e, b;
    e.kind = TemplateKind::Ellipse;
    b.kind = TemplateKind::Bitmap;
    b.width = 3;
    b.height = 2;
    b.pixels = {0, 90, 255, 30, 60, 200};
    info.templates = {e, b};
    info.metadata = {{"software", "concat test"}, {"painter.seed", "9"}};
    return info;
}

// Frame `i` of a clip with key frames at `keys` (deterministic from i).
Frame make_frame(uint32_t i, bool key, size_t live) {
    std::mt19937 rng(1000 + i);
    auto u = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    Frame f;
    f.type = key ? FrameType::Key : FrameType::Inter;
    if (!key)
        for (uint32_t k = 0; k < live; k += 3) f.removed.push_back(k);
    if (!key && i % 2) {
        f.motion.block_size = 16;
        f.motion.cols = 3;
        f.motion.rows = 2;
        for (int k = 0; k < 6; ++k) f.motion.vectors.push_back({int16_t(k - 3), int16_t(2 - k)});
    }
    for (int k = 0, n = key ? 30 : 8; k < n; ++k) {
        if (k % 5 == 4) {
            CurveStroke c;
            c.color = {uint8_t(u(0, 255)), uint8_t(u(0, 255)), uint8_t(u(0, 255)), 200};
            for (int p = 0; p < 3; ++p) c.points.push_back({u(0, 640), u(0, 480), uint32_t(u(8, 40))});
            f.added.push_back(Stroke::make_curve(c));
            continue;
        }
        StampStroke s;
        s.set = uint8_t(u(0, 1));
        s.tmpl = uint8_t(u(0, 1));
        s.orient = uint8_t(u(0, 7));
        s.x = u(0, 639);
        s.y = u(0, 479);
        s.color = {uint8_t(u(0, 255)), uint8_t(u(0, 255)), uint8_t(u(0, 255)), uint8_t(u(1, 255))};
        f.added.push_back(Stroke::make_stamp(s));
    }
    return f;
}

// Writes frames [from, to) of the clip (key frames where `is_key`), renumbered from 0.
void write_clip(const std::string& path, StreamInfo info, uint32_t from, uint32_t to, Coding coding,
                const std::vector<Roi>& rois = {}) {
    info.rois = rois;
    auto w = Writer::create(path, info, {coding});
    ASSERT_TRUE(w.ok()) << w.error().message;
    size_t live = 0;
    for (uint32_t i = from; i < to; ++i) {
        const bool key = i == from || i % 7 == 0;
        Frame f = make_frame(i, key, live);
        f.index = i - from;
        live = key ? f.added.size() : live - f.removed.size() + f.added.size();
        ASSERT_TRUE((*w)->append(f).ok());
    }
    ASSERT_TRUE((*w)->finish().ok());
}

TEST(Concat, JoinOfPartsIsTheWholeFileByteForByte) {
    for (Coding coding : {Coding::Range, Coding::Stored}) {
        Tmp t;
        // Parts start at key frames 0, 7, 12 (a forced key) and 21.
        const std::vector<std::pair<uint32_t, uint32_t>> cuts = {{0, 7}, {7, 12}, {12, 21}, {21, 26}};
        std::vector<std::string> parts;
        StreamInfo whole_info = base_info();
        std::vector<Roi> whole_rois;
        for (size_t k = 0; k < cuts.size(); ++k) {
            const auto [a, b] = cuts[k];
            StreamInfo pi = base_info();
            pi.metadata.emplace_back("part.shot", std::to_string(k) + "/4");  // dropped by the join
            pi.metadata.emplace_back("source.first_frame", std::to_string(1001 + a));
            std::vector<Roi> rois = {{1, 2, 3, 4, 5, 6}};
            whole_rois.push_back({a + 1, a + 2, 3, 4, 5, 6});
            parts.push_back(t("part" + std::to_string(k) + ".spt"));
            write_clip(parts.back(), pi, a, b, coding, rois);
        }
        whole_info.metadata.emplace_back("source.first_frame", "1001");
        // The whole clip in one Writer, with key frames where the parts start (12 is forced).
        {
            StreamInfo wi = whole_info;
            wi.rois = whole_rois;
            auto w = Writer::create(t("whole.spt"), wi, {coding});
            ASSERT_TRUE(w.ok());
            size_t live = 0;
            for (const auto& [a, b] : cuts)
                for (uint32_t i = a; i < b; ++i) {
                    const bool key = i == a || i % 7 == 0;
                    Frame f = make_frame(i, key, live);
                    f.index = i;
                    live = key ? f.added.size() : live - f.removed.size() + f.added.size();
                    ASSERT_TRUE((*w)->append(f).ok());
                }
            ASSERT_TRUE((*w)->finish().ok());
        }
        auto rep = concatenate(parts, t("joined.spt"));
        ASSERT_TRUE(rep.ok()) << rep.error().message;
        EXPECT_EQ(rep->frames, 26u);
        EXPECT_TRUE(rep->warnings.empty()) << rep->warnings.front();
        EXPECT_FALSE(fs::exists(t("joined.spt.partial")));
        const std::string joined = slurp(t("joined.spt")), whole = slurp(t("whole.spt"));
        ASSERT_EQ(joined.size(), whole.size());
        EXPECT_TRUE(joined == whole) << "coding " << int(coding);
        EXPECT_EQ(rep->bytes, joined.size());

        // And it reads back: every frame's strokes equal the part's.
        auto r = Reader::open(t("joined.spt"));
        ASSERT_TRUE(r.ok());
        EXPECT_TRUE((*r)->complete() && (*r)->has_index());
        EXPECT_EQ(first_frame_number((*r)->info()), 1001u);
        auto p2 = Reader::open(parts[2]);
        ASSERT_TRUE(p2.ok());
        for (size_t i = 0; i < 9; ++i) {
            auto a = (*r)->strokes_at(12 + i);
            auto b = (*p2)->strokes_at(i);
            ASSERT_TRUE(a.ok() && b.ok());
            EXPECT_EQ(**a, **b) << "frame " << 12 + i;
        }
    }
}

TEST(Concat, RefusesPartsThatDoNotAgreeNamingTheFile) {
    Tmp t;
    write_clip(t("a.spt"), base_info(), 0, 5, Coding::Range);
    auto refuse = [&](const std::string& name, StreamInfo info, const std::string& words) {
        write_clip(t(name), info, 0, 4, Coding::Range);
        auto rep = concatenate({t("a.spt"), t(name)}, t("out.spt"));
        ASSERT_FALSE(rep.ok()) << name;
        EXPECT_NE(rep.error().message.find(t(name)), std::string::npos) << rep.error().message;
        EXPECT_NE(rep.error().message.find(words), std::string::npos) << rep.error().message;
        EXPECT_FALSE(fs::exists(t("out.spt")));
        EXPECT_FALSE(fs::exists(t("out.spt.partial")));
    };
    StreamInfo i = base_info();
    i.header.width = 41;
    refuse("canvas.spt", i, "canvas");
    i = base_info();
    i.header.fps = {24, 1};
    refuse("fps.spt", i, "frame rate");
    i = base_info();
    i.header.sets = {{10, 5}, {5, 2}};
    refuse("sets.spt", i, "stroke sets");
    i = base_info();
    i.templates[1].pixels[0] = 1;
    refuse("tmpl.spt", i, "templates");
    i = base_info();
    i.header.background = {0, 0, 0};
    refuse("bg.spt", i, "background");
    i = base_info();
    i.header.orientations[3].cos_q14 -= 1;
    refuse("orient.spt", i, "orientation");

    // An incomplete part (a crashed writer): cut off its end.
    std::string bytes = slurp(t("a.spt"));
    {
        std::ofstream f(t("cut.spt"), std::ios::binary);
        f.write(bytes.data(), std::streamsize(bytes.size() - 30));
    }
    auto rep = concatenate({t("a.spt"), t("cut.spt")}, t("out.spt"));
    ASSERT_FALSE(rep.ok());
    EXPECT_NE(rep.error().message.find(t("cut.spt") + ": incomplete"), std::string::npos) << rep.error().message;
    // A flipped byte inside a frame: the CRC check of the copy (or the reader) names it.
    bytes[bytes.size() / 2] ^= 0x40;
    {
        std::ofstream f(t("bad.spt"), std::ios::binary);
        f.write(bytes.data(), std::streamsize(bytes.size()));
    }
    rep = concatenate({t("bad.spt")}, t("out.spt"));
    ASSERT_FALSE(rep.ok());
    EXPECT_NE(rep.error().message.find(t("bad.spt")), std::string::npos) << rep.error().message;
    EXPECT_FALSE(fs::exists(t("out.spt")));
    // The caller's own refusal (a plan's shots) stops the join before anything is written.
    ConcatOptions co;
    co.check_part = [&](size_t pos, const std::string& path, const StreamInfo&, uint64_t frames) -> Status {
        if (pos == 1) return make_error(Code::InvalidArgument, path + ": refused with " + std::to_string(frames) + " frames");
        return {};
    };
    rep = concatenate({t("a.spt"), t("a.spt")}, t("out.spt"), co);
    ASSERT_FALSE(rep.ok());
    EXPECT_EQ(rep.error().message, t("a.spt") + ": refused with 5 frames");
    EXPECT_FALSE(fs::exists(t("out.spt")));
}

TEST(Concat, MetadataAndFrameNumbersCombine) {
    StreamInfo a = base_info(), b = base_info(), c = base_info();
    a.metadata.emplace_back("title", "one");
    b.metadata.emplace_back("title", "two");
    a.metadata.emplace_back("source.first_frame", "1001");
    b.metadata.emplace_back("source.first_frame", "1011");
    c.metadata.emplace_back("source.first_frame", "1013");
    c.metadata.emplace_back("only.in.c", "x");
    a.metadata.emplace_back("part.shot", "0/3");
    a.rois = {{0, 9, 1, 1, 2, 2}};
    c.rois = {{1, 1, 3, 3, 4, 4}};
    std::vector<std::string> warn;
    auto j = join_info({a, b, c}, {10, 2, 5}, {"a", "b", "c"}, &warn);
    ASSERT_TRUE(j.ok()) << j.error().message;
    // Shared entries in the first part's order; `title` differs (dropped, warned); `part.` never.
    std::vector<std::pair<std::string, std::string>> want = {
        {"software", "concat test"}, {"painter.seed", "9"}, {"source.first_frame", "1001"}};
    EXPECT_EQ(j->metadata, want);
    ASSERT_EQ(warn.size(), 1u);
    EXPECT_NE(warn[0].find("'title'"), std::string::npos);
    EXPECT_EQ(j->header.frame_count, 17u);
    ASSERT_EQ(j->rois.size(), 2u);
    EXPECT_EQ(j->rois[1].first_frame, 13u);
    // Numbers that do not follow on: the numbering is dropped (frames number from 0).
    warn.clear();
    j = join_info({a, b}, {9, 2}, {"a", "b"}, &warn);
    ASSERT_TRUE(j.ok());
    EXPECT_FALSE(has_first_frame_number(*j));
    EXPECT_EQ(first_frame_number(*j), 0u);
    EXPECT_EQ(warn.size(), 2u);
    // Files without numbers join to a file without them.
    j = join_info({base_info(), base_info()}, {3, 4}, {"x", "y"});
    ASSERT_TRUE(j.ok());
    EXPECT_FALSE(has_first_frame_number(*j));
}

}  // namespace
