#include "io/ffmpeg_writer.hpp"

#include <cmath>
#include <cstring>
#include <vector>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
#include <libswscale/swscale.h>
}

#include "io/av_error.hpp"

namespace spt::video {

namespace {

using io::av_text;

}  // namespace

struct VideoFileWriter::Impl {
    std::string name;
    AVFormatContext* oc = nullptr;
    AVCodecContext* enc = nullptr;
    AVStream* st = nullptr;
    AVFrame* frame = nullptr;
    AVPacket* pkt = nullptr;
    SwsContext* sws = nullptr;
    int w = 0, h = 0;
    int64_t next_pts = 0;
    bool header = false, done = false;
    std::vector<uint8_t> rgb;

    ~Impl() {
        if (oc && header && !done) av_write_trailer(oc);
        sws_freeContext(sws);
        av_frame_free(&frame);
        av_packet_free(&pkt);
        avcodec_free_context(&enc);
        if (oc && !(oc->oformat->flags & AVFMT_NOFILE)) avio_closep(&oc->pb);
        avformat_free_context(oc);
    }

    Status fail(const std::string& what, int e) const {
        return make_error(Code::IoError, name + ": " + what + (e < 0 ? " (" + av_text(e) + ")" : std::string()));
    }

    // Sends `f` (null: flush) and writes what the encoder gives back.
    Status encode(const AVFrame* f) {
        if (int e = avcodec_send_frame(enc, f); e < 0) return fail("encoding a frame failed", e);
        for (;;) {
            int e = avcodec_receive_packet(enc, pkt);
            if (e == AVERROR(EAGAIN) || e == AVERROR_EOF) return {};
            if (e < 0) return fail("encoding a frame failed", e);
            if (pkt->duration == 0) pkt->duration = 1;  // one frame: the last frame's length too
            av_packet_rescale_ts(pkt, enc->time_base, st->time_base);
            pkt->stream_index = st->index;
            e = av_interleaved_write_frame(oc, pkt);
            if (e < 0) return fail("writing a frame failed", e);
        }
    }
};

VideoFileWriter::VideoFileWriter() : d_(std::make_unique<Impl>()) {}
VideoFileWriter::~VideoFileWriter() = default;

Status VideoFileWriter::open(const std::string& file, const std::string& ext, const std::string& name, double fps,
                             uint32_t w, uint32_t h) {
    Impl& d = *d_;
    d.name = name;
    d.w = int(w);
    d.h = int(h);
    if (int e = avformat_alloc_output_context2(&d.oc, nullptr, nullptr, file.c_str()); e < 0 || !d.oc)
        return d.fail("FFmpeg knows no video container for this name", e);
    const bool mjpeg = ext == ".avi";
    const AVCodec* codec = avcodec_find_encoder(mjpeg ? AV_CODEC_ID_MJPEG : AV_CODEC_ID_MPEG4);
    if (!codec) return d.fail(std::string("no ") + (mjpeg ? "Motion JPEG" : "MPEG-4") + " encoder", 0);
    d.st = avformat_new_stream(d.oc, nullptr);
    d.enc = avcodec_alloc_context3(codec);
    d.frame = av_frame_alloc();
    d.pkt = av_packet_alloc();
    if (!d.st || !d.enc || !d.frame || !d.pkt) return d.fail("out of memory", 0);
    // The rate as a fraction over 1001 when it is one of the NTSC rates, else over 1000.
    const double rate = fps > 0 && std::isfinite(fps) ? fps : 24.0;
    const AVRational r = av_d2q(rate, 1001000);
    d.enc->width = d.w;
    d.enc->height = d.h;
    d.enc->time_base = av_inv_q(r);
    d.enc->framerate = r;
    d.enc->pix_fmt = mjpeg ? AV_PIX_FMT_YUVJ420P : AV_PIX_FMT_YUV420P;
    d.enc->gop_size = 12;
    // A fixed quantiser: a preview as sharp as its frames allow, whatever the size.
    d.enc->flags |= AV_CODEC_FLAG_QSCALE;
    d.enc->global_quality = FF_QP2LAMBDA * 3;
    if (d.oc->oformat->flags & AVFMT_GLOBALHEADER) d.enc->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    if (int e = avcodec_open2(d.enc, codec, nullptr); e < 0)
        return d.fail("cannot open the " + std::string(codec->name) + " encoder for " + std::to_string(w) + "x" +
                          std::to_string(h),
                      e);
    if (int e = avcodec_parameters_from_context(d.st->codecpar, d.enc); e < 0) return d.fail("cannot set up the stream", e);
    d.st->time_base = d.enc->time_base;
    if (!(d.oc->oformat->flags & AVFMT_NOFILE))
        if (int e = avio_open(&d.oc->pb, file.c_str(), AVIO_FLAG_WRITE); e < 0) return d.fail("cannot create the file", e);
    if (int e = avformat_write_header(d.oc, nullptr); e < 0) return d.fail("cannot write the container's header", e);
    d.header = true;
    d.frame->format = d.enc->pix_fmt;
    d.frame->width = d.w;
    d.frame->height = d.h;
    if (int e = av_frame_get_buffer(d.frame, 0); e < 0) return d.fail("out of memory", e);
    d.sws = sws_getContext(d.w, d.h, AV_PIX_FMT_RGB24, d.w, d.h, d.enc->pix_fmt, SWS_BICUBIC, nullptr, nullptr, nullptr);
    if (!d.sws) return d.fail("cannot convert RGB to the encoder's pixels", 0);
    return {};
}

Status VideoFileWriter::write_rgb(const uint8_t* rgb) {
    Impl& d = *d_;
    if (int e = av_frame_make_writable(d.frame); e < 0) return d.fail("out of memory", e);
    // A copy with room after it: swscale's SIMD reads a little past the last row.
    const size_t bytes = size_t(d.w) * size_t(d.h) * 3;
    d.rgb.resize(bytes + 64);
    std::memcpy(d.rgb.data(), rgb, bytes);
    const uint8_t* src[4] = {d.rgb.data(), nullptr, nullptr, nullptr};
    const int stride[4] = {d.w * 3, 0, 0, 0};
    sws_scale(d.sws, src, stride, 0, d.h, d.frame->data, d.frame->linesize);
    d.frame->pts = d.next_pts++;
    return d.encode(d.frame);
}

Status VideoFileWriter::finish() {
    Impl& d = *d_;
    if (Status s = d.encode(nullptr); !s) return s;
    d.done = true;
    if (int e = av_write_trailer(d.oc); e < 0) return d.fail("cannot finish the file", e);
    if (!(d.oc->oformat->flags & AVFMT_NOFILE))
        if (int e = avio_closep(&d.oc->pb); e < 0) return d.fail("cannot close the file", e);
    return {};
}

}  // namespace spt::video
