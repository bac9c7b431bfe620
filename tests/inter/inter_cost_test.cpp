// An inter frame costs what changed (issue 34), for both styles, through `spt paint` as a user
// runs it, on the synthetic clips (change_clips.hpp): a frame where no pixel changed (by more
// than the target's RMS error) codes no stroke and renders as the one before, and one where
// little changed costs a fraction of its key frame. (The bound, 2 p x the key frame's
// bytes + 64, is measured for every frame by bench/corpus_bench.py; it does not hold on every
// clip yet, see the closing figures in cartoon/README.md.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "io/image_io.hpp"
#include "spt/reader.hpp"
#include "spt/render.hpp"
#include "video/change_clips.hpp"
#include "video/synthetic.hpp"

using namespace spt;

namespace {

constexpr double kTarget = 30;
// Under this share of changed pixels an inter frame costs at most half its key frame (+ 64 B).
// (The baseline re-added most strokes of a still drawing every frame: the 1.3 MB.)
constexpr double kLittle = 0.1;

struct Painted {
    std::unique_ptr<Reader> reader;
    std::vector<FrameEntry> frames;
};

Painted paint_clip(const spt_test::ChangeClip& clip, const std::string& style) {
    const auto dir = spt_test::temp_dir(clip.name + "_" + style);
    for (size_t i = 0; i < clip.frames.size(); ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "f.%04zu.png", i);
        Status s = io::write_image((dir / name).string(), clip.width, clip.height, clip.frames[i].data());
        EXPECT_TRUE(s.ok()) << s.error().message;
    }
    const std::string out = (dir / "clip.spt").string();
    const std::string cmd = std::string(SPT_TOOL) + " paint '" + (dir / "f.####.png").string() + "' -o '" + out +
                            "' --seed 1 --target-psnr " + std::to_string(kTarget) + " --style " + style +
                            " --threads 2 --progress none";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    Painted p;
    auto r = Reader::open(out);
    EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.error().message);
    if (!r.ok()) return p;
    p.reader = std::move(*r);
    p.frames = p.reader->frames();
    return p;
}

void expect_cost_of_change(const spt_test::ChangeClip& clip, const std::string& style) {
    SCOPED_TRACE(clip.name + ", --style " + style);
    Painted p = paint_clip(clip, style);
    ASSERT_EQ(p.frames.size(), clip.frames.size());
    uint64_t key_bytes = 0;
    for (size_t i = 0; i < p.frames.size(); ++i) {
        const FrameEntry& e = p.frames[i];
        if (e.type == FrameType::Key) {
            key_bytes = e.chunk_bytes;
            continue;
        }
        const double share = spt_test::changed_share(clip.frames[i - 1], clip.frames[i], kTarget);
        if (share < kLittle)
            EXPECT_LE(double(e.chunk_bytes), 0.5 * double(key_bytes) + 64)
                << "frame " << i << ": " << e.chunk_bytes << " bytes for p = " << share << " (key frame " << key_bytes
                << " bytes)";
        if (share == 0) {
            // Nothing changed: no stroke coded, and the frame renders as the one before.
            auto f = p.reader->read_frame(i);
            ASSERT_TRUE(f.ok()) << f.error().message;
            EXPECT_TRUE(f->added.empty()) << "frame " << i << " adds " << f->added.size() << " strokes";
            Canvas before(p.reader->info().header), now(p.reader->info().header);
            ASSERT_TRUE(p.reader->render_frame(i - 1, before).ok());
            ASSERT_TRUE(p.reader->render_frame(i, now).ok());
            EXPECT_EQ(before.rgb, now.rgb) << "frame " << i << " renders differently from frame " << i - 1;
        }
    }
}

class InterCost : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(InterCost, AnInterFrameCostsWhatChanged) {
    for (const spt_test::ChangeClip& clip : spt_test::change_clips()) expect_cost_of_change(clip, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Styles, InterCost, ::testing::Values("painterly", "cartoon"));

TEST(ChangeClips, TheBudgetsShareOfChangeSeesWhatMoved) {
    const auto clips = spt_test::change_clips();
    auto share = [&](const std::string& name, int t) {
        for (const auto& c : clips)
            if (c.name == name) return spt_test::changed_share(c.frames[t - 1], c.frames[t], kTarget);
        return -1.0;
    };
    EXPECT_EQ(share("still", 3), 0.0);
    EXPECT_GT(share("nearly-still", 3), 0.0);
    EXPECT_LT(share("nearly-still", 3), 0.05);
    EXPECT_GT(share("cut", 4), 0.2);
    EXPECT_EQ(share("held", 6), 0.0);
    EXPECT_GT(share("held", 2), 0.0);
}
