// spt export against files that spt verify refuses (issue 36 item 8): export decoded frames
// without applying them, so a removal or a move out of range and a frame over a work limit
// exported with exit 0 (and the JSON did not import again), and a file whose frames stop
// early exported what was left, or "frames": [], with exit 0. Every output kind is tried;
// each case checks the exit status, the message and that nothing is left behind.
#include "converter/cli_test_util.hpp"

using namespace spt_test;

namespace {

#define EXPECT_HAS(text, what) EXPECT_NE((text).find(what), std::string::npos) << "missing \"" << (what) << "\" in: " << (text)

// The chunk CRC of SPEC.md 2 (zlib's), so that a patched field is read, not refused as damage.
uint32_t crc32(const uint8_t* p, size_t n) {
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; ++i) {
        c ^= p[i];
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
    }
    return ~c;
}

uint32_t get_u32(const std::string& d, size_t at) {
    uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | uint8_t(d[at + size_t(i)]);
    return v;
}
void put_u32(std::string& d, size_t at, uint32_t v) {
    for (int i = 0; i < 4; ++i) d[at + size_t(i)] = char(uint8_t(v >> (8 * i)));
}

// Writes `frames` as a stored-mode file (format 1.2, for polygons) at `path`.
void write_frames(const std::string& path, std::vector<spt::Frame> frames) {
    spt::StreamInfo info = test_info();
    info.header.version_minor = 2;
    auto w = spt::Writer::create(path, info, {spt::Coding::Stored});
    ASSERT_TRUE(w.ok()) << w.error().message;
    for (size_t i = 0; i < frames.size(); ++i) {
        frames[i].index = uint32_t(i);
        auto s = (*w)->append(frames[i]);
        ASSERT_TRUE(s.ok()) << s.error().message;
    }
    ASSERT_TRUE((*w)->finish().ok());
}

// Sets the u32 at `rel` bytes into frame `pos`'s FRAM payload (0: its frame_index; 8: the
// first field of its body) and fixes the chunk's CRC.
void patch_frame_u32(const std::string& path, size_t pos, size_t rel, uint32_t value) {
    auto r = spt::Reader::open(path);
    ASSERT_TRUE(r.ok()) << r.error().message;
    const size_t chunk = size_t((*r)->frames().at(pos).offset);
    std::string d = spt::testing::slurp(path);
    const uint32_t length = get_u32(d, chunk);
    put_u32(d, chunk + 8 + rel, value);
    put_u32(d, chunk + 8 + length, crc32(reinterpret_cast<const uint8_t*>(d.data()) + chunk + 4, length + 4));
    std::ofstream(path, std::ios::binary | std::ios::trunc) << d;
}

spt::Stroke stamp(int32_t x, int32_t y) {
    spt::StampStroke s;
    s.x = x;
    s.y = y;
    s.color = {200, 40, 40, 255};
    return spt::Stroke::make_stamp(s);
}

spt::Frame key(std::vector<spt::Stroke> strokes) {
    spt::Frame f;
    f.added = std::move(strokes);
    return f;
}
spt::Frame inter() {
    spt::Frame f;
    f.type = spt::FrameType::Inter;
    return f;
}

// The export of `in` to each kind of output fails naming the file and `what`, and leaves the
// folder `out/` of `d` empty.
void every_export_fails(const TempDir& d, const std::string& in, const std::vector<std::string>& what) {
    const fs::path folder = d.file("out");
    for (const char* out : {"o.json", "o.####.svg", "o.html"}) {
        fs::create_directories(folder);
        auto r = run_spt(d, {"export", in, "-o", (folder / out).string()});
        std::vector<std::string> words{in};
        words.insert(words.end(), what.begin(), what.end());
        EXPECT_TRUE(failed_with(r, 1, words)) << out;
        for (const auto& e : fs::directory_iterator(folder)) ADD_FAILURE() << out << ": left " << e.path();
        fs::remove_all(folder);
    }
}

}  // namespace

// Frame 1 removes stroke 7 of a list of 2: export read the record and wrote it out.
TEST(HostileExport, ARemovalOutOfRangeIsAnErrorNamingTheFrame) {
    TempDir d;
    const std::string in = d.file("removal.spt");
    spt::Frame f = inter();
    f.removed = {1};
    write_frames(in, {key({stamp(100, 100), stamp(200, 200)}), f});
    patch_frame_u32(in, 1, 8 + 4, 7);  // removed[0], after removed_count
    every_export_fails(d, in, {"frame 1 (FRAM chunk at byte offset", "removed index 7"});
}

// A stamp at the edge of the coordinate range moved further out by frame 1's motion field.
TEST(HostileExport, AMoveOutOfRangeIsAnErrorNamingTheFrame) {
    TempDir d;
    const std::string in = d.file("motion.spt");
    spt::Frame f = inter();
    f.motion.block_size = 8;
    f.motion.cols = 8;
    f.motion.rows = 6;
    f.motion.vectors.assign(48, {int16_t(32767), int16_t(0)});
    write_frames(in, {key({stamp((1 << 24) - 16, 0)}), f});
    every_export_fails(d, in, {"frame 1 (FRAM chunk at byte offset", "motion moves stroke 0 outside"});
}

// 100 zig-zag polygons of 300 edges over all 48 rows at 16x16 samples: each is within the
// polygon work limit, together they are over it (SPEC.md 10).
TEST(HostileExport, AFrameOverTheWorkLimitIsAnErrorNamingTheFrame) {
    TempDir d;
    const std::string in = d.file("work.spt");
    std::vector<spt::Stroke> polygons;
    for (int i = 0; i < 100; ++i) {
        spt::PolygonStroke p;
        p.color = {10, 90, 200, 128};
        p.supersample = 16;
        for (int k = 0; k < 300; ++k) p.points.push_back({k * 3, k % 2 ? 47 * 16 : 0});
        polygons.push_back(spt::Stroke::make_polygon(std::move(p)));
    }
    write_frames(in, {key(std::move(polygons))});
    every_export_fails(d, in, {"frame 0 (FRAM chunk at byte offset", "units of rendering work"});
}

// Frame 1 numbered 2: the reader keeps frame 0 only, of the header's 2.
TEST(HostileExport, AFileThatSkipsAFrameIsAnError) {
    TempDir d;
    const std::string in = d.file("skip.spt");
    write_frames(in, {key({stamp(100, 100)}), inter()});
    patch_frame_u32(in, 1, 0, 2);
    every_export_fails(d, in, {"frame 1 (byte offset", "expected frame index 1", "the file holds 1 of 2 frames"});
    // The frame that is there is still exported when it alone is asked for, saying the damage.
    auto r = run_spt(d, {"export", in, "--frames", "0", "-o", d.file("o.svg")});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_HAS(r.err, "spt export: warning: " + in);
    EXPECT_TRUE(fs::exists(d.file("o.svg")));
}

// Frame 0 numbered 1: no frame at all, where export wrote "frames": [].
TEST(HostileExport, AFileWithNoDecodableFrameIsAnError) {
    TempDir d;
    const std::string in = d.file("none.spt");
    write_frames(in, {key({stamp(100, 100)})});
    patch_frame_u32(in, 0, 0, 1);
    every_export_fails(d, in, {"the file holds no decodable frame", "expected frame index 0"});
}

// Damage that loses no frame (a copy appended after the end) is said, and the export made.
TEST(HostileExport, DamageThatLosesNoFrameIsAWarning) {
    const std::string in = std::string(SPT_SOURCE_DIR) + "/tests/hostile/inputs/appended_copy.spt";
    TempDir d;
    auto r = run_spt(d, {"export", in, "-o", d.file("o.json")});
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_HAS(r.err, "spt export: warning: " + in);
    EXPECT_HAS(r.err, "bytes follow IEND");
    EXPECT_TRUE(fs::exists(d.file("o.json")));
}
