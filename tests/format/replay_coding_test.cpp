// Frame coding 2 (SPEC.md 7.7): the generator's test vectors, candidate domains, and round trips
// of strokes drawn from the generator (key and inter frames), with the fallback to coding 1 for
// strokes that do not replay.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "spt/spt.hpp"
#include "spt/replay.hpp"

using namespace spt;

namespace {

// below() is the high half of the 128-bit product, computed in 64-bit arithmetic (mul_high64)
// so that the public header needs no compiler extension; it must agree with the compiler's own
// 128-bit product everywhere (edges and random values). The test may use the extension.
uint64_t reference_high(uint64_t a, uint64_t b) {
    __extension__ typedef unsigned __int128 U128;
    return uint64_t((U128(a) * b) >> 64);
}

TEST(ReplayGenerator, PortableHighProductAgrees) {
    const uint64_t edge[] = {0, 1, 2, 0xFFFFFFFFull, 0x100000000ull, 0x8000000000000000ull, ~0ull, ~0ull - 1,
                             0x9E3779B97F4A7C15ull};
    for (uint64_t a : edge)
        for (uint64_t b : edge) EXPECT_EQ(reference_high(a, b), replay::below(a, b)) << a << " * " << b;
    EXPECT_EQ(replay::mul_high64(~0ull, ~0ull), ~0ull - 1);
    static_assert(replay::below(~0ull, ~0ull) == ~0ull - 1, "below() is usable in constant expressions");
    for (uint64_t i = 0; i < 100000; ++i) {
        const uint64_t a = replay::mix64(2 * i), b = replay::mix64(2 * i + 1) >> (i % 64);
        ASSERT_EQ(reference_high(a, b), replay::below(a, b)) << a << " * " << b;
    }
}

TEST(ReplayGenerator, SpecTestVectors) {
    EXPECT_EQ(replay::mix64(0), 0xe220a8397b1dcdafull);
    EXPECT_EQ(replay::mix64(1), 0x910a2dec89025cc1ull);
    const uint64_t pos[4] = {0x1cc18e4f26cc7702ull, 0x1fa9b0734dc08e3aull, 0x455db05b7273e47cull, 0x161c833549db0b57ull};
    for (uint64_t n = 0; n < 4; ++n) EXPECT_EQ(replay::draw(1, 0, n, replay::Stream::Position), pos[n]);
    EXPECT_EQ(replay::draw(1, 2, 5, replay::Stream::Template), 0xa3ae387c081a6151ull);
    EXPECT_EQ(replay::draw(1, 2, 5, replay::Stream::Orientation), 0x0a0a61f6e326d7eeull);
    EXPECT_EQ(replay::below(replay::draw(1, 0, 0, replay::Stream::Position), 256 * 170), 4888u);
    ReplayRegion r;
    r.use_rects = true;
    r.rects = {{10, 5, 4, 3}, {12, 6, 6, 2}};
    const replay::CandidateDomain d(32, 16, r);
    ASSERT_EQ(d.size(), 20u);
    const uint32_t want[4][4] = {{13, 7, 2, 2}, {12, 6, 1, 6}, {12, 5, 3, 4}, {17, 6, 1, 7}};
    for (int n = 0; n < 4; ++n) {
        const auto c = replay::candidate(7, 1, n, d, 4, 8);
        EXPECT_EQ(c.x, want[n][0]);
        EXPECT_EQ(c.y, want[n][1]);
        EXPECT_EQ(c.tmpl, want[n][2]);
        EXPECT_EQ(c.orient, want[n][3]);
    }
}

TEST(ReplayGenerator, DomainIsRasterOrderOfRegion) {
    ReplayRegion r;
    r.use_rects = true;
    r.rects = {{3, 2, 20, 9}, {0, 10, 5, 5}};
    r.use_blocks = true;
    r.block_size = 8;
    r.blocks = {1, 0, 1, 1, 1, 0, 0, 0, 1};  // 24x20 canvas: 3x3 blocks
    const uint32_t W = 24, H = 20;
    ASSERT_EQ(replay::check_region(r, W, H), "");
    std::vector<std::pair<uint32_t, uint32_t>> want;
    for (uint32_t y = 0; y < H; ++y)
        for (uint32_t x = 0; x < W; ++x) {
            bool in = false;
            for (const auto& q : r.rects) in = in || (x >= q.x && x < q.x + q.w && y >= q.y && y < q.y + q.h);
            if (in && r.blocks[(y / 8) * 3 + x / 8]) want.push_back({x, y});
        }
    const replay::CandidateDomain d(W, H, r);
    ASSERT_EQ(d.size(), want.size());
    for (size_t k = 0; k < want.size(); ++k) {
        uint32_t x, y;
        d.pixel(k, x, y);
        EXPECT_EQ(x, want[k].first);
        EXPECT_EQ(y, want[k].second);
        EXPECT_TRUE(d.contains(x, y));
    }
}

StreamInfo small_info() {
    StreamInfo info;
    info.header.width = 48;
    info.header.height = 32;
    info.header.fps = {24, 1};
    info.header.background = {250, 240, 230};
    info.header.sets = {{16, 8}, {6, 3}};
    info.header.orientations = default_orientations(8);
    Template e;
    e.kind = TemplateKind::Ellipse;
    Template b;
    b.kind = TemplateKind::Bitmap;
    b.width = b.height = 4;
    b.pixels = {0, 128, 128, 0, 128, 255, 255, 128, 128, 255, 255, 128, 0, 128, 128, 0};
    info.templates = {e, b};
    return info;
}

// Strokes as a painter drawing from the generator would accept them: every third candidate.
std::vector<Stroke> replay_strokes(const StreamInfo& info, const ReplayInfo& ri, int per_set, uint32_t salt) {
    std::vector<Stroke> out;
    for (uint32_t s = 0; s < info.header.sets.size(); ++s) {
        const ReplayRegion region = ri.regions.empty() ? ReplayRegion{} : ri.regions[s];
        const replay::CandidateDomain d(info.header.width, info.header.height, region);
        for (int i = 0; i < per_set; ++i) {
            const uint64_t n = uint64_t(i) * 3 + (i % 2);
            const auto c = replay::candidate(ri.seed, s, n, d, uint32_t(info.templates.size()), 8);
            StampStroke t;
            t.set = uint8_t(s);
            t.tmpl = c.tmpl;
            t.orient = ri.random_orientation ? c.orient : uint8_t((i * 5 + salt) % 8);
            t.x = int32_t(c.x) * 16 + 8;
            t.y = int32_t(c.y) * 16 + 8;
            t.color = Rgba8{uint8_t(i * 37 + salt), uint8_t(i * 11 + 90), uint8_t(255 - i * 7), 255};
            out.push_back(Stroke::make_stamp(t));
        }
    }
    return out;
}

std::string temp_path(const char* name) {
    return (std::filesystem::temp_directory_path() / (std::string("spt_replay_") + std::to_string(::getpid()) + "_" + name + ".spt")).string();
}

TEST(ReplayCoding, KeyAndInterFramesRoundTripWithFallback) {
    const StreamInfo info = small_info();
    const std::string path = temp_path("roundtrip");
    ReplayInfo ri;
    ri.present = true;
    ri.seed = 99;
    std::vector<Frame> frames(4);
    frames[0].added = replay_strokes(info, ri, 12, 0);
    frames[0].replay = ri;
    // Inter frame: removals, motion, new strokes drawn in a block region.
    frames[1].index = 1;
    frames[1].type = FrameType::Inter;
    frames[1].removed = {0, 5, 7};
    frames[1].motion.block_size = 16;
    frames[1].motion.cols = 3;
    frames[1].motion.rows = 2;
    frames[1].motion.vectors = {{16, 0}, {0, 0}, {-8, 4}, {0, 0}, {0, 0}, {3, 3}};
    ReplayInfo ri1 = ri;
    ri1.seed = 1234;
    ri1.random_orientation = true;
    ReplayRegion blocks;
    blocks.use_blocks = true;
    blocks.block_size = 8;
    blocks.blocks.assign(6 * 4, 0);
    blocks.blocks[3] = blocks.blocks[9] = blocks.blocks[10] = 1;
    ri1.regions = {blocks, blocks};
    frames[1].added = replay_strokes(info, ri1, 5, 3);
    frames[1].replay = ri1;
    // An edited stroke: falls back to coding 1.
    frames[2].index = 2;
    frames[2].type = FrameType::Inter;
    frames[2].added = replay_strokes(info, ri, 4, 1);
    frames[2].added[2].stamp.x += 3;  // off the pixel centre: no candidate has it
    frames[2].replay = ri;
    // A colour off the lattice of step 4: falls back too.
    frames[3].index = 3;
    frames[3].type = FrameType::Key;
    ReplayInfo ri3 = ri;
    ri3.color_step = 4;
    frames[3].added = replay_strokes(info, ri3, 6, 2);
    frames[3].replay = ri3;

    WriterOptions wo;
    wo.coding = Coding::Replay;
    {
        auto w = Writer::create(path, info, wo);
        ASSERT_TRUE(w) << w.error().message;
        for (const Frame& f : frames) ASSERT_TRUE((*w)->append(f));
        ASSERT_TRUE((*w)->finish());
    }
    auto r = Reader::open(path);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ((*r)->info().header.version_minor, 1);
    const Coding want[4] = {Coding::Replay, Coding::Replay, Coding::Range, Coding::Range};
    std::vector<Stroke> live;
    auto renderer = Renderer::create(info.header, info.templates);
    for (size_t i = 0; i < frames.size(); ++i) {
        EXPECT_EQ((*r)->frames()[i].coding, want[i]) << "frame " << i;
        ASSERT_TRUE(apply_frame(live, frames[i], info.header));
        auto got = (*r)->strokes_at(i);
        ASSERT_TRUE(got) << got.error().message;
        EXPECT_EQ(**got, live) << "frame " << i;
    }
    // Random access to an inter frame decodes its predecessor first.
    auto r2 = Reader::open(path);
    auto f1 = (*r2)->read_frame(1);
    ASSERT_TRUE(f1) << f1.error().message;
    EXPECT_EQ(f1->added, frames[1].added);
    EXPECT_EQ(f1->replay.regions, ri1.regions);
    std::filesystem::remove(path);
}

TEST(ReplayCoding, SmallerThanCoding1AndCorruptionIsAnError) {
    const StreamInfo info = small_info();
    ReplayInfo ri;
    ri.present = true;
    ri.seed = 5;
    Frame f;
    f.added = replay_strokes(info, ri, 40, 0);
    f.replay = ri;
    uint64_t size[2];
    const std::string path = temp_path("size");
    for (int k = 0; k < 2; ++k) {
        WriterOptions wo;
        wo.coding = k ? Coding::Replay : Coding::Range;
        auto w = Writer::create(path, info, wo);
        ASSERT_TRUE((*w)->append(f));
        ASSERT_TRUE((*w)->finish());
        size[k] = (*w)->stats().frame_bytes;
    }
    EXPECT_LT(size[1], size[0]);
    // Flip bits in the replayed stream: every outcome is a value or an error, never a crash.
    std::FILE* fp = std::fopen(path.c_str(), "rb");
    std::vector<uint8_t> bytes(size_t(std::filesystem::file_size(path)));
    ASSERT_EQ(std::fread(bytes.data(), 1, bytes.size(), fp), bytes.size());
    std::fclose(fp);
    auto r = Reader::open_memory(bytes.data(), bytes.size());
    ASSERT_TRUE(r);
    const uint64_t off = (*r)->frames()[0].offset;
    ReaderOptions ro;
    ro.verify_checksums = false;
    for (uint64_t i = off + 8 + 8 + 11; i < off + (*r)->frames()[0].chunk_bytes - 4; ++i) {
        auto b = bytes;
        b[i] ^= 0x5a;
        auto rr = Reader::open_memory(b.data(), b.size(), ro);
        if (!rr) continue;
        auto s = (*rr)->strokes_at(0);
        (void)s;
    }
    std::filesystem::remove(path);
}

}  // namespace
