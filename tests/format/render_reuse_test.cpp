// Reader::render_frame keeps the picture of a frame whose live list is unchanged (an empty
// inter frame, or the same frame again) instead of rendering it again: the bytes must be
// exactly those of a full render of strokes_at's live list, whatever the order of the calls
// and whatever the caller did to the canvas in between.
#include <gtest/gtest.h>

#include "format/coding_random_streams.hpp"
#include "format/render_reference.hpp"

using namespace spt;
using namespace spt::testing;

namespace {

// The full render of frame `pos`: strokes_at on a fresh reader, then Renderer::render.
std::vector<uint8_t> full_render(const std::vector<uint8_t>& file, size_t pos) {
    return spt_test::reference_render(file, pos);
}

Frame empty_inter(uint32_t index) {
    Frame f;
    f.index = index;
    f.type = FrameType::Inter;
    return f;
}

// Random key and inter frames with runs of empty inter frames between them: after a key frame
// of stamps (the reader's record path), after a key frame of other kinds, after an inter
// frame that changed the list, and at the end.
std::vector<uint8_t> file_with_still_stretches(uint64_t seed, bool painter_like, Coding coding) {
    StreamShapeOptions so;
    so.painter_like = painter_like;
    so.frames = 5;
    so.max_strokes = 80;
    RandomStream rs = make_random_stream(seed, so);
    std::vector<Frame> frames;
    for (Frame& f : rs.frames) {
        frames.push_back(f);
        for (int k = 0; k < 3; ++k) frames.push_back(empty_inter(0));
    }
    for (size_t i = 0; i < frames.size(); ++i) frames[i].index = uint32_t(i);
    rs.frames = frames;
    const std::string path = temp_path("still_" + std::to_string(seed) + "_" + std::to_string(int(coding)) + ".spt");
    EXPECT_TRUE(write_stream(path, rs, coding).ok());
    return read_bytes(path);
}

}  // namespace

TEST(RenderReuse, StillFramesGiveTheBytesOfAFullRender) {
    for (uint64_t seed : {3u, 11u, 29u}) {
        for (bool painter_like : {true, false}) {
            for (Coding coding : {Coding::Stored, Coding::Range}) {
                SCOPED_TRACE("seed " + std::to_string(seed) + (painter_like ? " stamps" : " all kinds") +
                             " coding " + std::to_string(int(coding)));
                const auto file = file_with_still_stretches(seed, painter_like, coding);
                auto r = Reader::open_memory(file.data(), file.size());
                ASSERT_TRUE(r.ok()) << r.error().message;
                const size_t n = (*r)->frames().size();
                std::vector<std::vector<uint8_t>> want(n);
                for (size_t i = 0; i < n; ++i) want[i] = full_render(file, i);
                // Forward, as a player or `spt verify` goes: still frames reuse the canvas.
                Canvas c;
                for (size_t i = 0; i < n; ++i) {
                    ASSERT_TRUE((*r)->render_frame(i, c).ok()) << i;
                    EXPECT_EQ(c.rgb, want[i]) << "frame " << i << " forward";
                }
                // The same frame again, backwards, and jumps: still the bytes of a full render.
                for (size_t i = n; i-- > 0;) {
                    ASSERT_TRUE((*r)->render_frame(i, c).ok()) << i;
                    EXPECT_EQ(c.rgb, want[i]) << "frame " << i << " backward";
                    ASSERT_TRUE((*r)->render_frame(i, c).ok()) << i;
                    EXPECT_EQ(c.rgb, want[i]) << "frame " << i << " again";
                }
                for (size_t i : {size_t(2), n - 1, size_t(0), size_t(5), size_t(1), size_t(9), size_t(4)}) {
                    if (i >= n) continue;
                    ASSERT_TRUE((*r)->render_frame(i, c).ok()) << i;
                    EXPECT_EQ(c.rgb, want[i]) << "frame " << i << " jump";
                }
                // The caller changed the canvas, or hands in another one: nothing is assumed.
                for (size_t i = 0; i < n; ++i) {
                    ASSERT_TRUE((*r)->render_frame(i, c).ok()) << i;
                    if (!c.rgb.empty()) c.rgb[c.rgb.size() / 2] ^= 1;
                    ASSERT_TRUE((*r)->render_frame(i, c).ok()) << i;
                    EXPECT_EQ(c.rgb, want[i]) << "frame " << i << " after the canvas changed";
                    Canvas other;
                    ASSERT_TRUE((*r)->render_frame(i, other).ok()) << i;
                    EXPECT_EQ(other.rgb, want[i]) << "frame " << i << " on another canvas";
                }
            }
        }
    }
}
