// Damaged input: truncation at every byte, single bit flips, absurd sizes and counts. The reader
// must never crash, must keep every complete frame before a cut, and must report each flip.
#include <gtest/gtest.h>

#include <cstring>

#include "format/coding_random_streams.hpp"

using namespace spt;
using namespace spt::testing;

namespace {

std::vector<uint8_t> sample_file(Coding coding, RandomStream* out = nullptr) {
    StreamShapeOptions o;
    o.max_side = 40;
    o.frames = 4;
    o.max_strokes = 6;
    RandomStream rs = make_random_stream(3, o);
    const std::string path = temp_path("robust-" + std::to_string(int(coding)) + ".spt");
    EXPECT_TRUE(write_stream(path, rs, coding).ok());
    auto b = read_bytes(path);
    std::remove(path.c_str());
    if (out) *out = rs;
    return b;
}

// Everything a reader can be asked; returns whether any error or warning was reported.
bool exercise(const std::vector<uint8_t>& b, size_t* good_frames = nullptr) {
    ReaderOptions ro;
    ro.limits.max_live_strokes = ro.limits.max_strokes_per_frame = 1u << 16;
    auto r = Reader::open_memory(b.data(), b.size(), ro);
    if (!r) {
        EXPECT_FALSE(r.error().message.empty());
        return true;
    }
    bool reported = !(*r)->warnings().empty() || !(*r)->complete();
    size_t good = 0;
    for (size_t i = 0; i < (*r)->frames().size(); ++i) {
        auto s = (*r)->strokes_at(i);
        if (!s) { reported = true; EXPECT_FALSE(s.error().message.empty()); break; }
        ++good;
        (void)(*r)->field_stats(i);
    }
    if (good_frames) *good_frames = good;
    return reported;
}

}  // namespace

TEST(ContainerRobustness, TruncationAtEveryByteKeepsCompleteFrames) {
    for (Coding coding : {Coding::Stored, Coding::Range}) {
        const auto full = sample_file(coding);
        auto r = Reader::open_memory(full.data(), full.size());
        ASSERT_TRUE(r.ok());
        std::vector<uint64_t> frame_end;
        for (const auto& e : (*r)->frames()) frame_end.push_back(e.offset + e.chunk_bytes);
        for (size_t cut = 0; cut < full.size(); ++cut) {
            std::vector<uint8_t> b(full.begin(), full.begin() + ptrdiff_t(cut));
            size_t expect = 0;
            while (expect < frame_end.size() && frame_end[expect] <= cut) ++expect;
            auto t = Reader::open_memory(b.data(), b.size());
            if (!t) continue;  // cut inside the header chunks: an error is the right answer
            EXPECT_FALSE((*t)->complete()) << "cut " << cut;
            EXPECT_FALSE((*t)->warnings().empty()) << "cut " << cut;
            EXPECT_EQ((*t)->frames().size(), expect) << "cut " << cut;
            for (size_t i = 0; i < (*t)->frames().size(); ++i) {
                auto s = (*t)->strokes_at(i);
                ASSERT_TRUE(s.ok()) << "cut " << cut << ": " << s.error().message;
                auto ref = (*r)->strokes_at(i);
                ASSERT_TRUE(ref.ok());
                EXPECT_EQ(**s, **ref);
            }
        }
    }
}

TEST(ContainerRobustness, EverySingleBitFlipIsReported) {
    for (Coding coding : {Coding::Stored, Coding::Range}) {
        const auto full = sample_file(coding);
        ASSERT_FALSE(exercise(full));
        size_t unreported = 0;
        for (size_t bit = 0; bit < full.size() * 8; ++bit) {
            auto b = full;
            b[bit / 8] ^= uint8_t(1u << (bit % 8));
            if (!exercise(b)) { ++unreported; ADD_FAILURE() << "flip of bit " << bit << " (byte " << bit / 8 << ") not reported"; }
            if (unreported > 5) break;
        }
    }
}

TEST(ContainerRobustness, ErrorsNameTheFrameAndOffset) {
    RandomStream rs;
    auto b = sample_file(Coding::Range, &rs);
    auto r = Reader::open_memory(b.data(), b.size());
    ASSERT_TRUE(r.ok());
    const auto e = (*r)->frames()[2];
    b[e.offset + 20] ^= 0x10;  // inside frame 2's body
    auto d = Reader::open_memory(b.data(), b.size());
    ASSERT_TRUE(d.ok());
    auto f = (*d)->read_frame(2);
    ASSERT_FALSE(f.ok());
    EXPECT_EQ(f.error().code, Code::Corrupt);
    EXPECT_NE(f.error().message.find("frame 2"), std::string::npos) << f.error().message;
    EXPECT_NE(f.error().message.find("byte offset " + std::to_string(e.offset)), std::string::npos) << f.error().message;
}

namespace {
// A tiny file with a patched HEAD/chunk field, CRCs recomputed so that only the value is wrong.
std::vector<uint8_t> patched(size_t field_offset_in_head, uint32_t value) {
    auto b = sample_file(Coding::Stored);
    // HEAD payload starts at 16 (signature 8, length 4, type 4).
    std::memcpy(&b[16 + field_offset_in_head], &value, 4);
    const uint32_t len = b[8] | b[9] << 8 | b[10] << 16 | uint32_t(b[11]) << 24;
    // CRC-32 over type + payload.
    uint32_t crc = ~0u;
    for (size_t i = 12; i < 16 + len; ++i) {
        crc ^= b[i];
        for (int k = 0; k < 8; ++k) crc = (crc & 1) ? 0xEDB88320u ^ (crc >> 1) : crc >> 1;
    }
    crc = ~crc;
    std::memcpy(&b[16 + len], &crc, 4);
    return b;
}
}  // namespace

// A reserved motion_present value (SPEC.md 7.1) is Unsupported wherever the body's counts are
// read: the frame table (index or scan) reads them with the decoder's own reader, so a file
// with one does not open.
TEST(ContainerRobustness, ReservedMotionFlagIsUnsupported) {
    for (Coding coding : {Coding::Range, Coding::Replay}) {
        auto b = sample_file(Coding::Range);
        auto r = Reader::open_memory(b.data(), b.size());
        ASSERT_TRUE(r.ok());
        size_t body = 0;
        for (const FrameEntry& e : (*r)->frames())
            if (e.type == FrameType::Inter) { body = size_t(e.offset) + 16; break; }
        ASSERT_NE(body, 0u) << "the sample has an inter frame";
        if (coding == Coding::Replay) b[body - 8 + 5] = 2;  // the FRAM coding byte: coding 2 reads the same counts
        size_t at = body;
        for (int k = 0; k < 2; ++k)
            while (b[at++] & 0x80) {}  // removed_count, added_count
        ASSERT_LE(b[at], 1);
        b[at] = 2;  // motion_present
        ReaderOptions ro;
        ro.verify_checksums = false;
        auto d = Reader::open_memory(b.data(), b.size(), ro);
        ASSERT_FALSE(d.ok()) << int(coding);
        EXPECT_EQ(d.error().code, Code::Unsupported) << d.error().message;
        EXPECT_NE(d.error().message.find("motion_present 2 is reserved"), std::string::npos) << d.error().message;
    }
}

TEST(ContainerLimits, AbsurdCanvasIsRejectedBeforeAllocation) {
    auto b = patched(8, 0x7FFFFFFF);  // width
    auto r = Reader::open_memory(b.data(), b.size());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, Code::LimitExceeded) << r.error().message;
    ReaderOptions tight;
    tight.limits.max_width = 8;
    auto b2 = sample_file(Coding::Stored);
    auto r2 = Reader::open_memory(b2.data(), b2.size(), tight);
    ASSERT_FALSE(r2.ok());
    EXPECT_EQ(r2.error().code, Code::LimitExceeded);
}

TEST(ContainerLimits, HugeChunkLengthIsRejected) {
    auto b = sample_file(Coding::Stored);
    b[8] = 0xFF; b[9] = 0xFF; b[10] = 0xFF; b[11] = 0x7F;  // HEAD length 2^31-1
    auto r = Reader::open_memory(b.data(), b.size());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, Code::LimitExceeded) << r.error().message;
    ReaderOptions big;
    big.limits.max_chunk_bytes = 0xFFFFFFFFu;
    auto r2 = Reader::open_memory(b.data(), b.size(), big);
    ASSERT_FALSE(r2.ok());
    EXPECT_EQ(r2.error().code, Code::Truncated) << r2.error().message;
}

TEST(ContainerLimits, HugeCountsInFramesAreRejected) {
    // A stored key frame claiming 2^32-1 strokes in a few bytes.
    StreamShapeOptions o;
    o.frames = 1;
    o.max_strokes = 0;
    RandomStream rs = make_random_stream(9, o);
    rs.frames[0].added.clear();
    const std::string path = temp_path("count.spt");
    ASSERT_TRUE(write_stream(path, rs, Coding::Stored).ok());
    auto r = Reader::open(path);
    ASSERT_TRUE(r.ok());
    Frame f;
    f.type = FrameType::Key;
    (void)f;
    auto b = read_bytes(path);
    const auto e = (*r)->frames()[0];
    // body starts at offset + 16: patch added_count, then fix the chunk CRC.
    const size_t body = size_t(e.offset) + 16;
    b[body] = b[body + 1] = b[body + 2] = b[body + 3] = 0xFF;
    uint32_t crc = ~0u;
    const size_t len = size_t(e.chunk_bytes) - 12;
    for (size_t i = size_t(e.offset) + 4; i < size_t(e.offset) + 8 + len; ++i) {
        crc ^= b[i];
        for (int k = 0; k < 8; ++k) crc = (crc & 1) ? 0xEDB88320u ^ (crc >> 1) : crc >> 1;
    }
    crc = ~crc;
    std::memcpy(&b[size_t(e.offset) + 8 + len], &crc, 4);
    auto d = Reader::open_memory(b.data(), b.size());
    ASSERT_TRUE(d.ok());
    auto fr = (*d)->read_frame(0);
    ASSERT_FALSE(fr.ok());
    EXPECT_EQ(fr.error().code, Code::LimitExceeded) << fr.error().message;
    std::remove(path.c_str());
}

TEST(ContainerWriter, RejectsInvalidFramesAndLeavesNoPartialFile) {
    StreamShapeOptions o;
    o.frames = 1;
    RandomStream rs = make_random_stream(4, o);
    const std::string path = temp_path("invalid.spt");
    std::remove(path.c_str());
    auto w = Writer::create(path, rs.info);
    ASSERT_TRUE(w.ok());
    Frame inter;
    inter.type = FrameType::Inter;
    EXPECT_EQ((*w)->append(inter).error().code, Code::InvalidArgument);  // first frame must be key
    Frame bad;
    bad.added.push_back(Stroke::make_stamp(StampStroke{200, 0, 0, 0, 0, {}}));
    EXPECT_EQ((*w)->append(bad).error().code, Code::InvalidArgument);     // set out of range
    ASSERT_TRUE((*w)->append(rs.frames[0]).ok());
    Frame rem;
    rem.index = 1;
    rem.type = FrameType::Inter;
    rem.removed = {uint32_t(rs.frames[0].added.size())};
    EXPECT_EQ((*w)->append(rem).error().code, Code::InvalidArgument);     // removal out of range
    EXPECT_TRUE(std::filesystem::exists(path + ".partial"));
    EXPECT_FALSE(std::filesystem::exists(path));
    (*w)->abort();
    EXPECT_FALSE(std::filesystem::exists(path + ".partial"));
    EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(ContainerWriter, ReservedCodingTwoIsUnsupported) {
    StreamShapeOptions o;
    o.frames = 1;
    RandomStream rs = make_random_stream(4, o);
    const std::string path = temp_path("coding2.spt");
    ASSERT_TRUE(write_stream(path, rs, Coding::Stored).ok());
    auto b = read_bytes(path);
    auto r = Reader::open_memory(b.data(), b.size());
    ASSERT_TRUE(r.ok());
    const size_t off = size_t((*r)->frames()[0].offset);
    b[off + 8 + 5] = 2;  // FRAM coding byte
    const uint32_t len = b[off] | b[off + 1] << 8 | b[off + 2] << 16 | uint32_t(b[off + 3]) << 24;
    uint32_t crc = ~0u;
    for (size_t i = off + 4; i < off + 8 + len; ++i) {
        crc ^= b[i];
        for (int k = 0; k < 8; ++k) crc = (crc & 1) ? 0xEDB88320u ^ (crc >> 1) : crc >> 1;
    }
    crc = ~crc;
    std::memcpy(&b[off + 8 + len], &crc, 4);
    // Coding 2 is defined since format 1.1 (SPEC.md 7.7): a stored body relabelled as coding 2
    // is not a valid coding-2 body, so opening or decoding it fails cleanly.
    auto d = Reader::open_memory(b.data(), b.size());
    if (d.ok()) {
        auto s = (*d)->strokes_at(0);
        EXPECT_FALSE(s.ok());
    }
    std::remove(path.c_str());
}
