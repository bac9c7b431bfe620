// Decode + render throughput of one 1280x720 key frame of 30,000 painter strokes, per frame
// coding (0 stored, 1 range, 2 decoder-replayed candidates), on one core.
//
// The frame is a real painting: kodim07 (or --image) scaled to cover 1280x720, painted by the
// painter library (default sets and templates, edge orientations, --max-strokes 30000, a low
// lambda so the stroke budget is what stops it). Painting takes a while, so the coding-2 file is
// cached (--cache DIR, default the system temp dir) and reused when its parameters match; it
// holds the frame's ReplayInfo, from which the coding 0 and 1 files are written in memory.
//
// It first prints the work in the frame: footprint pixels, and how many of them are visible
// (not covered later at full opacity) with the stroke rows holding them: the floor of what an
// occlusion-culling renderer would still have to blend and visit.
// Per coding, over `runs` runs (medians, thread CPU time, measured alternately so that machine
// load hits every coding alike):
//   decode   Reader::read_frame(0, frame) on an open reader, into the Frame of the previous
//            run, as a player reading frame after frame does (chunk read, CRC, body decode;
//            coding 2 also renders every stroke while decoding, SPEC.md 7.7)
//   live     Reader::strokes_at(0) on a freshly opened reader (decode + live list; the reader's
//            own first-use costs, e.g. coding 2's footprint cache, included)
//   render   Renderer::render(canvas, strokes), one thread
//   d+r fps  1 / (decode + render)
// and, for coding 0,
//   frame    Reader::render_frame(0, canvas) on the open reader: what a player calls, decode and
//            render in one (a coding-0 key frame of stamps renders straight from its records)
// plus render with 2 threads (wall time: only meaningful on an idle machine), and checks that
// every coding decodes to the painter's strokes and renders the painter's canvas; then
// playback: a player showing a coding-0 stream of 8 such key frames (the painting moved a few
// pixels per frame) with Reader::render_frame, frame after frame (the frames per second).
// Usage: decode_bench [runs] [--image PATH] [--max-strokes N] [--cache DIR] [--synthetic]
//                     [--only decode0|decode1|decode2|render|frame0]   (a loop of one phase, for perf)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "bench_timing.hpp"
#include "io/image_io.hpp"
#include "paint/painter.hpp"
#include "spt/spt.hpp"

using namespace spt;

namespace {

constexpr uint32_t kW = 1280, kH = 720;

using bench::median;
using bench::thread_seconds;
using bench::wall_seconds;

// Scales `img` to cover kW x kH (bilinear) and crops the centre.
io::Image cover(const io::Image& img) {
    io::Image out;
    out.width = kW;
    out.height = kH;
    out.rgb.resize(size_t(kW) * kH * 3);
    const double s = std::max(double(kW) / img.width, double(kH) / img.height);
    const double ox = (img.width * s - kW) / 2, oy = (img.height * s - kH) / 2;
    for (uint32_t y = 0; y < kH; ++y)
        for (uint32_t x = 0; x < kW; ++x) {
            const double sx = std::clamp((x + 0.5 + ox) / s - 0.5, 0.0, double(img.width - 1));
            const double sy = std::clamp((y + 0.5 + oy) / s - 0.5, 0.0, double(img.height - 1));
            const uint32_t x0 = uint32_t(sx), y0 = uint32_t(sy);
            const uint32_t x1 = std::min(x0 + 1, img.width - 1), y1 = std::min(y0 + 1, img.height - 1);
            const double fx = sx - x0, fy = sy - y0;
            for (int k = 0; k < 3; ++k) {
                auto at = [&](uint32_t xx, uint32_t yy) { return double(img.rgb[(size_t(yy) * img.width + xx) * 3 + k]); };
                const double v = (at(x0, y0) * (1 - fx) + at(x1, y0) * fx) * (1 - fy) + (at(x0, y1) * (1 - fx) + at(x1, y1) * fx) * fy;
                out.rgb[(size_t(y) * kW + x) * 3 + k] = uint8_t(std::lround(std::clamp(v, 0.0, 255.0)));
            }
        }
    return out;
}

std::vector<uint8_t> read_bytes(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::vector<uint8_t>(std::istreambuf_iterator<char>(f), {});
}

// Writes `f` with `coding` to `path` and returns the file's bytes (empty on failure).
std::vector<uint8_t> write(const std::string& path, const StreamInfo& info, const std::vector<Frame>& frames,
                           Coding coding, Coding* used) {
    WriterOptions wo;
    wo.coding = coding;
    auto w = Writer::create(path, info, wo);
    if (!w) { std::fprintf(stderr, "%s\n", w.error().message.c_str()); return {}; }
    Status s;
    for (const Frame& f : frames)
        if (s) s = (*w)->append(f);
    if (s) s = (*w)->finish();
    if (!s) { std::fprintf(stderr, "%s\n", s.error().message.c_str()); return {}; }
    auto bytes = read_bytes(path);
    if (used) {
        auto r = Reader::open_memory(bytes.data(), bytes.size());
        *used = r ? (*r)->frames()[0].coding : Coding::Stored;
    }
    return bytes;
}
std::vector<uint8_t> write(const std::string& path, const StreamInfo& info, const Frame& f, Coding coding,
                           Coding* used) {
    return write(path, info, std::vector<Frame>{f}, coding, used);
}

// Painter-like stamps without the painter's image: coarse strokes first, then finer ones, with
// colours of a smooth gradient (coding 2 is not available for these).
std::vector<Stroke> synthetic_strokes(const Header& h, size_t templates, size_t n) {
    std::mt19937 rng(7);
    std::vector<Stroke> v;
    const size_t sets = h.sets.size();
    for (size_t i = 0; i < n; ++i) {
        StampStroke s;
        s.set = uint8_t(std::min<size_t>(sets - 1, size_t(std::sqrt(double(i) / double(n)) * double(sets))));
        s.tmpl = uint8_t(rng() % templates);
        s.orient = uint8_t(rng() % h.orientations.size());
        const uint32_t x = rng() % h.width, y = rng() % h.height;
        s.x = int32_t(16 * x + 8);
        s.y = int32_t(16 * y + 8);
        s.color = {uint8_t(x * 255 / h.width), uint8_t(y * 255 / h.height), uint8_t((x + y) * 127 / (h.width + h.height) + rng() % 32), 255};
        v.push_back(Stroke::make_stamp(s));
    }
    return v;
}

struct Case {
    const char* name;
    Coding coding;
    std::vector<uint8_t> bytes;
    std::unique_ptr<Reader> reader;
    Frame decoded;  // decoded into again by every run
    std::vector<double> decode, live, render, total, frame;
    bool ok = true;
};

}  // namespace

int main(int argc, char** argv) {
    int runs = 15;
    std::string image = std::string(SPT_MEDIA_DIR) + "/stills/kodim07.tif";
    std::string cache = std::filesystem::temp_directory_path().string();
    uint64_t max_strokes = 30000;
    bool synthetic = false;
    std::string only;  // for profiling: "decode0", "decode1", "decode2", "render" or "frame0" in a loop
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
        if (a == "--image") image = next();
        else if (a == "--cache") cache = next();
        else if (a == "--max-strokes") max_strokes = std::strtoull(next().c_str(), nullptr, 10);
        else if (a == "--synthetic") synthetic = true;
        else if (a == "--only") only = next();
        else if (a == "--help" || a == "-h") {
            std::printf("usage: decode_bench [runs] [--image PATH] [--max-strokes N] [--cache DIR] [--synthetic] [--only PHASE]\n");
            return 0;
        } else if (!a.empty() && a[0] != '-') runs = std::max(1, std::atoi(a.c_str()));
        else { std::fprintf(stderr, "unknown option %s\n", a.c_str()); return 2; }
    }

    // ---- the frame ----
    paint::PaintSetup setup = paint::make_setup(kW, kH, {255, 255, 255}, paint::default_sets(kW, kH), paint::default_templates());
    StreamInfo info;
    info.header = setup.header;
    info.templates = setup.templates;
    Frame frame;
    Canvas painted;
    if (!synthetic && !std::filesystem::exists(image)) {
        std::fprintf(stderr, "%s not found: using synthetic strokes\n", image.c_str());
        synthetic = true;
    }
    if (synthetic) {
        frame.added = synthetic_strokes(info.header, info.templates.size(), size_t(max_strokes));
    } else {
        paint::PaintOptions po;
        po.seed = 1;
        po.max_strokes = max_strokes;
        po.lambda = 1;  // the stroke budget, not the rate-distortion rule, ends the painting
        const std::string key = std::filesystem::path(image).stem().string() + "_" + std::to_string(kW) + "x" +
                                std::to_string(kH) + "_" + std::to_string(max_strokes);
        const std::string cached = cache + "/decode_bench_" + key + ".c2.spt";
        std::error_code mkdir_error;
        std::filesystem::create_directories(cache, mkdir_error);  // a new --cache folder
        std::vector<uint8_t> c2 = read_bytes(cached);
        bool have = false;
        if (!c2.empty()) {
            auto r = Reader::open_memory(c2.data(), c2.size());
            const Header& h = r ? (*r)->info().header : info.header;
            if (r && h.width == kW && h.height == kH && h.sets == info.header.sets &&
                h.orientations == info.header.orientations && (*r)->info().templates == info.templates) {
                auto f = (*r)->read_frame(0);
                if (f && f->replay.present) { frame = std::move(*f); have = true; }
            }
        }
        if (!have && !c2.empty()) std::fprintf(stderr, "cache %s: %zu bytes, not usable\n", cached.c_str(), c2.size());
        if (!have) {
            auto img = io::read_image(image);
            if (!img) { std::fprintf(stderr, "%s\n", img.error().message.c_str()); return 1; }
            const io::Image model = cover(*img);
            auto rd = Renderer::create(setup.header, setup.templates);
            Canvas canvas(kW, kH, {255, 255, 255});
            std::fprintf(stderr, "painting %s at %ux%u, up to %llu strokes (cached in %s)...\n", image.c_str(), kW, kH,
                         (unsigned long long)max_strokes, cached.c_str());
            const double t0 = wall_seconds();
            const auto st = paint::paint({kW, kH, model.rgb.data()}, canvas, **rd, setup, po, frame.added);
            std::fprintf(stderr, "painted %llu strokes, %.2f dB, %.1f s\n", (unsigned long long)st.strokes, st.psnr,
                         wall_seconds() - t0);
            frame.replay = paint::replay_info(setup, po, kW, kH);
            Coding used;
            if (write(cached, info, frame, Coding::Replay, &used).empty()) return 1;
            if (used != Coding::Replay) std::fprintf(stderr, "warning: the painting did not code with coding 2\n");
        }
    }
    auto renderer = Renderer::create(info.header, info.templates);
    if (!renderer) { std::fprintf(stderr, "%s\n", renderer.error().message.c_str()); return 1; }
    painted = Canvas(kW, kH);
    if (!(*renderer)->render(painted, frame.added)) return 1;

    size_t stamps = 0;
    for (const Stroke& s : frame.added) stamps += s.kind == StrokeKind::Stamp;
    // Work of the frame: footprint pixels with non-zero coverage, summed over the strokes.
    uint64_t covered = 0;
    for (const Stroke& s : frame.added)
        if (s.kind == StrokeKind::Stamp) {
            const Mask& m = (*renderer)->stamp_footprint(s.stamp.set, s.stamp.tmpl, s.stamp.orient);
            for (uint8_t a : m.a) covered += a != 0;
        }
    std::printf("frame: %ux%u, %zu strokes (%zu stamps), %s; %.1f M footprint pixels (%.1f per canvas pixel)\n", kW, kH,
                frame.added.size(), stamps,
                synthetic ? "synthetic" : ("painted from " + std::filesystem::path(image).filename().string()).c_str(),
                1e-6 * double(covered), double(covered) / (double(kW) * kH));
    // How much of that work any renderer must do: a pixel is hidden from a stroke when a later
    // stroke covers it fully (coverage 255, alpha 255), which sets it to that stroke's colour
    // whatever was under it (SPEC 8.6). Visible pixels and rows are what an ideal
    // occlusion-culling renderer would still blend and visit.
    {
        const int64_t W = kW, H = kH;
        std::vector<int32_t> last_opaque(size_t(W * H), -1);
        auto place = [&](const Stroke& s, auto&& fn) {
            const Mask& m = (*renderer)->stamp_footprint(s.stamp.set, s.stamp.tmpl, s.stamp.orient);
            const int64_t cx = s.stamp.x >> 4, cy = s.stamp.y >> 4;
            for (uint32_t j = 0; j < m.h; ++j) {
                const int64_t y = cy + m.y0 + j;
                if (y < 0 || y >= H) continue;
                fn(j, y, m, cx);
            }
        };
        for (size_t k = frame.added.size(); k-- > 0;) {
            const Stroke& s = frame.added[k];
            if (s.kind != StrokeKind::Stamp || s.stamp.color.a != 255) continue;
            place(s, [&](uint32_t j, int64_t y, const Mask& m, int64_t cx) {
                for (uint32_t i = 0; i < m.w; ++i) {
                    const int64_t x = cx + m.x0 + i;
                    if (x >= 0 && x < W && m.a[size_t(j) * m.w + i] == 255 && last_opaque[size_t(y * W + x)] < 0)
                        last_opaque[size_t(y * W + x)] = int32_t(k);
                }
            });
        }
        uint64_t visible = 0, rows = 0, visible_rows = 0, visible_strokes = 0;
        for (size_t k = 0; k < frame.added.size(); ++k) {
            const Stroke& s = frame.added[k];
            if (s.kind != StrokeKind::Stamp) continue;
            const uint64_t before = visible;
            place(s, [&](uint32_t j, int64_t y, const Mask& m, int64_t cx) {
                bool any = false, seen = false;
                for (uint32_t i = 0; i < m.w; ++i) {
                    const int64_t x = cx + m.x0 + i;
                    if (x < 0 || x >= W || !m.a[size_t(j) * m.w + i]) continue;
                    seen = true;
                    if (int64_t(k) >= last_opaque[size_t(y * W + x)]) ++visible, any = true;
                }
                rows += seen;
                visible_rows += any;
            });
            visible_strokes += visible > before;
        }
        std::printf("occlusion: %.2f M footprint pixels visible (%.1f%%: not covered later at full opacity), %.0f k of "
                    "%.0f k stroke rows and %llu of %zu strokes with a visible pixel\n",
                    1e-6 * double(visible), 100.0 * double(visible) / double(std::max<uint64_t>(covered, 1)),
                    1e-3 * double(visible_rows), 1e-3 * double(rows), (unsigned long long)visible_strokes, stamps);
    }
    {
        std::vector<size_t> per(info.header.sets.size());
        for (const Stroke& s : frame.added)
            if (s.kind == StrokeKind::Stamp) ++per[s.stamp.set];
        std::printf("strokes per set:");
        for (size_t k = 0; k < per.size(); ++k)
            std::printf(" %ux%u:%zu", info.header.sets[k].width, info.header.sets[k].height, per[k]);
        std::printf("\n");
    }

    // ---- the files ----
    std::vector<Case> cases;
    const std::string tmp = std::filesystem::temp_directory_path().string() + "/decode_bench_" + std::to_string(::getpid());
    const Coding codings[3] = {Coding::Stored, Coding::Range, Coding::Replay};
    const char* names[3] = {"0 stored", "1 range", "2 replay"};
    for (int k = 0; k < 3; ++k) {
        if (k == 2 && !frame.replay.present) continue;
        Case c;
        c.name = names[k];
        Coding used;
        c.bytes = write(tmp + ".spt", info, frame, codings[k], &used);
        if (c.bytes.empty()) return 1;
        if (used != codings[k]) { std::fprintf(stderr, "coding %d fell back to %d\n", k, int(used)); continue; }
        c.coding = used;
        auto r = Reader::open_memory(c.bytes.data(), c.bytes.size());
        if (!r) { std::fprintf(stderr, "%s\n", r.error().message.c_str()); return 1; }
        c.reader = std::move(*r);
        cases.push_back(std::move(c));
    }
    std::filesystem::remove(tmp + ".spt");

    if (!only.empty()) {  // a loop over one phase (for perf), with the median time of a run
        Canvas cv(kW, kH);
        std::vector<double> t;
        for (int run = 0; run < runs; ++run) {
            const double t0 = thread_seconds();
            if (only == "render") (void)(*renderer)->render(cv, frame.added, 1);  // timed; checked above
            if (only == "frame0") (void)cases[0].reader->render_frame(0, cv, 1);
            for (Case& c : cases)
                if (only == std::string("decode") + char('0' + int(c.coding))) (void)c.reader->read_frame(0, c.decoded);
            t.push_back(thread_seconds() - t0);
        }
        std::printf("%s: %.3f ms (median of %d runs, thread CPU time)\n", only.c_str(), 1e3 * median(t), runs);
        return 0;
    }

    // ---- timing ----
    Canvas canvas(kW, kH), framed(kW, kH);
    for (int run = -1; run < runs; ++run) {  // run -1 warms up (footprints, page faults)
        for (Case& c : cases) {
            Frame* f = &c.decoded;
            double t0 = thread_seconds();
            const Status ds = c.reader->read_frame(0, *f);
            const double dec = thread_seconds() - t0;
            if (!ds) { std::fprintf(stderr, "%s: %s\n", c.name, ds.error().message.c_str()); return 1; }

            auto fresh = Reader::open_memory(c.bytes.data(), c.bytes.size());
            t0 = thread_seconds();
            auto live = (*fresh)->strokes_at(0);
            const double lv = thread_seconds() - t0;
            if (!live) { std::fprintf(stderr, "%s: %s\n", c.name, live.error().message.c_str()); return 1; }

            t0 = thread_seconds();
            const Status rs = (*renderer)->render(canvas, f->added, 1);
            const double ren = thread_seconds() - t0;
            if (!rs) { std::fprintf(stderr, "%s: %s\n", c.name, rs.error().message.c_str()); return 1; }
            // The player's call, decode and render in one (Reader::render_frame), for coding 0:
            // its key frames render straight from their records. (Other codings go through
            // strokes_at, which keeps the live list of the frame it decoded last: timing it
            // again on one frame would time the render alone.)
            double fr = 0;
            if (c.coding == Coding::Stored) {
                t0 = thread_seconds();
                const Status fs = c.reader->render_frame(0, framed, 1);
                fr = thread_seconds() - t0;
                if (!fs) { std::fprintf(stderr, "%s: %s\n", c.name, fs.error().message.c_str()); return 1; }
            }
            if (run < 0) {
                c.ok = f->added == frame.added && **live == frame.added && canvas.rgb == painted.rgb &&
                       (c.coding != Coding::Stored || framed.rgb == painted.rgb);
                continue;
            }
            if (c.coding == Coding::Stored) c.frame.push_back(fr);
            c.decode.push_back(dec);
            c.live.push_back(lv);
            c.render.push_back(ren);
            c.total.push_back(dec + ren);
        }
    }
    std::vector<double> two;
    for (int run = 0; run < runs; ++run) {
        const double t0 = wall_seconds();
        (void)(*renderer)->render(canvas, frame.added, 2);  // timed; the same frame rendered above
        two.push_back(wall_seconds() - t0);
    }

    std::printf("%-9s %9s %8s %10s %10s %10s %10s %9s  %s\n", "coding", "bytes", "B/stroke", "decode_ms", "live_ms",
                "render_ms", "d+r_ms", "d+r_fps", "decoded=painted");
    for (const Case& c : cases) {
        const double d = median(c.decode), l = median(c.live), r = median(c.render), t = median(c.total);
        std::printf("%-9s %9zu %8.2f %10.2f %10.2f %10.2f %10.2f %9.1f  %s\n", c.name, c.bytes.size(),
                    double(c.bytes.size()) / double(std::max<size_t>(1, frame.added.size())), 1e3 * d, 1e3 * l, 1e3 * r,
                    1e3 * t, 1.0 / t, c.ok ? "yes" : "NO");
    }
    for (const Case& c : cases)
        if (!c.frame.empty())
            std::printf("frame     %s: Reader::render_frame (decode + render in one, a player's call): %.2f ms, %.1f fps\n",
                        c.name, 1e3 * median(c.frame), 1.0 / median(c.frame));
    std::printf("render 2 threads (wall): %.2f ms, %.1f fps   [%d runs, medians, thread CPU time unless noted]\n",
                1e3 * median(two), 1.0 / median(two), runs);

    // ---- playback: what a player of a stream of such key frames sustains ----
    // kPlay key frames in one coding-0 file, frame k the painting moved by (3k, 2k) pixels (every
    // frame's bytes differ; the work per frame is the same), shown in order with
    // Reader::render_frame on one reader, `runs` passes. The timings above alternate codings and
    // renderers, so each phase starts with caches full of the others' data; here, as in a player,
    // one frame follows another.
    {
        constexpr uint32_t kPlay = 8;
        std::vector<Frame> play;
        for (uint32_t k = 0; k < kPlay; ++k) {
            Frame f;
            f.index = k;
            f.type = FrameType::Key;
            f.added = frame.added;
            for (Stroke& st : f.added)
                if (st.kind == StrokeKind::Stamp) {
                    st.stamp.x += int32_t(16 * 3 * k);
                    st.stamp.y += int32_t(16 * 2 * k);
                }
            play.push_back(std::move(f));
        }
        Coding used;
        const std::vector<uint8_t> bytes = write(tmp + ".play.spt", info, play, Coding::Stored, &used);
        std::filesystem::remove(tmp + ".play.spt");
        if (bytes.empty()) return 1;
        auto r = Reader::open_memory(bytes.data(), bytes.size());
        if (!r) { std::fprintf(stderr, "%s\n", r.error().message.c_str()); return 1; }
        Canvas shown(kW, kH), want(kW, kH);
        bool same = true;
        for (uint32_t k = 0; k < kPlay; ++k) {  // correctness first (and warm-up)
            if (!(*r)->render_frame(k, shown, 1) || !(*renderer)->render(want, play[k].added, 1)) return 1;
            same = same && shown.rgb == want.rgb;
        }
        std::vector<double> t;
        for (int run = 0; run < runs; ++run)
            for (uint32_t k = 0; k < kPlay; ++k) {
                const double t0 = thread_seconds();
                (void)(*r)->render_frame(k, shown, 1);
                t.push_back(thread_seconds() - t0);
            }
        std::printf("playback  %u key frames, coding 0, Reader::render_frame in order: %.2f ms a frame, %.1f fps  "
                    "(frames = render of their strokes: %s)\n",
                    kPlay, 1e3 * median(t), 1.0 / median(t), same ? "yes" : "NO");
        if (!same) return 1;
    }
    for (const Case& c : cases)
        if (!c.ok) return 1;
    return 0;
}
