// Rate bench: paints an image at one or more lambdas and codes the painting with frame coding 1
// and frame coding 2 (decoder-replayed candidates), checking that coding 2 decodes to exactly
// the painter's strokes and canvas. Prints one line per lambda:
//   image lambda strokes psnr bytes_c1 bytes_c2 B/stroke_c1 B/stroke_c2 [jxl_bytes ratio] fields
// Usage: rate_codec IMAGE [--lambda L1,L2,..] [--target-psnr DB] [--orient edges|random]
//                         [--seed N] [--color-step Q] [--jxl] [--tmp DIR] [--templates DIR]
// --templates DIR: the images of DIR (name order) instead of the built-in templates; a file
// whose name contains "rectangle" or "ellipse" becomes that analytic kind (4x4 supersampled
// ellipse), as default_templates() does for the rectangle. Prints header_bytes (templates).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "io/image_io.hpp"
#include "io/template_loader.hpp"
#include "paint/painter.hpp"
#include "spt/spt.hpp"

using namespace spt;

namespace {

struct Coded {
    uint64_t bytes = 0, frame_bytes = 0;
    FieldStats fields;
    bool ok = true;
    std::string why;
};

Coded code(const std::string& path, const StreamInfo& info, const Frame& frame, Coding coding,
           const std::vector<Stroke>& strokes, const Canvas& canvas) {
    Coded c;
    WriterOptions wo;
    wo.coding = coding;
    auto w = Writer::create(path, info, wo);
    if (!w) { c.ok = false; c.why = w.error().message; return c; }
    Status s = (*w)->append(frame);
    if (s) s = (*w)->finish();
    if (!s) { c.ok = false; c.why = s.error().message; return c; }
    c.bytes = (*w)->stats().total_bytes;
    c.frame_bytes = (*w)->stats().frame_bytes;
    c.fields = (*w)->stats().fields;
    auto r = Reader::open(path);
    if (!r) { c.ok = false; c.why = r.error().message; return c; }
    auto live = (*r)->strokes_at(0);
    if (!live) { c.ok = false; c.why = live.error().message; return c; }
    if (**live != strokes) { c.ok = false; c.why = "decoded strokes differ"; return c; }
    auto rd = Renderer::create((*r)->info().header, (*r)->info().templates);
    Canvas out((*r)->info().header.width, (*r)->info().header.height);
    if (!(*rd)->render(out, **live) || out.rgb != canvas.rgb) { c.ok = false; c.why = "decoded render differs"; }
    return c;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: rate_codec IMAGE [--lambda L1,L2,..] [--target-psnr DB] [--orient edges|random] [--seed N] [--color-step Q] [--jxl] [--tmp DIR]\n");
        return 2;
    }
    std::string image = argv[1], tmp = std::filesystem::temp_directory_path().string();
    std::vector<double> lambdas{64};
    paint::PaintOptions po;
    bool jxl = false;
    std::string templates_dir;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
        if (a == "--lambda") {
            lambdas.clear();
            std::stringstream ss(next());
            std::string t;
            while (std::getline(ss, t, ',')) lambdas.push_back(std::atof(t.c_str()));
        } else if (a == "--target-psnr") po.target_psnr = std::atof(next().c_str());
        else if (a == "--orient") po.orient = next() == "random" ? paint::OrientMode::Random : paint::OrientMode::Edges;
        else if (a == "--seed") po.seed = std::strtoull(next().c_str(), nullptr, 10);
        else if (a == "--jxl") jxl = true;
        else if (a == "--color-step") po.color_step = std::atoi(next().c_str());
        else if (a == "--tmp") tmp = next();
        else if (a == "--templates") templates_dir = next();
        else { std::fprintf(stderr, "unknown option %s\n", a.c_str()); return 2; }
    }
    auto img = io::read_image(image);
    if (!img) { std::fprintf(stderr, "%s\n", img.error().message.c_str()); return 1; }
    const uint32_t W = img->width, H = img->height;
    std::vector<Template> templates = paint::default_templates();
    if (!templates_dir.empty()) {
        auto t = io::load_templates(templates_dir);
        if (!t) { std::fprintf(stderr, "%s\n", t.error().message.c_str()); return 1; }
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(templates_dir))
            if (e.path().extension() == ".png") names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        templates = *t;
        for (size_t i = 0; i < templates.size() && i < names.size(); ++i) {
            Template& tp = templates[i];
            if (names[i].find("rectangle") != std::string::npos) tp = Template{TemplateKind::Rectangle, 0, 0, {}, "rectangle"};
            else if (names[i].find("ellipse") != std::string::npos) tp = Template{TemplateKind::Ellipse, 0, 0, {}, "ellipse", 4};
        }
    }
    paint::PaintSetup setup = paint::make_setup(W, H, {255, 255, 255}, paint::default_sets(W, H), templates);
    auto renderer = Renderer::create(setup.header, setup.templates);
    StreamInfo info;
    info.header = setup.header;
    info.templates = setup.templates;
    const std::string stem = tmp + "/rate_codec_" + std::to_string(::getpid());
    int status = 0;
    for (double lambda : lambdas) {
        po.lambda = lambda;
        Canvas canvas(W, H, {255, 255, 255});
        std::vector<Stroke> strokes;
        const auto t0 = std::chrono::steady_clock::now();
        const paint::PaintStats st = paint::paint({W, H, img->rgb.data()}, canvas, **renderer, setup, po, strokes);
        const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        Frame f;
        f.added = strokes;
        const Coded c1 = code(stem + ".c1.spt", info, f, Coding::Range, strokes, canvas);
        f.replay = paint::replay_info(setup, po, W, H);
        const Coded c2 = code(stem + ".c2.spt", info, f, Coding::Replay, strokes, canvas);
        if (!c1.ok || !c2.ok) {
            std::fprintf(stderr, "%s lambda %g: %s %s\n", image.c_str(), lambda, c1.why.c_str(), c2.why.c_str());
            status = 1;
        }
        const double n = std::max<double>(1, double(st.strokes));
        std::printf("%s %ux%u lambda %g strokes %llu psnr %.2f bytes_c1 %llu bytes_c2 %llu Bps_c1 %.3f Bps_c2 %.3f frameBps_c2 %.3f header_bytes %llu paint_s %.1f",
                    std::filesystem::path(image).filename().c_str(), W, H, lambda, (unsigned long long)st.strokes, st.psnr,
                    (unsigned long long)c1.bytes, (unsigned long long)c2.bytes, c1.bytes / n, c2.bytes / n, c2.frame_bytes / n,
                    (unsigned long long)(c2.bytes - c2.frame_bytes), secs);
        if (jxl) {
            const std::string png = stem + ".png", jx = stem + ".jxl";
            if (Status w = io::write_image(png, canvas); !w) { std::fprintf(stderr, "%s\n", w.error().message.c_str()); return 1; }
            const std::string cmd = "cjxl -d 0 -e 7 --quiet '" + png + "' '" + jx + "' >/dev/null 2>&1";
            if (std::system(cmd.c_str()) == 0) {
                const auto jb = std::filesystem::file_size(jx);
                std::printf(" jxl %llu jxl_ratio %.2f", (unsigned long long)jb, double(jb) / double(c2.bytes));
            }
            std::filesystem::remove(png);
            std::filesystem::remove(jx);
        }
        std::printf(" |");
        for (size_t i = 0; i < kFieldCount; ++i)
            if (c2.fields.bits[i] > 0) std::printf(" %s %.2f", field_name(Field(i)), c2.fields.bits[i] / n);
        std::printf(" (bits/stroke, coding 2)\n");
        std::fflush(stdout);
    }
    std::filesystem::remove(stem + ".c1.spt");
    std::filesystem::remove(stem + ".c2.spt");
    return status;
}
