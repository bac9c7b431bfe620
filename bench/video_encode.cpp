// video_encode: paints a clip with the video painter library and prints one CSV line per frame
// (index, type, strokes added/removed/live, bytes, seconds, PSNR) and a summary. Optionally
// dumps the source frames and the painted frames as raw rgb24 for ffmpeg and video_coherence.
//
//   video_encode INPUT OUT.spt [--frames A-B] [--width W] [--raw-source F] [--raw-paint F]
//                [--seed N] [--threads N] [--keyframe-interval N] [--max-strokes N]
//                [--max-inter-strokes N] [--repaint-error E] [--flow M] [--block B] [--sets S]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <opencv2/imgproc.hpp>

#include "frames/frame_source.hpp"
#include "video/video_encoder.hpp"

using namespace spt;
using namespace spt::video;

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: video_encode INPUT OUT.spt [options] (see the source)\n");
        return 2;
    }
    VideoPaintOptions o;
    o.input = argv[1];
    o.output = argv[2];
    o.install_signal_handlers = false;
    std::string raw_src, raw_paint;
    int width = 0;
    for (int i = 3; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--frames") o.frames = v;
        else if (k == "--width") width = std::atoi(v.c_str());
        else if (k == "--raw-source") raw_src = v;
        else if (k == "--raw-paint") raw_paint = v;
        else if (k == "--seed") o.paint.seed = std::strtoull(v.c_str(), nullptr, 10);
        else if (k == "--threads") o.paint.threads = std::atoi(v.c_str());
        else if (k == "--keyframe-interval") o.keyframe_interval = std::atoi(v.c_str());
        else if (k == "--max-strokes") o.paint.max_strokes = std::strtoull(v.c_str(), nullptr, 10);
        else if (k == "--max-inter-strokes") o.max_inter_strokes = std::strtoull(v.c_str(), nullptr, 10);
        else if (k == "--repaint-error") o.repaint_error = std::atof(v.c_str());
        else if (k == "--target-psnr") o.paint.target_psnr = std::atof(v.c_str());
        else if (k == "--flow-width") o.flow_width = std::atoi(v.c_str());
        else if (k == "--orient-refresh") o.orient_refresh = std::atoi(v.c_str());
        else if (k == "--flow-orientation") o.flow_orientation = std::atoi(v.c_str()) != 0;
        else if (k == "--cull-every") o.cull_every = std::atoi(v.c_str());
        else if (k == "--repaint-key-fraction") o.repaint_key_fraction = std::atof(v.c_str());
        else if (k == "--inter-threshold") o.inter_threshold = std::atof(v.c_str());
        else if (k == "--incremental") o.incremental_render = std::atoi(v.c_str()) != 0;
        else if (k == "--lambda") o.paint.lambda = std::atof(v.c_str());
        else if (k == "--temperature") o.paint.temperature = std::atof(v.c_str());
        else if (k == "--flow") { if (!parse_flow_method(v, o.flow)) return 2; }
        else if (k == "--block") o.block_size = std::atoi(v.c_str());
        else if (k == "--sets") o.sets = std::atoi(v.c_str());
        else if (k == "--cut-threshold") o.cut_threshold = std::atof(v.c_str());
        else { std::fprintf(stderr, "unknown option %s\n", k.c_str()); return 2; }
    }
    auto src = open_source(o.input, o.frames, true);
    if (!src) { std::fprintf(stderr, "%s\n", src.error().message.c_str()); return 1; }
    SourceFrame f;
    auto got = (*src)->next(f);
    if (!got || !*got) { std::fprintf(stderr, "no frames\n"); return 1; }
    // Optional resize (benches at 640x360 and 1280x720 from any clip).
    auto fit = [&](io::Image& img) {
        if (width <= 0 || int(img.width) == width) return;
        const int h = int(std::lround(double(img.height) * width / img.width)) & ~1;
        cv::Mat in(int(img.height), int(img.width), CV_8UC3, img.rgb.data()), out;
        cv::resize(in, out, cv::Size(width, h), 0, 0, width < int(img.width) ? cv::INTER_AREA : cv::INTER_CUBIC);
        img.width = uint32_t(out.cols);
        img.height = uint32_t(out.rows);
        img.rgb.assign(out.data, out.data + out.total() * 3);
    };
    fit(f.image);
    const Rational fps = (*src)->has_fps() ? (*src)->fps() : Rational{24, 1};
    auto enc = VideoEncoder::create(o, f.image.width, f.image.height, fps);
    if (!enc) { std::fprintf(stderr, "%s\n", enc.error().message.c_str()); return 1; }
    FILE* fs = raw_src.empty() ? nullptr : std::fopen(raw_src.c_str(), "wb");
    FILE* fp = raw_paint.empty() ? nullptr : std::fopen(raw_paint.c_str(), "wb");
    std::printf("# %ux%u %u/%u fps\n", f.image.width, f.image.height, fps.num, fps.den);
    std::printf("index,source,type,cut,added,removed,live,bytes,seconds,psnr,repaint,flow,render,paint,cull,orient\n");
    uint64_t bytes_before = (*enc)->bytes_written();
    uint64_t key_bytes = 0, inter_bytes = 0;
    for (;;) {
        auto r = (*enc)->add_frame(f.image.rgb.data(), f.number);
        if (!r) { std::fprintf(stderr, "%s\n", r.error().message.c_str()); return 1; }
        const uint64_t now = (*enc)->bytes_written();
        const uint64_t fb = now - bytes_before;
        bytes_before = now;
        (r->type == FrameType::Key ? key_bytes : inter_bytes) += fb;
        std::printf("%u,%ld,%s,%d,%u,%u,%u,%llu,%.4f,%.3f,%.3f,%.4f,%.4f,%.4f,%.4f,%.4f\n", r->index, r->source_number,
                    r->type == FrameType::Key ? "key" : "inter", int(r->cut), r->added, r->removed, r->live,
                    (unsigned long long)fb, r->seconds, r->psnr, r->repaint_fraction, r->seconds_flow, r->seconds_render, r->seconds_paint, r->seconds_cull, r->seconds_orient);
        std::fflush(stdout);
        if (fs) std::fwrite(f.image.rgb.data(), 1, f.image.rgb.size(), fs);
        if (fp) std::fwrite((*enc)->canvas().rgb.data(), 1, (*enc)->canvas().rgb.size(), fp);
        got = (*src)->next(f);
        if (!got) { std::fprintf(stderr, "%s\n", got.error().message.c_str()); return 1; }
        if (!*got) break;
        fit(f.image);
    }
    if (fs) std::fclose(fs);
    if (fp) std::fclose(fp);
    Status st = (*enc)->finish();
    if (!st) { std::fprintf(stderr, "%s\n", st.error().message.c_str()); return 1; }
    const VideoPaintReport& rep = (*enc)->report();
    const uint64_t inter = rep.frames - rep.key_frames;
    std::printf("# frames %llu key %llu cuts %llu bytes %llu mean_psnr %.2f max_live %llu\n",
                (unsigned long long)rep.frames, (unsigned long long)rep.key_frames, (unsigned long long)rep.cuts,
                (unsigned long long)rep.bytes, rep.mean_psnr, (unsigned long long)rep.max_live);
    std::printf("# ms_per_key %.1f ms_per_inter %.1f bytes_per_key %.0f bytes_per_inter %.0f\n",
                rep.key_frames ? 1000 * rep.seconds_key / rep.key_frames : 0.0,
                inter ? 1000 * rep.seconds_inter / inter : 0.0,
                rep.key_frames ? double(key_bytes) / rep.key_frames : 0.0, inter ? double(inter_bytes) / inter : 0.0);
    return 0;
}
