// Reader::render_frame, a player's decode + render in one call: it must give exactly
// Renderer::render of strokes_at's live list, and report exactly strokes_at's errors, whether
// it takes its fast path (a coding-0 key frame of stamps, handed from its records to the
// renderer's tiles by stamp_frame.hpp's interface) or the general one.
#include <gtest/gtest.h>

#include "format/render_reference.hpp"

#include <filesystem>
#include <fstream>
#include <random>

#include "format/coding_random_streams.hpp"
#include "format/golden_canonical.hpp"
#include "../format/src/stamp_frame.hpp"

using namespace spt;
using namespace spt::testing;

namespace {

const std::string kGolden = std::string(SPT_SOURCE_DIR) + "/tests/format/golden";

// What render_frame must give: strokes_at on a reader of its own, then Renderer::render.
std::vector<uint8_t> reference(const std::vector<uint8_t>& file, size_t pos, const ReaderOptions& o = {}) {
    return spt_test::reference_render(file, pos, o);
}

std::string error_of_strokes_at(const std::vector<uint8_t>& file, size_t pos, const ReaderOptions& o) {
    auto r = Reader::open_memory(file.data(), file.size(), o);
    if (!r) return "open: " + r.error().message;
    auto live = (*r)->strokes_at(pos);
    return live ? std::string() : live.error().message;
}

std::string error_of_render_frame(const std::vector<uint8_t>& file, size_t pos, const ReaderOptions& o) {
    auto r = Reader::open_memory(file.data(), file.size(), o);
    if (!r) return "open: " + r.error().message;
    Canvas c;
    const Status st = (*r)->render_frame(pos, c);
    return st ? std::string() : st.error().message;
}

// A stored file of painter-like frames (stamps only, some translucent; key and inter frames).
std::vector<uint8_t> painter_file(uint64_t seed, Coding coding = Coding::Stored) {
    StreamShapeOptions so;
    so.painter_like = true;
    so.frames = 6;
    so.max_strokes = 200;
    const RandomStream rs = make_random_stream(seed, so);
    const std::string path = temp_path("render_frame_" + std::to_string(seed) + ".spt");
    EXPECT_TRUE(write_stream(path, rs, coding).ok());
    return read_bytes(path);
}

// The 16-byte coding-0 record of a stamp (SPEC 6).
void put_record(std::vector<uint8_t>& out, const StampStroke& s) {
    out.push_back(0);
    out.push_back(s.set);
    out.push_back(s.tmpl);
    out.push_back(s.orient);
    for (int32_t v : {s.x, s.y})
        for (int k = 0; k < 4; ++k) out.push_back(uint8_t(uint32_t(v) >> (8 * k)));
    out.insert(out.end(), {s.color.r, s.color.g, s.color.b, s.color.a});
}

// The fast path as the reader takes it: a coding-0 key frame body of n records (a count, then
// the records) through the stored-frame decoder's stamp source to the renderer.
bool render_records(const Renderer& r, Canvas& c, const std::vector<uint8_t>& records, size_t n, unsigned threads,
                    uint64_t work_limit) {
    std::vector<uint8_t> body;
    for (int k = 0; k < 4; ++k) body.push_back(uint8_t(uint32_t(n) >> (8 * k)));
    body.insert(body.end(), records.begin(), records.end());
    detail::StampSource src;
    if (!detail::stored_key_stamps(body.data(), body.size(), Limits{}, src)) return false;
    const bool ok = detail::render_stamp_frame(r, c, src, threads, work_limit);
    // The same through fill() (sources without packed records): same answer, same pixels.
    detail::StampSource filled = src;
    filled.packed = nullptr;
    Canvas c2;
    const bool ok2 = detail::render_stamp_frame(r, c2, filled, threads, work_limit);
    EXPECT_EQ(ok2, ok);
    if (ok && ok2) EXPECT_EQ(c2.rgb, c.rgb);
    return ok;
}

}  // namespace

// Every frame of every golden file, in an order that moves strokes_at's incremental state back
// and forth, with one and two threads.
TEST(RenderFrame, EveryGoldenFrameRendersAsStrokesAtThenRender) {
    size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kGolden)) {
        if (entry.path().extension() != ".spt") continue;
        ++files;
        SCOPED_TRACE(entry.path().filename().string());
        const auto bytes = read_bytes(entry.path().string());
        auto r = Reader::open_memory(bytes.data(), bytes.size());
        ASSERT_TRUE(r.ok()) << r.error().message;
        const size_t n = (*r)->frames().size();
        std::vector<size_t> order;
        for (size_t k = n; k-- > 0;) order.push_back(k);
        for (size_t k = 0; k < n; ++k) order.push_back(k);
        for (size_t i = 0; i < order.size(); ++i) {
            const size_t pos = order[i];
            SCOPED_TRACE("frame " + std::to_string(pos));
            Canvas c;
            ASSERT_TRUE((*r)->render_frame(pos, c, unsigned(1 + i % 2)).ok());
            EXPECT_EQ(c.width, (*r)->info().header.width);
            EXPECT_EQ(c.rgb, reference(bytes, pos));
        }
    }
    EXPECT_GE(files, 20u);
}

TEST(RenderFrame, PainterLikeStreamsRenderAsStrokesAtThenRender) {
    for (uint64_t seed = 1; seed <= 12; ++seed) {
        for (Coding coding : {Coding::Stored, Coding::Range}) {
            SCOPED_TRACE("seed " + std::to_string(seed) + " coding " + std::to_string(int(coding)));
            const auto bytes = painter_file(seed, coding);
            auto r = Reader::open_memory(bytes.data(), bytes.size());
            ASSERT_TRUE(r.ok());
            for (size_t pos = 0; pos < (*r)->frames().size(); ++pos) {
                Canvas c;
                ASSERT_TRUE((*r)->render_frame(pos, c).ok());
                EXPECT_EQ(c.rgb, reference(bytes, pos)) << "frame " << pos;
            }
        }
    }
}

// The fast path itself: records render as the strokes they hold, and anything it cannot vouch
// for is declined (false), leaving the general path to report it.
TEST(RenderFrame, StampRecordsRenderAsTheirStrokesOrAreDeclined) {
    StreamShapeOptions so;
    so.painter_like = true;
    so.frames = 1;
    so.max_strokes = 400;
    for (uint64_t seed = 20; seed < 30; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        RandomStream rs = make_random_stream(seed, so);
        const Header& h = rs.info.header;
        auto made = Renderer::create(h, rs.info.templates);
        ASSERT_TRUE(made.ok());
        const Renderer& impl = **made;
        std::vector<uint8_t> records;
        for (const Stroke& s : rs.frames[0].added) {
            ASSERT_EQ(s.kind, StrokeKind::Stamp);
            put_record(records, s.stamp);
        }
        const size_t n = rs.frames[0].added.size();
        Canvas want, got;
        ASSERT_TRUE(impl.render(want, rs.frames[0].added).ok());
        ASSERT_TRUE(render_records(impl, got, records, n, 1, ~uint64_t(0)));
        EXPECT_EQ(got.rgb, want.rgb);
        ASSERT_TRUE(render_records(impl, got, records, n, 2, ~uint64_t(0)));
        EXPECT_EQ(got.rgb, want.rgb);
        if (n == 0) continue;

        const size_t k = 16 * (n / 2);  // a record in the middle
        auto declined = [&](size_t at, uint8_t value, uint64_t limit = ~uint64_t(0)) {
            std::vector<uint8_t> bad = records;
            bad[at] = value;
            Canvas c;
            return !render_records(impl, c, bad, n, 1, limit) && c.rgb.empty();
        };
        EXPECT_TRUE(declined(k, 1));                                  // kind 1: an affine stroke
        EXPECT_TRUE(declined(16 * (n - 1), 1));                       // the last record (a later batch)
        EXPECT_TRUE(declined(k + 1, uint8_t(h.sets.size())));         // set out of range
        EXPECT_TRUE(declined(k + 2, uint8_t(rs.info.templates.size())));  // template out of range
        EXPECT_TRUE(declined(k + 3, uint8_t(h.orientations.size())));  // orientation out of range
        EXPECT_TRUE(declined(k + 7, 0x40));                            // |x| above 2^24
        EXPECT_TRUE(declined(k, 0, 0));                                // over the fill-work limit
    }
    // A stamp too big for the footprint cache (a 4096 x 4096 set at 45 degrees) is drawn by the
    // general path from its inverse map: declined.
    Header h;
    h.width = h.height = 64;
    h.sets = {{4096, 4096}};
    h.orientations = default_orientations(8);
    Template disc;
    disc.kind = TemplateKind::Ellipse;
    auto made = Renderer::create(h, {disc});
    ASSERT_TRUE(made.ok());
    StampStroke big;
    big.orient = 2;
    big.x = big.y = 16 * 32 + 8;
    std::vector<uint8_t> rec;
    put_record(rec, big);
    Canvas c;
    EXPECT_FALSE(render_records(**made, c, rec, 1, 1, ~uint64_t(0)));
}

// Damaged files and tight limits: render_frame says exactly what strokes_at says.
TEST(RenderFrame, ErrorsAreThoseOfStrokesAt) {
    const auto good = painter_file(7);
    auto r = Reader::open_memory(good.data(), good.size());
    ASSERT_TRUE(r.ok());
    const FrameEntry& first = (*r)->frames()[0];
    ASSERT_EQ(first.type, FrameType::Key);
    ASSERT_GT(first.added, 0u);
    // The first stroke record of frame 0: chunk length and type, frame header, stroke count.
    const size_t record = size_t(first.offset) + 8 + 8 + 4;

    ReaderOptions unchecked;
    unchecked.verify_checksums = false;
    struct Case {
        const char* what;
        size_t at;
        uint8_t value;
        ReaderOptions opts;
    } cases[] = {
        {"a set out of range, checksums off", record + 1, 0xEE, unchecked},
        {"a reserved stroke kind, checksums off", record, 9, unchecked},
        {"a flipped byte, checksums on", record + 5, uint8_t(good[record + 5] ^ 0x10), ReaderOptions()},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        auto bad = good;
        bad[c.at] = c.value;
        const std::string want = error_of_strokes_at(bad, 0, c.opts);
        EXPECT_FALSE(want.empty());
        EXPECT_EQ(error_of_render_frame(bad, 0, c.opts), want);
    }
    ReaderOptions tight;
    tight.limits.max_fill_work = 10;
    EXPECT_FALSE(error_of_strokes_at(good, 0, tight).empty());
    EXPECT_EQ(error_of_render_frame(good, 0, tight), error_of_strokes_at(good, 0, tight));
    tight = ReaderOptions();
    tight.limits.max_live_strokes = first.added - 1;
    EXPECT_EQ(error_of_render_frame(good, 0, tight), error_of_strokes_at(good, 0, tight));
    EXPECT_EQ(error_of_render_frame(good, 99, {}), error_of_strokes_at(good, 99, {}));
}
