// End-to-end tests of `spt info`, `verify`, `render`, `pack` and `compare` on files made with
// spt::Writer (random strokes).
#include <gtest/gtest.h>

#include "cli_test_util.hpp"
#include "io/image_io.hpp"
#include "io_json_check.hpp"

using namespace spt_test;

namespace {

Json parse_json(const std::string& text) {
    Json j;
    std::string err;
    EXPECT_TRUE(JsonParser::parse(text, j, &err)) << err << "\n" << text;
    return j;
}

// Renders frame `f` of `path` with the library, for comparison with the tool's output.
std::vector<uint8_t> reference_render(const std::string& path, size_t f) {
    auto r = spt::Reader::open(path);
    EXPECT_TRUE(r.ok());
    auto live = (*r)->strokes_at(f);
    EXPECT_TRUE(live.ok());
    auto rend = spt::Renderer::create((*r)->info().header, (*r)->info().templates);
    EXPECT_TRUE(rend.ok());
    spt::Canvas c((*r)->info().header.width, (*r)->info().header.height);
    EXPECT_TRUE((*rend)->render(c, **live).ok());
    return c.rgb;
}

}  // namespace

// Every coding is named by libspt (spt::coding_name): a coding-2 file's frames say "replay",
// in the table and in JSON, not "stored".
TEST(CliInfo, NamesEveryCoding) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string golden = std::string(SPT_SOURCE_DIR) + "/tests/format/golden/";
    for (const auto& [file, coding] : {std::pair<const char*, const char*>{"replay_paint.spt", "replay"},
                                       {"replay_paint.stored.spt", "stored"}, {"random_mix.spt", "range"}}) {
        auto j = run_spt(d, {"info", golden + file, "--json", "--frames", "--no-fields"});
        ASSERT_EQ(j.code, 0) << j.err;
        EXPECT_EQ(parse_json(j.out)["frame_list"][0]["coding"].str, coding) << file;
        auto t = run_spt(d, {"info", golden + file, "--frames", "--no-fields"});
        ASSERT_EQ(t.code, 0) << t.err;
        EXPECT_NE(t.out.find(std::string(" key ") + (std::string(coding) == "range" ? " " : "") + coding + " "),
                  std::string::npos) << file << "\n" << t.out;
    }
}

TEST(CliInfo, TextAndJsonFields) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string f = d.file("a.spt");
    write_test_spt(f, 12, 5);
    auto t = run_spt(d, {"info", f});
    ASSERT_EQ(t.code, 0) << t.err;
    EXPECT_NE(t.out.find("64 x 48"), std::string::npos) << t.out;

    auto r = run_spt(d, {"info", f, "--json", "--frames"});
    ASSERT_EQ(r.code, 0) << r.err;
    Json j = parse_json(r.out);
    EXPECT_EQ(j["canvas"]["width"].num, 64);
    EXPECT_EQ(j["canvas"]["height"].num, 48);
    EXPECT_EQ(j["fps"]["num"].num, 12);
    EXPECT_EQ(j["frame_count"].num, 12);
    EXPECT_EQ(j["frames_found"].num, 12);
    EXPECT_TRUE(j["complete"].b);
    EXPECT_TRUE(j["has_index"].b);
    EXPECT_EQ(j["background"][0].num, 240);
    EXPECT_EQ(j["sets"].arr.size(), 2u);
    EXPECT_EQ(j["orientations"].arr.size(), 8u);
    ASSERT_EQ(j["templates"].arr.size(), 3u);
    EXPECT_EQ(j["templates"][2]["kind"].str, "bitmap");
    EXPECT_EQ(j["templates"][2]["name"].str, "blob");
    EXPECT_EQ(j["metadata"]["title"].str, "cli test");
    ASSERT_EQ(j["rois"].arr.size(), 1u);
    EXPECT_EQ(j["rois"][0]["w"].num, 20);
    ASSERT_EQ(j["key_frames"].arr.size(), 3u);
    EXPECT_EQ(j["key_frames"][1].num, 5);
    EXPECT_EQ(j["bytes"]["total"].num, double(fs::file_size(f)));
    const auto& b = j["bytes"];
    EXPECT_EQ(b["header"].num + b["frames"].num + b["tail"].num, b["total"].num);
    EXPECT_GT(b["strokes"].num, 0);
    EXPECT_TRUE(j.has("fields"));
    ASSERT_EQ(j["frame_list"].arr.size(), 12u);
    EXPECT_EQ(j["frame_list"][0]["type"].str, "key");
    EXPECT_EQ(j["frame_list"][0]["live"].num, 40);
    EXPECT_EQ(j["frame_list"][1]["type"].str, "inter");
    EXPECT_EQ(j["frame_list"][1]["removed"].num, 10);
    EXPECT_EQ(j["frame_list"][1]["live"].num, 40);
    EXPECT_EQ(j["strokes"]["max_live"].num, 40);
    // Added strokes by kind, against the library's own decode.
    double kinds[4] = {0, 0, 0, 0};
    auto rd = spt::Reader::open(f);
    ASSERT_TRUE(rd.ok());
    for (size_t i = 0; i < (*rd)->frames().size(); ++i) {
        auto fr = (*rd)->read_frame(i);
        ASSERT_TRUE(fr.ok());
        for (const auto& st : fr->added) kinds[size_t(st.kind)] += 1;
    }
    const auto& k = j["strokes"]["kinds"];
    EXPECT_EQ(k["stamp"].num, kinds[0]);
    EXPECT_EQ(k["affine"].num, kinds[1]);
    EXPECT_EQ(k["curve"].num, kinds[2]);
    EXPECT_EQ(k["polygon"].num, kinds[3]);
    EXPECT_EQ(kinds[0] + kinds[1] + kinds[2] + kinds[3], j["strokes"]["added"].num);
    EXPECT_GT(kinds[0], 0);
}

TEST(CliVerify, GoodFilePassesFlippedBitFails) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string f = d.file("good.spt");
    write_test_spt(f, 12, 5);
    auto ok = run_spt(d, {"verify", f});
    EXPECT_EQ(ok.code, 0) << ok.err;

    // Flip one bit inside frame 7's chunk (from the index in `info --json --frames`).
    auto info = run_spt(d, {"info", f, "--json", "--frames", "--no-fields"});
    ASSERT_EQ(info.code, 0);
    Json j = parse_json(info.out);
    const auto& fr = j["frame_list"][7];
    const size_t at = size_t(fr["offset"].num + fr["bytes"].num / 2);
    std::string bytes = slurp(f);
    bytes[at] = char(bytes[at] ^ 0x04);
    const std::string bad = d.file("bad.spt");
    std::ofstream(bad, std::ios::binary) << bytes;
    auto r = run_spt(d, {"verify", bad});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("bad.spt"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("frame 7"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(std::to_string(size_t(fr["offset"].num))), std::string::npos) << r.err;

    // A truncated file is not sound either.
    const std::string cut = d.file("cut.spt");
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, size_t(fr["offset"].num) + 3);
    EXPECT_EQ(run_spt(d, {"verify", cut}).code, 1);
}

// A 2 KB file whose one polygon has 1024 edges crossing every one of 2048 rows at 16x16
// samples would keep a renderer busy for half a minute (and its big brothers for hours): verify
// and render refuse it at once by the rendering-work limit (SPEC.md 10), naming the stroke.
TEST(CliVerify, PolygonRenderingBombIsRefused) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string f = d.file("star.spt");
    spt::StreamInfo info;
    spt::Header& h = info.header;
    h.width = h.height = 2048;
    h.sets = {spt::StrokeSet{16, 16}};
    h.orientations = spt::default_orientations(1);
    info.templates.resize(1);
    info.templates[0].kind = spt::TemplateKind::Ellipse;
    spt::PolygonStroke p;
    p.color = {255, 0, 0, 255};
    p.supersample = 16;
    for (int i = 0; i < 1024; ++i) p.points.push_back({int32_t(i * 32), (i % 2) ? 2048 * 16 - 1 : 0});
    spt::Frame fr;
    fr.added = {spt::Stroke::make_polygon(p)};
    auto w = spt::Writer::create(f, info);
    ASSERT_TRUE(w.ok()) << w.error().message;
    ASSERT_TRUE((*w)->append(fr).ok());
    ASSERT_TRUE((*w)->finish().ok());
    EXPECT_LT(fs::file_size(f), 8000u);
    for (const char* cmd : {"verify", "render"}) {
        std::vector<std::string> a = {cmd, f};
        if (std::string(cmd) == "render") a.insert(a.end(), {"-o", d.file("star.png")});
        auto r = run_spt(d, a);
        EXPECT_EQ(r.code, 1) << cmd;
        EXPECT_NE(r.err.find("rendering work"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("stroke 0"), std::string::npos) << r.err;
    }
    EXPECT_FALSE(fs::exists(d.file("star.png")));
}

TEST(CliRender, SingleFrameAndSequence) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string f = d.file("a.spt");
    write_test_spt(f, 12, 5);
    auto one = run_spt(d, {"render", f, "-o", d.file("one.png"), "--frame", "8"});
    ASSERT_EQ(one.code, 0) << one.err;
    auto img = spt::io::read_image(d.file("one.png"));
    ASSERT_TRUE(img.ok()) << img.error().message;
    EXPECT_EQ(img->rgb, reference_render(f, 8));

    auto first = run_spt(d, {"render", f, "-o", d.file("first.png")});
    ASSERT_EQ(first.code, 0) << first.err;
    EXPECT_EQ(spt::io::read_image(d.file("first.png"))->rgb, reference_render(f, 0));

    auto seq = run_spt(d, {"render", f, "-o", d.file("s.####.png"), "--frames", "6-9", "--progress", "json"});
    ASSERT_EQ(seq.code, 0) << seq.err;
    for (int i = 0; i < 12; ++i) {
        const std::string p = d.file("s." + std::string(i < 10 ? "000" : "00") + std::to_string(i) + ".png");
        EXPECT_EQ(fs::exists(p), i >= 6 && i <= 9) << p;
    }
    EXPECT_EQ(spt::io::read_image(d.file("s.0007.png"))->rgb, reference_render(f, 7));
    // Progress JSON went to stdout, one valid object per line, ending with "end".
    std::istringstream lines(seq.out);
    std::string line, last;
    while (std::getline(lines, line)) {
        parse_json(line);
        last = line;
    }
    EXPECT_EQ(parse_json(last)["event"].str, "end");

    auto off = run_spt(d, {"render", f, "-o", d.file("o_%03d.exr"), "--frames", "2", "--start", "100"});
    ASSERT_EQ(off.code, 0) << off.err;
    EXPECT_TRUE(fs::exists(d.file("o_102.exr")));

    auto several = run_spt(d, {"render", f, "-o", d.file("x.png"), "--frames", "1-3"});
    EXPECT_EQ(several.code, 2);
    auto beyond = run_spt(d, {"render", f, "-o", d.file("y.####.png"), "--frames", "10-20"});
    EXPECT_EQ(beyond.code, 1);
    EXPECT_FALSE(fs::exists(d.file("x.png")));
}

TEST(CliRender, PreviewVideo) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string f = d.file("a.spt");
    write_test_spt(f, 12, 5);
    auto v = run_spt(d, {"render", f, "-o", d.file("v.avi")});
    ASSERT_EQ(v.code, 0) << v.err;
    EXPECT_GT(fs::file_size(d.file("v.avi")), 1000u);
}

TEST(CliPack, StoredRangeRoundTripRendersIdentically) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string f = d.file("r.spt");
    write_test_spt(f, 12, 5, spt::Coding::Range);
    auto st = run_spt(d, {"pack", f, "-o", d.file("s.spt"), "--stored"});
    ASSERT_EQ(st.code, 0) << st.err;
    auto back = run_spt(d, {"pack", d.file("s.spt"), "-o", d.file("r2.spt")});
    ASSERT_EQ(back.code, 0) << back.err;
    EXPECT_GT(fs::file_size(d.file("s.spt")), fs::file_size(f));
    auto info = parse_json(run_spt(d, {"info", d.file("s.spt"), "--json", "--frames", "--no-fields"}).out);
    EXPECT_EQ(info["frame_list"][3]["coding"].str, "stored");
    EXPECT_EQ(info["metadata"]["painter"].str, "random");
    EXPECT_EQ(info["rois"].arr.size(), 1u);
    for (const char* name : {"r.spt", "s.spt", "r2.spt"}) {
        auto r = run_spt(d, {"render", d.file(name), "-o", d.file(std::string(name) + ".####.png")});
        ASSERT_EQ(r.code, 0) << r.err;
    }
    for (int i : {0, 4, 11}) {
        char n[16];
        std::snprintf(n, sizeof n, ".%04d.png", i);
        auto a = spt::io::read_image(d.file(std::string("r.spt") + n));
        auto b = spt::io::read_image(d.file(std::string("s.spt") + n));
        auto c = spt::io::read_image(d.file(std::string("r2.spt") + n));
        ASSERT_TRUE(a.ok() && b.ok() && c.ok());
        EXPECT_EQ(a->rgb, b->rgb) << i;
        EXPECT_EQ(a->rgb, c->rgb) << i;
    }
    EXPECT_EQ(run_spt(d, {"pack", f, "-o", f}).code, 2);
}

TEST(CliCompare, ImagesAndSequences) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string f = d.file("a.spt");
    write_test_spt(f, 6, 3);
    ASSERT_EQ(run_spt(d, {"render", f, "-o", d.file("a.####.png")}).code, 0);
    ASSERT_EQ(run_spt(d, {"render", f, "-o", d.file("b.####.png")}).code, 0);
    auto same = run_spt(d, {"compare", d.file("a.0001.png"), d.file("b.0001.png"), "--json"});
    ASSERT_EQ(same.code, 0) << same.err;
    Json j = parse_json(same.out);
    EXPECT_TRUE(j["identical"].b);
    EXPECT_EQ(j["psnr"].type, Json::Null);
    EXPECT_EQ(j["ssim"].num, 1);

    auto diff = run_spt(d, {"compare", d.file("a.0001.png"), d.file("a.0004.png"), "--json"});
    ASSERT_EQ(diff.code, 0) << diff.err;
    Json k = parse_json(diff.out);
    EXPECT_GT(k["psnr"].num, 5);
    EXPECT_LT(k["psnr"].num, 60);
    EXPECT_LT(k["ssim"].num, 1);
    EXPECT_EQ(run_spt(d, {"compare", d.file("a.0001.png"), d.file("a.0004.png"), "--min-psnr", "80"}).code, 1);

    auto seq = run_spt(d, {"compare", d.file("a.####.png"), d.file("b.####.png"), "--json"});
    ASSERT_EQ(seq.code, 0) << seq.err;
    Json s = parse_json(seq.out);
    EXPECT_EQ(s["count"].num, 6);
    EXPECT_EQ(s["min_ssim"].num, 1);

    std::vector<uint8_t> px(10 * 10 * 3, 0);
    ASSERT_TRUE(spt::io::write_image(d.file("small.png"), 10, 10, px.data()).ok());
    auto size = run_spt(d, {"compare", d.file("a.0001.png"), d.file("small.png")});
    EXPECT_EQ(size.code, 1);
    EXPECT_NE(size.err.find("small.png"), std::string::npos);
}

TEST(CliErrors, BadArgumentsAndMissingFiles) {
    REQUIRE_TOOL();
    TempDir d;
    const std::string f = d.file("a.spt");
    write_test_spt(f, 3, 3);
    const std::string missing = d.file("missing.spt");
    for (const auto& args : std::vector<std::vector<std::string>>{
             {"info"}, {"info", f, "--bogus"}, {"verify"}, {"render", f}, {"render", f, "-o"},
             {"render", f, "-o", d.file("x.png"), "--frames", "a-b"}, {"render", f, "-o", d.file("x.zzz")},
             {"render", f, "-o", d.file("x.png"), "--progress", "loud"}, {"pack", f},
             {"compare", d.file("x.png")}, {"info", f, "extra"}, {"render", f, "-o", d.file("x.png"), "--frame", "-1"}}) {
        auto r = run_spt(d, args);
        std::string joined;
        for (auto& a : args) joined += a + " ";
        EXPECT_EQ(r.code, 2) << joined << "\n" << r.err;
        EXPECT_FALSE(r.err.empty()) << joined;
    }
    for (const char* cmd : {"info", "verify"}) {
        auto r = run_spt(d, {cmd, missing});
        EXPECT_EQ(r.code, 1) << cmd;
        EXPECT_NE(r.err.find("missing.spt"), std::string::npos) << r.err;
    }
    auto r = run_spt(d, {"render", missing, "-o", d.file("o.png")});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("missing.spt"), std::string::npos) << r.err;
    auto p = run_spt(d, {"pack", missing, "-o", d.file("o.spt")});
    EXPECT_EQ(p.code, 1);
    EXPECT_NE(p.err.find("missing.spt"), std::string::npos) << p.err;
    auto c = run_spt(d, {"compare", d.file("nope1.png"), d.file("nope2.png")});
    EXPECT_EQ(c.code, 1);
    EXPECT_NE(c.err.find("nope1.png"), std::string::npos) << c.err;
    // Not a .spt file.
    std::ofstream(d.file("text.spt")) << "hello, not a stroke file";
    auto n = run_spt(d, {"info", d.file("text.spt")});
    EXPECT_EQ(n.code, 1);
    EXPECT_NE(n.err.find("text.spt"), std::string::npos) << n.err;
    // --help works everywhere and exits 0.
    for (const char* cmd : {"info", "verify", "render", "pack", "compare"}) {
        auto h = run_spt(d, {cmd, "--help"});
        EXPECT_EQ(h.code, 0) << cmd;
        EXPECT_NE(h.out.find("usage: spt"), std::string::npos) << cmd;
    }
}
