// Lead strokes in frame coding 2 (SPEC.md 7.7.5, format 1.5): polygons, curves and affine
// strokes coded as in coding 1 before the replayed stamps, which are predicted from the canvas
// the lead leaves. Round trips, the writer's choices (version, fallback, the smaller coding)
// and hostile bodies.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "spt/replay.hpp"
#include "spt/spt.hpp"

using namespace spt;

namespace {

StreamInfo lead_info() {
    StreamInfo info;
    info.header.width = 40;
    info.header.height = 30;
    info.header.fps = {24, 1};
    info.header.background = {250, 240, 230};
    info.header.sets = {{8, 4}, {4, 2}};
    info.header.orientations = default_orientations(8);
    Template e;
    e.kind = TemplateKind::Ellipse;
    info.templates = {e};
    return info;
}

Stroke polygon(int32_t x, int32_t y, Rgba8 c) {
    PolygonStroke p;
    p.color = c;
    p.supersample = 4;
    p.points = {{x, y}, {x + 16 * 12 + 5, y + 16 * 2}, {x + 16 * 7, y + 16 * 14 + 9}};
    return Stroke::make_polygon(p);
}

// `n` stamps per set from the generator (every other candidate accepted), colour step 1.
std::vector<Stroke> stamps(const StreamInfo& info, const ReplayInfo& ri, int n) {
    std::vector<Stroke> out;
    for (uint32_t s = 0; s < info.header.sets.size(); ++s) {
        const replay::CandidateDomain d(info.header.width, info.header.height, ri.regions.empty() ? ReplayRegion{} : ri.regions[s]);
        for (int i = 0; i < n; ++i) {
            const auto c = replay::candidate(ri.seed, s, uint64_t(2 * i), d, 1, 8);
            StampStroke t;
            t.set = uint8_t(s);
            t.tmpl = c.tmpl;
            t.orient = uint8_t(i % 8);
            t.x = int32_t(c.x) * 16 + 8;
            t.y = int32_t(c.y) * 16 + 8;
            t.color = Rgba8{uint8_t(40 + 9 * i), uint8_t(200 - 5 * i), uint8_t(90 + s * 60), 255};
            out.push_back(Stroke::make_stamp(t));
        }
    }
    return out;
}

std::string temp_path(const char* name) {
    return (std::filesystem::temp_directory_path() / ("spt_lead_" + std::to_string(::getpid()) + "_" + name + ".spt")).string();
}

std::vector<uint8_t> slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// A key frame led by a polygon, a curve and an affine stroke, and an inter frame (removals,
// motion) led by a polygon; both with enough stamps that coding 2 is the smaller.
std::vector<Frame> lead_frames(const StreamInfo& info) {
    ReplayInfo ri;
    ri.present = true;
    ri.seed = 7;
    Frame k;
    k.added.push_back(polygon(16 * 3, 16 * 4, {30, 120, 200, 255}));
    CurveStroke line;
    line.color = {20, 20, 30, 255};
    line.points = {{16 * 2, 16 * 25, 32}, {16 * 20 + 3, 16 * 12, 20}, {16 * 38, 16 * 5, 28}};
    k.added.push_back(Stroke::make_curve(line));
    AffineStroke blob;
    blob.tmpl = 0; blob.tx = 16 * 30; blob.ty = 16 * 20; blob.a = 96; blob.d = 64; blob.color = {220, 60, 40, 255};
    k.added.push_back(Stroke::make_affine(blob));
    for (const Stroke& s : stamps(info, ri, 24)) k.added.push_back(s);
    k.replay = ri;
    Frame i;
    i.index = 1;
    i.type = FrameType::Inter;
    i.removed = {1, 5, 6};
    i.motion.block_size = 16;
    i.motion.cols = 3;
    i.motion.rows = 2;
    i.motion.vectors = {{16, 0}, {0, 0}, {-8, 4}, {0, 0}, {0, 0}, {3, 3}};
    i.added.push_back(polygon(16 * 20, 16 * 10, {250, 210, 40, 255}));
    ReplayInfo ri1 = ri;
    ri1.seed = 8;
    for (const Stroke& s : stamps(info, ri1, 16)) i.added.push_back(s);
    i.replay = ri1;
    return {k, i};
}

Status write(const std::string& path, const StreamInfo& info, const std::vector<Frame>& frames) {
    WriterOptions wo;
    wo.coding = Coding::Replay;
    auto w = Writer::create(path, info, wo);
    if (!w) return w.error();
    for (const Frame& f : frames)
        if (auto st = (*w)->append(f); !st) return st;
    return (*w)->finish();
}

TEST(ReplayLead, PolygonsCurvesAndAffinesLeadTheReplayedStamps) {
    const StreamInfo info = lead_info();
    const std::vector<Frame> frames = lead_frames(info);
    const std::string path = temp_path("roundtrip");
    ASSERT_TRUE(write(path, info, frames));
    auto r = Reader::open(path);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ((*r)->info().header.version_minor, kLeadMinorVersion) << "the writer raises HEAD to 1.5 in place";
    std::vector<Stroke> live;
    for (size_t i = 0; i < frames.size(); ++i) {
        EXPECT_EQ((*r)->frames()[i].coding, Coding::Replay) << "frame " << i;
        ASSERT_TRUE(apply_frame(live, frames[i], info.header));
        auto got = (*r)->strokes_at(i);
        ASSERT_TRUE(got) << got.error().message;
        EXPECT_EQ(**got, live) << "frame " << i;
    }
    // The file renders as the strokes do (the decoder drew the lead before predicting stamps).
    auto rd = Renderer::create(info.header, info.templates);
    Canvas want(info.header), got(info.header);
    ASSERT_TRUE((*rd)->render(want, live));
    auto shown = (*r)->strokes_at(1);
    ASSERT_TRUE((*rd)->render(got, **shown));
    EXPECT_EQ(want.rgb, got.rgb);
    // Coded as coding 1, the same frames take more bytes.
    WriterOptions wo;
    wo.coding = Coding::Range;
    const std::string plain = temp_path("plain");
    {
        auto w = Writer::create(plain, info, wo);
        for (const Frame& f : frames) ASSERT_TRUE((*w)->append(f));
        ASSERT_TRUE((*w)->finish());
    }
    EXPECT_LT(std::filesystem::file_size(path), std::filesystem::file_size(plain));
    std::filesystem::remove(path);
    std::filesystem::remove(plain);
}

// The flags byte of a coding-2 key frame body: after added_count (a varint) and the seed.
uint8_t key_frame_flags(const std::vector<uint8_t>& file, const FrameEntry& e) {
    size_t p = size_t(e.offset) + 8 + 8;  // chunk length and type, frame header
    while (file[p] & 0x80) ++p;
    return file[p + 1 + 8];
}

// Sets drawing from one region code it once (flags bit 2) in a 1.5 file; sets with regions of
// their own code each; a file that is not 1.5 never uses the flag (its bytes stay).
TEST(ReplayLead, OneRegionForEverySetIsCodedOnce) {
    const StreamInfo info = lead_info();
    ReplayRegion blocks;
    blocks.use_blocks = true;
    blocks.block_size = 8;
    blocks.blocks = {1, 1, 0, 0, 0,  1, 1, 1, 0, 0,  0, 0, 1, 1, 0,  0, 0, 0, 1, 1};
    ReplayRegion other = blocks;
    other.blocks[0] = 0;
    other.blocks[4] = 1;
    auto frame = [&](bool lead, const ReplayRegion& r1) {
        Frame f;
        f.replay.present = true;
        f.replay.seed = 11;
        f.replay.regions = {blocks, r1};
        if (lead) f.added.push_back(polygon(16 * 4, 16 * 3, {10, 200, 90, 255}));
        for (const Stroke& s : stamps(info, f.replay, 24)) f.added.push_back(s);
        return f;
    };
    struct Case {
        bool lead;
        const ReplayRegion* r1;
        uint16_t version;
        bool one_region;
    } cases[] = {{true, &blocks, kLeadMinorVersion, true},
                 {true, &other, kLeadMinorVersion, false},
                 {false, &blocks, 1, false}};  // no lead: a 1.1 file, which never sets the flag
    for (const Case& c : cases) {
        const std::string path = temp_path("one_region");
        const Frame f = frame(c.lead, *c.r1);
        ASSERT_TRUE(write(path, info, {f}));
        auto r = Reader::open(path);
        ASSERT_TRUE(r) << r.error().message;
        EXPECT_EQ((*r)->info().header.version_minor, c.version);
        const FrameEntry& e = (*r)->frames()[0];
        ASSERT_EQ(e.coding, Coding::Replay);
        EXPECT_EQ((key_frame_flags(slurp(path), e) & 4) != 0, c.one_region) << "lead " << c.lead;
        auto got = (*r)->read_frame(0);
        ASSERT_TRUE(got) << got.error().message;
        EXPECT_EQ(got->added, f.added);
        EXPECT_EQ(got->replay.regions, f.replay.regions);
        std::filesystem::remove(path);
    }
}

TEST(ReplayLead, WriterFallsBackWhereALeadCannotOrShouldNotBeUsed) {
    const StreamInfo info = lead_info();
    ReplayInfo ri;
    ri.present = true;
    ri.seed = 3;
    // A polygon after a stamp: only the strokes before the first stamp can lead.
    Frame mixed;
    mixed.added = stamps(info, ri, 10);
    mixed.added.insert(mixed.added.begin() + 5, polygon(16, 16, {0, 0, 0, 255}));
    mixed.replay = ri;
    // A polygon and one stamp: coding 1 is smaller than a seed and candidate regions.
    Frame tiny;
    tiny.index = 1;
    tiny.type = FrameType::Key;
    tiny.added = {polygon(16 * 5, 16 * 5, {9, 9, 9, 255}), stamps(info, ri, 1).front()};
    tiny.replay = ri;
    const std::string path = temp_path("fallback");
    ASSERT_TRUE(write(path, info, {mixed, tiny}));
    auto r = Reader::open(path);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_EQ((*r)->info().header.version_minor, 2) << "no lead was written: polygons need 1.2 only";
    EXPECT_EQ((*r)->frames()[0].coding, Coding::Range);
    EXPECT_EQ((*r)->frames()[1].coding, Coding::Range);
    for (uint32_t i = 0; i < 2; ++i) {
        auto got = (*r)->strokes_at(i);
        ASSERT_TRUE(got) << got.error().message;
        EXPECT_EQ(**got, (i ? tiny : mixed).added);
    }
    std::filesystem::remove(path);
}

TEST(ReplayLead, HostileLeadsAreErrors) {
    const StreamInfo info = lead_info();
    const std::string path = temp_path("hostile");
    ASSERT_TRUE(write(path, info, lead_frames(info)));
    const std::vector<uint8_t> bytes = slurp(path);
    std::filesystem::remove(path);
    ReaderOptions unchecked;
    unchecked.verify_checksums = false;

    // The flag in a file that says 1.4: Corrupt, naming the version.
    auto old = bytes;
    ASSERT_EQ(old[18], kLeadMinorVersion);  // HEAD payload: u16 major, u16 minor
    old[18] = 4;
    auto r4 = Reader::open_memory(old.data(), old.size(), unchecked);
    ASSERT_TRUE(r4) << r4.error().message;
    auto f4 = (*r4)->strokes_at(0);
    ASSERT_FALSE(f4);
    EXPECT_EQ(f4.error().code, Code::Corrupt);
    EXPECT_NE(f4.error().message.find("1.5"), std::string::npos) << f4.error().message;

    // Polygons past the decoder's work limit: LimitExceeded before anything is drawn.
    ReaderOptions tight;
    tight.limits.max_polygon_work = 50;
    auto rl = Reader::open_memory(bytes.data(), bytes.size(), tight);
    ASSERT_TRUE(rl) << rl.error().message;
    auto fl = (*rl)->strokes_at(0);
    ASSERT_FALSE(fl);
    EXPECT_EQ(fl.error().code, Code::LimitExceeded) << fl.error().message;

    // Every byte of the key frame's body flipped: a value or an error, never a crash or a hang.
    auto r = Reader::open_memory(bytes.data(), bytes.size());
    ASSERT_TRUE(r);
    const FrameEntry& e = (*r)->frames()[0];
    size_t errors = 0;
    for (uint64_t i = e.offset + 8 + 8; i < e.offset + e.chunk_bytes - 4; ++i) {
        auto b = bytes;
        b[i] ^= 0x5a;
        auto rr = Reader::open_memory(b.data(), b.size(), unchecked);
        if (!rr) { ++errors; continue; }
        errors += !(*rr)->strokes_at(0);
    }
    EXPECT_GT(errors, 0u);
}

}  // namespace
