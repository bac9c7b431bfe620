// Helpers for the tests that run the built `spt` binary: temp folders, running a command with
// its exit code and output, and making .spt inputs with spt::Writer (random strokes).
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "spt/spt.hpp"
#include "temp_dir.hpp"

namespace spt_test {

namespace fs = std::filesystem;

struct RunResult {
    int code = -1;
    std::string out, err;
};

inline std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

using spt::testing::slurp;

// Writes `text` to `path` as it is (test inputs: lists, plans, scripts).
inline void write_text(const std::string& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    f << text;
}

// Runs SPT_TOOL with `args`; stdout and stderr are captured through files in `dir`.
inline RunResult run_spt(const TempDir& dir, const std::vector<std::string>& args) {
    std::string cmd = shell_quote(SPT_TOOL);
    for (const auto& a : args) cmd += " " + shell_quote(a);
    const std::string o = dir.file(".stdout"), e = dir.file(".stderr");
    cmd += " >" + shell_quote(o) + " 2>" + shell_quote(e) + " </dev/null";
    RunResult r;
    const int st = std::system(cmd.c_str());
    r.code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
    r.out = slurp(o);
    r.err = slurp(e);
    return r;
}

// A run that failed as it should: exit `code` (any failure for kAnyFailure) and each of `words`
// in its stderr.
constexpr int kAnyFailure = -1;
inline ::testing::AssertionResult failed_with(const RunResult& r, int code, const std::vector<std::string>& words) {
    if (code == kAnyFailure ? r.code == 0 : r.code != code)
        return ::testing::AssertionFailure() << "exit " << r.code << ", want " << code << ": " << r.err;
    for (const auto& w : words)
        if (r.err.find(w) == std::string::npos) return ::testing::AssertionFailure() << "no '" << w << "' in: " << r.err;
    return ::testing::AssertionSuccess();
}

// A command the tool must refuse: failed_with(code, words), and no `out` left behind.
inline ::testing::AssertionResult refused(const TempDir& dir, const std::vector<std::string>& args, int code,
                                          const std::vector<std::string>& words, const std::string& out) {
    if (auto failed = failed_with(run_spt(dir, args), code, words); !failed) return failed;
    if (fs::exists(out)) return ::testing::AssertionFailure() << out << " was left behind";
    return ::testing::AssertionSuccess();
}

// A small stream: 64x48 canvas, two sets, three templates, `frames` frames with a key frame
// every `key_every`, random stamp/affine/curve strokes, removals and a motion field.
inline spt::StreamInfo test_info() {
    spt::StreamInfo info;
    info.header.width = 64;
    info.header.height = 48;
    info.header.fps = {12, 1};
    info.header.background = {240, 235, 220};
    info.header.sets = {{12, 6}, {5, 3}};
    info.header.orientations = spt::default_orientations(8);
    spt::Template e, r, b;
    e.kind = spt::TemplateKind::Ellipse;
    r.kind = spt::TemplateKind::Rectangle;
    b.kind = spt::TemplateKind::Bitmap;
    b.width = 5;
    b.height = 4;
    b.name = "blob";
    for (int i = 0; i < 20; ++i) b.pixels.push_back(uint8_t(i * 13));
    info.templates = {e, r, b};
    info.metadata = {{"title", "cli test"}, {"painter", "random"}};
    return info;
}

inline spt::Stroke random_stroke(std::mt19937& rng) {
    auto u = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    spt::Rgba8 col{uint8_t(u(0, 255)), uint8_t(u(0, 255)), uint8_t(u(0, 255)), uint8_t(u(1, 255))};
    switch (u(0, 5)) {
        case 0: {
            spt::AffineStroke a;
            a.tmpl = uint8_t(u(0, 2));
            a.tx = u(0, 64 * 16);
            a.ty = u(0, 48 * 16);
            a.a = u(16, 120), a.b = u(-30, 30), a.c = u(-30, 30), a.d = u(16, 80);
            a.color = col;
            return spt::Stroke::make_affine(a);
        }
        case 1: {
            spt::CurveStroke c;
            c.color = col;
            for (int i = 0, n = u(2, 5); i < n; ++i)
                c.points.push_back({u(0, 64 * 16), u(0, 48 * 16), uint32_t(u(8, 60))});
            return spt::Stroke::make_curve(c);
        }
        default: {
            spt::StampStroke s;
            s.set = uint8_t(u(0, 1));
            s.tmpl = uint8_t(u(0, 2));
            s.orient = uint8_t(u(0, 7));
            s.x = u(0, 64 * 16 - 1);
            s.y = u(0, 48 * 16 - 1);
            s.color = col;
            return spt::Stroke::make_stamp(s);
        }
    }
}

inline void write_test_spt(const std::string& path, int frames = 12, int key_every = 5,
                           spt::Coding coding = spt::Coding::Range, uint32_t seed = 7) {
    std::mt19937 rng(seed);
    auto w = spt::Writer::create(path, test_info(), {coding});
    ASSERT_TRUE(w.ok()) << w.error().message;
    size_t live = 0;
    for (int i = 0; i < frames; ++i) {
        spt::Frame f;
        f.index = uint32_t(i);
        if (i % key_every == 0) {
            f.type = spt::FrameType::Key;
            for (int k = 0; k < 40; ++k) f.added.push_back(random_stroke(rng));
            live = f.added.size();
        } else {
            f.type = spt::FrameType::Inter;
            for (uint32_t k = 0; k < live; k += 4) f.removed.push_back(k);
            if (i % 2) {
                f.motion.block_size = 16;
                f.motion.cols = 4;
                f.motion.rows = 3;
                for (int k = 0; k < 12; ++k) f.motion.vectors.push_back({int16_t(k - 6), int16_t(3 - k % 5)});
            }
            for (int k = 0; k < 10; ++k) f.added.push_back(random_stroke(rng));
            live = live - f.removed.size() + f.added.size();
        }
        auto s = (*w)->append(f);
        ASSERT_TRUE(s.ok()) << "frame " << i << ": " << s.error().message;
    }
    ASSERT_TRUE((*w)->add_roi({2, 6, 8, 8, 20, 16}).ok());
    auto s = (*w)->finish();
    ASSERT_TRUE(s.ok()) << s.error().message;
}

// Fails (never skips) when the spt tool is missing: a test never passes by skipping.
#define REQUIRE_TOOL()                                                       \
    do {                                                                     \
        if (std::string(SPT_TOOL).empty() || !fs::exists(SPT_TOOL))          \
            GTEST_FAIL() << "the spt tool was not built: " << SPT_TOOL;      \
    } while (0)

}  // namespace spt_test
