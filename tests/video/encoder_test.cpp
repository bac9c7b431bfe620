// The video encoder end to end on small synthetic clips: what it paints is what a decoder
// renders, frame by frame, and the file seeks, stops cleanly and stays bounded.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <fstream>
#include <iterator>

#include "io/image_io.hpp"
#include "quick_options.hpp"
#include "spt/reader.hpp"
#include "spt/render.hpp"
#include "synthetic.hpp"
#include "video/stroke_cull.hpp"
#include "video/video_encoder.hpp"

using namespace spt;
using namespace spt::video;

namespace {

VideoPaintOptions small_options(const std::string& out) {
    VideoPaintOptions o = spt_test::quick_options(out, 7, 1, 400, 150);
    o.keyframe_interval = 100;
    return o;
}

std::vector<uint8_t> read_bytes(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), {}};
}

// Encodes `frames` frames of two shots (the cut at frame `cut`) and keeps every canvas.
std::vector<std::vector<uint8_t>> encode_clip(const VideoPaintOptions& o, uint32_t w, uint32_t h, int frames,
                                              int cut, VideoPaintReport* report = nullptr) {
    auto enc = VideoEncoder::create(o, w, h, Rational{24, 1});
    EXPECT_TRUE(enc.ok()) << enc.error().message;
    if (!enc.ok()) return {};
    std::vector<std::vector<uint8_t>> canvases;
    for (int i = 0; i < frames; ++i) {
        const int shot = i < cut ? 0 : 1;
        const auto rgb = spt_test::scene_frame(shot, i < cut ? i : i - cut, w, h, 1.5, 0.75);
        auto r = (*enc)->add_frame(rgb.data(), i);
        EXPECT_TRUE(r.ok()) << r.error().message;
        if (!r.ok()) return {};
        canvases.push_back((*enc)->canvas().rgb);
    }
    Status st = (*enc)->finish();
    EXPECT_TRUE(st.ok()) << st.error().message;
    if (report) *report = (*enc)->report();
    return canvases;
}

}  // namespace

TEST(VideoEncoder, EncoderCanvasIsTheDecodersForEveryFrame) {
    const auto dir = spt_test::temp_dir("roundtrip");
    const std::string out = (dir / "clip.spt").string();
    const uint32_t w = 96, h = 64;
    VideoPaintReport rep;
    const auto canvases = encode_clip(small_options(out), w, h, 24, 12, &rep);
    ASSERT_EQ(canvases.size(), 24u);
    EXPECT_EQ(rep.key_frame_indices.front(), 0u);
    EXPECT_NE(std::find(rep.key_frame_indices.begin(), rep.key_frame_indices.end(), 12u), rep.key_frame_indices.end())
        << "the cut at frame 12 starts a key frame";
    EXPECT_GT(rep.frames - rep.key_frames, 15u) << "most frames are inter frames";

    auto reader = Reader::open(out);
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    ASSERT_TRUE((*reader)->complete());
    ASSERT_EQ((*reader)->frames().size(), 24u);
    auto renderer = Renderer::create((*reader)->info().header, (*reader)->info().templates);
    ASSERT_TRUE(renderer.ok());
    Canvas c(w, h);
    for (size_t i = 0; i < canvases.size(); ++i) {
        auto strokes = (*reader)->strokes_at(i);
        ASSERT_TRUE(strokes.ok()) << strokes.error().message;
        ASSERT_TRUE((*renderer)->render(c, **strokes).ok());
        ASSERT_EQ(c.rgb, canvases[i]) << "frame " << i;
    }
    // Seeking: a fresh reader asked for a middle frame first gives the same list.
    auto seq = Reader::open(out);
    ASSERT_TRUE(seq.ok());
    std::vector<Stroke> sequential;
    for (size_t i = 0; i <= 18; ++i) sequential = **(*seq)->strokes_at(i);
    auto seek = Reader::open(out);
    ASSERT_TRUE(seek.ok());
    auto at = (*seek)->strokes_at(18);
    ASSERT_TRUE(at.ok());
    EXPECT_TRUE(**at == sequential);
    std::filesystem::remove_all(dir);
}

// Frame seeds are SplitMix64's outputs from the --seed: the values of the generator written out
// step by step (index + 1 increments of the golden gamma, then the output mix), so that shared
// code cannot change what a given --seed paints.
TEST(VideoEncoder, FrameSeedIsSplitMix64) {
    for (uint64_t seed : {uint64_t(0), uint64_t(1), uint64_t(42), ~uint64_t(0)})
        for (uint32_t index : {0u, 1u, 7u, 1000u, 0xFFFFFFFFu}) {
            uint64_t z = seed + 0x9E3779B97F4A7C15ull * (uint64_t(index) + 1);
            z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
            z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
            EXPECT_EQ(video::frame_seed(seed, index), z ^ (z >> 31)) << seed << " " << index;
        }
    EXPECT_EQ(video::frame_seed(0, 0), 0xe220a8397b1dcdafull);  // SplitMix64's first output from 0
}

TEST(VideoEncoder, SameSeedSameBytesWhateverTheThreads) {
    const auto dir = spt_test::temp_dir("determinism");
    const uint32_t w = 80, h = 48;
    auto o1 = small_options((dir / "a.spt").string());
    auto o2 = small_options((dir / "b.spt").string());
    o2.paint.threads = 2;
    encode_clip(o1, w, h, 10, 6);
    encode_clip(o2, w, h, 10, 6);
    const auto a = read_bytes(o1.output), b = read_bytes(o2.output);
    EXPECT_FALSE(a.empty());
    EXPECT_EQ(a, b);
    std::filesystem::remove_all(dir);
}

TEST(StrokeCull, RemovingHiddenStrokesKeepsEveryPixel) {
    const auto dir = spt_test::temp_dir("cull");
    const uint32_t w = 96, h = 64;
    auto o = small_options((dir / "c.spt").string());
    o.cull_every = 0;  // keep everything, then cull here
    auto enc = VideoEncoder::create(o, w, h, Rational{24, 1});
    ASSERT_TRUE(enc.ok()) << enc.error().message;
    for (int i = 0; i < 8; ++i) {
        const auto rgb = spt_test::scene_frame(0, i, w, h, 2.0, 1.0);
        ASSERT_TRUE((*enc)->add_frame(rgb.data(), i).ok());
    }
    std::vector<Stroke> live = (*enc)->live();
    // Stamps off the canvas and under an opaque full-canvas stroke are always removable.
    StampStroke off{0, 0, 0, -16 * 500, -16 * 500, {1, 2, 3, 255}};
    live.insert(live.begin(), Stroke::make_stamp(off));
    std::vector<uint8_t> scratch;
    auto hidden = hidden_strokes(live, (*enc)->renderer(), w, h, scratch);
    ASSERT_TRUE(hidden.ok()) << hidden.error().message;
    ASSERT_FALSE(hidden->empty());
    EXPECT_EQ(hidden->front(), 0u) << "the off-canvas stroke goes";
    std::vector<Stroke> kept;
    for (size_t i = 0, j = 0; i < live.size(); ++i) {
        if (j < hidden->size() && (*hidden)[j] == i) { ++j; continue; }
        kept.push_back(live[i]);
    }
    Canvas a(w, h), b(w, h);
    ASSERT_TRUE((*enc)->renderer().render(a, live).ok());
    ASSERT_TRUE((*enc)->renderer().render(b, kept).ok());
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_EQ(a.rgb, (*enc)->canvas().rgb);
    (*enc)->abort();
    std::filesystem::remove_all(dir);
}

TEST(VideoEncoder, LiveStrokesStayBoundedOverALongShot) {
    const auto dir = spt_test::temp_dir("bounded");
    const uint32_t w = 64, h = 48;
    auto o = small_options((dir / "long.spt").string());
    o.keyframe_interval = 100000;  // one shot, no key frame to reset the list
    o.paint.max_strokes = 150;
    o.max_inter_strokes = 40;
    o.cut_threshold = 1e9;         // never a cut
    o.repaint_key_fraction = 2.0;  // never a key frame for repainting
    auto enc = VideoEncoder::create(o, w, h, Rational{24, 1});
    ASSERT_TRUE(enc.ok()) << enc.error().message;
    size_t early_max = 0, late_max = 0;
    for (int i = 0; i < 2000; ++i) {
        // A pattern circling around: it keeps moving but never leaves.
        const double t = i * 0.05;
        const auto rgb = spt_test::scene_frame(i / 500 % 3, 0, w, h, 0, 0);
        std::vector<uint8_t> moved(rgb.size());
        const int dx = int(std::lround(6 * std::cos(t))), dy = int(std::lround(4 * std::sin(t)));
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x)
                for (int c = 0; c < 3; ++c)
                    moved[(y * w + x) * 3 + c] =
                        rgb[((uint32_t(int(y) + dy + h) % h) * w + (uint32_t(int(x) + dx + w) % w)) * 3 + c];
        auto r = (*enc)->add_frame(moved.data(), i);
        ASSERT_TRUE(r.ok()) << r.error().message;
        (i < 200 ? early_max : late_max) = std::max(i < 200 ? early_max : late_max, size_t(r->live));
    }
    ASSERT_TRUE((*enc)->finish().ok());
    std::printf("live strokes: max %zu over frames 0-199, max %zu over 200-1999\n", early_max, late_max);
    EXPECT_LE(late_max, 3 * early_max + 50) << "live strokes grow without bound: " << early_max << " -> " << late_max;
    std::filesystem::remove_all(dir);
}
